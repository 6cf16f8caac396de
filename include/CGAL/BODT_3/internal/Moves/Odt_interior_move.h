// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_BODT_3_INTERNAL_MOVES_ODT_INTERIOR_MOVE_H
#define CGAL_BODT_3_INTERNAL_MOVES_ODT_INTERIOR_MOVE_H

#include <CGAL/BODT_3/internal/Moves/Interpolation_error.h>
#include <CGAL/BODT_3/internal/Moves/Vertex_star.h>

namespace CGAL {
namespace BODT_3 {
namespace internal {

/// Algorithm 1, the original ODT move of an inner vertex (eq. 3):
///
///   x* = x0 - 1 / (2 |Omega_0|) sum_tau (1/3) S_tau n_tau sum_i |x_{tau,i} - x0|^2,
///
/// with n_tau the unit normal of the face opposite x0 pointing into tau. It is
/// the unconstrained minimizer of `Interpolation_error`: Q = |Omega_0|/4 I there,
/// so X = -b / (2 |Omega_0| / 4). Returns the displacement x* - x0.
struct Odt_interior_move
{
  template <class K>
  typename K::Vector_3 operator()(const Vertex_star<K>& star) const
  {
    const Interpolation_error<K> error(star);
    if(!(error.volume() > 0)) return typename K::Vector_3(0, 0, 0);
    return -(2.0 / error.volume()) * error.linear_term();
  }
};

} // namespace internal
} // namespace BODT_3
} // namespace CGAL

#endif // CGAL_BODT_3_INTERNAL_MOVES_ODT_INTERIOR_MOVE_H
