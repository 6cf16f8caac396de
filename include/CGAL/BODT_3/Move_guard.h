// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_BODT_3_MOVE_GUARD_H
#define CGAL_BODT_3_MOVE_GUARD_H

#include <CGAL/BODT_3/Smoothing_mesh.h>

#include <CGAL/Kernel/global_functions.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace CGAL {
namespace BODT_3 {

/// Decides whether a vertex may go to a new position, and applies accepted moves.
///
/// Validity (always): every finite cell incident to the vertex, in the mesh or
/// not, stays positively oriented, decided by CGAL's exact orientation predicate;
/// for a triangulation, every locally convex hull edge next to the vertex stays
/// convex, so the convex hull remains one.
///
/// Quality (when `quality_guard` is on): the smallest dihedral angle over the mesh
/// cells of the star does not decrease and the largest does not increase. Since a
/// move only changes the cells of its star, the mesh's extreme angles can then
/// never get worse. With a and b the unit outward normals of the two faces at an
/// edge, the dihedral angle theta there has |a + b|^2 = 2 - 2 cos(theta), which
/// grows with theta, and |a - b|^2 = 2 + 2 cos(theta), which shrinks: comparing
/// these instead of angles avoids inverse trigonometry on the hot path, and unlike
/// cosines they keep full relative precision near 0 and 180 degrees, where the
/// worst tetrahedra are.
///
/// A refused move is retried at 1/2, 1/4 and 1/8 of its length before giving up.
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
    worsens_quality
  };

  Move_guard(Smoothing_mesh<K>& mesh, bool quality_guard) : mesh_(mesh), quality_guard_(quality_guard)
  {
    if(!quality_guard_) return;
    small_.resize(mesh.cells.size());
    large_.resize(mesh.cells.size());
    for(std::size_t c = 0; c < mesh.cells.size(); ++c)
    {
      const auto& q = mesh.cells[c];
      cell_measures(mesh.points[q[0]], mesh.points[q[1]], mesh.points[q[2]], mesh.points[q[3]], small_[c], large_[c]);
    }
  }

  /// Moves `v` by `X`, or by the longest of X/2, X/4, X/8 that is accepted.
  /// Returns the fraction of X applied (0 when the vertex stays).
  double move(int v, const Vector& X)
  {
    const Point x0 = mesh_.points[v];
    double fraction = 1.0;
    for(int h = 0; h <= max_halvings; ++h, fraction *= 0.5)
    {
      const Point p = x0 + fraction * X;
      if(p == x0) return 0.0;
      if(accepts(v, p))
      {
        apply(v, p);
        return fraction;
      }
      if(h == 0) first_refusal_ = last_refusal_;
    }
    return 0.0;
  }

  /// Why the full-length move of the last refused vertex was refused.
  Refusal first_refusal() const { return first_refusal_; }

  /// Whether `v` may go to `p` (see the class comment). Leaves its verdict on the
  /// star's cell qualities in a buffer that `apply` uses.
  bool accepts(int v, const Point& p)
  {
    const auto& m = mesh_;
    for(int k = m.incidence_begin[v]; k < m.incidence_begin[v + 1]; ++k)
    {
      const auto& f = m.incidences[k].face;
      if(CGAL::orientation(p, m.points[f[0]], m.points[f[1]], m.points[f[2]]) != CGAL::POSITIVE)
      {
        last_refusal_ = m.in_mesh[m.incidences[k].cell] ? Refusal::inverts_mesh_cell : Refusal::inverts_outside_cell;
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
        last_refusal_ = Refusal::breaks_convex_hull;
        return false;
      }
    }
    last_refusal_ = Refusal::worsens_quality;
    if(!quality_guard_) return true;

    double old_small = 5, old_large = 5;
    for(int k = m.incidence_begin[v]; k < m.incidence_begin[v + 1]; ++k)
    {
      const int c = m.incidences[k].cell;
      if(!m.in_mesh[c]) continue;
      old_small = std::min(old_small, small_[c]);
      old_large = std::min(old_large, large_[c]);
    }
    scratch_.clear();
    for(int k = m.incidence_begin[v]; k < m.incidence_begin[v + 1]; ++k)
    {
      const int c = m.incidences[k].cell;
      if(!m.in_mesh[c]) continue;
      const auto& f = m.incidences[k].face;
      double small, large;
      cell_measures(p, m.points[f[0]], m.points[f[1]], m.points[f[2]], small, large);
      if(small < old_small || large < old_large) return false;
      scratch_.push_back({small, large});
    }
    return true;
  }

  /// Moves `v` to `p`, which `accepts(v, p)` has just approved.
  void apply(int v, const Point& p)
  {
    mesh_.points[v] = p;
    if(!quality_guard_) return;
    std::size_t i = 0;
    for(int k = mesh_.incidence_begin[v]; k < mesh_.incidence_begin[v + 1]; ++k)
    {
      const int c = mesh_.incidences[k].cell;
      if(!mesh_.in_mesh[c]) continue;
      small_[c] = scratch_[i].first;
      large_[c] = scratch_[i].second;
      ++i;
    }
  }

  /// Over the six dihedral angles of a tetrahedron, the smallest |a + b|^2 (which
  /// measures its smallest angle) and the smallest |a - b|^2 (its largest angle);
  /// both are larger for a better tetrahedron.
  static void cell_measures(const Point& p0, const Point& p1, const Point& p2, const Point& p3, double& small,
                            double& large)
  {
    const Point* p[4] = {&p0, &p1, &p2, &p3};
    Vector n[4];
    for(int k = 0; k < 4; ++k)
    {
      const auto& o = internal::kOpposite[k];
      n[k] = CGAL::cross_product(*p[o[1]] - *p[o[0]], *p[o[2]] - *p[o[0]]);   // outward
      const double len = std::sqrt(n[k].squared_length());
      n[k] = len > 0 ? n[k] / len : n[k];
    }
    small = large = 4;
    for(int k = 0; k < 4; ++k)
      for(int l = k + 1; l < 4; ++l)
      {
        small = std::min(small, (n[k] + n[l]).squared_length());
        large = std::min(large, (n[k] - n[l]).squared_length());
      }
  }

private:
  Smoothing_mesh<K>& mesh_;
  bool quality_guard_;
  std::vector<double> small_, large_;   // per cell, see cell_measures
  std::vector<std::pair<double, double>> scratch_;
  Refusal last_refusal_ = Refusal::worsens_quality;
  Refusal first_refusal_ = Refusal::worsens_quality;
};

} // namespace BODT_3
} // namespace CGAL

#endif // CGAL_BODT_3_MOVE_GUARD_H
