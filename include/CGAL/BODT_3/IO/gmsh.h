// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_BODT_3_IO_GMSH_H
#define CGAL_BODT_3_IO_GMSH_H

#include <CGAL/BODT_3/Tet_mesh.h>
#include <CGAL/BODT_3/IO/Mesh_io_error.h>
#include <CGAL/BODT_3/IO/Token_reader.h>
#include <CGAL/BODT_3/IO/check_tet_mesh.h>
#include <CGAL/BODT_3/IO/write_atomically.h>

#include <CGAL/Bbox_3.h>

#include <algorithm>
#include <cstddef>
#include <cstdio>
#include <iostream>
#include <limits>
#include <map>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace CGAL {
namespace BODT_3 {
namespace IO {

namespace internal_gmsh {

using BODT_3::internal::Token_reader;

// Gmsh element types kept: 15 point (corner), 1 line (edge), 2 triangle, 4 tetrahedron.
inline int kept_type_nodes(int type)
{
  switch(type)
  {
  case 15: return 1;
  case 1: return 2;
  case 2: return 3;
  case 4: return 4;
  default: return 0;
  }
}

// Sections Gmsh defines that hold nothing a `Tet_mesh` keeps; other ones are unknown.
inline bool is_unused_section(const std::string& name)
{
  static const char* const names[] = {"PartitionedEntities", "Periodic", "GhostElements",
                                      "Parametrizations", "NodeData", "ElementData",
                                      "ElementNodeData", "InterpolationScheme"};
  return std::find(std::begin(names), std::end(names), name) != std::end(names);
}

// Parses one ASCII `.msh` file, version 2.2 or 4.1, in a single pass.
class Msh_parser
{
public:
  Msh_parser(const std::string& file, std::ostream& warnings)
    : in_(file, '\0'), warnings_(warnings)
  {
    src_.file = file;
  }

  Tet_mesh parse()
  {
    read_format();
    bool have_nodes = false, have_elements = false;
    while(!in_.at_end())
    {
      const std::string t = in_.next("a section header");
      const long line = in_.line();
      if(t.size() < 2 || t[0] != '$')
        in_.error("expected a section header such as '$Nodes', found '" + t +
                  "'; the previous section may have more entries than its count says");
      const std::string name = t.substr(1);
      if(name.compare(0, 3, "End") == 0)
        in_.error("'" + t + "' closes a section that was not opened");
      if(name == "MeshFormat")
        in_.error("a second '$MeshFormat' section");
      else if(name == "Nodes")
      {
        if(have_nodes) in_.error("a second '$Nodes' section");
        have_nodes = true;
        if(version_ == 22) read_nodes_22(line); else read_nodes_41(line);
      }
      else if(name == "Elements")
      {
        if(have_elements) in_.error("a second '$Elements' section");
        if(!have_nodes) in_.error("section '$Elements' comes before '$Nodes'");
        have_elements = true;
        if(version_ == 22) read_elements_22(line); else read_elements_41(line);
      }
      else if(name == "Entities" && version_ == 41)
        read_entities(line);
      else
        skip_section(name, line);
    }
    if(!have_nodes) throw Mesh_io_error(src_.file, 0, "the file has no '$Nodes' section");
    if(!have_elements) throw Mesh_io_error(src_.file, 0, "the file has no '$Elements' section");

    // Version 4.1 labels come from entities, which need not precede the elements.
    for(const Block& b : blocks_)
    {
      auto it = entity_physical_.find({b.dim, b.tag});
      const int label = it == entity_physical_.end() ? 0 : it->second;
      std::vector<int>& labels = b.type == 4 ? mesh_.tet_labels
                                 : b.type == 2 ? mesh_.triangle_labels : mesh_.edge_labels;
      std::fill_n(labels.begin() + static_cast<std::ptrdiff_t>(b.first), b.count, label);
    }
    for(const auto& s : skipped_)
      warnings_ << "warning: " << src_.file << ":" << s.second.first << ": skipped " << s.second.second
                << " element(s) of Gmsh type " << s.first
                << "; only points, lines, triangles and 4-node tetrahedra are read\n";

    mesh_.vertex_refs.assign(mesh_.points.size(), 0);
    check_and_orient(mesh_, src_, warnings_);
    return std::move(mesh_);
  }

private:
  // Elements of one 4.1 block of a kept type other than points: their entity gives their label.
  struct Block
  {
    int dim, tag, type;
    std::size_t first, count;
  };

  void read_format()
  {
    const std::string first = in_.next("'$MeshFormat'");
    if(first != "$MeshFormat")
      in_.error("not a Gmsh mesh file: expected '$MeshFormat', found '" + first + "'");
    const long header = in_.line();
    const std::string v = in_.next("the format version");
    if(v == "2.2") version_ = 22;
    else if(v == "4.1") version_ = 41;
    else
      in_.error("Gmsh format version " + v + " is not supported; save the mesh as version 4.1 or 2.2");
    const int file_type = in_.next_int("the file type");
    // Stop before the binary part of a binary file.
    if(file_type == 1)
      in_.error("this is a binary Gmsh file; only ASCII files are supported (save with Mesh.Binary = 0)");
    if(file_type != 0)
      in_.error("file type " + std::to_string(file_type) + " is not valid; expected 0 (ASCII)");
    in_.next_int("the data size");
    expect_end("MeshFormat", header);
  }

  // Reads the integer that opens entry `i` of `n`: a '$' marker there means the count is wrong.
  long long entry_integer(const char* what, std::size_t i, std::size_t n, const char* entries)
  {
    const std::string t = in_.peek();
    if(!t.empty() && t[0] == '$')
    {
      in_.next(what);
      in_.error("found '" + t + "' after " + std::to_string(i) + " " + entries + ", but " +
                std::to_string(n) + " were announced; the count is wrong or entries are missing");
    }
    return in_.next_integer(what);
  }

  void expect_end(const std::string& section, long header_line)
  {
    const std::string end = "$End" + section;
    const std::string t = in_.next(("'" + end + "'").c_str());
    if(t == end) return;
    if(t[0] == '$')
      in_.error("expected '" + end + "' closing the section of line " + std::to_string(header_line) +
                ", found '" + t + "': the end marker is missing");
    in_.error("expected '" + end + "' closing the section of line " + std::to_string(header_line) +
              ", found '" + t + "': the section holds more entries than its header announces");
  }

  // Gmsh writes one node or element per line; anything left on the line is garbage.
  void expect_line_end(const std::string& what)
  {
    const std::string rest = in_.rest_of_line();
    if(!rest.empty())
      in_.error("unexpected '" + rest + "' after " + what);
  }

  void add_node_tag(long long tag, int index)
  {
    if(tag < 1)
      in_.error("node tag " + std::to_string(tag) + " is not positive");
    if(!node_index_.emplace(tag, index).second)
      in_.error("node tag " + std::to_string(tag) + " is defined twice");
  }

  int node(long long element)
  {
    const long long tag = in_.next_integer("a node tag");
    auto it = node_index_.find(tag);
    if(it == node_index_.end())
      in_.error("element " + std::to_string(element) + " refers to node " + std::to_string(tag) +
                ", which section '$Nodes' does not define");
    return it->second;
  }

  void read_point(std::size_t extra_coordinates)
  {
    const double x = in_.next_double("a node x coordinate");
    src_.vertex_lines.push_back(in_.line());
    const double y = in_.next_double("a node y coordinate");
    const double z = in_.next_double("a node z coordinate");
    for(std::size_t k = 0; k < extra_coordinates; ++k)
      in_.next_double("a parametric node coordinate");
    mesh_.points.emplace_back(x, y, z);
  }

  // Reads the nodes of an element of kept type `type` and stores it; `label` is its 2.2 label.
  // A point element on no geometric entity (all its 2.2 tags 0) is not a corner: mmg,
  // for one, writes such an element for every vertex.
  void read_element(int type, long long tag, int label, long line, bool on_entity = true)
  {
    int v[4] = {0, 0, 0, 0};
    for(int k = 0; k < kept_type_nodes(type); ++k)
      v[k] = node(tag);
    expect_line_end("element " + std::to_string(tag) + " of type " + std::to_string(type));
    switch(type)
    {
    case 15:
      if(on_entity) mesh_.corners.push_back(v[0]);
      break;
    case 1:
      mesh_.edges.push_back({v[0], v[1]});
      mesh_.edge_labels.push_back(label);
      break;
    case 2:
      mesh_.triangles.push_back({v[0], v[1], v[2]});
      mesh_.triangle_labels.push_back(label);
      src_.triangle_lines.push_back(line);
      break;
    default:
      mesh_.tets.push_back({v[0], v[1], v[2], v[3]});
      mesh_.tet_labels.push_back(label);
      src_.tet_lines.push_back(line);
    }
  }

  void skip_element(int type, long line)
  {
    in_.rest_of_line();
    auto& s = skipped_.emplace(type, std::make_pair(line, std::size_t(0))).first->second;
    ++s.second;
  }

  void read_nodes_22(long header)
  {
    const std::size_t n = in_.next_count("the number of nodes", 4);
    mesh_.points.reserve(n);
    src_.vertex_lines.reserve(n);
    for(std::size_t i = 0; i < n; ++i)
    {
      const long long tag = entry_integer("a node tag", i, n, "nodes");
      add_node_tag(tag, static_cast<int>(i));
      read_point(0);
      expect_line_end("node " + std::to_string(tag));
    }
    expect_end("Nodes", header);
  }

  // 2.2: "number type number-of-tags tags... nodes...", the first tag being the physical one.
  void read_elements_22(long header)
  {
    const std::size_t n = in_.next_count("the number of elements", 4);
    for(std::size_t i = 0; i < n; ++i)
    {
      const long long tag = entry_integer("an element number", i, n, "elements");
      const long line = in_.line();
      const int type = in_.next_int("an element type");
      if(kept_type_nodes(type) == 0)
      {
        skip_element(type, line);
        continue;
      }
      const std::size_t ntags = in_.next_count("the number of element tags", 1);
      int label = 0;
      bool tagged = false;
      for(std::size_t k = 0; k < ntags; ++k)
      {
        const int t = in_.next_int("an element tag");
        if(k == 0) label = t;
        tagged = tagged || t != 0;
      }
      read_element(type, tag, label, line, tagged);
    }
    expect_end("Elements", header);
  }

  // 4.1: points "tag x y z physicals"; curves, surfaces, volumes
  // "tag box(6) physicals bounding-entities", each list preceded by its length.
  void read_entities(long header)
  {
    std::size_t count[4], total = 0;
    for(int d = 0; d < 4; ++d)
      total += count[d] = in_.next_count("a number of entities", 5);
    std::size_t done = 0;
    for(int d = 0; d < 4; ++d)
      for(std::size_t i = 0; i < count[d]; ++i, ++done)
      {
        const long long tag = entry_integer("an entity tag", done, total, "entities");
        if(tag < 1 || tag > std::numeric_limits<int>::max())
          in_.error("entity tag " + std::to_string(tag) + " is out of range");
        for(int k = 0; k < (d == 0 ? 3 : 6); ++k)
          in_.next_double("an entity coordinate");
        const std::size_t nphys = in_.next_count("the number of physical tags", 1);
        for(std::size_t k = 0; k < nphys; ++k)
        {
          const int p = in_.next_int("a physical tag");
          if(k == 0) entity_physical_[{d, static_cast<int>(tag)}] = p;
        }
        if(d > 0)
        {
          const std::size_t nbound = in_.next_count("the number of bounding entities", 1);
          for(std::size_t k = 0; k < nbound; ++k)
            in_.next_int("a bounding entity tag");
        }
        expect_line_end("entity " + std::to_string(tag));
      }
    expect_end("Entities", header);
  }

  int entity_dimension(std::size_t block, std::size_t blocks, const char* entries)
  {
    const long long d = entry_integer("an entity dimension", block, blocks, entries);
    if(d < 0 || d > 3)
      in_.error("entity dimension " + std::to_string(d) + " is not 0, 1, 2 or 3");
    return static_cast<int>(d);
  }

  // 4.1: "blocks nodes min-tag max-tag", then per block "dim tag parametric count",
  // the block's node tags, then their coordinates.
  void read_nodes_41(long section_line)
  {
    const std::size_t blocks = in_.next_count("the number of node blocks", 4);
    const long header = in_.line();
    const std::size_t n = in_.next_count("the number of nodes", 4);
    in_.next_integer("the smallest node tag");
    in_.next_integer("the largest node tag");
    mesh_.points.reserve(n);
    src_.vertex_lines.reserve(n);
    for(std::size_t b = 0; b < blocks; ++b)
    {
      const int dim = entity_dimension(b, blocks, "node blocks");
      in_.next_int("an entity tag");
      const int parametric = in_.next_int("the parametric flag");
      if(parametric != 0 && parametric != 1)
        in_.error("the parametric flag is " + std::to_string(parametric) + ", not 0 or 1");
      const std::size_t m = in_.next_count("the number of nodes in the block", 4);
      if(m > n - mesh_.points.size())
        in_.error("the node blocks hold more than the " + std::to_string(n) +
                  " nodes the section header announces");
      const std::size_t first = mesh_.points.size();
      for(std::size_t j = 0; j < m; ++j)
      {
        const long long tag = entry_integer("a node tag", j, m, "nodes of the block");
        add_node_tag(tag, static_cast<int>(first + j));
        expect_line_end("node tag " + std::to_string(tag));
      }
      for(std::size_t j = 0; j < m; ++j)
      {
        read_point(parametric ? static_cast<std::size_t>(dim) : 0);
        expect_line_end("the coordinates of node " + std::to_string(first + j + 1) + " of the section");
      }
    }
    if(mesh_.points.size() != n)
      throw Mesh_io_error(src_.file, header, "the section header announces " + std::to_string(n) +
                                                 " nodes, but its blocks hold " +
                                                 std::to_string(mesh_.points.size()));
    expect_end("Nodes", section_line);
  }

  // 4.1: "blocks elements min-tag max-tag", then per block "dim tag type count" and
  // one "tag nodes..." line per element.
  void read_elements_41(long section_line)
  {
    const std::size_t blocks = in_.next_count("the number of element blocks", 4);
    const long header = in_.line();
    const std::size_t n = in_.next_count("the number of elements", 2);
    in_.next_integer("the smallest element tag");
    in_.next_integer("the largest element tag");
    std::size_t done = 0;
    for(std::size_t b = 0; b < blocks; ++b)
    {
      const int dim = entity_dimension(b, blocks, "element blocks");
      const int tag = in_.next_int("an entity tag");
      const int type = in_.next_int("an element type");
      const std::size_t m = in_.next_count("the number of elements in the block", 2);
      if(m > n - done)
        in_.error("the element blocks hold more than the " + std::to_string(n) +
                  " elements the section header announces");
      const std::size_t first = type == 4 ? mesh_.tets.size()
                                : type == 2 ? mesh_.triangles.size() : mesh_.edges.size();
      for(std::size_t j = 0; j < m; ++j)
      {
        const long long id = entry_integer("an element tag", j, m, "elements of the block");
        const long line = in_.line();
        if(kept_type_nodes(type) == 0)
          skip_element(type, line);
        else
          read_element(type, id, 0, line);
      }
      if(type == 1 || type == 2 || type == 4)
        blocks_.push_back({dim, tag, type, first, m});
      done += m;
    }
    if(done != n)
      throw Mesh_io_error(src_.file, header, "the section header announces " + std::to_string(n) +
                                                 " elements, but its blocks hold " + std::to_string(done));
    expect_end("Elements", section_line);
  }

  void skip_section(const std::string& name, long line)
  {
    const std::string end = "$End" + name;
    const std::string expected = "'" + end + "' closing the section of line " + std::to_string(line);
    for(std::string t = in_.next(expected.c_str()); t != end; t = in_.next(expected.c_str()))
      if(t[0] == '$')
        in_.error("found '" + t + "' inside section '$" + name + "' of line " + std::to_string(line) +
                  ": its end marker '" + end + "' is missing");
    if(name == "PhysicalNames") return;   // labels keep the physical tags; names have no place
    warnings_ << "warning: " << src_.file << ":" << line << ": "
              << (is_unused_section(name) ? "section '$" + name + "' is not used and will not be written back"
                                          : "unknown section '$" + name + "' skipped")
              << "\n";
  }

  Token_reader in_;
  std::ostream& warnings_;
  Tet_mesh mesh_;
  Tet_mesh_source src_;
  int version_ = 0;
  std::unordered_map<long long, int> node_index_;
  std::map<std::pair<int, int>, int> entity_physical_;   // first physical tag of a 4.1 entity
  std::vector<Block> blocks_;
  std::map<int, std::pair<long, std::size_t>> skipped_;  // type -> first line, count
};

inline const int* element_nodes(const Tet_mesh& mesh, int type, std::size_t i)
{
  switch(type)
  {
  case 15: return &mesh.corners[i];
  case 1: return mesh.edges[i].data();
  case 2: return mesh.triangles[i].data();
  default: return mesh.tets[i].data();
  }
}

inline const std::vector<int>& element_labels(const Tet_mesh& mesh, int type)
{
  return type == 1 ? mesh.edge_labels : type == 2 ? mesh.triangle_labels : mesh.tet_labels;
}

inline std::size_t number_of_elements(const Tet_mesh& mesh, int type)
{
  return type == 15 ? mesh.corners.size() : element_labels(mesh, type).size();
}

inline void write_doubles(std::ostream& out, const double* x, int n)
{
  char buf[32];
  for(int k = 0; k < n; ++k)
  {
    std::snprintf(buf, sizeof buf, k ? " %.17g" : "%.17g", x[k]);
    out << buf;
  }
}

inline void write_point(std::ostream& out, const Tet_mesh::Point& p)
{
  const double x[3] = {p.x(), p.y(), p.z()};
  write_doubles(out, x, 3);
}

inline void write_element_nodes(std::ostream& out, const Tet_mesh& mesh, int type, std::size_t i)
{
  const int* v = element_nodes(mesh, type, i);
  for(int k = 0; k < kept_type_nodes(type); ++k)
    out << ' ' << v[k] + 1;
  out << '\n';
}

inline void write_msh22(std::ostream& out, const Tet_mesh& mesh)
{
  out << "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n" << mesh.points.size() << "\n";
  for(std::size_t i = 0; i < mesh.points.size(); ++i)
  {
    out << i + 1 << ' ';
    write_point(out, mesh.points[i]);
    out << '\n';
  }
  const int types[4] = {15, 1, 2, 4};
  std::size_t n = 0;
  for(int type : types) n += number_of_elements(mesh, type);
  out << "$EndNodes\n$Elements\n" << n << "\n";
  std::size_t id = 0;
  for(int type : types)
    for(std::size_t i = 0; i < number_of_elements(mesh, type); ++i)
    {
      // Physical and elementary tag both carry the label; each corner is its own point.
      out << ++id << ' ' << type << " 2 ";
      if(type == 15)
        out << "0 " << i + 1;
      else
        out << element_labels(mesh, type)[i] << ' ' << element_labels(mesh, type)[i];
      write_element_nodes(out, mesh, type, i);
    }
  out << "$EndElements\n";
}

// Version 4.1 labels: for each dimension, one entity per label, tagged 1, 2, ... in
// increasing label order. A nonzero label is the entity's physical tag; label 0 (the
// outside of a whole triangulation) gets no physical tag, because Gmsh has no physical
// tag 0, and `read_gmsh` gives label 0 to elements of entities without one. Each corner
// is its own point entity. All nodes go in one block on volume 1.
inline void write_msh41(std::ostream& out, const Tet_mesh& mesh)
{
  const int types[4] = {15, 1, 2, 4};
  std::map<int, CGAL::Bbox_3> boxes[4];   // per dimension: label -> box of its elements
  std::map<int, int> entity_tag[4];       // per dimension: label -> entity tag
  for(int d = 1; d < 4; ++d)
  {
    const int type = types[d];
    for(std::size_t i = 0; i < number_of_elements(mesh, type); ++i)
    {
      CGAL::Bbox_3& box = boxes[d][element_labels(mesh, type)[i]];
      for(int k = 0; k < kept_type_nodes(type); ++k)
        box += mesh.points[element_nodes(mesh, type, i)[k]].bbox();
    }
    int tag = 0;
    for(const auto& lb : boxes[d]) entity_tag[d][lb.first] = ++tag;
  }

  out << "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Entities\n" << mesh.corners.size() << ' '
      << boxes[1].size() << ' ' << boxes[2].size() << ' ' << boxes[3].size() << "\n";
  for(std::size_t i = 0; i < mesh.corners.size(); ++i)
  {
    out << i + 1 << ' ';
    write_point(out, mesh.points[mesh.corners[i]]);
    out << " 0\n";
  }
  for(int d = 1; d < 4; ++d)
    for(const auto& lb : boxes[d])
    {
      const double box[6] = {lb.second.xmin(), lb.second.ymin(), lb.second.zmin(),
                             lb.second.xmax(), lb.second.ymax(), lb.second.zmax()};
      out << entity_tag[d][lb.first] << ' ';
      write_doubles(out, box, 6);
      if(lb.first == 0)
        out << " 0 0\n";
      else
        out << " 1 " << lb.first << " 0\n";
    }

  const std::size_t n = mesh.points.size();
  out << "$EndEntities\n$Nodes\n";
  if(n == 0)
    out << "0 0 0 0\n";
  else
  {
    out << "1 " << n << " 1 " << n << "\n3 1 0 " << n << "\n";
    for(std::size_t i = 0; i < n; ++i) out << i + 1 << '\n';
    for(const auto& p : mesh.points)
    {
      write_point(out, p);
      out << '\n';
    }
  }

  // Blocks are runs of consecutive elements with one label, so that the order of
  // the elements survives a round trip.
  struct Block { int dim, type; std::size_t begin, end; };
  std::vector<Block> blocks;
  std::size_t total = 0;
  for(int d = 0; d < 4; ++d)
  {
    const std::size_t m = number_of_elements(mesh, types[d]);
    total += m;
    for(std::size_t i = 0; i < m;)
    {
      std::size_t j = i + 1;
      if(d > 0)
        while(j < m && element_labels(mesh, types[d])[j] == element_labels(mesh, types[d])[i]) ++j;
      blocks.push_back({d, types[d], i, j});
      i = j;
    }
  }
  out << "$EndNodes\n$Elements\n" << blocks.size() << ' ' << total << ' ' << (total ? 1 : 0) << ' '
      << total << "\n";
  std::size_t id = 0;
  for(const Block& b : blocks)
  {
    const int tag = b.dim == 0 ? static_cast<int>(b.begin) + 1
                               : entity_tag[b.dim][element_labels(mesh, b.type)[b.begin]];
    out << b.dim << ' ' << tag << ' ' << b.type << ' ' << b.end - b.begin << '\n';
    for(std::size_t i = b.begin; i < b.end; ++i)
    {
      out << ++id;
      write_element_nodes(out, mesh, b.type, i);
    }
  }
  out << "$EndElements\n";
}

} // namespace internal_gmsh

/// Reads an ASCII Gmsh `.msh` file, format version 2.2 or 4.1. Keeps nodes (any
/// tags, numbered 0, 1, ... in file order), 4-node tetrahedra, triangles and lines
/// with labels, and point elements as corners; skips other element types and other
/// sections with a warning on `warnings`.
///
/// Labels: in version 2.2, an element's first tag (its physical tag, 0 without
/// tags). In version 4.1, the first physical tag of the element's entity, or 0
/// when the entity has none: elements in no physical group are unlabelled, as
/// Medit's label 0 says; `write_gmsh` relies on this to write label 0.
///
/// Throws `Mesh_io_error` ("file:line: what is wrong") on any defect, including
/// those `check_and_orient` finds.
inline Tet_mesh read_gmsh(const std::string& file, std::ostream& warnings = std::cerr)
{
  return internal_gmsh::Msh_parser(file, warnings).parse();
}

/// Writes `mesh` as an ASCII Gmsh `.msh` file, `version` 41 (format 4.1) or 22
/// (format 2.2), with 17 significant digits so that reading it back gives the same
/// doubles. Vertices, tetrahedra, triangles and edges with their labels, and
/// corners survive `read_gmsh`; vertex references, ridges and required vertices
/// do not, Gmsh having no place for them.
inline void write_gmsh(std::ostream& out, const Tet_mesh& mesh, int version = 41)
{
  if(version == 41)
    internal_gmsh::write_msh41(out, mesh);
  else if(version == 22)
    internal_gmsh::write_msh22(out, mesh);
  else
    throw std::invalid_argument("write_gmsh: version must be 41 or 22, not " + std::to_string(version));
}

inline void write_gmsh(const std::string& file, const Tet_mesh& mesh, int version = 41)
{
  write_atomically(file, [&](std::ostream& out) { write_gmsh(out, mesh, version); });
}

} // namespace IO
} // namespace BODT_3
} // namespace CGAL

#endif // CGAL_BODT_3_IO_GMSH_H
