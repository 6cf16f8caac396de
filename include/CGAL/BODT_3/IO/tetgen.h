// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_BODT_3_IO_TETGEN_H
#define CGAL_BODT_3_IO_TETGEN_H

#include <CGAL/BODT_3/Tet_mesh.h>
#include <CGAL/BODT_3/IO/internal/Mapped_file.h>
#include <CGAL/BODT_3/Mesh_io_error.h>
#include <CGAL/BODT_3/IO/internal/Output_buffer.h>
#include <CGAL/BODT_3/IO/internal/Token_reader.h>
#include <CGAL/BODT_3/internal/Mesh/check_tet_mesh.h>
#include <CGAL/BODT_3/IO/write_atomically.h>

#include <cmath>
#include <iostream>
#include <limits>
#include <memory>
#include <string>
#include <string_view>
#include <sys/stat.h>
#include <vector>

namespace CGAL {
namespace BODT_3 {
namespace IO {

namespace internal {


/// `path` without a TetGen extension (.node, .ele, .face, .edge).
inline std::string base_name(const std::string& path)
{
  for(const char* ext : {".node", ".ele", ".face", ".edge"})
  {
    const std::string e = ext;
    if(path.size() > e.size() && path.compare(path.size() - e.size(), e.size(), e) == 0)
      return path.substr(0, path.size() - e.size());
  }
  return path;
}

inline bool looks_like_tetgen(std::string_view head)
{
  const std::string_view t = internal::first_token(head, '#');
  if(t.empty()) return true;
  long long v;
  return internal::parse_integer(t, v);
}

// The texts of the files of one TetGen mesh; `face` and `edge` may be empty (absent).
struct Texts
{
  std::string node_file, ele_file, face_file, edge_file;
  std::string_view node, ele, face, edge;
};

inline int index(Token_reader& in, long long base, std::size_t limit, const char* entity, std::size_t entry)
{
  const long long v = in.next_integer("a node index");
  if(v < base || static_cast<unsigned long long>(v - base) >= limit)
    in.error(std::string(entity) + " " + std::to_string(entry + 1) + " refers to node " + std::to_string(v) +
             ", but node indices run from " + std::to_string(base) + " to " +
             std::to_string(base + static_cast<long long>(limit) - 1));
  return static_cast<int>(v - base);
}

inline int integral_label(Token_reader& in, const char* what)
{
  const double a = in.next_double(what);
  if(a != std::floor(a) || a < std::numeric_limits<int>::min() || a > std::numeric_limits<int>::max())
    in.error(std::string(what) + " is " + printable(in.peek_last()) + "; labels must be integers");
  return static_cast<int>(a);
}

inline Tet_mesh parse_tetgen(const Texts& t, std::ostream& warnings)
{
  Tet_mesh mesh;
  long long base = 0;
  {
    Token_reader in(t.node_file, t.node);
    const std::size_t n = in.next_count("the number of nodes", 4);
    if(n == 0) in.error("the file announces no nodes (TetGen keeps them in a .poly file then, which is not read)");
    if(n > static_cast<std::size_t>(std::numeric_limits<int>::max()))
      in.error("the number of nodes is " + std::to_string(n) + ", more than this reader can index");
    const int dim = in.next_int("the dimension");
    if(dim != 3) in.error("the dimension is " + std::to_string(dim) + "; only 3D meshes are supported");
    const std::size_t attributes = in.next_count("the number of attributes", 0);
    if(attributes > 1000) in.error("the number of node attributes is " + std::to_string(attributes) + ", more than any mesh holds");
    const int markers = in.next_int("the number of boundary markers");
    if(markers != 0 && markers != 1) in.error("the number of boundary markers is " + std::to_string(markers) + ", not 0 or 1");
    in.check_count("the number of nodes", n, 4 + attributes + static_cast<std::size_t>(markers));
    mesh.points.reserve(n);
    mesh.vertex_refs.reserve(n);
    for(std::size_t i = 0; i < n; ++i)
    {
      const long long id = in.next_integer("a node index");
      if(i == 0)
      {
        if(id != 0 && id != 1) in.error("the first node is numbered " + std::to_string(id) + ", not 0 or 1");
        base = id;
      }
      else if(id != base + static_cast<long long>(i))
        in.error("node " + std::to_string(id) + " comes where node " + std::to_string(base + static_cast<long long>(i)) +
                 " was expected; nodes must be numbered in order");
      const double x = in.next_double("a node x coordinate");
      const double y = in.next_double("a node y coordinate");
      const double z = in.next_double("a node z coordinate");
      for(std::size_t k = 0; k < attributes; ++k) in.next_double("a node attribute");
      mesh.points.emplace_back(x, y, z);
      mesh.vertex_refs.push_back(markers ? in.next_int("a boundary marker") : 0);
    }
  }
  BODT_3::internal::Tet_mesh_source src;
  src.file = t.ele_file;
  {
    Token_reader in(t.ele_file, t.ele);
    const std::size_t n = in.next_count("the number of tetrahedra", 5);
    const int nodes = in.next_int("the number of nodes per tetrahedron");
    if(nodes != 4 && nodes != 10) in.error("tetrahedra with " + std::to_string(nodes) + " nodes; TetGen writes 4 or 10");
    if(nodes == 10)
      warnings << "warning: " << t.ele_file << ": quadratic tetrahedra; their midside nodes are not used\n";
    const std::size_t attributes = in.next_count("the number of region attributes", 0);
    if(attributes > 1000) in.error("the number of region attributes is " + std::to_string(attributes) + ", more than any mesh holds");
    in.check_count("the number of tetrahedra", n, 1 + static_cast<std::size_t>(nodes) + attributes);
    mesh.tets.reserve(n);
    mesh.tet_labels.reserve(n);
    src.tet_lines.reserve(n);
    for(std::size_t i = 0; i < n; ++i)
    {
      in.next_integer("a tetrahedron index");
      src.tet_lines.push_back(in.line());
      std::array<int, 4> v;
      for(int k = 0; k < nodes; ++k)
      {
        const int id = index(in, base, mesh.points.size(), "tetrahedron", i);
        if(k < 4) v[k] = id;
      }
      int label = 0;
      for(std::size_t k = 0; k < attributes; ++k)
      {
        const int a = integral_label(in, "a region attribute");
        if(k == 0) label = a;
      }
      mesh.tets.push_back(v);
      mesh.tet_labels.push_back(label);
    }
  }
  if(!t.face_file.empty())
  {
    Token_reader in(t.face_file, t.face);
    const std::size_t n = in.next_count("the number of faces", 4);
    const int markers = in.next_int("the number of boundary markers");
    if(markers != 0 && markers != 1) in.error("the number of boundary markers is " + std::to_string(markers) + ", not 0 or 1");
    for(std::size_t i = 0; i < n; ++i)
    {
      in.next_integer("a face index");
      src.triangle_lines.push_back(in.line());
      std::array<int, 3> v;
      for(int& x : v) x = index(in, base, mesh.points.size(), "face", i);
      mesh.triangles.push_back(v);
      mesh.triangle_labels.push_back(markers ? in.next_int("a boundary marker") : 0);
      in.rest_of_line();   // TetGen's -nn adds the adjacent tetrahedra
    }
  }
  if(!t.edge_file.empty())
  {
    Token_reader in(t.edge_file, t.edge);
    const std::size_t n = in.next_count("the number of edges", 3);
    const int markers = in.next_int("the number of boundary markers");
    if(markers != 0 && markers != 1) in.error("the number of boundary markers is " + std::to_string(markers) + ", not 0 or 1");
    for(std::size_t i = 0; i < n; ++i)
    {
      in.next_integer("an edge index");
      std::array<int, 2> v;
      for(int& x : v) x = index(in, base, mesh.points.size(), "edge", i);
      mesh.edges.push_back(v);
      mesh.edge_labels.push_back(markers ? in.next_int("a boundary marker") : 0);
      in.rest_of_line();
    }
  }
  BODT_3::internal::check_and_orient(mesh, src, warnings);
  return mesh;
}

} // namespace internal

/// Reads a TetGen mesh: `BASE.node` and `BASE.ele`, with `BASE.face` and
/// `BASE.edge` when they exist; `path` is any of them or BASE itself. Keeps node
/// boundary markers as vertex references, the first region attribute of each
/// tetrahedron as its label (it must be an integer), faces and edges with their
/// boundary markers as labels. Indices start at 0 or 1 as the first node says.
/// Throws `Mesh_io_error` naming the file and line.
inline Tet_mesh read_tetgen(const std::string& path, std::ostream& warnings = std::cerr)
{
  using namespace internal;
  const std::string base = base_name(path);
  auto exists = [](const std::string& p) { struct stat st; return ::stat(p.c_str(), &st) == 0; };
  Texts t;
  t.node_file = base + ".node";
  t.ele_file = base + ".ele";
  const internal::Mapped_file node(t.node_file, "a TetGen .node file", looks_like_tetgen);
  const internal::Mapped_file ele(t.ele_file, "a TetGen .ele file", looks_like_tetgen);
  std::unique_ptr<internal::Mapped_file> face, edge;
  if(exists(base + ".face"))
  {
    t.face_file = base + ".face";
    face = std::make_unique<internal::Mapped_file>(t.face_file, "a TetGen .face file", looks_like_tetgen);
    t.face = face->bytes();
  }
  if(exists(base + ".edge"))
  {
    t.edge_file = base + ".edge";
    edge = std::make_unique<internal::Mapped_file>(t.edge_file, "a TetGen .edge file", looks_like_tetgen);
    t.edge = edge->bytes();
  }
  t.node = node.bytes();
  t.ele = ele.bytes();
  return parse_tetgen(t, warnings);
}

namespace internal {

inline void write_node(std::ostream& s, const Tet_mesh& mesh)
{
  internal::Output_buffer out(s);
  out.put_int(mesh.points.size()).put(" 3 0 1\n");
  for(std::size_t i = 0; i < mesh.points.size(); ++i)
  {
    const auto& p = mesh.points[i];
    out.put_int(i + 1).put(' ').put_double(p.x()).put(' ').put_double(p.y()).put(' ').put_double(p.z()).put(' ');
    out.put_int(i < mesh.vertex_refs.size() ? mesh.vertex_refs[i] : 0).put('\n');
  }
}

// A TetGen element list: a header "count, per-element size, markers" and, per
// element, its number, its vertices from 1 and its label.
template <class Element>
void write_elements(std::ostream& s, const std::vector<Element>& elements, const std::vector<int>& labels,
                    const char* header_rest)
{
  internal::Output_buffer out(s);
  out.put_int(elements.size()).put(header_rest);
  for(std::size_t i = 0; i < elements.size(); ++i)
  {
    out.put_int(i + 1);
    for(int v : elements[i]) out.put(' ').put_int(v + 1);
    out.put(' ').put_int(labels[i]).put('\n');
  }
}

inline void write_ele(std::ostream& s, const Tet_mesh& mesh) { write_elements(s, mesh.tets, mesh.tet_labels, " 4 1\n"); }

inline void write_face(std::ostream& s, const Tet_mesh& mesh)
{
  write_elements(s, mesh.triangles, mesh.triangle_labels, " 1\n");
}

inline void write_edge(std::ostream& s, const Tet_mesh& mesh) { write_elements(s, mesh.edges, mesh.edge_labels, " 1\n"); }

inline void write(std::ostream& node, std::ostream& ele, std::ostream& face, std::ostream& edge, const Tet_mesh& mesh)
{
  write_node(node, mesh);
  write_ele(ele, mesh);
  write_face(face, mesh);
  write_edge(edge, mesh);
}

} // namespace internal

/// Writes `mesh` as TetGen files `BASE.node` (vertex references as boundary
/// markers), `BASE.ele` (labels as one region attribute), `BASE.face` and
/// `BASE.edge` (labels as boundary markers), numbered from 1; `path` is any of
/// them or BASE. Each file is written atomically.
inline void write_tetgen(const std::string& path, const Tet_mesh& mesh)
{
  const std::string base = internal::base_name(path);
  write_atomically(base + ".node", [&](std::ostream& s) { internal::write_node(s, mesh); });
  write_atomically(base + ".ele", [&](std::ostream& s) { internal::write_ele(s, mesh); });
  write_atomically(base + ".face", [&](std::ostream& s) { internal::write_face(s, mesh); });
  write_atomically(base + ".edge", [&](std::ostream& s) { internal::write_edge(s, mesh); });
}

} // namespace IO
} // namespace BODT_3
} // namespace CGAL

#endif // CGAL_BODT_3_IO_TETGEN_H
