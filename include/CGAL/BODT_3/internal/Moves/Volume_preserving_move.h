// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_BODT_3_INTERNAL_MOVES_VOLUME_PRESERVING_MOVE_H
#define CGAL_BODT_3_INTERNAL_MOVES_VOLUME_PRESERVING_MOVE_H

#include <CGAL/BODT_3/internal/Moves/Bodt_feature_move.h>
#include <CGAL/BODT_3/internal/Moves/Bodt_surface_move.h>
#include <CGAL/BODT_3/internal/Moves/Odt_interior_move.h>
#include <CGAL/BODT_3/internal/Classification/Vertex_classification.h>
#include <CGAL/BODT_3/internal/Moves/Vertex_star.h>

#include <cmath>
#include <utility>
#include <vector>

namespace CGAL {
namespace BODT_3 {
namespace internal {

/// Chooses and applies the move of a vertex so that the volume of every
/// subdomain around it is kept. Each subdomain j of the star has a (B.1) normal
/// n_j (`Vertex_star::subdomain_normal`); a move X keeps subdomain j's volume iff
/// X . n_j = 0. So the vertex moves in the orthogonal complement of span{n_j}:
///  - rank 0 (inside one subdomain): ODT, Algorithm 1;
///  - rank 1 (on the boundary, or on an interface, where n_1 = -n_2): the tangent
///    plane, Algorithm 2 (Algorithm 3 along the feature direction projected on the
///    plane for a feature vertex);
///  - rank 2 (where two subdomains meet the outside, or three meet): the line
///    n_1 x n_2, Algorithm 3; a feature vertex moves there only if its feature
///    direction is within 60 degrees of that line;
///  - rank 3: no move.
/// `feature_direction` is used for feature vertices only.
struct Volume_preserving_move
{
  template <class K>
  typename K::Vector_3 operator()(const Vertex_star<K>& star, Vertex_kind kind,
                                  const typename K::Vector_3& feature_direction) const
  {
    using Vector = typename K::Vector_3;
    const Vector zero(0, 0, 0);
    if(kind == Vertex_kind::fixed || star.cells.empty()) return zero;
    if(kind == Vertex_kind::interior) return Odt_interior_move()(star);
    Vector basis[3];
    const int rank = normal_basis(star, basis);
    if(rank < 0) return zero;
    if(rank == 0)
      return kind == Vertex_kind::feature ? Bodt_feature_move()(star, feature_direction) : Odt_interior_move()(star);
    if(rank == 1)
    {
      if(kind == Vertex_kind::surface) return Bodt_surface_move()(star, basis[0]);
      const Vector d = feature_direction - (feature_direction * basis[0]) * basis[0];
      return Bodt_feature_move()(star, d);
    }
    if(rank == 2)
    {
      const Vector line = CGAL::cross_product(basis[0], basis[1]);
      if(kind == Vertex_kind::feature && !along(feature_direction, line)) return zero;
      return Bodt_feature_move()(star, line);
    }
    return zero;
  }

  /// An orthonormal basis of the moves that keep every subdomain's volume and the
  /// vertex on its feature: what the closed forms above minimize over. Returns how
  /// many directions: 3 inside a subdomain, 2 on a surface, 1 along a feature or a
  /// junction, 0 for a vertex that cannot move.
  template <class K>
  int free_directions(const Vertex_star<K>& star, Vertex_kind kind, const typename K::Vector_3& feature_direction,
                      typename K::Vector_3 out[3]) const
  {
    using Vector = typename K::Vector_3;
    if(kind == Vertex_kind::fixed || star.cells.empty()) return 0;
    Vector basis[3];
    const int rank = kind == Vertex_kind::interior ? 0 : normal_basis(star, basis);
    if(rank < 0 || rank == 3) return 0;
    auto unit = [](const Vector& v) { return v / std::sqrt(v.squared_length()); };
    if(kind == Vertex_kind::feature || rank == 2)
    {
      Vector d = rank == 2 ? CGAL::cross_product(basis[0], basis[1]) : feature_direction;
      for(int i = 0; i < rank && rank < 2; ++i) d = d - (d * basis[i]) * basis[i];
      if(kind == Vertex_kind::feature && rank == 2 && !along(feature_direction, d)) return 0;
      if(!(d.squared_length() > 0)) return 0;
      out[0] = unit(d);
      return 1;
    }
    if(rank == 0)
    {
      out[0] = Vector(1, 0, 0);
      out[1] = Vector(0, 1, 0);
      out[2] = Vector(0, 0, 1);
      return 3;
    }
    // The tangent plane of basis[0].
    const Vector n = basis[0];
    const Vector a = std::abs(n.x()) < 0.6 ? Vector(1, 0, 0) : Vector(0, 1, 0);
    out[0] = unit(a - (a * n) * n);
    out[1] = CGAL::cross_product(n, out[0]);
    return 2;
  }

private:
  // Orthonormal basis of span{n_j}, the (B.1) normals of the subdomains of the
  // star. A normal that vanishes (a part surrounding x0) or repeats another up to
  // round-off (two sides of an interface) adds no direction: residuals below 1e-9
  // of that subdomain's face area are dropped. The normals are taken in order of
  // that area, smallest first: on an interface the two sides give the same
  // direction, and the side with the smaller faces gives it with the smaller
  // rounding error (a side with faces of 1e10 beside faces of 1 loses the small
  // side's digits). Ties are broken by label. -1 for eight subdomains or more.
  template <class K>
  static int normal_basis(const Vertex_star<K>& star, typename K::Vector_3 basis[3])
  {
    using Vector = typename K::Vector_3;
    struct Part
    {
      int subdomain;
      double area;
    };
    Part parts[8];
    int nparts = 0;
    for(const auto& cell : star.cells)
    {
      int i = 0;
      while(i < nparts && parts[i].subdomain != cell.subdomain) ++i;
      if(i == nparts)
      {
        if(nparts == 8) return -1;   // eight subdomains at one point: leave it
        parts[nparts++] = Part{cell.subdomain, 0.0};
      }
      parts[i].area += 0.5 * std::sqrt(CGAL::cross_product(cell.b - cell.a, cell.c - cell.a).squared_length());
    }
    // At most eight parts: an insertion sort.
    for(int i = 1; i < nparts; ++i)
      for(int j = i; j > 0; --j)
      {
        const Part &x = parts[j], &y = parts[j - 1];
        if(!(x.area < y.area || (x.area == y.area && x.subdomain < y.subdomain))) break;
        std::swap(parts[j], parts[j - 1]);
      }
    int rank = 0;
    for(int k = 0; k < nparts; ++k)
    {
      Vector n = star.subdomain_normal(parts[k].subdomain);
      for(int i = 0; i < rank; ++i) n = n - (n * basis[i]) * basis[i];
      const double res = std::sqrt(n.squared_length());
      if(res > 1e-9 * parts[k].area && rank < 3) basis[rank++] = n / res;
    }
    return rank;
  }

  // Whether a feature direction follows the junction line n_1 x n_2 (whose length
  // is the sine between the normals): |d . line| >= |d| / 2.
  template <class Vector>
  static bool along(const Vector& feature_direction, const Vector& line)
  {
    const double len = std::sqrt(feature_direction.squared_length());
    return len > 0 && std::abs(feature_direction * line) >= 0.5 * len;
  }
};

} // namespace internal
} // namespace BODT_3
} // namespace CGAL

#endif // CGAL_BODT_3_INTERNAL_MOVES_VOLUME_PRESERVING_MOVE_H
