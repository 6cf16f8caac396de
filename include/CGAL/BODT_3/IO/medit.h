// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_BODT_3_IO_MEDIT_H
#define CGAL_BODT_3_IO_MEDIT_H

#include <CGAL/BODT_3/Tet_mesh.h>
#include <CGAL/BODT_3/IO/Mesh_io_error.h>
#include <CGAL/BODT_3/IO/Token_reader.h>
#include <CGAL/BODT_3/IO/check_tet_mesh.h>
#include <CGAL/BODT_3/IO/write_atomically.h>

#include <cctype>
#include <cstdio>
#include <iostream>
#include <map>
#include <string>

namespace CGAL {
namespace BODT_3 {
namespace IO {

namespace internal_medit {

using BODT_3::internal::Token_reader;

inline bool is_keyword(const std::string& t)
{
  return !t.empty() && std::isalpha(static_cast<unsigned char>(t[0]));
}

// Sections whose entries are plain numbers we do not keep: tokens per entry.
inline const std::map<std::string, std::size_t>& ignored_sections()
{
  static const std::map<std::string, std::size_t> s = {
      {"Normals", 3}, {"NormalAtVertices", 2}, {"NormalAtTriangleVertices", 3},
      {"Tangents", 3}, {"TangentAtVertices", 2}, {"TangentAtEdges", 3},
      {"RequiredEdges", 1}, {"RequiredTriangles", 1}, {"Quadrilaterals", 5},
      {"Hexahedra", 9}, {"Prisms", 7}, {"Pyramids", 6}};
  return s;
}

inline int read_index(Token_reader& in, std::size_t limit, const char* entity, const char* plural,
                      std::size_t entry, std::size_t count)
{
  if(is_keyword(in.peek()))
  {
    in.next("a vertex index");
    in.error("the section ends after " + std::to_string(entry) + " of the " + std::to_string(count) + " " +
             plural + " its count announces (found '" + in.peek_last() + "')");
  }
  const long long v = in.next_integer("a vertex index");
  if(v < 1 || static_cast<unsigned long long>(v) > limit)
    in.error(std::string(entity) + " " + std::to_string(entry + 1) + " refers to vertex " + std::to_string(v) +
             ", but vertex indices run from 1 to " + std::to_string(limit));
  return static_cast<int>(v - 1);
}

} // namespace internal_medit

/// Reads a Medit `.mesh` file (ASCII). Keeps vertices with references, tetrahedra
/// with subdomain labels, triangles with patch labels, `Edges`, `Corners`, `Ridges`
/// and `RequiredVertices`; skips other sections with a warning on `warnings`.
/// Throws `Mesh_io_error` ("file:line: what is wrong") on any defect, including
/// those `check_and_orient` finds.
inline Tet_mesh read_medit(const std::string& file, std::ostream& warnings = std::cerr)
{
  using namespace internal_medit;
  Token_reader in(file);
  Tet_mesh mesh;
  Tet_mesh_source src;
  src.file = file;
  bool have_vertices = false, have_dimension = false;
  // Indices into sections that may come before the section they refer to are checked last.
  std::vector<long> corner_lines, required_lines, ridge_lines, edge_lines;

  std::string first = in.next("the keyword MeshVersionFormatted");
  if(first != "MeshVersionFormatted")
    in.error("not a Medit mesh file: expected 'MeshVersionFormatted', found '" + first + "'");
  const int version = in.next_int("the format version");
  if(version < 1 || version > 4)
    in.error("unsupported MeshVersionFormatted " + std::to_string(version));

  while(!in.at_end())
  {
    const std::string kw = in.next("a section keyword");
    if(kw == "End") break;
    if(!is_keyword(kw))
      in.error("expected a section keyword, found '" + kw +
               "'; the previous section may have more entries than its count says");
    if(kw == "Dimension")
    {
      const int d = in.next_int("the dimension");
      if(d != 3)
        in.error("this is a " + std::to_string(d) + "D mesh; only 3D tetrahedral meshes are supported");
      have_dimension = true;
    }
    else if(kw == "Vertices")
    {
      if(have_vertices) in.error("a second 'Vertices' section");
      have_vertices = true;
      const std::size_t n = in.next_count("the number of vertices", 4);
      mesh.points.reserve(n);
      mesh.vertex_refs.reserve(n);
      src.vertex_lines.reserve(n);
      for(std::size_t i = 0; i < n; ++i)
      {
        if(is_keyword(in.peek()))
        {
          in.next("a vertex");
          in.error("the section ends after " + std::to_string(i) + " of the " + std::to_string(n) +
                   " vertices its count announces (found '" + in.peek_last() + "')");
        }
        const double x = in.next_double("a vertex x coordinate");
        src.vertex_lines.push_back(in.line());
        const double y = in.next_double("a vertex y coordinate");
        const double z = in.next_double("a vertex z coordinate");
        mesh.points.emplace_back(x, y, z);
        mesh.vertex_refs.push_back(in.next_int("a vertex reference"));
      }
    }
    else if(kw == "Tetrahedra" || kw == "Triangles" || kw == "Edges")
    {
      if(!have_vertices) in.error("section '" + kw + "' comes before 'Vertices'");
      const std::size_t arity = kw == "Tetrahedra" ? 4 : kw == "Triangles" ? 3 : 2;
      const char* entity = kw == "Tetrahedra" ? "tetrahedron" : kw == "Triangles" ? "triangle" : "edge";
      const char* plural = kw == "Tetrahedra" ? "tetrahedra" : kw == "Triangles" ? "triangles" : "edges";
      const std::size_t n = in.next_count(("the number of " + std::string(plural)).c_str(), arity + 1);
      for(std::size_t i = 0; i < n; ++i)
      {
        int v[4] = {0, 0, 0, 0};
        long line = 0;
        for(std::size_t k = 0; k < arity; ++k)
        {
          v[k] = read_index(in, mesh.points.size(), entity, plural, i, n);
          if(k == 0) line = in.line();
        }
        const int label = in.next_int("a label");
        if(arity == 4)
        {
          mesh.tets.push_back({v[0], v[1], v[2], v[3]});
          mesh.tet_labels.push_back(label);
          src.tet_lines.push_back(line);
        }
        else if(arity == 3)
        {
          mesh.triangles.push_back({v[0], v[1], v[2]});
          mesh.triangle_labels.push_back(label);
          src.triangle_lines.push_back(line);
        }
        else
        {
          mesh.edges.push_back({v[0], v[1]});
          mesh.edge_labels.push_back(label);
          edge_lines.push_back(line);
        }
      }
    }
    else if(kw == "Corners" || kw == "RequiredVertices" || kw == "Ridges")
    {
      const std::size_t n = in.next_count(("the number of " + kw).c_str(), 1);
      std::vector<int>& target = kw == "Corners" ? mesh.corners
                                 : kw == "Ridges" ? mesh.ridges : mesh.required_vertices;
      std::vector<long>& lines = kw == "Corners" ? corner_lines
                                 : kw == "Ridges" ? ridge_lines : required_lines;
      for(std::size_t i = 0; i < n; ++i)
      {
        target.push_back(static_cast<int>(in.next_integer("an index") - 1));
        lines.push_back(in.line());
      }
    }
    else
    {
      auto it = ignored_sections().find(kw);
      if(it != ignored_sections().end())
      {
        const long line = in.line();
        const std::size_t n = in.next_count(("the number of " + kw).c_str(), it->second);
        for(std::size_t i = 0; i < n * it->second; ++i)
          in.next_double(("an entry of section " + kw).c_str());
        warnings << "warning: " << file << ":" << line << ": section '" << kw
                 << "' is not used and will not be written back\n";
      }
      else
      {
        const long line = in.line();
        std::size_t skipped = 0;
        while(!in.at_end() && !is_keyword(in.peek()))
        {
          in.next("an entry");
          ++skipped;
        }
        warnings << "warning: " << file << ":" << line << ": unknown section '" << kw << "' skipped ("
                 << skipped << " values)\n";
      }
    }
  }

  if(!have_dimension)
    warnings << "warning: " << file << ": no 'Dimension' keyword; assuming 3\n";
  if(!have_vertices)
    throw Mesh_io_error(file, 0, "the file has no 'Vertices' section");

  auto check_refs = [&](const std::vector<int>& ids, const std::vector<long>& lines, std::size_t limit,
                        const char* section, const char* what) {
    for(std::size_t i = 0; i < ids.size(); ++i)
      if(ids[i] < 0 || static_cast<std::size_t>(ids[i]) >= limit)
        throw Mesh_io_error(file, lines[i],
                            std::string(section) + " entry " + std::to_string(i + 1) + " refers to " +
                                what + " " + std::to_string(ids[i] + 1) + ", but valid " + what +
                                "s are 1 to " + std::to_string(limit));
  };
  check_refs(mesh.corners, corner_lines, mesh.points.size(), "Corners", "vertex");
  check_refs(mesh.required_vertices, required_lines, mesh.points.size(), "RequiredVertices", "vertex");
  check_refs(mesh.ridges, ridge_lines, mesh.edges.size(), "Ridges", "edge");

  check_and_orient(mesh, src, warnings);
  return mesh;
}

/// Writes `mesh` as a Medit `.mesh` file (format version 2, 17 significant digits,
/// so that reading it back gives the same doubles).
inline void write_medit(std::ostream& out, const Tet_mesh& mesh)
{
  char buf[128];
  out << "MeshVersionFormatted 2\n\nDimension 3\n\nVertices\n" << mesh.points.size() << "\n";
  for(std::size_t i = 0; i < mesh.points.size(); ++i)
  {
    const auto& p = mesh.points[i];
    std::snprintf(buf, sizeof buf, "%.17g %.17g %.17g %d\n", p.x(), p.y(), p.z(),
                  i < mesh.vertex_refs.size() ? mesh.vertex_refs[i] : 0);
    out << buf;
  }
  if(!mesh.triangles.empty())
  {
    out << "\nTriangles\n" << mesh.triangles.size() << "\n";
    for(std::size_t i = 0; i < mesh.triangles.size(); ++i)
    {
      const auto& t = mesh.triangles[i];
      out << t[0] + 1 << ' ' << t[1] + 1 << ' ' << t[2] + 1 << ' ' << mesh.triangle_labels[i] << '\n';
    }
  }
  out << "\nTetrahedra\n" << mesh.tets.size() << "\n";
  for(std::size_t i = 0; i < mesh.tets.size(); ++i)
  {
    const auto& t = mesh.tets[i];
    out << t[0] + 1 << ' ' << t[1] + 1 << ' ' << t[2] + 1 << ' ' << t[3] + 1 << ' ' << mesh.tet_labels[i]
        << '\n';
  }
  if(!mesh.edges.empty())
  {
    out << "\nEdges\n" << mesh.edges.size() << "\n";
    for(std::size_t i = 0; i < mesh.edges.size(); ++i)
      out << mesh.edges[i][0] + 1 << ' ' << mesh.edges[i][1] + 1 << ' ' << mesh.edge_labels[i] << '\n';
  }
  auto write_list = [&](const char* kw, const std::vector<int>& ids) {
    if(ids.empty()) return;
    out << "\n" << kw << "\n" << ids.size() << "\n";
    for(int i : ids) out << i + 1 << '\n';
  };
  write_list("Corners", mesh.corners);
  write_list("RequiredVertices", mesh.required_vertices);
  write_list("Ridges", mesh.ridges);
  out << "\nEnd\n";
}

inline void write_medit(const std::string& file, const Tet_mesh& mesh)
{
  write_atomically(file, [&](std::ostream& out) { write_medit(out, mesh); });
}

} // namespace IO
} // namespace BODT_3
} // namespace CGAL

#endif // CGAL_BODT_3_IO_MEDIT_H
