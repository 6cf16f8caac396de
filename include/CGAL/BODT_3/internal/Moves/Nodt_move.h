// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_BODT_3_INTERNAL_MOVES_NODT_MOVE_H
#define CGAL_BODT_3_INTERNAL_MOVES_NODT_MOVE_H

#include <CGAL/BODT_3/internal/Moves/Interpolation_error.h>
#include <CGAL/BODT_3/internal/Moves/Vertex_star.h>

namespace CGAL {
namespace BODT_3 {
namespace internal {

/// The Natural ODT move of a boundary vertex (Tournois et al. 2009), the
/// baseline the paper compares B-ODT with: the minimizer of the interpolation
/// error over every direction, not only the tangent plane, so the vertex leaves
/// the boundary and is projected back onto it afterwards (the paper's description:
/// the weighted centroid of the star plus a compensation along the normals of
/// the boundary triangles). With Q and b of `Interpolation_error`, the error is
/// X^T Q X + b . X up to cubic terms, exactly its second-order expansion at X = 0
/// (the cubic terms of Appendix C have no quadratic part), so the move is the
/// Newton step X = -Q^{-1} b / 2: the centroid term is Q = |Omega_0|/4 I and the
/// b of ODT, the compensation the boundary terms of Q and b. Inside, it is ODT.
/// Where Q is not positive definite the vertex does not move. Returns X.
struct Nodt_move
{
  template <class K>
  typename K::Vector_3 operator()(const Vertex_star<K>& star) const
  {
    using Vector = typename K::Vector_3;
    const Interpolation_error<K> error(star);
    const Vector e[3] = {Vector(1, 0, 0), Vector(0, 1, 0), Vector(0, 0, 1)};
    double q[3][3], b[3];
    for(int i = 0; i < 3; ++i)
    {
      b[i] = error.linear(e[i]);
      for(int j = 0; j < 3; ++j) q[i][j] = error.quadratic(e[i], e[j]);
    }
    // Positive definite: the leading minors are positive (Sylvester).
    const double m1 = q[0][0], m2 = q[0][0] * q[1][1] - q[0][1] * q[1][0];
    const double det = q[0][0] * (q[1][1] * q[2][2] - q[1][2] * q[2][1]) -
                       q[0][1] * (q[1][0] * q[2][2] - q[1][2] * q[2][0]) +
                       q[0][2] * (q[1][0] * q[2][1] - q[1][1] * q[2][0]);
    if(!(m1 > 0) || !(m2 > 0) || !(det > 0)) return Vector(0, 0, 0);
    // X = -Q^{-1} b / 2, by Cramer's rule.
    double x[3];
    for(int k = 0; k < 3; ++k)
    {
      double m[3][3];
      for(int i = 0; i < 3; ++i)
        for(int j = 0; j < 3; ++j) m[i][j] = j == k ? -0.5 * b[i] : q[i][j];
      x[k] = (m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
              m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0])) /
             det;
    }
    return Vector(x[0], x[1], x[2]);
  }
};

} // namespace internal
} // namespace BODT_3
} // namespace CGAL

#endif // CGAL_BODT_3_INTERNAL_MOVES_NODT_MOVE_H
