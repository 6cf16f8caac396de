// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_BODT_3_IO_VTU_H
#define CGAL_BODT_3_IO_VTU_H

#include <CGAL/BODT_3/Tet_mesh.h>
#include <CGAL/BODT_3/IO/internal/Byte_reader.h>
#include <CGAL/BODT_3/IO/internal/Mapped_file.h>
#include <CGAL/BODT_3/Mesh_io_error.h>
#include <CGAL/BODT_3/IO/internal/Output_buffer.h>
#include <CGAL/BODT_3/IO/internal/Token_reader.h>
#include <CGAL/BODT_3/internal/Mesh/check_tet_mesh.h>
#include <CGAL/BODT_3/IO/internal/vtk_cells.h>
#include <CGAL/BODT_3/IO/write_atomically.h>

#include <zlib.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <iostream>
#include <limits>
#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace CGAL {
namespace BODT_3 {
namespace IO {

namespace internal {


inline int base64_value(char c)
{
  if(c >= 'A' && c <= 'Z') return c - 'A';
  if(c >= 'a' && c <= 'z') return c - 'a' + 26;
  if(c >= '0' && c <= '9') return c - '0' + 52;
  if(c == '+') return 62;
  if(c == '/') return 63;
  return -1;
}

/// Decodes base64 four characters at a time, each group padded or not, so that
/// VTK's separately encoded header and data decode as one run. Blanks are skipped.
inline bool base64_decode(std::string_view in, std::vector<unsigned char>& out)
{
  int quad[4];
  int n = 0, pad = 0;
  for(char c : in)
  {
    if(internal::is_space(c)) continue;
    if(c == '=') { quad[n++] = 0; ++pad; }
    else
    {
      const int v = base64_value(c);
      if(v < 0 || pad > 0) return false;
      quad[n++] = v;
    }
    if(n == 4)
    {
      const unsigned bits = (unsigned(quad[0]) << 18) | (unsigned(quad[1]) << 12) | (unsigned(quad[2]) << 6) | unsigned(quad[3]);
      if(pad > 2) return false;
      out.push_back(static_cast<unsigned char>(bits >> 16));
      if(pad < 2) out.push_back(static_cast<unsigned char>(bits >> 8 & 0xff));
      if(pad < 1) out.push_back(static_cast<unsigned char>(bits & 0xff));
      n = 0;
      pad = 0;
    }
  }
  return n == 0;
}

// A <DataArray> and where its content is.
struct Array
{
  std::string_view parent, type, name, format;
  long long components = 1;
  long long offset = -1;
  std::size_t tag = 0, begin = 0, end = 0;
};

// The parts of a VTK XML UnstructuredGrid file a mesh needs.
class Vtu_parser
{
public:
  Vtu_parser(const std::string& file, std::string_view text, std::ostream& warnings)
    : file_(file), text_(text), warnings_(warnings)
  {}

  bool binary() const { return binary_; }

  Tet_mesh parse()
  {
    if(text_.find_first_not_of(" \t\r\n") == std::string_view::npos)
      throw Mesh_io_error(file_, 0, "the file is empty");
    scan();
    const Array* points = nullptr;
    const Array* connectivity = nullptr;
    const Array* offsets = nullptr;
    const Array* types = nullptr;
    const Array* labels = nullptr;
    const Array* refs = nullptr;
    int label_rank = 100;
    for(const Array& a : arrays_)
    {
      if(a.parent == "Points") points = &a;
      else if(a.parent == "Cells")
      {
        if(a.name == "connectivity") connectivity = &a;
        else if(a.name == "offsets") offsets = &a;
        else if(a.name == "types") types = &a;
      }
      else if(a.parent == "CellData")
      {
        const int r = internal::label_array_rank(a.name);
        if(r >= 0 && r < label_rank && a.components == 1) { labels = &a; label_rank = r; }
      }
      else if(a.parent == "PointData" && internal::is_vertex_ref_array(a.name) && a.components == 1)
        refs = &a;
    }
    if(!points) error(0, "the piece has no <Points> data array");
    if(!connectivity || !offsets || !types)
      error(0, "the piece's <Cells> lack a 'connectivity', 'offsets' or 'types' data array");

    Tet_mesh mesh;
    if(points->components != 3)
      error(points->tag, "the points have " + std::to_string(points->components) + " components, not 3");
    const std::vector<double> xyz = values<double>(*points, 3 * number_of_points_);
    for(std::size_t i = 0; i < xyz.size(); ++i)
      if(!std::isfinite(xyz[i]))
        error(points->tag, "point " + std::to_string(i / 3) + " has a coordinate that is not a finite number");
    mesh.points.reserve(xyz.size() / 3);
    for(std::size_t i = 0; i + 2 < xyz.size(); i += 3) mesh.points.emplace_back(xyz[i], xyz[i + 1], xyz[i + 2]);
    mesh.vertex_refs.assign(mesh.points.size(), 0);
    if(refs)
    {
      const std::vector<long long> r = values<long long>(*refs, number_of_points_);
      for(std::size_t i = 0; i < r.size(); ++i)
      {
        if(r[i] < std::numeric_limits<int>::min() || r[i] > std::numeric_limits<int>::max())
          error(refs->tag, "point " + std::to_string(i) + " has reference " + std::to_string(r[i]) + ", out of range");
        mesh.vertex_refs[i] = static_cast<int>(r[i]);
      }
    }

    std::vector<long long> off = values<long long>(*offsets, number_of_cells_);
    off.insert(off.begin(), 0);   // VTK XML offsets give each cell's end
    const std::vector<long long> conn = values<long long>(*connectivity, std::size_t(-1));
    const std::vector<long long> typ = values<long long>(*types, number_of_cells_);
    std::vector<long long> lab;
    if(labels) lab = values<long long>(*labels, number_of_cells_);
    std::map<long long, std::size_t> skipped;
    internal::add_cells(mesh, conn, off, typ, labels ? &lab : nullptr, skipped,
                            [&](const std::string& m) { error(connectivity->tag, m); });
    internal::warn_skipped(warnings_, file_, skipped);
    if(!labels)
      warnings_ << "warning: " << file_ << ": no cell data array of labels ('label', 'medit:ref', "
                   "'gmsh:physical', ...); every cell gets label 0\n";
    BODT_3::internal::Tet_mesh_source src;
    src.file = file_;
    BODT_3::internal::check_and_orient(mesh, src, warnings_);
    return mesh;
  }

private:
  long line_at(std::size_t pos) const
  {
    return 1 + static_cast<long>(std::count(text_.begin(), text_.begin() + static_cast<std::ptrdiff_t>(std::min(pos, text_.size())), '\n'));
  }

  [[noreturn]] void error(std::size_t pos, const std::string& message) const
  {
    throw Mesh_io_error(file_, pos > 0 ? line_at(pos) : 0, message);
  }

  static std::string_view attribute(std::string_view attrs, std::string_view key)
  {
    std::size_t p = 0;
    while((p = attrs.find(key, p)) != std::string_view::npos)
    {
      const bool starts = p == 0 || internal::is_space(attrs[p - 1]);
      std::size_t q = p + key.size();
      while(q < attrs.size() && internal::is_space(attrs[q])) ++q;
      if(starts && q < attrs.size() && attrs[q] == '=')
      {
        ++q;
        while(q < attrs.size() && internal::is_space(attrs[q])) ++q;
        if(q < attrs.size() && (attrs[q] == '"' || attrs[q] == '\''))
        {
          const std::size_t e = attrs.find(attrs[q], q + 1);
          if(e != std::string_view::npos) return attrs.substr(q + 1, e - q - 1);
        }
        return {};
      }
      p += key.size();
    }
    return {};
  }

  long long integer_attribute(std::string_view attrs, std::string_view key, std::size_t pos, long long fallback)
  {
    const std::string_view v = attribute(attrs, key);
    if(v.empty()) return fallback;
    long long x;
    if(!internal::parse_integer(v, x) || x < 0)
      error(pos, "attribute " + std::string(key) + "=\"" + printable(v) + "\" is not a non-negative integer");
    return x;
  }

  // One pass over the tags, up to <AppendedData>, whose raw bytes are not XML.
  void scan()
  {
    std::vector<std::string_view> stack;
    int pieces = 0;
    bool root = false;
    std::size_t p = 0;
    while((p = text_.find('<', p)) != std::string_view::npos)
    {
      if(text_.compare(p, 4, "<!--") == 0)
      {
        const std::size_t e = text_.find("-->", p + 4);
        if(e == std::string_view::npos) error(p, "a comment is not closed");
        p = e + 3;
        continue;
      }
      if(text_.compare(p, 2, "<?") == 0)
      {
        const std::size_t e = text_.find("?>", p + 2);
        if(e == std::string_view::npos) error(p, "a processing instruction is not closed");
        p = e + 2;
        continue;
      }
      // The tag's end: the first '>' outside quotes.
      std::size_t e = p + 1;
      char quote = 0;
      for(; e < text_.size(); ++e)
      {
        if(quote) { if(text_[e] == quote) quote = 0; }
        else if(text_[e] == '"' || text_[e] == '\'') quote = text_[e];
        else if(text_[e] == '>') break;
      }
      if(e >= text_.size()) error(p, "a tag is not closed; the file is truncated");
      const bool closing = text_[p + 1] == '/';
      const bool self_closing = text_[e - 1] == '/';
      std::size_t n = p + 1 + closing;
      std::size_t ne = n;
      while(ne < e && !internal::is_space(text_[ne]) && text_[ne] != '/') ++ne;
      const std::string_view name = text_.substr(n, ne - n);
      const std::string_view attrs = text_.substr(ne, e - ne - (self_closing ? 1 : 0));
      if(closing)
      {
        if(stack.empty() || stack.back() != name)
          error(p, "closing tag </" + printable(name) + "> does not match " +
                       (stack.empty() ? std::string("any open tag") : "<" + printable(stack.back()) + ">"));
        stack.pop_back();
        p = e + 1;
        continue;
      }
      if(!root)
      {
        if(name != "VTKFile")
          error(p, "not a VTK XML file: the first element is <" + printable(name) + ">, not <VTKFile>");
        root = true;
        const std::string_view type = attribute(attrs, "type");
        if(type != "UnstructuredGrid")
          error(p, "a VTK XML file of type '" + printable(type) + "'; only UnstructuredGrid (.vtu) is read");
        const std::string_view order = attribute(attrs, "byte_order");
        swap_ = order == "BigEndian";
        if(!order.empty() && order != "BigEndian" && order != "LittleEndian")
          error(p, "byte_order '" + printable(order) + "' is neither LittleEndian nor BigEndian");
        const std::string_view header = attribute(attrs, "header_type");
        if(header == "UInt64") header_size_ = 8;
        else if(!header.empty() && header != "UInt32")
          error(p, "header_type '" + printable(header) + "' is neither UInt32 nor UInt64");
        const std::string_view compressor = attribute(attrs, "compressor");
        if(compressor == "vtkZLibDataCompressor") compressed_ = true;
        else if(!compressor.empty())
          error(p, "compressor '" + printable(compressor) + "' is not supported; save with zlib or no compression");
      }
      if(name == "Piece")
      {
        if(++pieces > 1) error(p, "the file has more than one <Piece>; only single-piece files are read");
        number_of_points_ = static_cast<std::size_t>(integer_attribute(attrs, "NumberOfPoints", p, 0));
        number_of_cells_ = static_cast<std::size_t>(integer_attribute(attrs, "NumberOfCells", p, 0));
      }
      if(name == "AppendedData")
      {
        const std::string_view encoding = attribute(attrs, "encoding");
        if(encoding != "raw")
          error(p, "appended data in encoding '" + printable(encoding) + "' is not supported; save it raw");
        const std::size_t u = text_.find('_', e + 1);
        if(u == std::string_view::npos) error(p, "<AppendedData> has no '_' before its data");
        appended_ = u + 1;
        break;
      }
      if(name == "DataArray")
      {
        Array a;
        a.parent = stack.empty() ? std::string_view() : stack.back();
        a.type = attribute(attrs, "type");
        a.name = attribute(attrs, "Name");
        a.format = attribute(attrs, "format");
        a.components = integer_attribute(attrs, "NumberOfComponents", p, 1);
        a.offset = integer_attribute(attrs, "offset", p, -1);
        a.tag = p;
        a.begin = a.end = e + 1;
        if(!self_closing)
        {
          const std::size_t c = text_.find("</DataArray", e + 1);
          if(c == std::string_view::npos) error(p, "<DataArray> is not closed; the file is truncated");
          a.end = c;
          arrays_.push_back(a);
          stack.push_back(name);
          p = c;   // its content is not XML to scan
          continue;
        }
        arrays_.push_back(a);
      }
      if(!self_closing) stack.push_back(name);
      p = e + 1;
    }
    if(!root) error(0, "not a VTK XML file: no <VTKFile> element");
    if(pieces == 0) error(0, "the file has no <Piece>");
  }

  static std::size_t type_size(std::string_view t)
  {
    if(t == "Int8" || t == "UInt8") return 1;
    if(t == "Int16" || t == "UInt16") return 2;
    if(t == "Int32" || t == "UInt32" || t == "Float32") return 4;
    if(t == "Int64" || t == "UInt64" || t == "Float64") return 8;
    return 0;
  }

  // The bytes after a binary header (UInt32 or UInt64 sizes), uncompressed.
  std::vector<unsigned char> payload(const Array& a, const unsigned char* p, std::size_t size)
  {
    internal::Byte_reader in(file_, std::string_view(reinterpret_cast<const char*>(p), size), swap_);
    auto header = [&](const char* what) -> std::uint64_t {
      return header_size_ == 8 ? in.get<std::uint64_t>(what) : in.get<std::uint32_t>(what);
    };
    std::vector<unsigned char> out;
    if(!compressed_)
    {
      const std::uint64_t n = header("the size of a data array");
      if(n > in.remaining())
        error(a.tag, "data array '" + printable(a.name) + "' announces " + std::to_string(n) + " bytes, but only " +
                         std::to_string(in.remaining()) + " follow; the file is truncated");
      out.assign(p + in.position(), p + in.position() + n);
      return out;
    }
    const std::uint64_t blocks = header("the number of compressed blocks");
    const std::uint64_t block = header("the block size");
    const std::uint64_t last = header("the last block size");
    in.check_count("the number of compressed blocks", blocks, header_size_);
    std::vector<std::uint64_t> sizes(blocks);
    std::uint64_t total = 0;
    for(auto& s : sizes) { s = header("a compressed block size"); total += s; }
    if(total > in.remaining())
      error(a.tag, "data array '" + printable(a.name) + "' announces " + std::to_string(total) +
                       " compressed bytes, but only " + std::to_string(in.remaining()) + " follow");
    // zlib cannot expand data more than about 1032 times: a larger claim is a damaged header.
    const std::uint64_t full = blocks == 0 ? 0 : (blocks - 1) * block + (last == 0 ? block : last);
    if(block > (std::uint64_t(1) << 32) || full > 1100 * total + 4096)
      error(a.tag, "data array '" + printable(a.name) + "' claims " + std::to_string(full) +
                       " bytes from " + std::to_string(total) + " compressed ones, more than zlib can give");
    out.resize(full);
    std::size_t at = in.position(), done = 0;
    for(std::uint64_t b = 0; b < blocks; ++b)
    {
      uLongf want = static_cast<uLongf>(b + 1 == blocks ? full - done : block);
      const int r = ::uncompress(out.data() + done, &want, p + at, static_cast<uLong>(sizes[b]));
      if(r != Z_OK || want != (b + 1 == blocks ? full - done : block))
        error(a.tag, "data array '" + printable(a.name) + "': compressed block " + std::to_string(b) +
                         " does not inflate to its announced size");
      at += sizes[b];
      done += want;
    }
    return out;
  }

  // The values of array `a`, which must hold `expected` of them (any number when -1).
  template <class T>
  std::vector<T> values(const Array& a, std::size_t expected)
  {
    std::vector<T> v;
    const std::string what = "data array '" + printable(a.name) + "'";
    if(a.format == "ascii")
    {
      binary_ = false;
      const std::string_view content = text_.substr(a.begin, a.end - a.begin);
      std::size_t p = 0;
      while(p < content.size())
      {
        while(p < content.size() && internal::is_space(content[p])) ++p;
        if(p >= content.size()) break;
        std::size_t e = p;
        while(e < content.size() && !internal::is_space(content[e])) ++e;
        const std::string_view t = content.substr(p, e - p);
        double d;
        long long i;
        if constexpr(std::is_same_v<T, double>)
        {
          if(!internal::parse_double(t, d)) error(a.begin + p, what + " holds '" + printable(t) + "', not a number");
          v.push_back(d);
        }
        else if(internal::parse_integer(t, i)) v.push_back(i);
        else if(internal::parse_double(t, d) && d == std::floor(d) && std::fabs(d) < 9e18) v.push_back(static_cast<long long>(d));
        else error(a.begin + p, what + " holds '" + printable(t) + "', not an integer");
        p = e;
      }
    }
    else
    {
      std::vector<unsigned char> bytes;
      if(a.format == "binary")
      {
        std::vector<unsigned char> raw;
        if(!base64_decode(text_.substr(a.begin, a.end - a.begin), raw))
          error(a.tag, what + " is not valid base64");
        bytes = payload(a, raw.data(), raw.size());
      }
      else if(a.format == "appended")
      {
        if(appended_ == 0) error(a.tag, what + " is appended, but the file has no <AppendedData>");
        if(a.offset < 0 || static_cast<unsigned long long>(a.offset) > text_.size() - appended_)
          error(a.tag, what + " has offset " + std::to_string(a.offset) + ", past the end of the file");
        const std::size_t at = appended_ + static_cast<std::size_t>(a.offset);
        bytes = payload(a, reinterpret_cast<const unsigned char*>(text_.data()) + at, text_.size() - at);
      }
      else
        error(a.tag, what + " has format '" + printable(a.format) + "', not ascii, binary or appended");
      const std::size_t s = type_size(a.type);
      if(s == 0) error(a.tag, what + " has type '" + printable(a.type) + "', which this reader does not know");
      if(bytes.size() % s != 0)
        error(a.tag, what + " holds " + std::to_string(bytes.size()) + " bytes, not a multiple of its value size");
      v.resize(bytes.size() / s);
      // The type is decided once per array, not per value.
      const std::string_view t = a.type;
      if(t == "Float64") convert<double>(a, bytes, v);
      else if(t == "Float32") convert<float>(a, bytes, v);
      else if(t == "Int8") convert<std::int8_t>(a, bytes, v);
      else if(t == "UInt8") convert<std::uint8_t>(a, bytes, v);
      else if(t == "Int16") convert<std::int16_t>(a, bytes, v);
      else if(t == "UInt16") convert<std::uint16_t>(a, bytes, v);
      else if(t == "Int32") convert<std::int32_t>(a, bytes, v);
      else if(t == "UInt32") convert<std::uint32_t>(a, bytes, v);
      else if(t == "Int64") convert<std::int64_t>(a, bytes, v);
      else convert<std::uint64_t>(a, bytes, v);
    }
    if(expected != std::size_t(-1) && v.size() != expected)
      error(a.tag, what + " holds " + std::to_string(v.size()) + " values, but " + std::to_string(expected) +
                       " are expected from the piece's NumberOfPoints or NumberOfCells");
    return v;
  }

  template <class S>
  S load(const unsigned char* p) const
  {
    S s;
    std::memcpy(&s, p, sizeof s);
    return swap_ ? internal::byte_swapped(s) : s;
  }

  template <class S, class T>
  void convert(const Array& a, const std::vector<unsigned char>& bytes, std::vector<T>& v)
  {
    for(std::size_t i = 0; i < v.size(); ++i)
    {
      const S s = load<S>(bytes.data() + i * sizeof(S));
      if constexpr(std::is_floating_point_v<S>) v[i] = to<T>(a, static_cast<double>(s));
      else if constexpr(std::is_same_v<S, std::uint64_t>)
      {
        if(s > static_cast<std::uint64_t>(std::numeric_limits<long long>::max()))
          error(a.tag, "data array '" + printable(a.name) + "' holds " + std::to_string(s) + ", out of range");
        v[i] = static_cast<T>(s);
      }
      else v[i] = static_cast<T>(s);
    }
  }

  template <class T>
  T to(const Array& a, double d)
  {
    if constexpr(std::is_same_v<T, double>) return d;
    else
    {
      if(!(d == std::floor(d) && std::fabs(d) < 9e18))
        error(a.tag, "data array '" + printable(a.name) + "' holds " + std::to_string(d) + " where an integer is expected");
      return static_cast<T>(d);
    }
  }

  std::string file_;
  std::string_view text_;
  std::ostream& warnings_;
  std::vector<Array> arrays_;
  bool swap_ = false, compressed_ = false, binary_ = true;
  std::size_t header_size_ = 4;
  std::size_t appended_ = 0;
  std::size_t number_of_points_ = 0, number_of_cells_ = 0;
};

inline bool looks_like_vtu(std::string_view head)
{
  const std::size_t p = head.find_first_not_of(" \t\r\n");
  return p == std::string_view::npos || head[p] == '<';
}

/// Parses the bytes of a `.vtu` file named `file`; `binary` receives whether its
/// arrays are binary (inline base64 or appended) rather than ASCII.
inline Tet_mesh parse_vtu(const std::string& file, std::string_view bytes, std::ostream& warnings, bool& binary)
{
  Vtu_parser parser(file, bytes, warnings);
  Tet_mesh mesh = parser.parse();
  binary = parser.binary();
  return mesh;
}

} // namespace internal

/// Reads a VTK XML UnstructuredGrid (`.vtu`) file of one piece: ASCII, inline
/// base64 or raw appended arrays, zlib-compressed or not, either byte order, 32- or
/// 64-bit headers. Keeps points, tetrahedra, triangles, lines and vertex cells
/// (as corners); labels come from the first cell data array among "label",
/// "medit:ref", "gmsh:physical", "subdomain", "CellEntityIds", "tetgen:ref";
/// vertex references from point data "ref" or "medit:ref". Other cell types are
/// skipped with a warning. Throws `Mesh_io_error`. `binary`, when given, receives
/// whether the arrays were binary.
inline Tet_mesh read_vtu(const std::string& file, std::ostream& warnings = std::cerr, bool* binary = nullptr)
{
  const internal::Mapped_file data(file, "a VTK XML file", internal::looks_like_vtu);
  bool b = false;
  Tet_mesh mesh = internal::parse_vtu(file, data.bytes(), warnings, b);
  if(binary) *binary = b;
  return mesh;
}

/// Writes `mesh` as a VTK XML UnstructuredGrid (`.vtu`) for ParaView: the points
/// (Float64), then as cells the tetrahedra (VTK type 10), the boundary triangles
/// (5), the edges (3) and the corners (1, a vertex cell each); cell data "label"
/// (subdomain of a tetrahedron, patch of a triangle, label of an edge, 0 for a
/// corner), "dimension" (3, 2, 1, 0: threshold it to see subdomains or patches)
/// and "min_dihedral_angle" (degrees, -1 for cells that are not tetrahedra); point
/// data "ref" (the vertex references). `binary` writes raw appended data (64-bit
/// headers), otherwise ASCII with numbers that read back bit for bit.
inline void write_vtu(std::ostream& stream, const Tet_mesh& mesh, bool binary = true)
{
  const internal::Cells cells{mesh};
  const std::size_t np = mesh.points.size(), nc = cells.size();
  internal::Output_buffer out(stream);
  std::uint64_t offset = 0;
  auto array = [&](const char* type, const char* name, int components, std::size_t count, std::size_t value_size) {
    out.put("        <DataArray type=\"").put(type).put("\" Name=\"").put(name).put('"');
    if(components != 1) out.put(" NumberOfComponents=\"").put_int(components).put('"');
    if(binary)
    {
      out.put(" format=\"appended\" offset=\"").put_int(offset).put("\"/>\n");
      offset += 8 + count * value_size;
    }
    else
      out.put(" format=\"ascii\">\n");
  };
  auto end_array = [&] { if(!binary) out.put("\n        </DataArray>\n"); };
  auto sep = [&](std::size_t i) { out.put(i % 12 == 11 ? '\n' : ' '); };

  out.put("<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" "
          "header_type=\"UInt64\">\n  <UnstructuredGrid>\n    <Piece NumberOfPoints=\"")
     .put_int(np).put("\" NumberOfCells=\"").put_int(nc).put("\">\n      <PointData Scalars=\"ref\">\n");
  array("Int32", "ref", 1, np, 4);
  if(!binary)
    for(std::size_t i = 0; i < np; ++i) { out.put_int(i < mesh.vertex_refs.size() ? mesh.vertex_refs[i] : 0); sep(i); }
  end_array();
  out.put("      </PointData>\n      <CellData Scalars=\"label\">\n");
  array("Int32", "label", 1, nc, 4);
  std::size_t i = 0;
  if(!binary) cells.for_each([&](int, const int*, int, int label, long long) { out.put_int(label); sep(i++); });
  end_array();
  array("UInt8", "dimension", 1, nc, 1);
  i = 0;
  if(!binary) cells.for_each([&](int, const int*, int n, int, long long) { out.put_int(n - 1); sep(i++); });
  end_array();
  array("Float64", "min_dihedral_angle", 1, nc, 8);
  i = 0;
  if(!binary) cells.for_each([&](int, const int*, int, int, long long t) { out.put_double(cells.min_angle(t)); sep(i++); });
  end_array();
  out.put("      </CellData>\n      <Points>\n");
  array("Float64", "Points", 3, 3 * np, 8);
  if(!binary)
    for(std::size_t k = 0; k < np; ++k)
    {
      const auto& p = mesh.points[k];
      out.put_double(p.x()).put(' ').put_double(p.y()).put(' ').put_double(p.z()).put(k + 1 < np ? "\n" : "");
    }
  end_array();
  out.put("      </Points>\n      <Cells>\n");
  array("Int64", "connectivity", 1, cells.connectivity_size(), 8);
  i = 0;
  if(!binary)
    cells.for_each([&](int, const int* v, int n, int, long long) {
      for(int k = 0; k < n; ++k) { out.put_int(v[k]); sep(i++); }
    });
  end_array();
  array("Int64", "offsets", 1, nc, 8);
  i = 0;
  std::size_t end = 0;
  if(!binary) cells.for_each([&](int, const int*, int n, int, long long) { out.put_int(end += n); sep(i++); });
  end_array();
  array("UInt8", "types", 1, nc, 1);
  i = 0;
  if(!binary) cells.for_each([&](int type, const int*, int, int, long long) { out.put_int(type); sep(i++); });
  end_array();
  out.put("      </Cells>\n    </Piece>\n  </UnstructuredGrid>\n");
  if(binary)
  {
    out.put("  <AppendedData encoding=\"raw\">\n   _");
    out.put_binary(static_cast<std::uint64_t>(4 * np));
    for(std::size_t k = 0; k < np; ++k) out.put_binary(static_cast<std::int32_t>(k < mesh.vertex_refs.size() ? mesh.vertex_refs[k] : 0));
    out.put_binary(static_cast<std::uint64_t>(4 * nc));
    cells.for_each([&](int, const int*, int, int label, long long) { out.put_binary(static_cast<std::int32_t>(label)); });
    out.put_binary(static_cast<std::uint64_t>(nc));
    cells.for_each([&](int, const int*, int n, int, long long) { out.put_binary(static_cast<std::uint8_t>(n - 1)); });
    out.put_binary(static_cast<std::uint64_t>(8 * nc));
    cells.for_each([&](int, const int*, int, int, long long t) { out.put_binary(cells.min_angle(t)); });
    out.put_binary(static_cast<std::uint64_t>(24 * np));
    for(const auto& p : mesh.points) out.put_binary(p.x()).put_binary(p.y()).put_binary(p.z());
    out.put_binary(static_cast<std::uint64_t>(8 * cells.connectivity_size()));
    cells.for_each([&](int, const int* v, int n, int, long long) {
      for(int k = 0; k < n; ++k) out.put_binary(static_cast<std::int64_t>(v[k]));
    });
    out.put_binary(static_cast<std::uint64_t>(8 * nc));
    end = 0;
    cells.for_each([&](int, const int*, int n, int, long long) { out.put_binary(static_cast<std::int64_t>(end += n)); });
    out.put_binary(static_cast<std::uint64_t>(nc));
    cells.for_each([&](int type, const int*, int, int, long long) { out.put_binary(static_cast<std::uint8_t>(type)); });
    out.put("\n  </AppendedData>\n");
  }
  out.put("</VTKFile>\n");
}

inline void write_vtu(const std::string& file, const Tet_mesh& mesh, bool binary = true)
{
  write_atomically(file, [&](std::ostream& out) { write_vtu(out, mesh, binary); });
}

} // namespace IO
} // namespace BODT_3
} // namespace CGAL

#endif // CGAL_BODT_3_IO_VTU_H
