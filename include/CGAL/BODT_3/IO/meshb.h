// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_BODT_3_IO_MESHB_H
#define CGAL_BODT_3_IO_MESHB_H

#include <CGAL/BODT_3/Tet_mesh.h>
#include <CGAL/BODT_3/IO/internal/Byte_reader.h>
#include <CGAL/BODT_3/IO/internal/Mapped_file.h>
#include <CGAL/BODT_3/Mesh_io_error.h>
#include <CGAL/BODT_3/IO/internal/Output_buffer.h>
#include <CGAL/BODT_3/internal/Mesh/check_tet_mesh.h>
#include <CGAL/BODT_3/IO/write_atomically.h>

#include <array>
#include <cmath>
#include <cstring>
#include <cstdint>
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


// Keyword codes of the Gamma Mesh Format (libMeshb's GmfKwdCod) that we read or write.
enum Keyword : std::int32_t
{
  dimension = 3, vertices = 4, edges = 5, triangles = 6, tetrahedra = 8, corners = 13, ridges = 14,
  required_vertices = 15, end = 54
};

// The layout a MeshVersionFormatted implies: version 1 stores reals as floats,
// 2 as doubles, 3 adds 64-bit keyword positions, 4 adds 64-bit integers.
struct Layout
{
  int version;
  std::size_t real() const { return version == 1 ? 4 : 8; }
  std::size_t integer() const { return version == 4 ? 8 : 4; }
  std::size_t position() const { return version >= 3 ? 8 : 4; }
};

inline bool looks_like_meshb(std::string_view head)
{
  if(head.size() < 4) return true;
  std::int32_t code;
  std::memcpy(&code, head.data(), 4);
  return code == 1 || code == (1 << 24);
}

inline const char* keyword_name(std::int32_t k)
{
  static const std::map<std::int32_t, const char*> names = {
      {7, "Quadrilaterals"}, {9, "Prisms"}, {10, "Hexahedra"}, {16, "RequiredEdges"},
      {17, "RequiredTriangles"}, {20, "NormalAtVertices"}, {21, "NormalAtTriangleVertices"},
      {49, "Pyramids"}, {50, "BoundingBox"}, {59, "Tangents"}, {60, "Normals"}, {61, "TangentAtVertices"},
      {62, "SolAtVertices"}};
  const auto it = names.find(k);
  return it == names.end() ? nullptr : it->second;
}

class Meshb_parser
{
public:
  Meshb_parser(const std::string& file, std::string_view bytes, std::ostream& warnings)
    : in_(file, bytes), warnings_(warnings)
  {}

  int version() const { return layout_.version; }

  Tet_mesh parse()
  {
    if(in_.remaining() == 0) throw Mesh_io_error(in_.file(), 0, "the file is empty");
    const std::int32_t code = in_.get<std::int32_t>("the byte order mark 1");
    if(code != 1)
    {
      if(internal::byte_swapped(code) != 1)
        in_.error("not a Medit binary mesh file: it starts with " + std::to_string(code) + ", not 1");
      in_.set_swap(true);
    }
    const std::int32_t version = in_.get<std::int32_t>("the format version");
    if(version < 1 || version > 4)
      in_.error("unsupported MeshVersionFormatted " + std::to_string(version));
    layout_.version = version;

    std::vector<std::uint64_t> corner_ids, required_ids, ridge_ids;
    bool have_vertices = false, have_dimension = false;
    while(in_.remaining() > 0)
    {
      const std::size_t at = in_.position();
      const std::int32_t kw = in_.get<std::int32_t>("a keyword code");
      const std::uint64_t next = position("the position of the next keyword");
      if(kw == end) break;
      if(next != 0 && (next <= in_.position() || next > in_.bytes().size()))
        in_.error("the keyword at byte " + std::to_string(at) + " says the next one is at byte " +
                  std::to_string(next) + ", which is not between it and the end of the file (" +
                  std::to_string(in_.bytes().size()) + " bytes)");
      switch(kw)
      {
      case dimension:
      {
        const std::int32_t d = in_.get<std::int32_t>("the dimension");
        if(d != 3)
          in_.error("this is a " + std::to_string(d) + "D mesh; only 3D tetrahedral meshes are supported");
        have_dimension = true;
        break;
      }
      case vertices:
      {
        if(have_vertices) in_.error("a second 'Vertices' keyword");
        have_vertices = true;
        const std::size_t n = count("the number of vertices", 3 * layout_.real() + layout_.integer());
        if(n > static_cast<std::size_t>(std::numeric_limits<int>::max()))
          in_.error("the number of vertices is " + std::to_string(n) + ", more than this reader can index");
        mesh_.points.reserve(n);
        mesh_.vertex_refs.reserve(n);
        for(std::size_t i = 0; i < n; ++i)
        {
          double c[3];
          for(double& x : c)
          {
            x = real();
            if(!std::isfinite(x))
              in_.error("vertex " + std::to_string(i + 1) + " has a coordinate that is not a finite number");
          }
          mesh_.points.emplace_back(c[0], c[1], c[2]);
          mesh_.vertex_refs.push_back(label("a vertex reference"));
        }
        break;
      }
      case edges: elements<2>(mesh_.edges, mesh_.edge_labels, "edge", have_vertices); break;
      case triangles: elements<3>(mesh_.triangles, mesh_.triangle_labels, "triangle", have_vertices); break;
      case tetrahedra: elements<4>(mesh_.tets, mesh_.tet_labels, "tetrahedron", have_vertices); break;
      case corners: ids(corner_ids, "Corners"); break;
      case ridges: ids(ridge_ids, "Ridges"); break;
      case required_vertices: ids(required_ids, "RequiredVertices"); break;
      default:
        if(next == 0)
          in_.error("keyword " + std::to_string(kw) + " is not one this reader knows, and the file does not say "
                    "where the next keyword is");
        warnings_ << "warning: " << in_.file() << ": at byte " << at << ": "
                  << (keyword_name(kw) ? std::string("section '") + keyword_name(kw) + "' is not used and will not be written back"
                                       : "unknown keyword " + std::to_string(kw) + " skipped")
                  << "\n";
      }
      if(next == 0) break;
      if(in_.position() > next)
        in_.error("the keyword at byte " + std::to_string(at) + " holds more data than fits before the next "
                  "keyword, at byte " + std::to_string(next));
      in_.seek(static_cast<std::size_t>(next), "the position of the next keyword");
    }
    if(!have_dimension)
      warnings_ << "warning: " << in_.file() << ": no 'Dimension' keyword; assuming 3\n";
    if(!have_vertices)
      throw Mesh_io_error(in_.file(), 0, "the file has no 'Vertices' keyword");
    resolve(corner_ids, mesh_.points.size(), "Corners", "vertex", mesh_.corners);
    resolve(required_ids, mesh_.points.size(), "RequiredVertices", "vertex", mesh_.required_vertices);
    resolve(ridge_ids, mesh_.edges.size(), "Ridges", "edge", mesh_.ridges);

    BODT_3::internal::Tet_mesh_source src;
    src.file = in_.file();
    BODT_3::internal::check_and_orient(mesh_, src, warnings_);
    return std::move(mesh_);
  }

private:
  std::uint64_t position(const char* what)
  {
    if(layout_.position() == 8) return in_.get<std::uint64_t>(what);
    return in_.get<std::uint32_t>(what);
  }

  // A count, as wide as the version says, that the rest of the file must be able to hold.
  std::size_t count(const char* what, std::size_t bytes_per_entry)
  {
    const std::int64_t n = layout_.version == 4 ? in_.get<std::int64_t>(what) : in_.get<std::int32_t>(what);
    if(n < 0) in_.error(std::string(what) + " is negative (" + std::to_string(n) + ")");
    in_.check_count(what, static_cast<unsigned long long>(n), bytes_per_entry);
    return static_cast<std::size_t>(n);
  }

  double real()
  {
    if(layout_.real() == 4) return in_.get<float>("a coordinate");
    return in_.get<double>("a coordinate");
  }

  std::int64_t integer(const char* what)
  {
    return layout_.integer() == 8 ? in_.get<std::int64_t>(what) : in_.get<std::int32_t>(what);
  }

  int label(const char* what)
  {
    const std::int64_t v = integer(what);
    if(v < std::numeric_limits<int>::min() || v > std::numeric_limits<int>::max())
      in_.error(std::string(what) + " " + std::to_string(v) + " is out of range");
    return static_cast<int>(v);
  }

  template <std::size_t N>
  void elements(std::vector<std::array<int, N>>& out, std::vector<int>& labels, const char* entity,
                bool have_vertices)
  {
    if(!have_vertices) in_.error(std::string("the ") + entity + "s come before the vertices");
    const std::size_t n = count("a number of elements", (N + 1) * layout_.integer());
    const std::size_t limit = mesh_.points.size();
    out.reserve(out.size() + n);
    labels.reserve(labels.size() + n);
    for(std::size_t i = 0; i < n; ++i)
    {
      std::array<int, N> v;
      for(std::size_t k = 0; k < N; ++k)
      {
        const std::int64_t id = integer("a vertex index");
        if(id < 1 || static_cast<std::uint64_t>(id) > limit)
          in_.error(std::string(entity) + " " + std::to_string(i + 1) + " refers to vertex " + std::to_string(id) +
                    ", but vertex indices run from 1 to " + std::to_string(limit));
        v[k] = static_cast<int>(id - 1);
      }
      out.push_back(v);
      labels.push_back(label("a label"));
    }
  }

  void ids(std::vector<std::uint64_t>& out, const char* section)
  {
    const std::size_t n = count((std::string("the number of ") + section).c_str(), layout_.integer());
    for(std::size_t i = 0; i < n; ++i)
    {
      const std::int64_t v = integer("an index");
      out.push_back(v < 1 ? 0 : static_cast<std::uint64_t>(v));
    }
  }

  void resolve(const std::vector<std::uint64_t>& ids, std::size_t limit, const char* section, const char* what,
               std::vector<int>& out)
  {
    for(std::size_t i = 0; i < ids.size(); ++i)
    {
      if(ids[i] < 1 || ids[i] > limit)
        throw Mesh_io_error(in_.file(), 0, std::string(section) + " entry " + std::to_string(i + 1) +
                                               " refers to " + what + " " + std::to_string(ids[i]) +
                                               ", but valid " + what + "s are 1 to " + std::to_string(limit));
      out.push_back(static_cast<int>(ids[i] - 1));
    }
  }

  Byte_reader in_;
  std::ostream& warnings_;
  Layout layout_{2};
  Tet_mesh mesh_;
};

/// Parses the bytes of a `.meshb` file named `file`; `version` receives its
/// MeshVersionFormatted.
inline Tet_mesh parse_meshb(const std::string& file, std::string_view bytes, std::ostream& warnings, int& version)
{
  Meshb_parser parser(file, bytes, warnings);
  Tet_mesh mesh = parser.parse();
  version = parser.version();
  return mesh;
}

// Bytes the file takes in `layout`, to know whether 32-bit positions can address it.
inline std::uint64_t file_size(const Tet_mesh& mesh, Layout layout)
{
  const std::uint64_t header = 4 + layout.position() + layout.integer();
  std::uint64_t s = 8 + (4 + layout.position() + 4) + (4 + layout.position());
  s += header + mesh.points.size() * (3 * layout.real() + layout.integer());
  s += header + mesh.tets.size() * 5 * layout.integer();
  if(!mesh.triangles.empty()) s += header + mesh.triangles.size() * 4 * layout.integer();
  if(!mesh.edges.empty()) s += header + mesh.edges.size() * 3 * layout.integer();
  for(const auto* ids : {&mesh.corners, &mesh.required_vertices, &mesh.ridges})
    if(!ids->empty()) s += header + ids->size() * layout.integer();
  return s;
}

} // namespace internal

/// Reads a Medit binary `.meshb` file, MeshVersionFormatted 1 to 4 as libMeshb
/// writes them (either byte order). Keeps what `read_medit` keeps; skips other
/// keywords with a warning. Throws `Mesh_io_error` ("file: at byte N: what is
/// wrong"). `version`, when given, receives the file's version.
inline Tet_mesh read_meshb(const std::string& file, std::ostream& warnings = std::cerr, int* version = nullptr)
{
  const internal::Mapped_file data(file, "a Medit binary mesh file", internal::looks_like_meshb);
  int v = 0;
  Tet_mesh mesh = internal::parse_meshb(file, data.bytes(), warnings, v);
  if(version) *version = v;
  return mesh;
}

/// Writes `mesh` as a Medit binary `.meshb` file in the machine's byte order,
/// MeshVersionFormatted `version`: 1 stores coordinates as floats (lossy), 2 as
/// doubles with 32-bit keyword positions, 3 with 64-bit positions, 4 with 64-bit
/// integers too. A version 1 or 2 file larger than 32-bit positions can address is
/// written as version 3 instead.
inline void write_meshb(std::ostream& stream, const Tet_mesh& mesh, int version = 2)
{
  using namespace internal;
  if(version < 1 || version > 4)
    throw std::invalid_argument("write_meshb: version must be 1 to 4, not " + std::to_string(version));
  Layout layout{version};
  if(layout.position() == 4 && file_size(mesh, layout) > std::numeric_limits<std::int32_t>::max())
    layout.version = 3;
  internal::Output_buffer out(stream);
  auto position = [&](std::uint64_t p) {
    if(layout.position() == 8) out.put_binary(p);
    else out.put_binary(static_cast<std::uint32_t>(p));
  };
  auto integer = [&](std::int64_t v) {
    if(layout.integer() == 8) out.put_binary(v);
    else out.put_binary(static_cast<std::int32_t>(v));
  };
  auto keyword = [&](Keyword k, std::size_t n, std::size_t entry_bytes) {
    out.put_binary(static_cast<std::int32_t>(k));
    position(out.written() + layout.position() + layout.integer() + n * entry_bytes);
    integer(static_cast<std::int64_t>(n));
  };
  out.put_binary(std::int32_t(1)).put_binary(static_cast<std::int32_t>(layout.version));
  out.put_binary(static_cast<std::int32_t>(dimension));
  position(out.written() + layout.position() + 4);
  out.put_binary(std::int32_t(3));

  keyword(vertices, mesh.points.size(), 3 * layout.real() + layout.integer());
  for(std::size_t i = 0; i < mesh.points.size(); ++i)
  {
    const auto& p = mesh.points[i];
    if(layout.real() == 4)
      out.put_binary(static_cast<float>(p.x())).put_binary(static_cast<float>(p.y())).put_binary(static_cast<float>(p.z()));
    else
      out.put_binary(p.x()).put_binary(p.y()).put_binary(p.z());
    integer(i < mesh.vertex_refs.size() ? mesh.vertex_refs[i] : 0);
  }
  if(!mesh.triangles.empty())
  {
    keyword(triangles, mesh.triangles.size(), 4 * layout.integer());
    for(std::size_t i = 0; i < mesh.triangles.size(); ++i)
    {
      for(int v : mesh.triangles[i]) integer(v + 1);
      integer(mesh.triangle_labels[i]);
    }
  }
  keyword(tetrahedra, mesh.tets.size(), 5 * layout.integer());
  for(std::size_t i = 0; i < mesh.tets.size(); ++i)
  {
    for(int v : mesh.tets[i]) integer(v + 1);
    integer(mesh.tet_labels[i]);
  }
  if(!mesh.edges.empty())
  {
    keyword(edges, mesh.edges.size(), 3 * layout.integer());
    for(std::size_t i = 0; i < mesh.edges.size(); ++i)
    {
      integer(mesh.edges[i][0] + 1);
      integer(mesh.edges[i][1] + 1);
      integer(mesh.edge_labels[i]);
    }
  }
  auto write_list = [&](Keyword k, const std::vector<int>& ids) {
    if(ids.empty()) return;
    keyword(k, ids.size(), layout.integer());
    for(int i : ids) integer(i + 1);
  };
  write_list(corners, mesh.corners);
  write_list(required_vertices, mesh.required_vertices);
  write_list(ridges, mesh.ridges);
  out.put_binary(static_cast<std::int32_t>(end));
  position(0);
}

inline void write_meshb(const std::string& file, const Tet_mesh& mesh, int version = 2)
{
  if(version < 1 || version > 4)
    throw std::invalid_argument("write_meshb: version must be 1 to 4, not " + std::to_string(version));
  write_atomically(file, [&](std::ostream& out) { write_meshb(out, mesh, version); });
}

} // namespace IO
} // namespace BODT_3
} // namespace CGAL

#endif // CGAL_BODT_3_IO_MESHB_H
