// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_BODT_3_IO_GMSH_H
#define CGAL_BODT_3_IO_GMSH_H

#include <CGAL/BODT_3/Tet_mesh.h>
#include <CGAL/BODT_3/IO/internal/Byte_reader.h>
#include <CGAL/BODT_3/IO/internal/Mapped_file.h>
#include <CGAL/BODT_3/Mesh_io_error.h>
#include <CGAL/BODT_3/IO/internal/Output_buffer.h>
#include <CGAL/BODT_3/IO/internal/Token_reader.h>
#include <CGAL/BODT_3/internal/Mesh/check_tet_mesh.h>
#include <CGAL/BODT_3/IO/write_atomically.h>

#include <CGAL/Bbox_3.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <iostream>
#include <limits>
#include <map>
#include <stdexcept>
#include <string>
#include <string_view>
#include <unordered_map>
#include <utility>
#include <vector>

namespace CGAL {
namespace BODT_3 {
namespace IO {

namespace internal {


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

// Nodes of every element type a binary file may hold: skipping elements there needs
// their size. 0 for types this table does not know.
inline int type_nodes(int type)
{
  static const int n[] = {0, 2, 3, 4, 4, 8, 6, 5, 3, 6, 9, 10, 27, 18, 14, 1, 8, 20, 15, 13, 9, 10, 12,
                          15, 15, 21, 4, 5, 6, 20, 35, 56};
  if(type >= 0 && type < static_cast<int>(sizeof n / sizeof n[0])) return n[type];
  return type == 92 ? 64 : type == 93 ? 125 : 0;
}

// Sections Gmsh defines that hold nothing a `Tet_mesh` keeps; other ones are unknown.
inline bool is_unused_section(std::string_view name)
{
  static const char* const names[] = {"PartitionedEntities", "Periodic", "GhostElements",
                                      "Parametrizations", "NodeData", "ElementData",
                                      "ElementNodeData", "InterpolationScheme"};
  for(const char* n : names)
    if(name == n) return true;
  return false;
}

inline bool looks_like_gmsh(std::string_view head)
{
  const std::string_view t = internal::first_token(head, '\0');
  return t.empty() || std::string_view("$MeshFormat").substr(0, t.size()) == t;
}

// Node tags to vertex indices: a table when the tags are dense (Gmsh numbers them
// 1..n), a hash map otherwise.
class Node_index
{
public:
  template <class Duplicate>
  void build(const std::vector<long long>& tags, Duplicate&& duplicate)
  {
    if(tags.empty()) return;
    const auto mm = std::minmax_element(tags.begin(), tags.end());
    min_ = *mm.first;
    const unsigned long long span = static_cast<unsigned long long>(*mm.second - min_);
    dense_ = span <= 4 * static_cast<unsigned long long>(tags.size()) + 1024;
    if(dense_)
    {
      table_.assign(span + 1, -1);
      for(std::size_t i = 0; i < tags.size(); ++i)
      {
        int& slot = table_[static_cast<std::size_t>(tags[i] - min_)];
        if(slot >= 0) duplicate(i);
        slot = static_cast<int>(i);
      }
    }
    else
    {
      map_.reserve(tags.size());
      for(std::size_t i = 0; i < tags.size(); ++i)
        if(!map_.emplace(tags[i], static_cast<int>(i)).second) duplicate(i);
    }
  }

  /// The vertex of node `tag`, -1 if there is none.
  int find(long long tag) const
  {
    if(dense_)
    {
      if(tag < min_ || static_cast<unsigned long long>(tag - min_) >= table_.size()) return -1;
      return table_[static_cast<std::size_t>(tag - min_)];
    }
    const auto it = map_.find(tag);
    return it == map_.end() ? -1 : it->second;
  }

private:
  bool dense_ = true;
  long long min_ = 0;
  std::vector<int> table_;
  std::unordered_map<long long, int> map_;
};

// Parses one `.msh` file, version 2.2 or 4.1, ASCII or binary, in a single pass.
class Msh_parser
{
public:
  Msh_parser(const std::string& file, std::string_view bytes, std::ostream& warnings)
    : in_(file, bytes, '\0'), bin_(file, bytes), warnings_(warnings)
  {
    src_.file = file;
  }

  int version() const { return version_; }
  bool binary() const { return binary_; }

  Tet_mesh parse()
  {
    read_format();
    bool have_nodes = false, have_elements = false;
    while(!in_.at_end())
    {
      const std::string_view t = in_.next("a section header");
      const long line = in_.line();
      if(t.size() < 2 || t[0] != '$')
        in_.error("expected a section header such as '$Nodes', found '" + printable(t) +
                  "'; the previous section may have more entries than its count says");
      const std::string name(t.substr(1));
      if(name.compare(0, 3, "End") == 0)
        in_.error("'" + printable(t) + "' closes a section that was not opened");
      if(name == "MeshFormat")
        in_.error("a second '$MeshFormat' section");
      else if(name == "Nodes")
      {
        if(have_nodes) in_.error("a second '$Nodes' section");
        have_nodes = true;
        if(version_ == 22) read_nodes_22(line); else read_nodes_41(line);
        build_node_index();
      }
      else if(name == "Elements")
      {
        if(have_elements) in_.error("a second '$Elements' section");
        if(!have_nodes) in_.error("section '$Elements' comes before '$Nodes'");
        have_elements = true;
        if(version_ == 22) read_elements_22(line); else read_elements_41(line);
      }
      else if(name == "Entities" && version_ == 41)
      {
        if(have_entities_) in_.error("a second '$Entities' section");
        have_entities_ = true;
        read_entities(line);
      }
      else
        skip_section(name, line);
    }
    if(!have_nodes) throw Mesh_io_error(src_.file, 0, "the file has no '$Nodes' section");
    if(!have_elements) throw Mesh_io_error(src_.file, 0, "the file has no '$Elements' section");

    // Version 4.1 labels come from entities, which need not precede the elements. A
    // file without $Entities (meshio writes such files) has its label in the entity tag.
    for(const Block& b : blocks_)
    {
      auto it = entity_physical_.find({b.dim, b.tag});
      const int label = !have_entities_ ? b.tag : it == entity_physical_.end() ? 0 : it->second;
      std::vector<int>& labels = b.type == 4 ? mesh_.tet_labels
                                 : b.type == 2 ? mesh_.triangle_labels : mesh_.edge_labels;
      std::fill_n(labels.begin() + static_cast<std::ptrdiff_t>(b.first), b.count, label);
    }
    for(const auto& s : skipped_)
      warnings_ << "warning: " << src_.file << ":" << s.second.first << ": skipped " << s.second.second
                << " element(s) of Gmsh type " << s.first
                << "; only points, lines, triangles and 4-node tetrahedra are read\n";

    mesh_.vertex_refs.assign(mesh_.points.size(), 0);
    BODT_3::internal::check_and_orient(mesh_, src_, warnings_);
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
    const std::string_view first = in_.next("'$MeshFormat'");
    if(first != "$MeshFormat")
      in_.error("not a Gmsh mesh file: expected '$MeshFormat', found '" + printable(first) + "'");
    const long header = in_.line();
    const std::string_view v = in_.next("the format version");
    if(v == "2.2") version_ = 22;
    else if(v == "4.1") version_ = 41;
    else
      in_.error("Gmsh format version " + printable(v) + " is not supported; save the mesh as version 4.1 or 2.2");
    const int file_type = in_.next_int("the file type");
    if(file_type != 0 && file_type != 1)
      in_.error("file type " + std::to_string(file_type) + " is not valid; expected 0 (ASCII) or 1 (binary)");
    binary_ = file_type == 1;
    const int data_size = in_.next_int("the data size");
    if(data_size != 8)
      in_.error("data size " + std::to_string(data_size) + " is not supported; Gmsh writes 8");
    if(binary_)
    {
      // One int written as 1, in the writer's byte order, after the end of the line.
      skip_to_next_line();
      bin_.seek(in_.position(), "the byte order mark");
      const std::int32_t one = bin_.get<std::int32_t>("the binary byte order mark");
      if(one != 1)
      {
        if(internal::byte_swapped(one) != 1)
          bin_.error("the binary byte order mark is " + std::to_string(one) + ", not 1");
        bin_.set_swap(true);
      }
      in_.set_position(bin_.position(), in_.current_line() + 1);
    }
    expect_end("MeshFormat", header);
  }

  void skip_to_next_line()
  {
    in_.rest_of_line();
    const std::size_t p = in_.position();
    if(p >= in_.text().size())
      in_.error("the file ends where binary data was expected; it is truncated");
    in_.set_position(p + 1, in_.current_line() + 1);
  }

  // Starts binary data after the current text line (Gmsh ends each header line with '\n').
  void begin_binary()
  {
    skip_to_next_line();
    bin_.seek(in_.position(), "binary data");
  }

  void end_binary()
  {
    in_.set_position(bin_.position(), in_.current_line());
  }

  // Reads the integer that opens entry `i` of `n`: a '$' marker there means the count is wrong.
  long long entry_integer(const char* what, std::size_t i, std::size_t n, const char* entries)
  {
    if(in_.peek_char() == '$')
    {
      const std::string t(in_.next(what));
      in_.error("found '" + printable(t) + "' after " + std::to_string(i) + " " + entries + ", but " +
                std::to_string(n) + " were announced; the count is wrong or entries are missing");
    }
    return in_.next_integer(what);
  }

  void expect_end(const std::string& section, long header_line)
  {
    const std::string end = "$End" + section;
    const std::string_view t = in_.next(("'" + end + "'").c_str());
    if(t == end) return;
    if(t[0] == '$')
      in_.error("expected '" + end + "' closing the section of line " + std::to_string(header_line) +
                ", found '" + printable(t) + "': the end marker is missing");
    in_.error("expected '" + end + "' closing the section of line " + std::to_string(header_line) +
              ", found '" + printable(t) + "': the section holds more entries than its header announces");
  }

  // Gmsh writes one node or element per line; anything left on the line is garbage.
  template <class What>
  void expect_line_end(What&& what)
  {
    if(!in_.line_is_done())
      in_.error("unexpected '" + printable(in_.rest_of_line()) + "' after " + what());
  }

  void add_node_tag(long long tag)
  {
    if(tag < 1)
      in_.error("node tag " + std::to_string(tag) + " is not positive");
    node_tags_.push_back(tag);
  }

  void build_node_index()
  {
    index_.build(node_tags_, [&](std::size_t i) {
      const std::string m = "node tag " + std::to_string(node_tags_[i]) + " is defined twice";
      if(binary_) throw Mesh_io_error(src_.file, 0, m);
      throw Mesh_io_error(src_.file, src_.vertex_lines[i], m);
    });
    node_tags_ = std::vector<long long>();
  }

  int node(long long element)
  {
    const long long tag = in_.next_integer("a node tag");
    const int v = index_.find(tag);
    if(v < 0)
      in_.error("element " + std::to_string(element) + " refers to node " + std::to_string(tag) +
                ", which section '$Nodes' does not define");
    return v;
  }

  int binary_node(long long element, long long tag)
  {
    const int v = index_.find(tag);
    if(v < 0)
      bin_.error("element " + std::to_string(element) + " refers to node " + std::to_string(tag) +
                 ", which section '$Nodes' does not define");
    return v;
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

  void binary_point()
  {
    double c[3];
    for(double& x : c)
    {
      x = bin_.get<double>("a node coordinate");
      if(!std::isfinite(x)) bin_.error("a node coordinate is not a finite number");
    }
    mesh_.points.emplace_back(c[0], c[1], c[2]);
  }

  // Stores element `v` of kept type `type`; `label` is its 2.2 label. A point element
  // on no geometric entity (all its 2.2 tags 0) is not a corner: mmg, for one, writes
  // such an element for every vertex.
  void store_element(int type, const int* v, int label, long line, bool on_entity)
  {
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

  // Reads the nodes of an element of kept type `type` from the text and stores it.
  void read_element(int type, long long tag, int label, long line, bool on_entity = true)
  {
    int v[4] = {0, 0, 0, 0};
    for(int k = 0; k < kept_type_nodes(type); ++k)
      v[k] = node(tag);
    expect_line_end([&] { return "element " + std::to_string(tag) + " of type " + std::to_string(type); });
    store_element(type, v, label, line, on_entity);
  }

  void skip_element(int type, long line)
  {
    in_.rest_of_line();
    note_skipped(type, line, 1);
  }

  void note_skipped(int type, long line, std::size_t count)
  {
    auto& s = skipped_.emplace(type, std::make_pair(line, std::size_t(0))).first->second;
    s.second += count;
  }

  std::size_t binary_count(const char* what, std::size_t bytes_per_entry)
  {
    const std::uint64_t n = bin_.get<std::uint64_t>(what);
    bin_.check_count(what, n, bytes_per_entry);
    return static_cast<std::size_t>(n);
  }

  void check_vertex_count(std::size_t n)
  {
    if(n > static_cast<std::size_t>(std::numeric_limits<int>::max()))
      in_.error("the file announces " + std::to_string(n) + " nodes, more than this reader can index");
  }

  void read_nodes_22(long header)
  {
    const std::size_t n = binary_ ? 0 : in_.next_count("the number of nodes", 4);
    if(binary_)
    {
      const long long m = in_.next_integer("the number of nodes");
      if(m < 0) in_.error("the number of nodes is negative (" + std::to_string(m) + ")");
      begin_binary();
      bin_.check_count("the number of nodes", static_cast<unsigned long long>(m), 28);
      check_vertex_count(static_cast<std::size_t>(m));
      mesh_.points.reserve(static_cast<std::size_t>(m));
      node_tags_.reserve(static_cast<std::size_t>(m));
      for(long long i = 0; i < m; ++i)
      {
        const std::int32_t tag = bin_.get<std::int32_t>("a node tag");
        if(tag < 1) bin_.error("node tag " + std::to_string(tag) + " is not positive");
        node_tags_.push_back(tag);
        binary_point();
      }
      end_binary();
      expect_end("Nodes", header);
      return;
    }
    check_vertex_count(n);
    mesh_.points.reserve(n);
    src_.vertex_lines.reserve(n);
    node_tags_.reserve(n);
    for(std::size_t i = 0; i < n; ++i)
    {
      const long long tag = entry_integer("a node tag", i, n, "nodes");
      add_node_tag(tag);
      read_point(0);
      expect_line_end([&] { return "node " + std::to_string(tag); });
    }
    expect_end("Nodes", header);
  }

  // 2.2: "number type number-of-tags tags... nodes...", the first tag being the physical one.
  // Binary: blocks "type count number-of-tags", then per element "number tags... nodes...".
  void read_elements_22(long header)
  {
    if(binary_)
    {
      const long long n = in_.next_integer("the number of elements");
      if(n < 0) in_.error("the number of elements is negative (" + std::to_string(n) + ")");
      begin_binary();
      bin_.check_count("the number of elements", static_cast<unsigned long long>(n), 8);
      long long done = 0;
      while(done < n)
      {
        const std::int32_t type = bin_.get<std::int32_t>("an element type");
        const std::int32_t count = bin_.get<std::int32_t>("a number of elements");
        const std::int32_t ntags = bin_.get<std::int32_t>("a number of element tags");
        if(count < 1 || count > n - done)
          bin_.error("a block of " + std::to_string(count) + " elements, but " + std::to_string(n - done) +
                     " of the announced " + std::to_string(n) + " remain");
        if(ntags < 0 || ntags > 1000)
          bin_.error("an element has " + std::to_string(ntags) + " tags");
        const int nodes = type_nodes(type);
        if(nodes == 0)
          bin_.error("element type " + std::to_string(type) + " is unknown; its size cannot be known");
        const std::size_t words = 1 + static_cast<std::size_t>(ntags) + static_cast<std::size_t>(nodes);
        bin_.check_count("the number of elements in the block", static_cast<unsigned long long>(count), 4 * words);
        if(kept_type_nodes(type) == 0)
        {
          bin_.skip(4 * words * static_cast<std::size_t>(count), "the elements");
          note_skipped(type, 0, static_cast<std::size_t>(count));
        }
        else
          for(std::int32_t j = 0; j < count; ++j)
          {
            const std::int32_t id = bin_.get<std::int32_t>("an element number");
            int label = 0;
            bool tagged = false;
            for(std::int32_t k = 0; k < ntags; ++k)
            {
              const std::int32_t t = bin_.get<std::int32_t>("an element tag");
              if(k == 0) label = t;
              tagged = tagged || t != 0;
            }
            int v[4] = {0, 0, 0, 0};
            for(int k = 0; k < nodes; ++k)
              v[k] = binary_node(id, bin_.get<std::int32_t>("a node tag"));
            store_element(type, v, label, 0, tagged);
          }
        done += count;
      }
      end_binary();
      expect_end("Elements", header);
      return;
    }
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

  void set_physical(int d, long long tag, int physical)
  {
    entity_physical_[{d, static_cast<int>(tag)}] = physical;
  }

  // 4.1: points "tag x y z physicals"; curves, surfaces, volumes
  // "tag box(6) physicals bounding-entities", each list preceded by its length.
  void read_entities(long header)
  {
    std::size_t count[4], total = 0;
    if(binary_)
    {
      begin_binary();
      for(int d = 0; d < 4; ++d)
        total += count[d] = binary_count("a number of entities", 36);
      for(int d = 0; d < 4; ++d)
        for(std::size_t i = 0; i < count[d]; ++i)
        {
          const std::int32_t tag = bin_.get<std::int32_t>("an entity tag");
          if(tag < 1) bin_.error("entity tag " + std::to_string(tag) + " is out of range");
          bin_.skip(8 * (d == 0 ? 3 : 6), "an entity's coordinates");
          const std::size_t nphys = binary_count("the number of physical tags", 4);
          for(std::size_t k = 0; k < nphys; ++k)
          {
            const std::int32_t p = bin_.get<std::int32_t>("a physical tag");
            if(k == 0) set_physical(d, tag, p);
          }
          if(d > 0)
            bin_.skip(4 * binary_count("the number of bounding entities", 4), "the bounding entities");
        }
      end_binary();
      expect_end("Entities", header);
      return;
    }
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
          if(k == 0) set_physical(d, tag, p);
        }
        if(d > 0)
        {
          const std::size_t nbound = in_.next_count("the number of bounding entities", 1);
          for(std::size_t k = 0; k < nbound; ++k)
            in_.next_int("a bounding entity tag");
        }
        expect_line_end([&] { return "entity " + std::to_string(tag); });
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
    if(binary_)
    {
      begin_binary();
      const std::size_t blocks = binary_count("the number of node blocks", 20);
      const std::size_t n = binary_count("the number of nodes", 32);
      check_vertex_count(n);
      bin_.skip(16, "the node tag range");
      mesh_.points.reserve(n);
      node_tags_.reserve(n);
      for(std::size_t b = 0; b < blocks; ++b)
      {
        const std::int32_t dim = bin_.get<std::int32_t>("an entity dimension");
        bin_.get<std::int32_t>("an entity tag");
        const std::int32_t parametric = bin_.get<std::int32_t>("the parametric flag");
        if(dim < 0 || dim > 3) bin_.error("entity dimension " + std::to_string(dim) + " is not 0, 1, 2 or 3");
        if(parametric != 0 && parametric != 1)
          bin_.error("the parametric flag is " + std::to_string(parametric) + ", not 0 or 1");
        const std::size_t extra = parametric ? static_cast<std::size_t>(dim) : 0;
        const std::size_t m = binary_count("the number of nodes in the block", 8 * (4 + extra));
        if(m > n - mesh_.points.size())
          bin_.error("the node blocks hold more than the " + std::to_string(n) +
                     " nodes the section header announces");
        for(std::size_t j = 0; j < m; ++j)
        {
          const std::uint64_t tag = bin_.get<std::uint64_t>("a node tag");
          if(tag < 1 || tag > static_cast<std::uint64_t>(std::numeric_limits<long long>::max()))
            bin_.error("node tag " + std::to_string(tag) + " is out of range");
          node_tags_.push_back(static_cast<long long>(tag));
        }
        for(std::size_t j = 0; j < m; ++j)
        {
          binary_point();
          bin_.skip(8 * extra, "parametric coordinates");
        }
      }
      if(mesh_.points.size() != n)
        bin_.error("the section header announces " + std::to_string(n) + " nodes, but its blocks hold " +
                   std::to_string(mesh_.points.size()));
      end_binary();
      expect_end("Nodes", section_line);
      return;
    }
    const std::size_t blocks = in_.next_count("the number of node blocks", 4);
    const long header = in_.line();
    const std::size_t n = in_.next_count("the number of nodes", 4);
    check_vertex_count(n);
    in_.next_integer("the smallest node tag");
    in_.next_integer("the largest node tag");
    mesh_.points.reserve(n);
    src_.vertex_lines.reserve(n);
    node_tags_.reserve(n);
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
        add_node_tag(tag);
        expect_line_end([&] { return "node tag " + std::to_string(tag); });
      }
      for(std::size_t j = 0; j < m; ++j)
      {
        read_point(parametric ? static_cast<std::size_t>(dim) : 0);
        expect_line_end([&] { return "the coordinates of node " + std::to_string(first + j + 1) + " of the section"; });
      }
    }
    if(mesh_.points.size() != n)
      throw Mesh_io_error(src_.file, header, "the section header announces " + std::to_string(n) +
                                                 " nodes, but its blocks hold " +
                                                 std::to_string(mesh_.points.size()));
    expect_end("Nodes", section_line);
  }

  std::size_t first_of_type(int type) const
  {
    return type == 4 ? mesh_.tets.size() : type == 2 ? mesh_.triangles.size() : mesh_.edges.size();
  }

  // 4.1: "blocks elements min-tag max-tag", then per block "dim tag type count" and
  // one "tag nodes..." line per element.
  void read_elements_41(long section_line)
  {
    if(binary_)
    {
      begin_binary();
      const std::size_t blocks = binary_count("the number of element blocks", 20);
      const std::size_t n = binary_count("the number of elements", 16);
      bin_.skip(16, "the element tag range");
      std::size_t done = 0;
      for(std::size_t b = 0; b < blocks; ++b)
      {
        const std::int32_t dim = bin_.get<std::int32_t>("an entity dimension");
        const std::int32_t tag = bin_.get<std::int32_t>("an entity tag");
        const std::int32_t type = bin_.get<std::int32_t>("an element type");
        if(dim < 0 || dim > 3) bin_.error("entity dimension " + std::to_string(dim) + " is not 0, 1, 2 or 3");
        const int nodes = type_nodes(type);
        if(nodes == 0)
          bin_.error("element type " + std::to_string(type) + " is unknown; its size cannot be known");
        const std::size_t m = binary_count("the number of elements in the block", 8 * (1 + static_cast<std::size_t>(nodes)));
        if(m > n - done)
          bin_.error("the element blocks hold more than the " + std::to_string(n) +
                     " elements the section header announces");
        const std::size_t first = first_of_type(type);
        if(kept_type_nodes(type) == 0)
        {
          bin_.skip(8 * (1 + static_cast<std::size_t>(nodes)) * m, "the elements");
          note_skipped(type, 0, m);
        }
        else
        {
          for(std::size_t j = 0; j < m; ++j)
          {
            const std::uint64_t id = bin_.get<std::uint64_t>("an element tag");
            int v[4] = {0, 0, 0, 0};
            for(int k = 0; k < nodes; ++k)
            {
              const std::uint64_t t = bin_.get<std::uint64_t>("a node tag");
              v[k] = binary_node(static_cast<long long>(id),
                                 t > static_cast<std::uint64_t>(std::numeric_limits<long long>::max()) ? -1
                                                                                                        : static_cast<long long>(t));
            }
            store_element(type, v, 0, 0, true);
          }
          if(type != 15) blocks_.push_back({dim, tag, type, first, m});
        }
        done += m;
      }
      if(done != n)
        bin_.error("the section header announces " + std::to_string(n) + " elements, but its blocks hold " +
                   std::to_string(done));
      end_binary();
      expect_end("Elements", section_line);
      return;
    }
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
      const std::size_t first = first_of_type(type);
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
    if(binary_ && name != "PhysicalNames")
    {
      // Binary data may hold anything but the end marker at the start of a line.
      const std::string marker = "\n" + end;
      const std::size_t at = in_.text().find(marker, in_.position());
      if(at == std::string_view::npos)
        in_.error("section '$" + name + "' of line " + std::to_string(line) + " has no end marker '" + end + "'");
      in_.set_position(at + 1, in_.current_line());
      in_.next(expected.c_str());
    }
    else
      for(std::string_view t = in_.next(expected.c_str()); t != end; t = in_.next(expected.c_str()))
        if(t[0] == '$')
          in_.error("found '" + printable(t) + "' inside section '$" + name + "' of line " + std::to_string(line) +
                    ": its end marker '" + end + "' is missing");
    if(name == "PhysicalNames") return;   // labels keep the physical tags; names have no place
    warnings_ << "warning: " << src_.file << ":" << line << ": "
              << (is_unused_section(name) ? "section '$" + name + "' is not used and will not be written back"
                                          : "unknown section '$" + printable(name) + "' skipped")
              << "\n";
  }

  Token_reader in_;
  Byte_reader bin_;
  std::ostream& warnings_;
  Tet_mesh mesh_;
  BODT_3::internal::Tet_mesh_source src_;
  int version_ = 0;
  bool binary_ = false;
  bool have_entities_ = false;
  std::vector<long long> node_tags_;
  Node_index index_;
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


inline void write_point(Output_buffer& out, const Tet_mesh::Point& p)
{
  out.put_double(p.x()).put(' ').put_double(p.y()).put(' ').put_double(p.z());
}

inline void write_element_nodes(Output_buffer& out, const Tet_mesh& mesh, int type, std::size_t i)
{
  const int* v = element_nodes(mesh, type, i);
  for(int k = 0; k < kept_type_nodes(type); ++k)
    out.put(' ').put_int(v[k] + 1);
  out.put('\n');
}

inline void check_int32(std::size_t n, const char* what)
{
  if(n > static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max()))
    throw std::invalid_argument(std::string("write_gmsh: too many ") + what + " for Gmsh 2.2 binary");
}

inline void write_msh22(std::ostream& stream, const Tet_mesh& mesh, bool binary)
{
  Output_buffer out(stream);
  out.put(binary ? "$MeshFormat\n2.2 1 8\n" : "$MeshFormat\n2.2 0 8\n");
  if(binary) out.put_binary(std::int32_t(1)).put('\n');
  out.put("$EndMeshFormat\n$Nodes\n").put_int(mesh.points.size()).put('\n');
  check_int32(mesh.points.size(), "nodes");
  for(std::size_t i = 0; i < mesh.points.size(); ++i)
  {
    const auto& p = mesh.points[i];
    if(binary)
      out.put_binary(static_cast<std::int32_t>(i + 1)).put_binary(p.x()).put_binary(p.y()).put_binary(p.z());
    else
    {
      out.put_int(i + 1).put(' ');
      write_point(out, p);
      out.put('\n');
    }
  }
  if(binary) out.put('\n');
  const int types[4] = {15, 1, 2, 4};
  std::size_t n = 0;
  for(int type : types) n += number_of_elements(mesh, type);
  check_int32(n, "elements");
  out.put("$EndNodes\n$Elements\n").put_int(n).put('\n');
  std::int32_t id = 0;
  for(int type : types)
  {
    const std::size_t m = number_of_elements(mesh, type);
    if(binary && m > 0)
      out.put_binary(std::int32_t(type)).put_binary(static_cast<std::int32_t>(m)).put_binary(std::int32_t(2));
    for(std::size_t i = 0; i < m; ++i)
    {
      // Physical and elementary tag both carry the label; each corner is its own point.
      const std::int32_t physical = type == 15 ? 0 : element_labels(mesh, type)[i];
      const std::int32_t elementary = type == 15 ? static_cast<std::int32_t>(i + 1) : physical;
      ++id;
      if(binary)
      {
        out.put_binary(id).put_binary(physical).put_binary(elementary);
        const int* v = element_nodes(mesh, type, i);
        for(int k = 0; k < kept_type_nodes(type); ++k) out.put_binary(static_cast<std::int32_t>(v[k] + 1));
      }
      else
      {
        out.put_int(id).put(' ').put_int(type).put(" 2 ").put_int(physical).put(' ').put_int(elementary);
        write_element_nodes(out, mesh, type, i);
      }
    }
  }
  if(binary) out.put('\n');
  out.put("$EndElements\n");
}

// Version 4.1 labels: for each dimension, one entity per label, tagged 1, 2, ... in
// increasing label order. A nonzero label is the entity's physical tag; label 0 (the
// outside of a whole triangulation) gets no physical tag, because Gmsh has no physical
// tag 0, and `read_gmsh` gives label 0 to elements of entities without one. Each corner
// is its own point entity. All nodes go in one block on volume 1.
inline void write_msh41(std::ostream& stream, const Tet_mesh& mesh, bool binary)
{
  Output_buffer out(stream);
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
  auto size = [&](std::size_t v) -> Output_buffer& {
    return binary ? out.put_binary(static_cast<std::uint64_t>(v)) : out.put_int(v);
  };
  auto sep = [&](char c) { if(!binary) out.put(c); };

  out.put(binary ? "$MeshFormat\n4.1 1 8\n" : "$MeshFormat\n4.1 0 8\n");
  if(binary) out.put_binary(std::int32_t(1)).put('\n');
  out.put("$EndMeshFormat\n$Entities\n");
  const std::size_t counts[4] = {mesh.corners.size(), boxes[1].size(), boxes[2].size(), boxes[3].size()};
  for(int d = 0; d < 4; ++d) { size(counts[d]); sep(d < 3 ? ' ' : '\n'); }
  for(std::size_t i = 0; i < mesh.corners.size(); ++i)
  {
    const auto& p = mesh.points[mesh.corners[i]];
    if(binary)
      out.put_binary(static_cast<std::int32_t>(i + 1)).put_binary(p.x()).put_binary(p.y()).put_binary(p.z())
         .put_binary(std::uint64_t(0));
    else
    {
      out.put_int(i + 1).put(' ');
      write_point(out, p);
      out.put(" 0\n");
    }
  }
  for(int d = 1; d < 4; ++d)
    for(const auto& lb : boxes[d])
    {
      const double box[6] = {lb.second.xmin(), lb.second.ymin(), lb.second.zmin(),
                             lb.second.xmax(), lb.second.ymax(), lb.second.zmax()};
      if(binary)
      {
        out.put_binary(static_cast<std::int32_t>(entity_tag[d][lb.first]));
        for(double b : box) out.put_binary(b);
        if(lb.first == 0) out.put_binary(std::uint64_t(0));
        else out.put_binary(std::uint64_t(1)).put_binary(static_cast<std::int32_t>(lb.first));
        out.put_binary(std::uint64_t(0));
      }
      else
      {
        out.put_int(entity_tag[d][lb.first]);
        for(double b : box) out.put(' ').put_double(b);
        if(lb.first == 0)
          out.put(" 0 0\n");
        else
          out.put(" 1 ").put_int(lb.first).put(" 0\n");
      }
    }
  if(binary) out.put('\n');

  const std::size_t n = mesh.points.size();
  out.put("$EndEntities\n$Nodes\n");
  if(binary)
  {
    out.put_binary(std::uint64_t(n ? 1 : 0)).put_binary(std::uint64_t(n)).put_binary(std::uint64_t(n ? 1 : 0))
       .put_binary(std::uint64_t(n));
    if(n > 0)
    {
      out.put_binary(std::int32_t(3)).put_binary(std::int32_t(1)).put_binary(std::int32_t(0)).put_binary(std::uint64_t(n));
      for(std::size_t i = 0; i < n; ++i) out.put_binary(static_cast<std::uint64_t>(i + 1));
      for(const auto& p : mesh.points) out.put_binary(p.x()).put_binary(p.y()).put_binary(p.z());
    }
    out.put('\n');
  }
  else if(n == 0)
    out.put("0 0 0 0\n");
  else
  {
    out.put("1 ").put_int(n).put(" 1 ").put_int(n).put("\n3 1 0 ").put_int(n).put('\n');
    for(std::size_t i = 0; i < n; ++i) out.put_int(i + 1).put('\n');
    for(const auto& p : mesh.points)
    {
      write_point(out, p);
      out.put('\n');
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
  out.put("$EndNodes\n$Elements\n");
  size(blocks.size()); sep(' '); size(total); sep(' '); size(total ? 1 : 0); sep(' '); size(total); sep('\n');
  std::size_t id = 0;
  for(const Block& b : blocks)
  {
    const int tag = b.dim == 0 ? static_cast<int>(b.begin) + 1
                               : entity_tag[b.dim][element_labels(mesh, b.type)[b.begin]];
    if(binary)
    {
      out.put_binary(static_cast<std::int32_t>(b.dim)).put_binary(static_cast<std::int32_t>(tag))
         .put_binary(static_cast<std::int32_t>(b.type)).put_binary(static_cast<std::uint64_t>(b.end - b.begin));
      for(std::size_t i = b.begin; i < b.end; ++i)
      {
        out.put_binary(static_cast<std::uint64_t>(++id));
        const int* v = element_nodes(mesh, b.type, i);
        for(int k = 0; k < kept_type_nodes(b.type); ++k) out.put_binary(static_cast<std::uint64_t>(v[k] + 1));
      }
    }
    else
    {
      out.put_int(b.dim).put(' ').put_int(tag).put(' ').put_int(b.type).put(' ').put_int(b.end - b.begin).put('\n');
      for(std::size_t i = b.begin; i < b.end; ++i)
      {
        out.put_int(++id);
        write_element_nodes(out, mesh, b.type, i);
      }
    }
  }
  if(binary) out.put('\n');
  out.put("$EndElements\n");
}

/// Parses the bytes of a `.msh` file named `file`; `version` (22 or 41) and
/// `binary` receive what the file is.
inline Tet_mesh parse_gmsh(const std::string& file, std::string_view bytes, std::ostream& warnings, int& version,
                      bool& binary)
{
  Msh_parser parser(file, bytes, warnings);
  Tet_mesh mesh = parser.parse();
  version = parser.version();
  binary = parser.binary();
  return mesh;
}

} // namespace internal

/// Reads a Gmsh `.msh` file, format version 2.2 or 4.1, ASCII or binary (either
/// byte order). Keeps nodes (any tags, numbered 0, 1, ... in file order), 4-node
/// tetrahedra, triangles and lines with labels, and point elements as corners;
/// skips other element types and other sections with a warning on `warnings`.
///
/// Labels: in version 2.2, an element's first tag (its physical tag, 0 without
/// tags). In version 4.1, the first physical tag of the element's entity, or 0
/// when the entity has none: elements in no physical group are unlabelled, as
/// Medit's label 0 says; `write_gmsh` relies on this to write label 0. A 4.1 file
/// without `$Entities` (as meshio writes them) gives each element its entity tag.
///
/// Throws `Mesh_io_error` ("file:line: what is wrong", or "file: at byte N: ..."
/// inside binary data) on any defect, including those `check_and_orient` finds.
/// `version` (22 or 41) and `binary`, when given, receive what the file is.
inline Tet_mesh read_gmsh(const std::string& file, std::ostream& warnings = std::cerr, int* version = nullptr,
                          bool* binary = nullptr)
{
  const internal::Mapped_file data(file, "a Gmsh mesh file", internal::looks_like_gmsh);
  int v = 0;
  bool b = false;
  Tet_mesh mesh = internal::parse_gmsh(file, data.bytes(), warnings, v, b);
  if(version) *version = v;
  if(binary) *binary = b;
  return mesh;
}

/// Writes `mesh` as a Gmsh `.msh` file, `version` 41 (format 4.1) or 22 (format
/// 2.2), ASCII or `binary` (the machine's byte order, as Gmsh does), with numbers
/// in the shortest form that reads back to the same double. Vertices, tetrahedra,
/// triangles and edges with their labels, and corners survive `read_gmsh`; vertex
/// references, ridges and required vertices do not, Gmsh having no place for them.
inline void write_gmsh(std::ostream& out, const Tet_mesh& mesh, int version = 41, bool binary = false)
{
  if(version == 41)
    internal::write_msh41(out, mesh, binary);
  else if(version == 22)
    internal::write_msh22(out, mesh, binary);
  else
    throw std::invalid_argument("write_gmsh: version must be 41 or 22, not " + std::to_string(version));
}

inline void write_gmsh(const std::string& file, const Tet_mesh& mesh, int version = 41, bool binary = false)
{
  if(version != 41 && version != 22)
    throw std::invalid_argument("write_gmsh: version must be 41 or 22, not " + std::to_string(version));
  write_atomically(file, [&](std::ostream& out) { write_gmsh(out, mesh, version, binary); });
}

} // namespace IO
} // namespace BODT_3
} // namespace CGAL

#endif // CGAL_BODT_3_IO_GMSH_H
