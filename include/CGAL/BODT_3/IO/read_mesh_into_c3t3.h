// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_BODT_3_IO_READ_MESH_INTO_C3T3_H
#define CGAL_BODT_3_IO_READ_MESH_INTO_C3T3_H

#include <CGAL/BODT_3/IO/mesh_io.h>
#include <CGAL/BODT_3/Tet_mesh_conversion.h>

#include <iostream>
#include <string>

namespace CGAL {
namespace BODT_3 {

/// Reads a mesh file (see `IO::read_mesh`) into `c3t3` with `tet_mesh_to_c3t3`.
/// Throws `Mesh_io_error` naming the file read (for TetGen, the `.ele` file when
/// the tetrahedra cannot form a triangulation).
template <class C3T3>
void read_mesh_into_c3t3(const std::string& path, C3T3& c3t3, std::ostream& warnings = std::cerr)
{
  const Tet_mesh mesh = IO::read_mesh(path, warnings);
  tet_mesh_to_c3t3(mesh, c3t3, mesh.source);
}

} // namespace BODT_3
} // namespace CGAL

#endif // CGAL_BODT_3_IO_READ_MESH_INTO_C3T3_H
