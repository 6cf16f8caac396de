// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_BODT_3_INTERNAL_SMOOTHING_LOCAL_SMOOTHING_H
#define CGAL_BODT_3_INTERNAL_SMOOTHING_LOCAL_SMOOTHING_H

#include <CGAL/BODT_3/internal/Mesh/Triangulation_adapter.h>
#include <CGAL/BODT_3/internal/Mesh/Flat_mesh.h>
#include <CGAL/BODT_3/internal/Classification/Tensor_voting.h>
#include <CGAL/BODT_3/internal/Classification/Vertex_classification.h>
#include <CGAL/BODT_3/internal/Moves/Vertex_star.h>
#include <CGAL/BODT_3/internal/Smoothing/Boundary_distance_guard.h>
#include <CGAL/BODT_3/internal/Smoothing/Volume_budget.h>
#include <CGAL/BODT_3/internal/Moves/Volume_preserving_move.h>
#include <CGAL/BODT_3/internal/Utilities/bare_point.h>
#include <CGAL/BODT_3/internal/Quality/tet_quality.h>

#include <CGAL/FPU.h>
#include <CGAL/Kernel/global_functions.h>
#include <CGAL/Kernel_traits.h>

#include <algorithm>
#include <array>
#include <iterator>
#include <vector>

namespace CGAL {
namespace BODT_3 {
namespace internal {

/// The B-ODT move of single vertices, made on the triangulation itself: what a
/// split needs right away, before the flat view of the sweeps is re-read. The
/// move is the sweep's (`Volume_preserving_move` by the vertex's kind) and is
/// checked the same way: every finite cell around the vertex stays positively
/// oriented (exact predicate), the star's worst mesh cell does not get worse and
/// stays within the bounds, and the convex hull stays locally convex where it is
/// now (as in the sweeps), and, with a `budget`, a move that may change a
/// subdomain's volume is paid from it as in the sweeps (Move_guard), and, with a
/// `distance` guard, a surface vertex and its surface triangles stay near the
/// input's surface; a refused move is tried at 1/2, 1/4, 1/8.
template <class Adapter>
class Local_smoothing
{
public:
  using Tr = typename Adapter::Triangulation;
  using Vertex_handle = typename Adapter::Vertex_handle;
  using Cell_handle = typename Adapter::Cell_handle;
  using Point = Bare_point_t<Tr>;
  using K = typename CGAL::Kernel_traits<Point>::Kernel;
  using Vector = typename K::Vector_3;

  Local_smoothing(Adapter& adapter, const Dihedral_bounds& bounds, Quality_measure measure,
                  const Tensor_voting_options& voting, Volume_budget* budget = nullptr,
                  const Boundary_distance_guard<K>* distance = nullptr)
    : adapter_(adapter), bounds_(bounds), measure_(measure), voting_(voting),
      budget_(budget && budget->limited() ? budget : nullptr),
      distance_(distance && distance->active() ? distance : nullptr)
  {}

  /// Moves `v` by its move for `kind` (a feature vertex moves along the chord
  /// between `a` and `b`, its neighbours on the curve, or by tensor voting when
  /// they are unknown). Returns whether it moved.
  bool move(Vertex_handle v, Vertex_kind kind, Vertex_handle a = Vertex_handle(), Vertex_handle b = Vertex_handle())
  {
    if(kind == Vertex_kind::fixed) return false;
    const Tr& tr = adapter_.triangulation();
    all_cells_.clear();
    tr.tds().incident_cells(v, std::back_inserter(all_cells_));
    cells_.clear();
    hull_.clear();
    for(const Cell_handle& c : all_cells_)
      if(tr.is_infinite(c))
      {
        if(adapter_.convex_hull()) add_hull_checks(c);
      }
      else
        cells_.push_back(c);
    gather(v);
    Vector direction(0, 0, 0);
    if(kind == Vertex_kind::feature)
      direction = a != Vertex_handle() ? bare_point(tr, b) - bare_point(tr, a) : tensor_vote(star_, voting_).direction;
    const Vector X = Volume_preserving_move()(star_, kind, direction);
    if(X == CGAL::NULL_VECTOR) return false;

    double old_worst = 2;
    for(const Cell_handle& c : cells_)
      if(adapter_.region(c).kind == Region_kind::mesh) old_worst = std::min(old_worst, quality(c, v, star_.x0));
    double fraction = 1;
    for(int h = 0; h < 4; ++h, fraction *= 0.5)
    {
      const Point p = star_.x0 + fraction * X;
      if(p == star_.x0) return false;
      if(accepts(v, p, old_worst))
      {
        set_bare_point(tr, v, p);
        if(budget_) budget_->spend(cost_);
        return true;
      }
    }
    return false;
  }

private:
  double quality(Cell_handle c, Vertex_handle v, const Point& p) const
  {
    const Tr& tr = adapter_.triangulation();
    Point q[4];
    for(int k = 0; k < 4; ++k) q[k] = c->vertex(k) == v ? p : bare_point(tr, c->vertex(k));
    return tet_quality(measure_, q[0], q[1], q[2], q[3]);
  }

  // For a hull facet (the finite facet of infinite cell c) and each hull facet next
  // to it, the far vertex of the neighbour must stay on the inner side; checks
  // that do not hold now (a boundary that is no convex hull) are left out.
  void add_hull_checks(Cell_handle c)
  {
    const Tr& tr = adapter_.triangulation();
    const int i = c->index(tr.infinite_vertex());
    const Cell_handle fc = c->neighbor(i);
    const auto& o = internal::facet_opposite[fc->index(c)];
    const std::array<Vertex_handle, 3> f = {fc->vertex(o[0]), fc->vertex(o[2]), fc->vertex(o[1])};
    for(int k = 0; k < 4; ++k)
    {
      if(k == i) continue;
      const Cell_handle nc = c->neighbor(k);
      const Vertex_handle w = nc->vertex(nc->index(c));
      if(tr.is_infinite(w)) continue;
      if(CGAL::orientation(bare_point(tr, f[0]), bare_point(tr, f[1]), bare_point(tr, f[2]), bare_point(tr, w)) !=
         CGAL::NEGATIVE)
        hull_.push_back({f[0], f[1], f[2], w});
    }
  }

  bool accepts(Vertex_handle v, const Point& p, double old_worst)
  {
    const Tr& tr = adapter_.triangulation();
    for(const auto& h : hull_)
    {
      Point q[4];
      for(int k = 0; k < 4; ++k) q[k] = h[k] == v ? p : bare_point(tr, h[k]);
      if(CGAL::orientation(q[0], q[1], q[2], q[3]) == CGAL::NEGATIVE) return false;
    }
    for(const Cell_handle& c : cells_)
    {
      Point q[4];
      for(int k = 0; k < 4; ++k) q[k] = c->vertex(k) == v ? p : bare_point(tr, c->vertex(k));
      if(CGAL::orientation(q[0], q[1], q[2], q[3]) != CGAL::POSITIVE) return false;
      if(adapter_.region(c).kind != Region_kind::mesh) continue;
      const double quality = tet_quality(measure_, q[0], q[1], q[2], q[3]);
      if(quality < old_worst ||
         !bounds_.contains(q[0], q[1], q[2], q[3], measure_ == Quality_measure::min_dihedral_sine ? quality : 0.0))
        return false;
    }
    return volume_within_budget(p) && stays_near_surface(p);
  }

  // Whether the vertex at p, and its surface triangles, are within the distance bound.
  bool stays_near_surface(const Point& p)
  {
    return !distance_ || distance_->keeps_near(star_.x0, p, surface_, scratch_);
  }

  // Whether moving the star's vertex to p costs no more than the budget allows
  // (leaves the cost in cost_). A vertex inside one subdomain keeps its volume.
  bool volume_within_budget(const Point& p)
  {
    cost_ = 0;
    if(!budget_ || star_.cells.empty()) return true;
    bool one = !star_.on_boundary();
    for(const auto& c : star_.cells) one = one && c.subdomain == star_.cells[0].subdomain;
    if(one) return true;
    change_.clear();
    {
      CGAL::Protect_FPU_rounding<true> upward;
      for(const auto& c : star_.cells) change_.add_move(c.subdomain, star_.x0, p, c.a, c.b, c.c);
    }
    cost_ = budget_->cost(change_);
    return cost_ <= budget_->allowance();
  }

  // The star as the moves see it (Vertex_star's conventions).
  void gather(Vertex_handle v)
  {
    const Tr& tr = adapter_.triangulation();
    star_.clear();
    surface_.clear();
    star_.x0 = bare_point(tr, v);
    for(const Cell_handle& c : cells_)
    {
      const auto r = adapter_.region(c);
      if(r.kind != Region_kind::mesh) continue;
      const int i = c->index(v);
      const auto& o = internal::facet_opposite[i];
      star_.cells.push_back({bare_point(tr, c->vertex(o[0])), bare_point(tr, c->vertex(o[1])),
                             bare_point(tr, c->vertex(o[2])), static_cast<int>(r.subdomain)});
      for(int j = 0; j < 4; ++j)
      {
        if(j == i || adapter_.region(c->neighbor(j)) == r) continue;
        // A boundary or interface triangle (v, x, y): the distance bound's concern.
        std::array<Point, 2> xy;
        for(int k = 0, m = 0; k < 4; ++k)
          if(k != i && k != j) xy[m++] = bare_point(tr, c->vertex(k));
        surface_.push_back(xy);
        if(adapter_.region(c->neighbor(j)).kind == Region_kind::mesh) continue;
        // The facet opposite j, oriented with its normal out of the mesh, from v.
        const auto& f = internal::facet_opposite[j];
        for(int k = 0; k < 3; ++k)
          if(c->vertex(f[k]) == v)
            star_.boundary.push_back({bare_point(tr, c->vertex(f[(k + 1) % 3])), bare_point(tr, c->vertex(f[(k + 2) % 3]))});
      }
    }
  }

  Adapter& adapter_;
  Dihedral_bounds bounds_;
  Quality_measure measure_;
  Tensor_voting_options voting_;
  std::vector<Cell_handle> all_cells_, cells_;   // around the vertex; the finite ones
  std::vector<std::array<Vertex_handle, 4>> hull_;
  Vertex_star<K> star_;
  Volume_budget* budget_;   // null: volume not priced
  Volume_change change_;
  double cost_ = 0;   // of the position judged last
  const Boundary_distance_guard<K>* distance_;   // null: no bound on the surface
  std::vector<std::array<Point, 2>> surface_;     // the other vertices of the surface triangles around the vertex
  typename Boundary_distance_guard<K>::Scratch scratch_;
};

} // namespace internal
} // namespace BODT_3
} // namespace CGAL

#endif // CGAL_BODT_3_INTERNAL_SMOOTHING_LOCAL_SMOOTHING_H
