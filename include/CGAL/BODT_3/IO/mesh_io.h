// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_BODT_3_IO_MESH_IO_H
#define CGAL_BODT_3_IO_MESH_IO_H

#include <CGAL/BODT_3/Tet_mesh.h>
#include <CGAL/BODT_3/IO/Mesh_io_error.h>
#include <CGAL/BODT_3/IO/gmsh.h>
#include <CGAL/BODT_3/IO/medit.h>
#include <CGAL/BODT_3/IO/vtu.h>

#include <cctype>
#include <iostream>
#include <string>

namespace CGAL {
namespace BODT_3 {
namespace IO {

enum class Mesh_format { medit, gmsh, vtu, unknown };

/// The format a file name asks for: `.mesh` (Medit), `.msh` (Gmsh), `.vtu` (VTK).
inline Mesh_format format_of(const std::string& path)
{
  auto ends_with = [&](const std::string& ext) {
    if(path.size() < ext.size()) return false;
    for(std::size_t i = 0; i < ext.size(); ++i)
      if(std::tolower(static_cast<unsigned char>(path[path.size() - ext.size() + i])) != ext[i])
        return false;
    return true;
  };
  if(ends_with(".mesh")) return Mesh_format::medit;
  if(ends_with(".msh")) return Mesh_format::gmsh;
  if(ends_with(".vtu")) return Mesh_format::vtu;
  return Mesh_format::unknown;
}

/// Reads a mesh in the format its name says: `.mesh` or `.msh` (`.vtu` is written
/// for viewing only). Throws `Mesh_io_error`.
inline Tet_mesh read_mesh(const std::string& path, std::ostream& warnings = std::cerr)
{
  switch(format_of(path))
  {
  case Mesh_format::medit: return read_medit(path, warnings);
  case Mesh_format::gmsh: return read_gmsh(path, warnings);
  case Mesh_format::vtu:
    throw Mesh_io_error(path, 0, "reading .vtu is not supported; read a .mesh or .msh file");
  default:
    throw Mesh_io_error(path, 0, "unknown mesh format: the file name must end in .mesh or .msh");
  }
}

/// Writes a mesh in the format its name says (`.msh` as Gmsh 4.1), atomically.
/// Throws `Mesh_io_error`.
inline void write_mesh(const std::string& path, const Tet_mesh& mesh)
{
  switch(format_of(path))
  {
  case Mesh_format::medit: write_medit(path, mesh); return;
  case Mesh_format::gmsh: write_gmsh(path, mesh, 41); return;
  case Mesh_format::vtu: write_vtu(path, mesh); return;
  default:
    throw Mesh_io_error(path, 0, "unknown mesh format: the file name must end in .mesh, .msh or .vtu");
  }
}

} // namespace IO
} // namespace BODT_3
} // namespace CGAL

#endif // CGAL_BODT_3_IO_MESH_IO_H
