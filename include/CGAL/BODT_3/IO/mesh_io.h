// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_BODT_3_IO_MESH_IO_H
#define CGAL_BODT_3_IO_MESH_IO_H

#include <CGAL/BODT_3/Tet_mesh.h>
#include <CGAL/BODT_3/Mesh_io_error.h>
#include <CGAL/BODT_3/IO/gmsh.h>
#include <CGAL/BODT_3/IO/medit.h>
#include <CGAL/BODT_3/IO/meshb.h>
#include <CGAL/BODT_3/IO/tetgen.h>
#include <CGAL/BODT_3/IO/vtk.h>
#include <CGAL/BODT_3/IO/vtu.h>

#include <cctype>
#include <iostream>
#include <stdexcept>
#include <string>

namespace CGAL {
namespace BODT_3 {
namespace IO {

/// The mesh file formats: Medit ASCII `.mesh` and binary `.meshb`, Gmsh `.msh`,
/// VTK XML `.vtu`, legacy VTK `.vtk`, TetGen `.node/.ele/.face/.edge`.
enum class Mesh_format { medit, gmsh, vtu, meshb, vtk, tetgen, unknown };

/// A format with its variant: what a file was read as, or how to write one.
struct Mesh_file_format
{
  Mesh_format format = Mesh_format::unknown;
  /// Medit and Medit binary: MeshVersionFormatted 1 to 4; Gmsh: 22 or 41; legacy VTK:
  /// 42 or 51 (the version times ten); unused otherwise.
  int version = 0;
  /// Gmsh, VTU and legacy VTK: binary data rather than ASCII.
  bool binary = false;

  friend bool operator==(const Mesh_file_format& a, const Mesh_file_format& b)
  {
    return a.format == b.format && a.version == b.version && a.binary == b.binary;
  }
  friend bool operator!=(const Mesh_file_format& a, const Mesh_file_format& b) { return !(a == b); }
};

/// The format a file name asks for by its extension (any case): `.mesh`, `.meshb`,
/// `.msh`, `.vtu`, `.vtk`, `.node`/`.ele`/`.face`/`.edge` (TetGen).
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
  if(ends_with(".meshb")) return Mesh_format::meshb;
  if(ends_with(".msh")) return Mesh_format::gmsh;
  if(ends_with(".vtu")) return Mesh_format::vtu;
  if(ends_with(".vtk")) return Mesh_format::vtk;
  if(ends_with(".node") || ends_with(".ele") || ends_with(".face") || ends_with(".edge")) return Mesh_format::tetgen;
  return Mesh_format::unknown;
}

/// The variant written when nothing else asks for one: Medit version 2 (doubles),
/// Gmsh 4.1 ASCII, binary VTU (what ParaView writes), legacy VTK 4.2 ASCII.
inline Mesh_file_format default_file_format(Mesh_format format)
{
  switch(format)
  {
  case Mesh_format::medit: return {format, 2, false};
  case Mesh_format::meshb: return {format, 2, true};
  case Mesh_format::gmsh: return {format, 41, false};
  case Mesh_format::vtu: return {format, 0, true};
  case Mesh_format::vtk: return {format, 42, false};
  case Mesh_format::tetgen: return {format, 0, false};
  default: return {};
  }
}

/// The default variant of the format `path`'s extension names.
inline Mesh_file_format file_format_of(const std::string& path) { return default_file_format(format_of(path)); }

/// The format to write `output_path` in when the mesh was read as `input`: the
/// input's variant (version, binary or not) when the output's extension names the
/// input's format, otherwise the default variant of the output's extension. So
/// `in.msh` (2.2 binary) -> `out.msh` stays 2.2 binary, `in.msh` -> `out.vtu` is a
/// binary VTU.
inline Mesh_file_format output_format(const std::string& output_path, const Mesh_file_format& input)
{
  const Mesh_format f = format_of(output_path);
  return f == input.format ? input : default_file_format(f);
}

/// The names `parse_format_name` accepts, for help texts and error messages.
inline const char* format_names()
{
  return "mesh, meshb (meshb1 to meshb4 for a version), msh (= msh41), msh22, msh41, msh22-binary, msh41-binary, "
         "vtu (binary), vtu-ascii, vtk (= vtk42), vtk51, vtk-binary, vtk51-binary, tetgen";
}

/// The format named `name` (see `format_names()`), for a `--format` option.
/// Throws `std::invalid_argument` for any other name.
inline Mesh_file_format parse_format_name(const std::string& name)
{
  using F = Mesh_format;
  static const std::pair<const char*, Mesh_file_format> names[] = {
      {"mesh", {F::medit, 2, false}},         {"meshb", {F::meshb, 2, true}},
      {"meshb1", {F::meshb, 1, true}},        {"meshb2", {F::meshb, 2, true}},
      {"meshb3", {F::meshb, 3, true}},        {"meshb4", {F::meshb, 4, true}},
      {"msh", {F::gmsh, 41, false}},          {"msh41", {F::gmsh, 41, false}},
      {"msh22", {F::gmsh, 22, false}},        {"msh41-binary", {F::gmsh, 41, true}},
      {"msh22-binary", {F::gmsh, 22, true}},  {"vtu", {F::vtu, 0, true}},
      {"vtu-ascii", {F::vtu, 0, false}},      {"vtk", {F::vtk, 42, false}},
      {"vtk42", {F::vtk, 42, false}},         {"vtk51", {F::vtk, 51, false}},
      {"vtk-binary", {F::vtk, 42, true}},     {"vtk42-binary", {F::vtk, 42, true}},
      {"vtk51-binary", {F::vtk, 51, true}},   {"tetgen", {F::tetgen, 0, false}}};
  for(const auto& n : names)
    if(name == n.first) return n.second;
  throw std::invalid_argument("unknown mesh format '" + name + "'; the formats are " + format_names());
}

/// A short name of `f` as `parse_format_name` reads it ("msh22-binary", ...).
inline std::string format_name(const Mesh_file_format& f)
{
  switch(f.format)
  {
  case Mesh_format::medit: return "mesh";
  case Mesh_format::meshb: return "meshb" + std::to_string(f.version);
  case Mesh_format::gmsh: return "msh" + std::to_string(f.version) + (f.binary ? "-binary" : "");
  case Mesh_format::vtu: return f.binary ? "vtu" : "vtu-ascii";
  case Mesh_format::vtk: return "vtk" + std::to_string(f.version) + (f.binary ? "-binary" : "");
  case Mesh_format::tetgen: return "tetgen";
  default: return "unknown";
  }
}

/// Reads a mesh in the format its name says and fills `format` with what the file
/// was (so that `output_format` can keep it). `threads` read and check an ASCII
/// Medit file (0: all cores); the result does not depend on it. Throws `Mesh_io_error`.
inline Tet_mesh read_mesh(const std::string& path, Mesh_file_format& format, std::ostream& warnings = std::cerr,
                          int threads = 1)
{
  format = {format_of(path), 0, false};
  switch(format.format)
  {
  case Mesh_format::medit: return read_medit(path, warnings, &format.version, threads);
  case Mesh_format::meshb: format.binary = true; return read_meshb(path, warnings, &format.version);
  case Mesh_format::gmsh: return read_gmsh(path, warnings, &format.version, &format.binary);
  case Mesh_format::vtu: return read_vtu(path, warnings, &format.binary);
  case Mesh_format::vtk: return read_vtk(path, warnings, &format.version, &format.binary);
  case Mesh_format::tetgen: return read_tetgen(path, warnings);
  default:
    throw Mesh_io_error(path, 0, "unknown mesh format: the file name must end in .mesh, .meshb, .msh, .vtu, "
                                 ".vtk, .node or .ele");
  }
}

/// Reads a mesh in the format its name says. Throws `Mesh_io_error`.
inline Tet_mesh read_mesh(const std::string& path, std::ostream& warnings = std::cerr)
{
  Mesh_file_format format;
  return read_mesh(path, format, warnings);
}

/// Writes `mesh` to `path` in `format`, whatever the extension (TetGen writes the
/// files BASE.node, .ele, .face and .edge, BASE being `path` without a TetGen
/// extension), atomically. A legacy VTK version other than 42 and 51 is written as
/// 42, a Gmsh version other than 22 and 41 as 41 (so that any version read can be
/// kept). `threads` format an ASCII Medit file (0: all cores); the bytes do not
/// depend on it. Throws `Mesh_io_error`.
inline void write_mesh(const std::string& path, const Tet_mesh& mesh, const Mesh_file_format& format,
                       int threads = 1)
{
  switch(format.format)
  {
  case Mesh_format::medit:
    write_medit(path, mesh, format.version >= 1 && format.version <= 4 ? format.version : 2, threads);
    return;
  case Mesh_format::meshb: write_meshb(path, mesh, format.version >= 1 && format.version <= 4 ? format.version : 2); return;
  case Mesh_format::gmsh: write_gmsh(path, mesh, format.version == 22 ? 22 : 41, format.binary); return;
  case Mesh_format::vtu: write_vtu(path, mesh, format.binary); return;
  case Mesh_format::vtk: write_vtk(path, mesh, format.binary, format.version == 51 ? 51 : 42); return;
  case Mesh_format::tetgen: write_tetgen(path, mesh); return;
  default:
    throw Mesh_io_error(path, 0, "unknown mesh format: the file name must end in .mesh, .meshb, .msh, .vtu, "
                                 ".vtk, .node or .ele");
  }
}

/// Writes a mesh in the default variant of the format its name says (see
/// `default_file_format`), atomically. Throws `Mesh_io_error`.
inline void write_mesh(const std::string& path, const Tet_mesh& mesh)
{
  write_mesh(path, mesh, file_format_of(path));
}

} // namespace IO
} // namespace BODT_3
} // namespace CGAL

#endif // CGAL_BODT_3_IO_MESH_IO_H
