// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_BODT_3_INTERNAL_SMOOTHING_MOVE_GUARD_H
#define CGAL_BODT_3_INTERNAL_SMOOTHING_MOVE_GUARD_H

#include <CGAL/BODT_3/internal/Mesh/Flat_mesh.h>
#include <CGAL/BODT_3/internal/Smoothing/Boundary_distance_guard.h>
#include <CGAL/BODT_3/internal/Utilities/Thread_workers.h>
#include <CGAL/BODT_3/internal/Smoothing/Volume_budget.h>
#include <CGAL/BODT_3/internal/Quality/tet_quality.h>

#include <CGAL/FPU.h>

#include <CGAL/Kernel/global_functions.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace CGAL {
namespace BODT_3 {
namespace internal {

/// Decides whether a vertex may go to a new position, and applies accepted moves.
///
/// Validity (always): every finite cell incident to the vertex, in the mesh or
/// not, stays positively oriented, decided by CGAL's exact orientation predicate;
/// for a triangulation, every locally convex hull edge next to the vertex stays
/// convex, so the convex hull remains one.
///
/// Volume (with a budget): a vertex whose mesh cells are of one subdomain and
/// which is on no boundary keeps that volume exactly, since its link stays; any
/// other move costs what `Volume_change` bounds for the subdomains of its star,
/// and is refused above the allowance `allow` set (see Volume_budget).
///
/// Quality (when `quality_guard` is on): the worst mesh cell of the star, by the
/// measure of tet_quality.h (minimum dihedral sine by default), is not worse after the move,
/// and every mesh cell of the star stays within `bounds` (the input's extreme
/// dihedral angles). Since a move only changes the cells of its star, the mesh's
/// worst cell never gets worse, nor does either extreme angle.
///
/// Surface (with a `Boundary_distance_guard`): a vertex on the boundary or an
/// interface, and its surface triangles, stay within the bound of the input's surface.
///
/// A refused move is retried at 1/2, 1/4 and 1/8 of its length before giving up.
///
/// What one attempt leaves behind (the star's new qualities, why it was refused)
/// lives in a `Trial` that the caller owns: vertices with disjoint stars can be
/// judged and moved concurrently, each thread with its own trial.
template <class K>
class Move_guard
{
public:
  using Point = typename K::Point_3;
  using Vector = typename K::Vector_3;

  static constexpr int max_halvings = 3;

  /// Why the last refused position was refused.
  enum class Refusal
  {
    inverts_mesh_cell,
    inverts_outside_cell,
    breaks_convex_hull,
    changes_volume,
    worsens_quality,
    leaves_surface
  };

  /// The state of one attempt, owned by the caller (one per thread).
  struct Trial
  {
    std::vector<double> qualities;   // the star's mesh cells at the position judged last
    Refusal last_refusal = Refusal::worsens_quality;
    Refusal first_refusal = Refusal::worsens_quality;   // of the full-length move
    Volume_change volume;
    double cost = 0;   // of the position judged last, in the budget's units
    typename Boundary_distance_guard<K>::Scratch surface;
    std::vector<std::array<Point, 2>> corners;   // of the surface triangles around the vertex
  };

  /// `threads` measure the cells (`refresh`); nothing depends on their number.
  /// `budget`, when given, prices the moves that may change a subdomain's volume;
  /// `distance`, when given and active, bounds how far the surface may go.
  Move_guard(Flat_mesh<K>& mesh, bool quality_guard, const Dihedral_bounds& bounds,
             Quality_measure measure = Quality_measure::min_dihedral_sine, int threads = 1,
             const Volume_budget* budget = nullptr, const Boundary_distance_guard<K>* distance = nullptr)
    : mesh_(mesh), quality_guard_(quality_guard), bounds_(bounds), measure_(measure), workers_(threads),
      budget_(budget && budget->limited() ? budget : nullptr),
      distance_(distance && distance->active() ? distance : nullptr)
  {
    if(budget_) allowance_ = budget_->allowance();
    refresh();
  }

  /// The most a move may cost until the next call (a share of the budget's allowance).
  void allow(double allowance) { allowance_ = allowance; }

  /// Whether moves of `v` keep every subdomain's volume exactly (see the class comment).
  bool keeps_volume(int v) const { return !budget_ || keeps_volume_[v]; }

  /// Re-reads the cell qualities, which vertices keep their volume and the
  /// surface triangles around each vertex, after the mesh's cells changed.
  void refresh()
  {
    const int nv = static_cast<int>(mesh_.number_of_vertices());
    stale_.assign(nv, 0);
    if(distance_) surface_facets_by_vertex(mesh_, surface_begin_, surface_facets_);
    if(budget_)
    {
      keeps_volume_.assign(nv, 1);
      workers_.for_each(0, nv, [this](char&, int v) { keeps_volume_[v] = keeps_volume_now(v); }, 1024);
    }
    if(!quality_guard_) return;
    quality_.resize(mesh_.cells.size());
    workers_.for_each(0, static_cast<int>(mesh_.cells.size()), [this](char&, int c) { quality_[c] = measure(c); },
                      1024);
  }

  /// The same as `refresh()` after the cells changed as `moves` says
  /// (Flat_view::Cell_moves) and the vertices `moved` went elsewhere than by
  /// `apply`, measuring only what may have changed: the new cells, and the cells
  /// around a vertex moved since the last refresh (`apply` measures a cell from
  /// the moved vertex, a refresh in the cell's order, which may round otherwise);
  /// the other cells keep their quality, moved with them.
  template <class Moves>
  void refresh(const Moves& moves, const std::vector<int>& moved)
  {
    if(moves.whole)
    {
      refresh();
      return;
    }
    const int nv = static_cast<int>(mesh_.number_of_vertices());
    stale_.resize(nv, 0);   // a new vertex is in new cells only
    for(int v : moved) stale_[v] = 1;
    if(distance_) surface_facets_by_vertex(mesh_, surface_begin_, surface_facets_);
    if(budget_)
    {
      // Only a vertex of a new cell has other cells around it than before.
      keeps_volume_.resize(nv, 1);
      for(int c : moves.fresh)
        for(int v : mesh_.cells[c]) keeps_volume_[v] = keeps_volume_now(v);
    }
    if(quality_guard_)
    {
      moves.shift.relocate(quality_, 1, moves.kept_before, mesh_.cells.size());
      for(int c : moves.fresh) quality_[c] = measure(c);
      // Each cell once, whatever the number of its vertices that moved (after a
      // sweep, most of them).
      workers_.for_each(0, static_cast<int>(mesh_.cells.size()), [this](char&, int c) {
        const auto& q = mesh_.cells[c];
        if(stale_[q[0]] || stale_[q[1]] || stale_[q[2]] || stale_[q[3]]) quality_[c] = measure(c);
      }, 1024);
    }
    std::fill(stale_.begin(), stale_.end(), 0);
  }

  /// Moves `v` by `X`, or by the longest of X/2, X/4, X/8 that is accepted;
  /// each position goes through `place` first (NODT projects it on the boundary).
  /// Returns the fraction of X applied (0 when the vertex stays).
  template <class Place>
  double move(int v, const Vector& X, const Place& place, Trial& trial)
  {
    const Point x0 = mesh_.points[v];
    double fraction = 1.0;
    for(int h = 0; h <= max_halvings; ++h, fraction *= 0.5)
    {
      const Point p = place(x0 + fraction * X);
      if(p == x0) return 0.0;
      if(accepts(v, p, trial))
      {
        apply(v, p, trial);
        return fraction;
      }
      if(h == 0) trial.first_refusal = trial.last_refusal;
    }
    return 0.0;
  }

  double move(int v, const Vector& X, Trial& trial)
  {
    return move(v, X, [](const Point& p) { return p; }, trial);
  }

  /// The quality of cell `c` now.
  double cell_quality(int c) const { return quality_[c]; }

  /// The worst quality of the mesh cells around `v` now.
  double worst_around(int v) const
  {
    double worst = 2;
    for(int k = mesh_.incidence_begin[v]; k < mesh_.incidence_begin[v + 1]; ++k)
    {
      const int c = mesh_.incidences[k].cell;
      if(mesh_.in_mesh[c]) worst = std::min(worst, quality_[c]);
    }
    return worst;
  }

  /// The worst quality of the mesh cells around the vertex at the position the
  /// last successful `accepts` with this trial judged (2 without mesh cells).
  static double accepted_worst(const Trial& trial)
  {
    double worst = 2;
    for(double q : trial.qualities) worst = std::min(worst, q);
    return worst;
  }

  /// Whether `v` may go to `p` (see the class comment). Leaves the star's new
  /// cell qualities in the trial, for `apply`.
  bool accepts(int v, const Point& p, Trial& trial) const
  {
    return judge(v, mesh_.points[v], p, nullptr, allowance_, trial);
  }

  /// What the vertex was judged against, for `accepts_from`: where it is, the
  /// worst quality of its star's mesh cells there, and the allowance.
  struct Vertex_state
  {
    Point position;
    double worst;
    double allowance;
  };

  /// `accepts` for `v` as if it were in `state` (its neighbours where they are):
  /// a search that moves `v` several times can be judged without writing the
  /// mesh, and applied later if nothing it read changed.
  bool accepts_from(int v, const Vertex_state& state, const Point& p, Trial& trial) const
  {
    return judge(v, state.position, p, &state.worst, state.allowance, trial);
  }

  /// Whether `apply` moved vertex `v` since the last refresh (which measures its
  /// cells again).
  bool moved_since_refresh(int v) const { return v < static_cast<int>(stale_.size()) && stale_[v]; }

  /// The allowance moves are judged against now.
  double allowance() const { return allowance_; }

private:
  // `accepts` with v at x0, its star's worst quality `worst` (null: read from
  // the mesh), and `allowance`.
  bool judge(int v, const Point& x0, const Point& p, const double* worst, double allowance, Trial& trial) const
  {
    const auto& m = mesh_;
    for(int k = m.incidence_begin[v]; k < m.incidence_begin[v + 1]; ++k)
    {
      const auto& f = m.incidences[k].face;
      if(CGAL::orientation(p, m.points[f[0]], m.points[f[1]], m.points[f[2]]) != CGAL::POSITIVE)
      {
        trial.last_refusal = m.in_mesh[m.incidences[k].cell] ? Refusal::inverts_mesh_cell : Refusal::inverts_outside_cell;
        return false;
      }
    }
    for(int k = m.hull_begin[v]; k < m.hull_begin[v + 1]; ++k)
    {
      const auto& h = m.vertex_hull_checks[k];
      const Point& a = h[0] == v ? p : m.points[h[0]];
      const Point& b = h[1] == v ? p : m.points[h[1]];
      const Point& c = h[2] == v ? p : m.points[h[2]];
      if(CGAL::orientation(a, b, c, m.points[h[3]]) == CGAL::NEGATIVE)
      {
        trial.last_refusal = Refusal::breaks_convex_hull;
        return false;
      }
    }
    trial.cost = 0;
    if(!keeps_volume(v))
    {
      trial.volume.clear();
      {
        CGAL::Protect_FPU_rounding<true> upward;
        for(int k = m.incidence_begin[v]; k < m.incidence_begin[v + 1]; ++k)
        {
          const int c = m.incidences[k].cell;
          if(!m.in_mesh[c]) continue;
          const auto& f = m.incidences[k].face;
          trial.volume.add_move(m.subdomain[c], x0, p, m.points[f[0]], m.points[f[1]], m.points[f[2]]);
        }
      }
      trial.cost = budget_->cost(trial.volume);
      if(!(trial.cost <= allowance))
      {
        trial.last_refusal = Refusal::changes_volume;
        return false;
      }
    }
    trial.last_refusal = Refusal::worsens_quality;
    if(quality_guard_ && !keeps_quality(v, p, worst ? *worst : worst_around(v), trial)) return false;
    if(distance_ && !stays_near_surface(v, x0, p, trial))
    {
      trial.last_refusal = Refusal::leaves_surface;
      return false;
    }
    return true;
  }

public:
  /// Moves `v` to `p`, which `accepts(v, p, trial)` has just approved.
  void apply(int v, const Point& p, const Trial& trial) { apply(v, p, trial.qualities); }

  /// Moves `v` to `p`, with `qualities` those an approving trial left there.
  void apply(int v, const Point& p, const std::vector<double>& qualities)
  {
    mesh_.points[v] = p;
    if(!quality_guard_) return;
    stale_[v] = 1;
    std::size_t i = 0;
    for(int k = mesh_.incidence_begin[v]; k < mesh_.incidence_begin[v + 1]; ++k)
    {
      const int c = mesh_.incidences[k].cell;
      if(mesh_.in_mesh[c]) quality_[c] = qualities[i++];
    }
  }

private:
  double measure(int c) const
  {
    const auto& q = mesh_.cells[c];
    return tet_quality(measure_, mesh_.points[q[0]], mesh_.points[q[1]], mesh_.points[q[2]], mesh_.points[q[3]]);
  }

  // Whether every move of v keeps the volumes (see the class comment).
  bool keeps_volume_now(int v) const
  {
    int first = -1;   // the first mesh cell around v
    bool one = mesh_.boundary_begin[v] == mesh_.boundary_begin[v + 1];
    for(int k = mesh_.incidence_begin[v]; one && k < mesh_.incidence_begin[v + 1]; ++k)
    {
      const int c = mesh_.incidences[k].cell;
      if(!mesh_.in_mesh[c]) continue;
      if(first < 0) first = c;
      one = mesh_.subdomain[c] == mesh_.subdomain[first];
    }
    return one;
  }

  // The quality part of `accepts`: the star's worst mesh cell is not worse at p,
  // and every mesh cell of the star is within the bounds.
  bool keeps_quality(int v, const Point& p, double old_worst, Trial& trial) const
  {
    const auto& m = mesh_;
    trial.qualities.clear();
    for(int k = m.incidence_begin[v]; k < m.incidence_begin[v + 1]; ++k)
    {
      const int c = m.incidences[k].cell;
      if(!m.in_mesh[c]) continue;
      const auto& f = m.incidences[k].face;
      const Point &a = m.points[f[0]], &b = m.points[f[1]], &d = m.points[f[2]];
      const Measured_tet<Point> tet(measure_, p, a, b, d);
      const double q = tet.quality();
      if(q < old_worst || !tet.within(bounds_)) return false;
      trial.qualities.push_back(q);
    }
    return true;
  }

  // The surface part of `accepts`: a vertex with surface triangles stays, with
  // them, within the distance bound.
  bool stays_near_surface(int v, const Point& x0, const Point& p, Trial& trial) const
  {
    trial.corners.clear();
    for(int k = surface_begin_[v]; k < surface_begin_[v + 1]; ++k)
      trial.corners.push_back({mesh_.points[surface_facets_[k][0]], mesh_.points[surface_facets_[k][1]]});
    return distance_->keeps_near(x0, p, trial.corners, trial.surface);
  }

  Flat_mesh<K>& mesh_;
  bool quality_guard_;
  Dihedral_bounds bounds_;
  Quality_measure measure_;
  std::vector<double> quality_;   // per cell
  std::vector<char> stale_;   // per vertex: moved by `apply` since the last refresh
  Thread_workers<char> workers_;
  const Volume_budget* budget_;     // null: volume not priced
  double allowance_ = 0;
  std::vector<char> keeps_volume_;   // per vertex
  const Boundary_distance_guard<K>* distance_;   // null: no bound on the surface
  std::vector<int> surface_begin_;               // per vertex, into surface_facets_
  std::vector<std::array<int, 2>> surface_facets_;
};

} // namespace internal
} // namespace BODT_3
} // namespace CGAL

#endif // CGAL_BODT_3_INTERNAL_SMOOTHING_MOVE_GUARD_H
