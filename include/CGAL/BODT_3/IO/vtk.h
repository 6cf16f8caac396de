// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_BODT_3_IO_VTK_H
#define CGAL_BODT_3_IO_VTK_H

#include <CGAL/BODT_3/Tet_mesh.h>
#include <CGAL/BODT_3/IO/internal/Byte_reader.h>
#include <CGAL/BODT_3/IO/internal/Mapped_file.h>
#include <CGAL/BODT_3/Mesh_io_error.h>
#include <CGAL/BODT_3/IO/internal/Output_buffer.h>
#include <CGAL/BODT_3/IO/internal/Token_reader.h>
#include <CGAL/BODT_3/internal/Mesh/check_tet_mesh.h>
#include <CGAL/BODT_3/IO/internal/vtk_cells.h>
#include <CGAL/BODT_3/IO/write_atomically.h>

#include <cmath>
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


// Bytes of a legacy VTK data type; 0 for names it does not have.
inline std::size_t legacy_type_size(std::string_view t)
{
  if(t == "unsigned_char" || t == "char") return 1;
  if(t == "unsigned_short" || t == "short") return 2;
  if(t == "unsigned_int" || t == "int" || t == "float") return 4;
  if(t == "unsigned_long" || t == "long" || t == "double" || t == "vtktypeint64" || t == "vtktypeuint64" ||
     t == "vtkIdType")
    return 8;
  return 0;
}

inline bool looks_like_legacy(std::string_view head)
{
  const std::size_t p = head.find_first_not_of(" \t\r\n");
  return p == std::string_view::npos || head[p] == '#';
}

// A legacy `.vtk` file: text headers, ASCII or big-endian binary data.
class Legacy_parser
{
public:
  Legacy_parser(const std::string& file, std::string_view bytes, std::ostream& warnings)
    : in_(file, bytes, '\0'), bin_(file, bytes, true), warnings_(warnings)
  {}

  int version() const { return version_; }
  bool binary() const { return binary_; }

  Tet_mesh parse()
  {
    read_header();
    std::vector<long long> offsets, connectivity, types, labels;
    int label_rank = 100;
    bool have_points = false, have_cells = false, have_types = false;
    enum { none, point_data, cell_data } attributes = none;
    std::size_t attribute_count = 0;
    while(!in_.at_end())
    {
      const std::string kw = upper(in_.next("a section keyword"));
      const long line = in_.line();
      if(kw == "POINTS")
      {
        if(have_points) in_.error("a second POINTS section");
        have_points = true;
        const std::size_t n = count("the number of points", 3);
        if(n > static_cast<std::size_t>(std::numeric_limits<int>::max()))
          in_.error("the number of points is " + std::to_string(n) + ", more than this reader can index");
        const std::string type(in_.next("the points' data type"));
        const std::vector<double> xyz = read_values<double>(3 * n, type, "a point coordinate");
        mesh_.points.reserve(n);
        for(std::size_t i = 0; i < n; ++i)
        {
          if(!std::isfinite(xyz[3 * i]) || !std::isfinite(xyz[3 * i + 1]) || !std::isfinite(xyz[3 * i + 2]))
            throw Mesh_io_error(in_.file(), line, "point " + std::to_string(i) + " has a coordinate that is not a finite number");
          mesh_.points.emplace_back(xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]);
        }
        mesh_.vertex_refs.assign(n, 0);
      }
      else if(kw == "CELLS")
      {
        if(have_cells) in_.error("a second CELLS section");
        have_cells = true;
        const std::size_t a = count("the number of cells", 1);
        const std::size_t b = count("the size of the cell list", 1);
        if(version_ >= 50)
        {
          expect("OFFSETS");
          const std::string ot(in_.next("the offsets' data type"));
          offsets = read_values<long long>(a, ot, "an offset");
          expect("CONNECTIVITY");
          const std::string ct(in_.next("the connectivity's data type"));
          connectivity = read_values<long long>(b, ct, "a point index");
        }
        else
        {
          // "count i1 i2 ..." per cell, as ints.
          const std::vector<long long> list = read_values<long long>(b, "int", "a cell list entry");
          // Each cell takes at least its size in the list: a larger count is damage, and
          // must not size an allocation (binary counts are not bounded by the text).
          if(a > list.size())
            throw Mesh_io_error(in_.file(), line, "CELLS announces " + std::to_string(a) + " cells, but its list holds " +
                                                      std::to_string(list.size()) + " numbers");
          offsets.reserve(a + 1);
          offsets.push_back(0);
          std::size_t p = 0;
          for(std::size_t c = 0; c < a; ++c)
          {
            if(p >= list.size() || list[p] < 0 || static_cast<unsigned long long>(list[p]) > list.size() - p - 1)
              throw Mesh_io_error(in_.file(), line, "the cell list ends inside cell " + std::to_string(c) + " of " +
                                                        std::to_string(a) + ": its size is wrong");
            connectivity.insert(connectivity.end(), list.begin() + static_cast<std::ptrdiff_t>(p + 1),
                                list.begin() + static_cast<std::ptrdiff_t>(p + 1 + list[p]));
            p += 1 + static_cast<std::size_t>(list[p]);
            offsets.push_back(static_cast<long long>(connectivity.size()));
          }
          if(p != list.size())
            throw Mesh_io_error(in_.file(), line, "the cell list holds " + std::to_string(list.size()) +
                                                      " numbers, but its " + std::to_string(a) + " cells use " +
                                                      std::to_string(p));
        }
      }
      else if(kw == "CELL_TYPES")
      {
        if(have_types) in_.error("a second CELL_TYPES section");
        have_types = true;
        const std::size_t n = count("the number of cell types", 1);
        types = read_values<long long>(n, "int", "a cell type");
      }
      else if(kw == "CELL_DATA" || kw == "POINT_DATA")
      {
        attributes = kw == "CELL_DATA" ? cell_data : point_data;
        attribute_count = count("the number of values", 1);
      }
      else if(kw == "SCALARS" || kw == "FIELD")
      {
        if(attributes == none) in_.error(kw + " outside CELL_DATA and POINT_DATA");
        const std::string name(in_.next("the array name"));
        std::size_t arrays = 1;
        if(kw == "FIELD") arrays = count("the number of arrays", 4);
        for(std::size_t k = 0; k < arrays; ++k)
        {
          std::string array = name, type;
          std::size_t components = 1, tuples = attribute_count;
          if(kw == "FIELD")
          {
            array = std::string(in_.next("an array name"));
            components = count("the number of components", 1);
            tuples = count("the number of tuples", 1);
            type = std::string(in_.next("the array's data type"));
          }
          else
          {
            type = std::string(in_.next("the scalars' data type"));
            if(!in_.line_is_done()) components = count("the number of components", 1);
            expect("LOOKUP_TABLE");
            in_.next("a lookup table name");
          }
          if(components > 0 && tuples > std::numeric_limits<std::size_t>::max() / components)
            in_.error("array '" + printable(array) + "' is too large");
          if(type == "float" || type == "double")
          {
            const std::vector<double> v = read_values<double>(components * tuples, type, "a value");
            if(components == 1 && attributes == cell_data && internal::label_array_rank(array) >= 0 &&
               internal::label_array_rank(array) < label_rank)
            {
              labels.clear();
              for(double d : v)
              {
                if(!(d == std::floor(d) && std::fabs(d) < 2e9))
                  in_.error("array '" + printable(array) + "' holds " + std::to_string(d) + ", not an integer label");
                labels.push_back(static_cast<long long>(d));
              }
              label_rank = internal::label_array_rank(array);
            }
          }
          else
          {
            std::vector<long long> v = read_values<long long>(components * tuples, type, "a value");
            if(components == 1 && attributes == cell_data && internal::label_array_rank(array) >= 0 &&
               internal::label_array_rank(array) < label_rank)
            {
              labels = std::move(v);
              label_rank = internal::label_array_rank(array);
            }
            else if(components == 1 && attributes == point_data && internal::is_vertex_ref_array(array))
            {
              if(v.size() != mesh_.points.size())
                in_.error("point array '" + printable(array) + "' has " + std::to_string(v.size()) + " values for " +
                          std::to_string(mesh_.points.size()) + " points");
              for(std::size_t i = 0; i < v.size(); ++i)
              {
                if(v[i] < std::numeric_limits<int>::min() || v[i] > std::numeric_limits<int>::max())
                  in_.error("point " + std::to_string(i) + " has reference " + std::to_string(v[i]) + ", out of range");
                mesh_.vertex_refs[i] = static_cast<int>(v[i]);
              }
            }
          }
        }
      }
      else if(kw == "VECTORS" || kw == "NORMALS" || kw == "TENSORS")
      {
        if(attributes == none) in_.error(kw + " outside CELL_DATA and POINT_DATA");
        in_.next("the array name");
        const std::string type(in_.next("the data type"));
        read_values<double>((kw == "TENSORS" ? 9 : 3) * attribute_count, type, "a value");
      }
      else if(kw == "METADATA")
      {
        // Free text up to a blank line (VTK 5.1).
        in_.rest_of_line();
        for(;;)
        {
          const std::size_t p = in_.position();
          if(p >= in_.text().size()) break;
          in_.set_position(p + 1, in_.current_line() + 1);
          if(in_.line_is_done()) { in_.rest_of_line(); break; }
          in_.rest_of_line();
        }
      }
      else
        in_.error("section '" + printable(kw) + "' is not one this reader knows (POINTS, CELLS, CELL_TYPES, "
                  "CELL_DATA, POINT_DATA, SCALARS, FIELD, ...)");
    }
    if(!have_points) throw Mesh_io_error(in_.file(), 0, "the file has no POINTS section");
    if(!have_cells || !have_types) throw Mesh_io_error(in_.file(), 0, "the file has no CELLS or no CELL_TYPES section");
    std::map<long long, std::size_t> skipped;
    internal::add_cells(mesh_, connectivity, offsets, types, labels.empty() ? nullptr : &labels, skipped,
                            [&](const std::string& m) { throw Mesh_io_error(in_.file(), 0, m); });
    internal::warn_skipped(warnings_, in_.file(), skipped);
    if(labels.empty())
      warnings_ << "warning: " << in_.file() << ": no cell data array of labels ('label', 'medit:ref', "
                   "'gmsh:physical', ...); every cell gets label 0\n";
    BODT_3::internal::Tet_mesh_source src;
    src.file = in_.file();
    BODT_3::internal::check_and_orient(mesh_, src, warnings_);
    return std::move(mesh_);
  }

private:
  static std::string upper(std::string_view s)
  {
    std::string u(s);
    for(char& c : u) if(c >= 'a' && c <= 'z') c = static_cast<char>(c - 'a' + 'A');
    return u;
  }

  void read_header()
  {
    const std::string_view first = in_.rest_of_line();
    if(first.compare(0, 5, "# vtk") != 0)
      in_.error("not a legacy VTK file: the first line is '" + printable(first) + "', not '# vtk DataFile Version ...'");
    const std::size_t v = first.rfind(' ');
    const std::string_view number = first.substr(v + 1);
    const std::size_t dot = number.find('.');
    long long major = 0, minor = 0;
    if(dot == std::string_view::npos || !internal::parse_integer(number.substr(0, dot), major) ||
       !internal::parse_integer(number.substr(dot + 1), minor) || major < 1 || major > 5 || minor < 0 || minor > 9)
      in_.error("version '" + printable(number) + "' is not a legacy VTK version such as 4.2 or 5.1");
    version_ = static_cast<int>(10 * major + minor);
    next_line();
    in_.rest_of_line();   // the title
    next_line();
    const std::string encoding = upper(in_.next("ASCII or BINARY"));
    if(encoding != "ASCII" && encoding != "BINARY")
      in_.error("expected ASCII or BINARY on line 3, found '" + printable(encoding) + "'");
    binary_ = encoding == "BINARY";
    if(upper(in_.next("DATASET")) != "DATASET") in_.error("expected 'DATASET UNSTRUCTURED_GRID'");
    const std::string type = upper(in_.next("the dataset type"));
    if(type != "UNSTRUCTURED_GRID")
      in_.error("a " + printable(type) + " dataset; only UNSTRUCTURED_GRID is read");
  }

  void next_line()
  {
    const std::size_t p = in_.position();
    if(p >= in_.text().size()) in_.error("the file ends in its header; it is truncated");
    in_.set_position(p + 1, in_.current_line() + 1);
  }

  void expect(const char* word)
  {
    const std::string_view t = in_.next(word);
    if(upper(t) != word) in_.error(std::string("expected '") + word + "', found '" + printable(t) + "'");
  }

  std::size_t count(const char* what, std::size_t tokens_per_entry)
  {
    return in_.next_count(what, binary_ ? 0 : tokens_per_entry);
  }

  template <class T>
  std::vector<T> read_values(std::size_t n, const std::string& type, const char* what)
  {
    const std::size_t size = legacy_type_size(type);
    if(size == 0) in_.error("data type '" + printable(type) + "' is not one this reader knows");
    std::vector<T> v;
    if(!binary_)
    {
      in_.check_count("the number of values", n, 1);
      v.reserve(n);
      for(std::size_t i = 0; i < n; ++i)
      {
        if constexpr(std::is_same_v<T, double>) v.push_back(in_.next_double(what));
        else v.push_back(in_.next_integer(what));
      }
      return v;
    }
    // Binary data starts on the line after its header.
    in_.rest_of_line();
    bin_.seek(std::min(in_.position() + 1, in_.text().size()), "binary data");
    bin_.check_count("the number of values", n, size);
    v.resize(n);
    // The type is decided once per array, not per value.
    const std::string& t = type;
    if(t == "double") fill<double>(v);
    else if(t == "float") fill<float>(v);
    else if(t == "unsigned_char") fill<std::uint8_t>(v);
    else if(t == "char") fill<std::int8_t>(v);
    else if(t == "unsigned_short") fill<std::uint16_t>(v);
    else if(t == "short") fill<std::int16_t>(v);
    else if(t == "unsigned_int") fill<std::uint32_t>(v);
    else if(t == "int") fill<std::int32_t>(v);
    else if(t == "unsigned_long" || t == "vtktypeuint64") fill<std::uint64_t>(v);
    else fill<std::int64_t>(v);
    in_.set_position(bin_.position(), in_.current_line() + 1);
    return v;
  }

  template <class S, class T>
  void fill(std::vector<T>& v)
  {
    for(T& x : v)
    {
      const S s = bin_.get<S>("a value");
      if constexpr(std::is_floating_point_v<S>) x = checked<T>(static_cast<double>(s));
      else if constexpr(std::is_same_v<S, std::uint64_t>)
      {
        if(s > static_cast<std::uint64_t>(std::numeric_limits<long long>::max())) bin_.error("a value is out of range");
        x = static_cast<T>(s);
      }
      else x = static_cast<T>(s);
    }
  }

  template <class T>
  T checked(double d)
  {
    if constexpr(std::is_same_v<T, double>) return d;
    else
    {
      if(!(d == std::floor(d) && std::fabs(d) < 9e18)) bin_.error("a value is not an integer");
      return static_cast<T>(d);
    }
  }

  internal::Token_reader in_;
  internal::Byte_reader bin_;
  std::ostream& warnings_;
  Tet_mesh mesh_;
  int version_ = 42;
  bool binary_ = false;
};

/// Parses the bytes of a legacy `.vtk` file named `file`; `version` (e.g. 42 for
/// 4.2) and `binary` receive what the file is.
inline Tet_mesh parse_legacy(const std::string& file, std::string_view bytes, std::ostream& warnings, int& version,
                             bool& binary)
{
  Legacy_parser parser(file, bytes, warnings);
  Tet_mesh mesh = parser.parse();
  version = parser.version();
  binary = parser.binary();
  return mesh;
}

} // namespace internal

/// Reads a legacy VTK `.vtk` file holding an UNSTRUCTURED_GRID, versions 2.0 to
/// 5.1 (the "CELLS n size" list and the 5.1 OFFSETS/CONNECTIVITY layout), ASCII or
/// BINARY. Keeps what `read_vtu` keeps, with labels from SCALARS or FIELD cell data
/// of the same names. Throws `Mesh_io_error`. `version` and `binary`, when given,
/// receive what the file is.
inline Tet_mesh read_vtk(const std::string& file, std::ostream& warnings = std::cerr, int* version = nullptr,
                         bool* binary = nullptr)
{
  const internal::Mapped_file data(file, "a legacy VTK file", internal::looks_like_legacy);
  int v = 0;
  bool b = false;
  Tet_mesh mesh = internal::parse_legacy(file, data.bytes(), warnings, v, b);
  if(version) *version = v;
  if(binary) *binary = b;
  return mesh;
}

/// Writes `mesh` as a legacy VTK `.vtk` UNSTRUCTURED_GRID, `version` 42 ("CELLS n
/// size" lists, read by every VTK tool) or 51 (OFFSETS and CONNECTIVITY), ASCII
/// or `binary` (big-endian, as the format requires), with the cells and arrays of
/// `write_vtu`: "label", "dimension", "min_dihedral_angle" as cell scalars, "ref"
/// as point scalars.
inline void write_vtk(std::ostream& stream, const Tet_mesh& mesh, bool binary = false, int version = 42)
{
  if(version != 42 && version != 51)
    throw std::invalid_argument("write_vtk: version must be 42 or 51, not " + std::to_string(version));
  using internal::byte_swapped;
  const internal::Cells cells{mesh};
  const std::size_t np = mesh.points.size(), nc = cells.size();
  internal::Output_buffer out(stream);
  std::size_t column = 0;
  auto end_values = [&] { out.put('\n'); column = 0; };
  auto sep = [&] { if(!binary) out.put(++column % 12 == 0 ? '\n' : ' '); };
  auto int32 = [&](long long v) { if(binary) out.put_binary(byte_swapped(static_cast<std::int32_t>(v))); else out.put_int(v); sep(); };
  auto int64 = [&](long long v) { if(binary) out.put_binary(byte_swapped(static_cast<std::int64_t>(v))); else out.put_int(v); sep(); };
  auto real = [&](double v) { if(binary) out.put_binary(byte_swapped(v)); else out.put_double(v); sep(); };

  out.put(version == 51 ? "# vtk DataFile Version 5.1\n" : "# vtk DataFile Version 4.2\n");
  out.put("tetrahedral mesh written by CGAL BODT_3\n").put(binary ? "BINARY\n" : "ASCII\n");
  out.put("DATASET UNSTRUCTURED_GRID\nPOINTS ").put_int(np).put(" double\n");
  for(const auto& p : mesh.points) { real(p.x()); real(p.y()); real(p.z()); }
  end_values();
  if(version == 51)
  {
    out.put("CELLS ").put_int(nc + 1).put(' ').put_int(cells.connectivity_size()).put("\nOFFSETS vtktypeint64\n");
    std::size_t end = 0;
    int64(0);
    cells.for_each([&](int, const int*, int n, int, long long) { int64(static_cast<long long>(end += n)); });
    end_values();
    out.put("CONNECTIVITY vtktypeint64\n");
    cells.for_each([&](int, const int* v, int n, int, long long) { for(int k = 0; k < n; ++k) int64(v[k]); });
  }
  else
  {
    out.put("CELLS ").put_int(nc).put(' ').put_int(nc + cells.connectivity_size()).put('\n');
    cells.for_each([&](int, const int* v, int n, int, long long) {
      int32(n);
      for(int k = 0; k < n; ++k) int32(v[k]);
    });
  }
  end_values();
  out.put("CELL_TYPES ").put_int(nc).put('\n');
  cells.for_each([&](int type, const int*, int, int, long long) { int32(type); });
  end_values();
  out.put("CELL_DATA ").put_int(nc).put("\nSCALARS label int 1\nLOOKUP_TABLE default\n");
  cells.for_each([&](int, const int*, int, int label, long long) { int32(label); });
  end_values();
  out.put("SCALARS dimension int 1\nLOOKUP_TABLE default\n");
  cells.for_each([&](int, const int*, int n, int, long long) { int32(n - 1); });
  end_values();
  out.put("SCALARS min_dihedral_angle double 1\nLOOKUP_TABLE default\n");
  cells.for_each([&](int, const int*, int, int, long long t) { real(cells.min_angle(t)); });
  end_values();
  out.put("POINT_DATA ").put_int(np).put("\nSCALARS ref int 1\nLOOKUP_TABLE default\n");
  for(std::size_t i = 0; i < np; ++i) int32(i < mesh.vertex_refs.size() ? mesh.vertex_refs[i] : 0);
  end_values();
}

inline void write_vtk(const std::string& file, const Tet_mesh& mesh, bool binary = false, int version = 42)
{
  if(version != 42 && version != 51)
    throw std::invalid_argument("write_vtk: version must be 42 or 51, not " + std::to_string(version));
  write_atomically(file, [&](std::ostream& out) { write_vtk(out, mesh, binary, version); });
}

} // namespace IO
} // namespace BODT_3
} // namespace CGAL

#endif // CGAL_BODT_3_IO_VTK_H
