// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_BODT_3_IO_MEDIT_H
#define CGAL_BODT_3_IO_MEDIT_H

#include <CGAL/BODT_3/Tet_mesh.h>
#include <CGAL/BODT_3/IO/internal/Mapped_file.h>
#include <CGAL/BODT_3/Mesh_io_error.h>
#include <CGAL/BODT_3/IO/internal/Output_buffer.h>
#include <CGAL/BODT_3/IO/internal/Token_reader.h>
#include <CGAL/BODT_3/internal/Mesh/check_tet_mesh.h>
#include <CGAL/BODT_3/IO/write_atomically.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iostream>
#include <limits>
#include <map>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace CGAL {
namespace BODT_3 {
namespace IO {

namespace internal {


// Sections whose entries are plain numbers we do not keep: tokens per entry.
inline const std::map<std::string, std::size_t, std::less<>>& ignored_sections()
{
  static const std::map<std::string, std::size_t, std::less<>> s = {
      {"Normals", 3}, {"NormalAtVertices", 2}, {"NormalAtTriangleVertices", 3},
      {"Tangents", 3}, {"TangentAtVertices", 2}, {"TangentAtEdges", 3},
      {"RequiredEdges", 1}, {"RequiredTriangles", 1}, {"Quadrilaterals", 5},
      {"Hexahedra", 9}, {"Prisms", 7}, {"Pyramids", 6}};
  return s;
}

inline int read_index(Token_reader& in, std::size_t limit, const char* entity, const char* plural,
                      std::size_t entry, std::size_t count)
{
  if(in.next_is_word())
  {
    in.next("a vertex index");
    in.error("the section ends after " + std::to_string(entry) + " of the " + std::to_string(count) + " " +
             plural + " its count announces (found '" + internal::printable(in.peek_last()) + "')");
  }
  const long long v = in.next_integer("a vertex index");
  if(v < 1 || static_cast<unsigned long long>(v) > limit)
    in.error(std::string(entity) + " " + std::to_string(entry + 1) + " refers to vertex " + std::to_string(v) +
             ", but vertex indices run from 1 to " + std::to_string(limit));
  return static_cast<int>(v - 1);
}

inline bool looks_like_medit(std::string_view head)
{
  const std::string_view t = internal::first_token(head, '#');
  return t.empty() || std::string_view("MeshVersionFormatted").substr(0, t.size()) == t;
}

/// Reads `n` elements of `N` vertex indices and a label in parallel (`Token_reader::read_rows`),
/// appended to `cells`, `labels` and `lines`; false, with nothing appended, when they must
/// be read token by token.
template <std::size_t N>
bool read_rows(Token_reader& in, std::size_t n, int threads, std::size_t vertices,
               std::vector<std::array<int, N>>& cells, std::vector<int>& labels, std::vector<long>& lines)
{
  const std::size_t base = cells.size();
  cells.resize(base + n);
  labels.resize(base + n);
  lines.resize(base + n);
  const bool read = in.read_rows(n, N + 1, threads, [&](std::size_t i, long line, const std::string_view* f) {
    long long v;
    for(std::size_t k = 0; k < N; ++k)
    {
      if(!internal::parse_integer(f[k], v) || v < 1 || static_cast<unsigned long long>(v) > vertices) return false;
      cells[base + i][k] = static_cast<int>(v - 1);
    }
    if(!internal::parse_integer(f[N], v) || v < std::numeric_limits<int>::min() ||
       v > std::numeric_limits<int>::max())
      return false;
    labels[base + i] = static_cast<int>(v);
    lines[base + i] = line;
    return true;
  });
  if(!read)
  {
    cells.resize(base);
    labels.resize(base);
    lines.resize(base);
  }
  return read;
}

/// Parses the text of an ASCII Medit file named `file`; `version` receives its
/// MeshVersionFormatted. Sections laid out one entry per line are read on
/// `threads` threads (0: all cores); the result does not depend on their number.
inline Tet_mesh parse_medit(const std::string& file, std::string_view text, std::ostream& warnings, int& version,
                      int threads = 1)
{
  Token_reader in(file, text);
  Tet_mesh mesh;
  BODT_3::internal::Tet_mesh_source src;
  src.file = file;
  bool have_vertices = false, have_dimension = false;
  // Indices into sections that may come before the section they refer to are checked
  // last, in their full width: 4294967297 must not become 1.
  std::vector<long long> corners, required, ridges;
  std::vector<long> corner_lines, required_lines, ridge_lines;

  const std::string_view first = in.next("the keyword MeshVersionFormatted");
  if(first != "MeshVersionFormatted")
    in.error("not a Medit mesh file: expected 'MeshVersionFormatted', found '" + internal::printable(first) + "'");
  version = in.next_int("the format version");
  if(version < 1 || version > 4)
    in.error("unsupported MeshVersionFormatted " + std::to_string(version));

  while(!in.at_end())
  {
    const std::string_view kw = in.next("a section keyword");
    if(kw == "End") break;
    const char c0 = kw[0];
    if(!((c0 >= 'a' && c0 <= 'z') || (c0 >= 'A' && c0 <= 'Z')))
      in.error("expected a section keyword, found '" + internal::printable(kw) +
               "'; the previous section may have more entries than its count says");
    const std::string name(kw);
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
      if(n > static_cast<std::size_t>(std::numeric_limits<int>::max()))
        in.error("the number of vertices is " + std::to_string(n) + ", more than this reader can index");
      mesh.points.resize(n);
      mesh.vertex_refs.resize(n);
      src.vertex_lines.resize(n);
      const bool read = in.read_rows(n, 4, threads, [&](std::size_t i, long line, const std::string_view* f) {
        double x, y, z;
        long long ref;
        if(!internal::parse_double(f[0], x) || !internal::parse_double(f[1], y) ||
           !internal::parse_double(f[2], z) || !std::isfinite(x) || !std::isfinite(y) || !std::isfinite(z) ||
           !internal::parse_integer(f[3], ref) || ref < std::numeric_limits<int>::min() ||
           ref > std::numeric_limits<int>::max())
          return false;
        mesh.points[i] = Tet_mesh::Point(x, y, z);
        mesh.vertex_refs[i] = static_cast<int>(ref);
        src.vertex_lines[i] = line;
        return true;
      });
      if(read) continue;
      mesh.points.clear();
      mesh.vertex_refs.clear();
      src.vertex_lines.clear();
      for(std::size_t i = 0; i < n; ++i)
      {
        if(in.next_is_word())
        {
          in.next("a vertex");
          in.error("the section ends after " + std::to_string(i) + " of the " + std::to_string(n) +
                   " vertices its count announces (found '" + internal::printable(in.peek_last()) + "')");
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
      if(!have_vertices) in.error("section '" + name + "' comes before 'Vertices'");
      const std::size_t arity = kw == "Tetrahedra" ? 4 : kw == "Triangles" ? 3 : 2;
      const char* entity = kw == "Tetrahedra" ? "tetrahedron" : kw == "Triangles" ? "triangle" : "edge";
      const char* plural = kw == "Tetrahedra" ? "tetrahedra" : kw == "Triangles" ? "triangles" : "edges";
      const std::size_t n = in.next_count(("the number of " + std::string(plural)).c_str(), arity + 1);
      if(arity == 4 && read_rows(in, n, threads, mesh.points.size(), mesh.tets, mesh.tet_labels, src.tet_lines)) continue;
      if(arity == 3 && read_rows(in, n, threads, mesh.points.size(), mesh.triangles, mesh.triangle_labels,
                                 src.triangle_lines))
        continue;
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
        }
      }
    }
    else if(kw == "Corners" || kw == "RequiredVertices" || kw == "Ridges")
    {
      const std::size_t n = in.next_count(("the number of " + name).c_str(), 1);
      std::vector<long long>& target = kw == "Corners" ? corners : kw == "Ridges" ? ridges : required;
      std::vector<long>& lines = kw == "Corners" ? corner_lines : kw == "Ridges" ? ridge_lines : required_lines;
      for(std::size_t i = 0; i < n; ++i)
      {
        target.push_back(in.next_integer("an index"));
        lines.push_back(in.line());
      }
    }
    else
    {
      auto it = ignored_sections().find(kw);
      if(it != ignored_sections().end())
      {
        const long line = in.line();
        const std::size_t n = in.next_count(("the number of " + name).c_str(), it->second);
        for(std::size_t i = 0; i < n * it->second; ++i)
          in.next_double(("an entry of section " + name).c_str());
        warnings << "warning: " << file << ":" << line << ": section '" << name
                 << "' is not used and will not be written back\n";
      }
      else
      {
        const long line = in.line();
        std::size_t skipped = 0;
        while(!in.at_end() && !in.next_is_word())
        {
          in.next("an entry");
          ++skipped;
        }
        warnings << "warning: " << file << ":" << line << ": unknown section '" << internal::printable(kw)
                 << "' skipped (" << skipped << " values)\n";
      }
    }
  }

  if(!have_dimension)
    warnings << "warning: " << file << ": no 'Dimension' keyword; assuming 3\n";
  if(!have_vertices)
    throw Mesh_io_error(file, 0, "the file has no 'Vertices' section");

  auto check_refs = [&](const std::vector<long long>& ids, const std::vector<long>& lines, std::size_t limit,
                        const char* section, const char* what, std::vector<int>& out) {
    out.reserve(ids.size());
    for(std::size_t i = 0; i < ids.size(); ++i)
    {
      if(ids[i] < 1 || static_cast<unsigned long long>(ids[i]) > limit)
        throw Mesh_io_error(file, lines[i],
                            std::string(section) + " entry " + std::to_string(i + 1) + " refers to " + what +
                                " " + std::to_string(ids[i]) + ", but valid " + what + "s are 1 to " +
                                std::to_string(limit));
      out.push_back(static_cast<int>(ids[i] - 1));
    }
  };
  check_refs(corners, corner_lines, mesh.points.size(), "Corners", "vertex", mesh.corners);
  check_refs(required, required_lines, mesh.points.size(), "RequiredVertices", "vertex", mesh.required_vertices);
  check_refs(ridges, ridge_lines, mesh.edges.size(), "Ridges", "edge", mesh.ridges);

  BODT_3::internal::check_and_orient(mesh, src, warnings, threads);
  return mesh;
}

} // namespace internal

/// Reads a Medit `.mesh` file (ASCII, any MeshVersionFormatted 1 to 4; numbers
/// are read as doubles whatever the version). Keeps vertices with references,
/// tetrahedra with subdomain labels, triangles with patch labels, `Edges`,
/// `Corners`, `Ridges` and `RequiredVertices`; skips other sections with a warning
/// on `warnings`. Throws `Mesh_io_error` ("file:line: what is wrong") on any
/// defect, including those `check_and_orient` finds. `version`, when given,
/// receives the file's MeshVersionFormatted. `threads`: how many threads read
/// (0: all cores); the result does not depend on it.
inline Tet_mesh read_medit(const std::string& file, std::ostream& warnings = std::cerr, int* version = nullptr,
                           int threads = 1)
{
  const internal::Mapped_file data(file, "a Medit mesh file", internal::looks_like_medit);
  int v = 0;
  Tet_mesh mesh = internal::parse_medit(file, data.bytes(), warnings, v, threads);
  if(version) *version = v;
  return mesh;
}

/// Writes `mesh` as an ASCII Medit `.mesh` file, MeshVersionFormatted `version`
/// (1 to 4; it says how a binary reader should size numbers and changes nothing
/// in ASCII). Coordinates are written in the shortest form that reads back to the
/// same double.
inline void write_medit(std::ostream& stream, const Tet_mesh& mesh, int version = 2, int threads = 1)
{
  if(version < 1 || version > 4)
    throw std::invalid_argument("write_medit: version must be 1 to 4, not " + std::to_string(version));
  internal::Output_buffer out(stream);
  out.put("MeshVersionFormatted ").put_int(version).put("\n\nDimension 3\n\nVertices\n").put_int(mesh.points.size()).put('\n');
  internal::put_rows(out, mesh.points.size(), threads, [&mesh](internal::Text_block& row, std::size_t i) {
    const auto& p = mesh.points[i];
    row.put_double(p.x()).put(' ').put_double(p.y()).put(' ').put_double(p.z()).put(' ');
    row.put_int(i < mesh.vertex_refs.size() ? mesh.vertex_refs[i] : 0).put('\n');
  });
  if(!mesh.triangles.empty())
  {
    out.put("\nTriangles\n").put_int(mesh.triangles.size()).put('\n');
    for(std::size_t i = 0; i < mesh.triangles.size(); ++i)
    {
      const auto& t = mesh.triangles[i];
      out.put_int(t[0] + 1).put(' ').put_int(t[1] + 1).put(' ').put_int(t[2] + 1).put(' ');
      out.put_int(mesh.triangle_labels[i]).put('\n');
    }
  }
  out.put("\nTetrahedra\n").put_int(mesh.tets.size()).put('\n');
  internal::put_rows(out, mesh.tets.size(), threads, [&mesh](internal::Text_block& row, std::size_t i) {
    const auto& t = mesh.tets[i];
    row.put_int(t[0] + 1).put(' ').put_int(t[1] + 1).put(' ').put_int(t[2] + 1).put(' ').put_int(t[3] + 1);
    row.put(' ').put_int(mesh.tet_labels[i]).put('\n');
  });
  if(!mesh.edges.empty())
  {
    out.put("\nEdges\n").put_int(mesh.edges.size()).put('\n');
    for(std::size_t i = 0; i < mesh.edges.size(); ++i)
      out.put_int(mesh.edges[i][0] + 1).put(' ').put_int(mesh.edges[i][1] + 1).put(' ').put_int(mesh.edge_labels[i]).put('\n');
  }
  auto write_list = [&](const char* kw, const std::vector<int>& ids) {
    if(ids.empty()) return;
    out.put("\n").put(kw).put("\n").put_int(ids.size()).put('\n');
    for(int i : ids) out.put_int(i + 1).put('\n');
  };
  write_list("Corners", mesh.corners);
  write_list("RequiredVertices", mesh.required_vertices);
  write_list("Ridges", mesh.ridges);
  out.put("\nEnd\n");
}

inline void write_medit(const std::string& file, const Tet_mesh& mesh, int version = 2, int threads = 1)
{
  write_atomically(file, [&](std::ostream& out) { write_medit(out, mesh, version, threads); });
}

} // namespace IO
} // namespace BODT_3
} // namespace CGAL

#endif // CGAL_BODT_3_IO_MEDIT_H
