// Every format and variant: a round trip keeps what the format can hold (coordinates
// bit for bit, labels, boundary triangles with patch ids), reading reports the variant
// so that the output can keep it, and damaged files give a Mesh_io_error naming the file.
#include <CGAL/BODT_3/IO/mesh_io.h>

#include "io_test_meshes.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using namespace bodt_test;
namespace IO = CGAL::BODT_3::IO;
using CGAL::BODT_3::Mesh_io_error;
using CGAL::BODT_3::Tet_mesh;
using Point = Tet_mesh::Point;
using F = IO::Mesh_format;

namespace {

struct Variant
{
  std::string file;
  IO::Mesh_file_format format;
};

std::vector<Variant> variants()
{
  return {{"a.mesh", {F::medit, 2, false}},        {"a3.mesh", {F::medit, 3, false}},
          {"a.meshb", {F::meshb, 2, true}},        {"a3.meshb", {F::meshb, 3, true}},
          {"a4.meshb", {F::meshb, 4, true}},       {"a22.msh", {F::gmsh, 22, false}},
          {"a41.msh", {F::gmsh, 41, false}},       {"a22b.msh", {F::gmsh, 22, true}},
          {"a41b.msh", {F::gmsh, 41, true}},       {"a.vtu", {F::vtu, 0, true}},
          {"ascii.vtu", {F::vtu, 0, false}},       {"a.vtk", {F::vtk, 42, false}},
          {"b.vtk", {F::vtk, 42, true}},           {"a51.vtk", {F::vtk, 51, false}},
          {"b51.vtk", {F::vtk, 51, true}},         {"a.node", {F::tetgen, 0, false}}};
}

// What each format holds beyond points, tetrahedra, triangles and edges with labels.
void expect_kept(const Tet_mesh& a, const Tet_mesh& b, F format)
{
  if(format != F::tetgen)
  {
    EXPECT_EQ(a.corners, b.corners);
  }
  else
  {
    EXPECT_TRUE(b.corners.empty());
  }
  if(format != F::gmsh)
  {
    EXPECT_EQ(a.vertex_refs, b.vertex_refs);
  }
  if(format == F::medit || format == F::meshb)
  {
    EXPECT_EQ(a.ridges, b.ridges);
    EXPECT_EQ(a.required_vertices, b.required_vertices);
  }
}

void expect_same_except_corners(const Tet_mesh& a, const Tet_mesh& b)
{
  Tet_mesh c = a;
  c.corners = b.corners;
  expect_same_mesh_content(c, b);
}

std::string bytes_of(const fs::path& p) { return read_text(p); }

template <class T>
void put(std::string& s, T v)
{
  char b[sizeof(T)];
  std::memcpy(b, &v, sizeof(T));
  s.append(b, sizeof(T));
}

// Runs `f`, which must throw a Mesh_io_error naming `file` with `words` in it.
template <class Fn>
void expect_error(Fn f, const fs::path& file, const std::string& words)
{
  try
  {
    f();
    ADD_FAILURE() << "no Mesh_io_error for " << file;
  }
  catch(const Mesh_io_error& e)
  {
    const std::string what = e.what();
    EXPECT_NE(what.find(file.string()), std::string::npos) << what;
    EXPECT_NE(what.find(words), std::string::npos) << what;
  }
}

void expect_read_error(const std::string& name, const std::string& content, const std::string& words)
{
  const fs::path p = write_file(name, content);
  std::ostringstream warnings;
  expect_error([&] { IO::read_mesh(p.string(), warnings); }, p, words);
}

} // namespace

TEST(Formats, RoundTripEveryVariant)
{
  const Tet_mesh m = grid_mesh();
  for(const Variant& v : variants())
  {
    SCOPED_TRACE(v.file);
    const fs::path p = tmp_dir() / v.file;
    IO::write_mesh(p.string(), m, v.format);
    std::ostringstream warnings;
    IO::Mesh_file_format read_as;
    const Tet_mesh r = IO::read_mesh(p.string(), read_as, warnings);
    EXPECT_EQ(read_as, v.format) << IO::format_name(read_as);
    EXPECT_EQ(warnings.str(), "");
    expect_same_except_corners(m, r);
    expect_kept(m, r, v.format.format);

    // Written again in the variant it was read as: the same bytes.
    const fs::path q = tmp_dir() / ("again_" + v.file);
    IO::write_mesh(q.string(), r, IO::output_format(q.string(), read_as));
    if(v.format.format == F::tetgen)
    {
      for(const char* ext : {".node", ".ele", ".face", ".edge"})
        EXPECT_EQ(bytes_of(tmp_dir() / ("a" + std::string(ext))), bytes_of(tmp_dir() / ("again_a" + std::string(ext))));
    }
    else
    {
      EXPECT_EQ(bytes_of(p), bytes_of(q));
    }
  }
}

TEST(Formats, MeshbVersionOneStoresFloats)
{
  const Tet_mesh m = grid_mesh();
  const fs::path p = tmp_dir() / "v1.meshb";
  IO::write_meshb(p.string(), m, 1);
  std::ostringstream warnings;
  int version = 0;
  const Tet_mesh r = IO::read_meshb(p.string(), warnings, &version);
  EXPECT_EQ(version, 1);
  ASSERT_EQ(r.points.size(), m.points.size());
  for(std::size_t i = 0; i < m.points.size(); ++i)
    for(int c = 0; c < 3; ++c)
      EXPECT_EQ(r.points[i][c], static_cast<double>(static_cast<float>(m.points[i][c])));
  EXPECT_EQ(r.tets, m.tets);
  EXPECT_EQ(r.triangle_labels, m.triangle_labels);
  // Version 1: 4-byte floats, integers and positions; each keyword has a 12-byte header.
  const std::uintmax_t expected = 8 + 12 + (12 + 16 * m.points.size()) + (12 + 16 * m.triangles.size()) +
                                  (12 + 20 * m.tets.size()) + (12 + 12 * m.edges.size()) + (12 + 4 * m.corners.size()) +
                                  (12 + 4 * m.required_vertices.size()) + (12 + 4 * m.ridges.size()) + 8;
  EXPECT_EQ(fs::file_size(p), expected);
}

TEST(Formats, MeshbLayoutAsLibMeshbWritesIt)
{
  // A hand-made version 2 file: code 1, version 2, Dimension, Vertices, Tetrahedra, End,
  // each keyword followed by the absolute position of the next one; little- and big-endian.
  auto build = [](bool big) {
    std::string b;
    auto i32 = [&](std::int32_t v) {
      char c[4];
      std::memcpy(c, &v, 4);
      if(big) std::reverse(c, c + 4);
      b.append(c, 4);
    };
    auto f64 = [&](double v) {
      char c[8];
      std::memcpy(c, &v, 8);
      if(big) std::reverse(c, c + 8);
      b.append(c, 8);
    };
    i32(1); i32(2);
    i32(3); i32(20); i32(3);
    const double pts[4][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    i32(4); i32(20 + 12 + 4 * 28); i32(4);
    for(const auto& p : pts)
    {
      for(double x : p) f64(x);
      i32(5);
    }
    i32(8); i32(static_cast<std::int32_t>(b.size() + 8 + 20)); i32(1);
    for(int v : {1, 2, 3, 4, 7}) i32(v);
    i32(54); i32(0);
    return b;
  };
  for(bool big : {false, true})
  {
    SCOPED_TRACE(big ? "big-endian" : "little-endian");
    const std::string b = build(big);
    const fs::path p = write_file(big ? "big.meshb" : "little.meshb", b);
    std::ostringstream warnings;
    const Tet_mesh m = IO::read_meshb(p.string(), warnings);
    EXPECT_EQ(warnings.str(), "");
    EXPECT_EQ(m.points[3], Point(0, 0, 1));
    EXPECT_EQ(m.vertex_refs, std::vector<int>(4, 5));
    EXPECT_EQ(m.tets, (std::vector<std::array<int, 4>>{{0, 1, 2, 3}}));
    EXPECT_EQ(m.tet_labels, std::vector<int>{7});
    // Our writer gives the same bytes, in the machine's (little-endian) order.
    const fs::path q = tmp_dir() / "ours.meshb";
    IO::write_meshb(q.string(), m, 2);
    EXPECT_EQ(bytes_of(q), build(false));
  }
}

TEST(Formats, OutputKeepsTheInputVariant)
{
  const IO::Mesh_file_format msh22b{F::gmsh, 22, true};
  EXPECT_EQ(IO::output_format("out.msh", msh22b), msh22b);
  EXPECT_EQ(IO::output_format("out.MSH", msh22b), msh22b);
  EXPECT_EQ(IO::output_format("out.vtu", msh22b), (IO::Mesh_file_format{F::vtu, 0, true}));
  EXPECT_EQ(IO::output_format("out.mesh", msh22b), (IO::Mesh_file_format{F::medit, 2, false}));
  EXPECT_EQ(IO::output_format("out.meshb", {F::meshb, 4, true}), (IO::Mesh_file_format{F::meshb, 4, true}));
  EXPECT_EQ(IO::output_format("out.xyz", msh22b).format, F::unknown);
  for(const char* name : {"mesh", "meshb3", "msh22", "msh41-binary", "vtu", "vtu-ascii", "vtk51-binary", "tetgen"})
    EXPECT_EQ(IO::format_name(IO::parse_format_name(name)), name);
  EXPECT_EQ(IO::parse_format_name("msh"), (IO::Mesh_file_format{F::gmsh, 41, false}));
  EXPECT_THROW(IO::parse_format_name("stl"), std::invalid_argument);
  EXPECT_EQ(IO::format_of("x.ele"), F::tetgen);
  EXPECT_EQ(IO::format_of("x.meshb"), F::meshb);
}

TEST(Formats, ExplicitFormatWhateverTheExtension)
{
  const Tet_mesh m = grid_mesh();
  const fs::path p = tmp_dir() / "gmsh_inside.mesh";
  IO::write_mesh(p.string(), m, IO::parse_format_name("msh22"));
  EXPECT_EQ(bytes_of(p).substr(0, 20), "$MeshFormat\n2.2 0 8\n");
}

// A damaged file of each format gives an error naming the file, never a crash.
TEST(FormatErrors, DamagedBinaryFiles)
{
  const Tet_mesh m = grid_mesh();
  for(const Variant& v : variants())
  {
    if(v.format.format == F::tetgen) continue;
    SCOPED_TRACE(v.file);
    const fs::path p = tmp_dir() / v.file;
    IO::write_mesh(p.string(), m, v.format);
    const std::string full = bytes_of(p);
    // Cut anywhere: always an error, for 40 cut points across the file.
    for(int k = 1; k < 40; ++k)
    {
      const std::size_t cut = full.size() * static_cast<std::size_t>(k) / 40;
      const fs::path q = write_file("cut_" + std::to_string(k) + "_" + v.file, full.substr(0, cut));
      std::ostringstream warnings;
      try
      {
        IO::read_mesh(q.string(), warnings);
        ADD_FAILURE() << "accepted " << v.file << " cut at byte " << cut << " of " << full.size();
      }
      catch(const Mesh_io_error& e)
      {
        EXPECT_NE(std::string(e.what()).find(q.string()), std::string::npos) << e.what();
      }
    }
  }
}

TEST(FormatErrors, IndicesAreCheckedInTheirFullWidth)
{
  // 4294967297 = 2^32 + 1 must not become vertex 1.
  const std::string medit = "MeshVersionFormatted 2\nDimension 3\nVertices\n4\n0 0 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 0\n"
                            "Tetrahedra\n1\n1 2 3 4 1\n";
  for(const char* section : {"Corners", "RequiredVertices"})
    expect_read_error(std::string(section) + ".mesh", medit + section + "\n1\n4294967297\nEnd\n",
                      std::string(section) + " entry 1 refers to vertex 4294967297");
  expect_read_error("ridges.mesh", medit + "Edges\n1\n1 2 0\nRidges\n1\n4294967297\nEnd\n",
                    "Ridges entry 1 refers to edge 4294967297");
  expect_read_error("tet.mesh", medit.substr(0, medit.size() - 10) + "1 2 3 4294967297 1\n",
                    "refers to vertex 4294967297");
  expect_read_error("huge.mesh", medit + "Corners\n1\n99999999999999999999999\nEnd\n", "out of range");

  // Gmsh: node tags and element node references in 64 bits.
  const std::string msh = "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n4\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n"
                          "$EndNodes\n$Elements\n1\n1 4 2 1 1 1 2 3 4294967297\n$EndElements\n";
  expect_read_error("tag.msh", msh, "refers to node 4294967297");

  // VTU and legacy VTK: connectivity in 64 bits.
  expect_read_error("conn.vtk",
                    "# vtk DataFile Version 4.2\nx\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS 4 double\n0 0 0 1 0 0 0 1 0 0 0 1\n"
                    "CELLS 1 5\n4 0 1 2 4294967297\nCELL_TYPES 1\n10\n",
                    "refers to point 4294967297");
  expect_read_error("conn.vtu",
                    "<VTKFile type=\"UnstructuredGrid\"><UnstructuredGrid><Piece NumberOfPoints=\"4\" NumberOfCells=\"1\">"
                    "<Points><DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">0 0 0 1 0 0 0 1 0 0 0 1"
                    "</DataArray></Points><Cells><DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">0 1 2 "
                    "4294967297</DataArray><DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">4</DataArray>"
                    "<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">10</DataArray></Cells></Piece>"
                    "</UnstructuredGrid></VTKFile>\n",
                    "refers to point 4294967297");

  // TetGen.
  const fs::path node = write_file("t.node", "4 3 0 0\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n");
  write_file("t.ele", "1 4 0\n1 1 2 3 4294967297\n");
  std::ostringstream warnings;
  expect_error([&] { IO::read_mesh(node.string(), warnings); }, tmp_dir() / "t.ele", "refers to node 4294967297");

  // Medit binary, version 4: 64-bit indices. Four vertices, one tetrahedron: the header
  // (8 bytes), Dimension (16), Vertices (20 + 4 * 32), then Tetrahedra's 20-byte header.
  Tet_mesh m;
  m.points = {Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0), Point(0, 0, 1)};
  m.vertex_refs.assign(4, 0);
  m.tets = {{0, 1, 2, 3}};
  m.tet_labels = {1};
  const fs::path b = tmp_dir() / "v4.meshb";
  IO::write_meshb(b.string(), m, 4);
  std::string bytes = bytes_of(b);
  const std::size_t fourth = 8 + 16 + 20 + 4 * 32 + 20 + 3 * 8;
  std::int64_t old;
  std::memcpy(&old, bytes.data() + fourth, 8);
  ASSERT_EQ(old, 4);
  const std::int64_t big = (std::int64_t(1) << 32) + 1;
  std::memcpy(&bytes[fourth], &big, 8);
  expect_read_error("big.meshb", bytes, "refers to vertex 4294967297");
}

TEST(FormatErrors, CountsLargerThanTheFile)
{
  expect_read_error("count.mesh", "MeshVersionFormatted 2\nDimension 3\nVertices\n1000000000000\n0 0 0 0\n",
                    "more entries than the rest of the file can hold");
  expect_read_error("count.msh", "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n99999999999\n1 0 0 0\n",
                    "more entries than the rest of the file can hold");
  std::string b;
  put<std::int32_t>(b, 1);
  put<std::int32_t>(b, 2);
  put<std::int32_t>(b, 4);
  put<std::int32_t>(b, 0);
  put<std::int32_t>(b, 2000000000);
  expect_read_error("count.meshb", b, "the rest of the file holds at most");
  expect_read_error("count.vtk", "# vtk DataFile Version 4.2\nx\nBINARY\nDATASET UNSTRUCTURED_GRID\nPOINTS 1000000000 double\n\n",
                    "the rest of the file holds at most");
  // Found by fuzzing: a binary cell count that only the cell list bounds (it made the
  // reader reserve 266 GB).
  std::string cells = "# vtk DataFile Version 4.2\nx\nBINARY\nDATASET UNSTRUCTURED_GRID\nPOINTS 4 double\n";
  for(double x : {0., 0., 0., 1., 0., 0., 0., 1., 0., 0., 0., 1.})
  {
    char b[8];
    std::memcpy(b, &x, 8);
    std::reverse(b, b + 8);
    cells.append(b, 8);
  }
  cells += "\nCELLS 33333333333 5\n";
  for(std::int32_t v : {4, 0, 1, 2, 3})
  {
    char b[4];
    std::memcpy(b, &v, 4);
    std::reverse(b, b + 4);
    cells.append(b, 4);
  }
  cells += "\nCELL_TYPES 1\n";
  expect_read_error("cells.vtk", cells, "CELLS announces 33333333333 cells, but its list holds 5 numbers");
}

TEST(FormatErrors, NotTheFormatItsNameSays)
{
  const std::string medit = read_text(write_file("ok.mesh", "MeshVersionFormatted 2\n"));
  expect_read_error("medit.meshb", medit, "not a Medit binary mesh file");
  expect_read_error("medit.vtu", medit, "not a VTK XML file");
  expect_read_error("medit.vtk", medit, "not a legacy VTK file");
  expect_read_error("medit.msh", medit, "not a Gmsh mesh file");
  expect_read_error("polydata.vtu", "<VTKFile type=\"PolyData\"></VTKFile>", "only UnstructuredGrid");
  expect_read_error("lz4.vtu", "<VTKFile type=\"UnstructuredGrid\" compressor=\"vtkLZ4DataCompressor\"></VTKFile>",
                    "not supported");
  expect_read_error("empty.meshb", "", "empty");
  expect_read_error("empty.vtu", "", "empty");
  expect_read_error("empty.vtk", "", "empty");
}

TEST(FormatErrors, CompressedVtuClaimingTooMuch)
{
  // A zlib block header that claims 2^40 bytes from 10 compressed ones.
  std::string header;
  put<std::uint32_t>(header, 1);
  put<std::uint32_t>(header, 1u << 30);
  put<std::uint32_t>(header, 1u << 30);
  put<std::uint32_t>(header, 10);
  header += std::string(10, 'x');
  static const char* const b64 = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string enc;
  for(std::size_t i = 0; i < header.size(); i += 3)
  {
    unsigned v = static_cast<unsigned char>(header[i]) << 16;
    if(i + 1 < header.size()) v |= static_cast<unsigned char>(header[i + 1]) << 8;
    if(i + 2 < header.size()) v |= static_cast<unsigned char>(header[i + 2]);
    enc += b64[v >> 18 & 63];
    enc += b64[v >> 12 & 63];
    enc += i + 1 < header.size() ? b64[v >> 6 & 63] : '=';
    enc += i + 2 < header.size() ? b64[v & 63] : '=';
  }
  expect_read_error("bomb.vtu",
                    "<VTKFile type=\"UnstructuredGrid\" compressor=\"vtkZLibDataCompressor\"><UnstructuredGrid>"
                    "<Piece NumberOfPoints=\"1\" NumberOfCells=\"0\"><Points><DataArray type=\"Float64\" "
                    "NumberOfComponents=\"3\" format=\"binary\">" + enc + "</DataArray></Points><Cells>"
                    "<DataArray Name=\"connectivity\" type=\"Int64\" format=\"ascii\"></DataArray>"
                    "<DataArray Name=\"offsets\" type=\"Int64\" format=\"ascii\"></DataArray>"
                    "<DataArray Name=\"types\" type=\"UInt8\" format=\"ascii\"></DataArray></Cells></Piece>"
                    "</UnstructuredGrid></VTKFile>",
                    "more than zlib can give");
}

TEST(Formats, VtuWithTrianglesShowsSubdomainsAndPatches)
{
  // What ParaView needs: each tetrahedron's subdomain and each triangle's patch as cell data.
  const Tet_mesh m = grid_mesh();
  const fs::path p = tmp_dir() / "labels.vtu";
  IO::write_vtu(p.string(), m, true);
  std::ostringstream warnings;
  const Tet_mesh r = IO::read_vtu(p.string(), warnings);
  EXPECT_EQ(r.tet_labels, m.tet_labels);
  EXPECT_EQ(r.triangles, m.triangles);
  EXPECT_EQ(r.triangle_labels, m.triangle_labels);
  const std::string text = read_text(p);
  for(const char* name : {"Name=\"label\"", "Name=\"dimension\"", "Name=\"min_dihedral_angle\"", "Name=\"ref\""})
    EXPECT_NE(text.find(name), std::string::npos) << name;
}
