// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_BODT_3_INTERNAL_MOVES_VERTEX_STAR_H
#define CGAL_BODT_3_INTERNAL_MOVES_VERTEX_STAR_H

#include <CGAL/Kernel/global_functions.h>

#include <vector>

namespace CGAL {
namespace BODT_3 {
namespace internal {

/// The neighbourhood Omega_0 of a vertex x0, as a move sees it: the mesh
/// tetrahedra incident to x0, each given by its face opposite x0, and the
/// boundary triangles of Omega_0 that contain x0.
///
/// Conventions (checked by the tests):
/// - a cell (a, b, c) has `orientation(x0, a, b, c) == POSITIVE`;
/// - a boundary facet (a, b) is the triangle (x0, a, b), ordered so that
///   (a - x0) x (b - x0) points out of Omega_0: these are the paper's
///   consecutive ring vertices (y_i, y_{i+1}).
/// A vertex inside the mesh has no boundary facet. A vertex on the interface of
/// two subdomains sees the cells of both, with their labels, and no boundary facet
/// there, since the union of its cells surrounds it.
template <class K>
struct Vertex_star
{
  using Point = typename K::Point_3;
  using Vector = typename K::Vector_3;

  struct Cell
  {
    Point a, b, c;
    int subdomain;
  };

  struct Boundary_facet
  {
    Point a, b;
  };

  Point x0;
  std::vector<Cell> cells;
  std::vector<Boundary_facet> boundary;

  void clear()
  {
    cells.clear();
    boundary.clear();
  }

  bool on_boundary() const { return !boundary.empty(); }

  /// The tangent-plane normal of eq. (B.1), n = sum S_i n_i over the boundary
  /// triangles (x0, y_i, y_{i+1}), not normalized. Moving x0 perpendicular to it
  /// keeps |Omega_0| (Appendix B).
  Vector boundary_normal() const
  {
    Vector n(0, 0, 0);
    for(const Boundary_facet& f : boundary)
      n = n + 0.5 * CGAL::cross_product(f.a - x0, f.b - x0);
    return n;
  }

  /// sum over the cells of `subdomain` of S_tau n_tau, with n_tau the unit normal of
  /// the face opposite x0 pointing towards x0. By (B.4) this is the (B.1) normal of
  /// that subdomain's part of the star; it is zero when the part surrounds x0.
  Vector subdomain_normal(int subdomain) const
  {
    Vector n(0, 0, 0);
    for(const Cell& t : cells)
      if(t.subdomain == subdomain)
        n = n - 0.5 * CGAL::cross_product(t.b - t.a, t.c - t.a);
    return n;
  }
};

} // namespace internal
} // namespace BODT_3
} // namespace CGAL

#endif // CGAL_BODT_3_INTERNAL_MOVES_VERTEX_STAR_H
