// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_BODT_3_INTERNAL_MOVES_BODT_SURFACE_MOVE_H
#define CGAL_BODT_3_INTERNAL_MOVES_BODT_SURFACE_MOVE_H

#include <CGAL/BODT_3/internal/Moves/Interpolation_error.h>
#include <CGAL/BODT_3/internal/Moves/Vertex_star.h>

#include <cmath>

namespace CGAL {
namespace BODT_3 {
namespace internal {

/// Algorithm 2, the basic B-ODT move of a boundary vertex: x* = x0 + u s + v t on
/// the tangent plane through x0 with normal `normal` (eq. B.1 keeps the volume),
/// minimizing Error = E u^2 + F v^2 + G uv + H u + I v by solving
///
///   [2E  G ] [u]   [-H]
///   [G   2F] [v] = [-I].
///
/// With Q and b of `Interpolation_error`, E = s^T Q s, F = t^T Q t, G = 2 s^T Q t,
/// H = b.s, I = b.t, which are the printed coefficients with F using
/// Y_i x Y_{i+1} (the printed Y_1 x Y_2 is a typesetting slip). Where the system
/// has no unique minimum (4EF <= G^2, or E <= 0) the vertex does not move.
/// Returns the displacement x* - x0.
struct Bodt_surface_move
{
  template <class K>
  typename K::Vector_3 operator()(const Vertex_star<K>& star, const typename K::Vector_3& normal) const
  {
    using Vector = typename K::Vector_3;
    const Vector zero(0, 0, 0);
    const double len = std::sqrt(normal.squared_length());
    if(!(len > 0)) return zero;
    const Vector n = normal / len;
    // s: the axis least aligned with n, made orthogonal to n; t = n x s.
    const double ax = std::abs(n.x()), ay = std::abs(n.y()), az = std::abs(n.z());
    const Vector e = (ax <= ay && ax <= az) ? Vector(1, 0, 0) : (ay <= az ? Vector(0, 1, 0) : Vector(0, 0, 1));
    Vector s = e - (e * n) * n;
    s = s / std::sqrt(s.squared_length());
    const Vector t = CGAL::cross_product(n, s);

    const Interpolation_error<K> error(star);
    const double E = error.quadratic(s, s);
    const double F = error.quadratic(t, t);
    const double G = 2.0 * error.quadratic(s, t);
    const double H = error.linear(s);
    const double I = error.linear(t);
    const double det = 4.0 * E * F - G * G;
    if(!(E > 0) || !(det > 0)) return zero;
    const double u = (-2.0 * F * H + G * I) / det;
    const double v = (-2.0 * E * I + G * H) / det;
    return u * s + v * t;
  }
};

} // namespace internal
} // namespace BODT_3
} // namespace CGAL

#endif // CGAL_BODT_3_INTERNAL_MOVES_BODT_SURFACE_MOVE_H
