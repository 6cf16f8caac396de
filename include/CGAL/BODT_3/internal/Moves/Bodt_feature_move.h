// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_BODT_3_INTERNAL_MOVES_BODT_FEATURE_MOVE_H
#define CGAL_BODT_3_INTERNAL_MOVES_BODT_FEATURE_MOVE_H

#include <CGAL/BODT_3/internal/Moves/Interpolation_error.h>
#include <CGAL/BODT_3/internal/Moves/Vertex_star.h>

#include <cmath>

namespace CGAL {
namespace BODT_3 {
namespace internal {

/// Algorithm 3, the advanced B-ODT move of a vertex on a feature curve:
/// x* = x0 + f d along the feature direction d, minimizing Error = A f^2 + B f,
/// so f = -B / (2A), with A = d^T Q d and B = b.d from `Interpolation_error`.
/// The caller gives d perpendicular to the (B.1) normal (the feature direction
/// projected onto the tangent plane): only then is the volume kept and the
/// error exactly quadratic. Where A <= 0 there is no minimum and the vertex does
/// not move. Returns the displacement x* - x0.
struct Bodt_feature_move
{
  template <class K>
  typename K::Vector_3 operator()(const Vertex_star<K>& star, const typename K::Vector_3& direction) const
  {
    using Vector = typename K::Vector_3;
    const double len = std::sqrt(direction.squared_length());
    if(!(len > 0)) return Vector(0, 0, 0);
    const Vector d = direction / len;
    const Interpolation_error<K> error(star);
    const double A = error.quadratic(d, d);
    const double B = error.linear(d);
    if(!(A > 0)) return Vector(0, 0, 0);
    return (-B / (2.0 * A)) * d;
  }
};

} // namespace internal
} // namespace BODT_3
} // namespace CGAL

#endif // CGAL_BODT_3_INTERNAL_MOVES_BODT_FEATURE_MOVE_H
