// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_BODT_3_RETURN_CODE_H
#define CGAL_BODT_3_RETURN_CODE_H

#include <CGAL/Mesh_optimization_return_code.h>

#include <ostream>

namespace CGAL {
namespace BODT_3 {

/// The name of a return code as CGAL spells the enumerator, e.g.
/// "MAX_ITERATION_NUMBER_REACHED".
inline const char* to_string(Mesh_optimization_return_code code)
{
  switch(code)
  {
  case BOUND_REACHED: return "BOUND_REACHED";
  case TIME_LIMIT_REACHED: return "TIME_LIMIT_REACHED";
  case CANT_IMPROVE_ANYMORE: return "CANT_IMPROVE_ANYMORE";
  case CONVERGENCE_REACHED: return "CONVERGENCE_REACHED";
  case MAX_ITERATION_NUMBER_REACHED: return "MAX_ITERATION_NUMBER_REACHED";
  case ALL_VERTICES_FROZEN: return "ALL_VERTICES_FROZEN";
  case MESH_OPTIMIZATION_UNKNOWN_ERROR: return "MESH_OPTIMIZATION_UNKNOWN_ERROR";
  }
  return "MESH_OPTIMIZATION_UNKNOWN_ERROR";
}

} // namespace BODT_3

/// `std::cout << code` prints the enumerator's name instead of its number. It is
/// declared in namespace CGAL, the enumeration's own, because that is where
/// argument-dependent lookup finds it; CGAL 5.5 declares no such operator.
inline std::ostream& operator<<(std::ostream& out, Mesh_optimization_return_code code)
{
  return out << BODT_3::to_string(code);
}

} // namespace CGAL

#endif // CGAL_BODT_3_RETURN_CODE_H
