// Gmsh reading and writing (versions 2.2 and 4.1), VTU writing, and bad Gmsh input:
// round trips keep every coordinate bit and every label, hand-written files read as
// expected, and each defect gives a Mesh_io_error naming the file and the line.
#include <CGAL/BODT_3/IO/gmsh.h>
#include <CGAL/BODT_3/IO/medit.h>
#include <CGAL/BODT_3/IO/mesh_io.h>
#include <CGAL/BODT_3/IO/vtu.h>

#include "io_test_meshes.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using namespace bodt_test;
namespace IO = CGAL::BODT_3::IO;
using CGAL::BODT_3::Mesh_io_error;
using CGAL::BODT_3::Tet_mesh;
using Point = Tet_mesh::Point;

namespace {

// Runs `f`, which must throw Mesh_io_error at `line` of `file` with `words` in the message.
template <class F>
void expect_error(F f, const fs::path& file, long line, const std::string& words)
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
    EXPECT_EQ(e.line(), line) << what;
    if(line > 0)
    {
      EXPECT_NE(what.find(file.string() + ":" + std::to_string(line) + ": "), std::string::npos) << what;
    }
    EXPECT_NE(what.find(words), std::string::npos) << what;
  }
}

void expect_read_error(const std::string& name, const std::string& text, long line, const std::string& words)
{
  const fs::path p = write_file(name, text);
  std::ostringstream warnings;
  expect_error([&] { IO::read_gmsh(p.string(), warnings); }, p, line, words);
}

// Two tetrahedra sharing face (7 8 12), node tags with gaps, a corner, a line, a
// triangle with physical tags, and a quadrangle to skip.
const char* const good_22 =
    "$MeshFormat\n"                 // line 1
    "2.2 0 8\n"                     // 2
    "$EndMeshFormat\n"              // 3
    "$PhysicalNames\n"              // 4
    "1\n"                           // 5
    "3 4 \"body\"\n"                // 6
    "$EndPhysicalNames\n"           // 7
    "$Nodes\n"                      // 8
    "5\n"                           // 9
    "3 0 0 0\n"                     // 10
    "7 1 0 0\n"                     // 11
    "8 0 1 0\n"                     // 12
    "12 0 0 1\n"                    // 13
    "40 1 1 1\n"                    // 14
    "$EndNodes\n"                   // 15
    "$Elements\n"                   // 16
    "6\n"                           // 17
    "1 15 2 0 1 40\n"               // 18
    "2 1 2 9 2 3 7\n"               // 19
    "3 2 2 11 3 3 8 7\n"            // 20
    "4 4 2 4 1 3 7 8 12\n"          // 21
    "5 4 3 5 1 0 7 8 12 40\n"       // 22
    "6 3 2 1 1 3 7 40 8\n"          // 23
    "$EndElements\n";               // 24

// The same mesh in 4.1: an unlabelled curve (no physical tag), a surface with
// physical tag 3, a volume with physical tag 7, nodes in two blocks, and a
// quadrangle on a surface that $Entities does not declare.
const char* const good_41 =
    "$MeshFormat\n"                           // line 1
    "4.1 0 8\n"                               // 2
    "$EndMeshFormat\n"                        // 3
    "$Comments\n"                             // 4
    "written by hand\n"                       // 5
    "$EndComments\n"                          // 6
    "$Entities\n"                             // 7
    "1 1 1 1\n"                               // 8
    "1 1 1 1 0\n"                             // 9
    "1 0 0 0 1 0 0 0 2 1 -2\n"                // 10
    "5 0 0 0 1 1 0 1 3 1 1\n"                 // 11
    "9 0 0 0 1 1 1 1 7 1 5\n"                 // 12
    "$EndEntities\n"                          // 13
    "$Nodes\n"                                // 14
    "2 5 10 50\n"                             // 15
    "3 9 0 4\n"                               // 16
    "10\n"                                    // 17
    "20\n"                                    // 18
    "30\n"                                    // 19
    "40\n"                                    // 20
    "0 0 0\n"                                 // 21
    "1 0 0\n"                                 // 22
    "0 1 0\n"                                 // 23
    "0 0 1\n"                                 // 24
    "0 1 0 1\n"                               // 25
    "50\n"                                    // 26
    "1 1 1\n"                                 // 27
    "$EndNodes\n"                             // 28
    "$Elements\n"                             // 29
    "5 6 101 106\n"                           // 30
    "0 1 15 1\n"                              // 31
    "101 50\n"                                // 32
    "1 1 1 1\n"                               // 33
    "102 10 20\n"                             // 34
    "2 5 2 1\n"                               // 35
    "103 10 30 20\n"                          // 36
    "3 9 4 2\n"                               // 37
    "104 10 20 30 40\n"                       // 38
    "105 20 30 40 50\n"                       // 39
    "2 6 3 1\n"                               // 40
    "106 10 20 50 30\n"                       // 41
    "$EndElements\n";                         // 42

void expect_hand_written_mesh(const Tet_mesh& m, int edge_label, int triangle_label, int tet_label_0,
                              int tet_label_1)
{
  const std::vector<Point> points = {Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0), Point(0, 0, 1),
                                     Point(1, 1, 1)};
  EXPECT_EQ(m.points, points);
  EXPECT_EQ(m.vertex_refs, std::vector<int>(5, 0));
  EXPECT_EQ(m.tets, (std::vector<std::array<int, 4>>{{0, 1, 2, 3}, {1, 2, 3, 4}}));
  EXPECT_EQ(m.tet_labels, (std::vector<int>{tet_label_0, tet_label_1}));
  EXPECT_EQ(m.triangles, (std::vector<std::array<int, 3>>{{0, 2, 1}}));
  EXPECT_EQ(m.triangle_labels, (std::vector<int>{triangle_label}));
  EXPECT_EQ(m.edges, (std::vector<std::array<int, 2>>{{0, 1}}));
  EXPECT_EQ(m.edge_labels, (std::vector<int>{edge_label}));
  EXPECT_EQ(m.corners, (std::vector<int>{4}));
}

} // namespace

TEST(Gmsh, ReadsHandWritten22)
{
  const fs::path p = write_file("hand22.msh", good_22);
  std::ostringstream warnings;
  const Tet_mesh m = IO::read_gmsh(p.string(), warnings);
  expect_hand_written_mesh(m, 9, 11, 4, 5);
  // One warning for the skipped quadrangle, at its line; none for $PhysicalNames.
  EXPECT_NE(warnings.str().find(p.string() + ":23: skipped 1 element(s) of Gmsh type 3"), std::string::npos)
      << warnings.str();
  EXPECT_EQ(warnings.str().find("PhysicalNames"), std::string::npos) << warnings.str();
}

TEST(Gmsh, ReadsHandWritten41)
{
  const fs::path p = write_file("hand41.msh", good_41);
  std::ostringstream warnings;
  const Tet_mesh m = IO::read_gmsh(p.string(), warnings);
  expect_hand_written_mesh(m, 0, 3, 7, 7);
  EXPECT_NE(warnings.str().find(p.string() + ":41: skipped 1 element(s) of Gmsh type 3"), std::string::npos)
      << warnings.str();
  EXPECT_NE(warnings.str().find(p.string() + ":4: unknown section '$Comments'"), std::string::npos)
      << warnings.str();
}

TEST(Gmsh, SkipsEachUnsupportedTypeWithOneWarning)
{
  // Two more quadrangles in 2.2: still a single warning, counting three.
  std::string text = good_22;
  text = with_line(text, 17, "8");
  text = with_line(text, 23, "6 3 2 1 1 3 7 40 8\n7 3 2 1 1 3 7 40 8\n8 3 2 1 1 3 7 40 8");
  const fs::path p = write_file("three_quads.msh", text);
  std::ostringstream warnings;
  IO::read_gmsh(p.string(), warnings);
  const std::string w = warnings.str();
  EXPECT_NE(w.find(":23: skipped 3 element(s) of Gmsh type 3"), std::string::npos) << w;
  EXPECT_EQ(w.find("warning", w.find("warning") + 1), std::string::npos) << w;
}

TEST(Gmsh, RoundTripKeepsEverythingGmshHolds)
{
  const Tet_mesh original = grid_mesh();
  const fs::path medit = tmp_dir() / "grid.mesh";
  IO::write_medit(medit.string(), original);
  std::ostringstream warnings;
  const Tet_mesh m0 = IO::read_medit(medit.string(), warnings);
  ASSERT_EQ(m0.tets.size(), 162u);
  expect_same_mesh_content(original, m0);

  for(int version : {22, 41})
  {
    SCOPED_TRACE("version " + std::to_string(version));
    const fs::path msh = tmp_dir() / ("grid" + std::to_string(version) + ".msh");
    IO::write_gmsh(msh.string(), m0, version);
    EXPECT_EQ(read_text(msh).substr(0, 20), std::string("$MeshFormat\n") + (version == 22 ? "2.2 0 8\n" : "4.1 0 8\n"));
    const Tet_mesh m1 = IO::read_gmsh(msh.string(), warnings);
    expect_same_mesh_content(m0, m1);

    // .mesh -> .msh -> .mesh
    const fs::path back = tmp_dir() / ("grid_back" + std::to_string(version) + ".mesh");
    IO::write_medit(back.string(), m1);
    expect_same_mesh_content(m0, IO::read_medit(back.string(), warnings));
  }
  EXPECT_EQ(warnings.str(), "");
}

TEST(Gmsh, WritesNoPhysicalTagZeroIn41)
{
  // Label 0 must be an entity without physical tag; every other label its physical tag.
  std::ostringstream out;
  IO::write_gmsh(out, grid_mesh(), 41);
  std::istringstream in(out.str());
  std::string line;
  while(std::getline(in, line) && line != "$Entities") {}
  std::size_t count[4];
  in >> count[0] >> count[1] >> count[2] >> count[3];
  EXPECT_EQ(count[0], 8u);   // one point entity per corner
  EXPECT_EQ(count[1], 3u);   // edge labels 0, 10, -3
  EXPECT_EQ(count[2], 3u);
  EXPECT_EQ(count[3], 3u);   // tet labels 0, 1, 2
  std::getline(in, line);
  for(std::size_t i = 0; i < count[0]; ++i) std::getline(in, line);
  std::vector<std::vector<int>> physicals;
  for(int d = 1; d < 4; ++d)
    for(std::size_t i = 0; i < count[d]; ++i)
    {
      int tag;
      double box[6];
      std::size_t nphys;
      in >> tag;
      for(double& b : box) in >> b;
      in >> nphys;
      std::vector<int> p(nphys);
      for(int& x : p) in >> x;
      physicals.push_back(p);
      std::getline(in, line);
    }
  ASSERT_TRUE(in.good());
  EXPECT_EQ(physicals, (std::vector<std::vector<int>>{{-3}, {}, {10}, {-3}, {}, {10}, {}, {1}, {2}}));
}

TEST(Gmsh, DispatchByExtension)
{
  const Tet_mesh m = grid_mesh();
  const fs::path msh = tmp_dir() / "dispatch.msh";
  IO::write_mesh(msh.string(), m);
  EXPECT_EQ(read_text(msh).substr(0, 20), "$MeshFormat\n4.1 0 8\n");
  std::ostringstream warnings;
  expect_same_mesh_content(m, IO::read_mesh(msh.string(), warnings));

  const fs::path vtu = tmp_dir() / "dispatch.vtu";
  IO::write_mesh(vtu.string(), m);
  EXPECT_NE(read_text(vtu).find("<VTKFile type=\"UnstructuredGrid\""), std::string::npos);
  IO::Mesh_file_format f;
  const Tet_mesh v = IO::read_mesh(vtu.string(), f, warnings);
  EXPECT_EQ(f, (IO::Mesh_file_format{IO::Mesh_format::vtu, 0, true}));
  EXPECT_EQ(v.triangles, m.triangles);

  const fs::path other = tmp_dir() / "dispatch.obj";
  expect_error([&] { IO::read_mesh(other.string(), warnings); }, other, 0, "must end in .mesh, .meshb, .msh");
  expect_error([&] { IO::write_mesh(other.string(), m); }, other, 0, "must end in .mesh, .meshb, .msh");
  EXPECT_FALSE(fs::exists(other));
}

TEST(Gmsh, RealCubeMsh)
{
  const std::string dir = BODT_SHARED_DATA;
  if(!fs::exists(dir + "/cube.msh") || !fs::exists(dir + "/cube.mesh"))
    GTEST_SKIP() << "no " << dir << "/cube.msh";
  std::ostringstream warnings;
  const Tet_mesh g = IO::read_gmsh(dir + "/cube.msh", warnings);
  const Tet_mesh m = IO::read_medit(dir + "/cube.mesh", warnings);
  EXPECT_EQ(g.number_of_vertices(), 152u);
  EXPECT_EQ(g.number_of_tets(), 373u);
  EXPECT_EQ(g.triangles.size(), 300u);
  EXPECT_EQ(g.edges.size(), 60u);
  // mmg writes a point element, with no tags, for each of the 152 vertices: none is a corner.
  EXPECT_TRUE(g.corners.empty());
  EXPECT_EQ(g.points, m.points);
  // Same tetrahedra, compared as vertex sets in any order.
  auto sorted = [](const Tet_mesh& x) {
    std::vector<std::array<int, 4>> t = x.tets;
    for(auto& c : t) std::sort(c.begin(), c.end());
    std::sort(t.begin(), t.end());
    return t;
  };
  EXPECT_EQ(sorted(g), sorted(m));
  // Both readers orient the same tetrahedra the same way.
  EXPECT_EQ(g.tets, m.tets);

  // The real mesh round-trips through both versions too.
  for(int version : {22, 41})
  {
    const fs::path msh = tmp_dir() / ("cube" + std::to_string(version) + ".msh");
    IO::write_gmsh(msh.string(), m, version);
    expect_same_mesh_content(m, IO::read_gmsh(msh.string(), warnings));
  }
}

TEST(GmshErrors, Truncated)
{
  // Cut in the middle of line 22, as an interrupted copy leaves it.
  const std::string text = good_22;
  expect_read_error("truncated.msh", text.substr(0, text.find("5 4 3 5 1 0 7 8") + 15), 22,
                    "the file ends where a node tag was expected; it is truncated");
  // Cut in the nodes: the count on line 9 is more than the rest of the file can hold.
  expect_read_error("truncated_nodes.msh", text.substr(0, text.find("12 0 0 1") + 6), 9, "truncated");
}

TEST(GmshErrors, NodeCountTooLarge)
{
  expect_read_error("count_large.msh", with_line(good_22, 9, "6"), 15, "after 5 nodes, but 6 were announced");
}

TEST(GmshErrors, NodeCountTooSmall)
{
  expect_read_error("count_small.msh", with_line(good_22, 9, "4"), 14, "expected '$EndNodes'");
}

TEST(GmshErrors, ElementCountWrong)
{
  expect_read_error("elements_large.msh", with_line(good_22, 17, "7"), 24, "after 6 elements, but 7 were announced");
}

TEST(GmshErrors, NotFiniteCoordinate)
{
  expect_read_error("nan.msh", with_line(good_22, 12, "8 nan 1 0"), 12, "not a finite number");
  expect_read_error("inf.msh", with_line(good_22, 11, "7 1 0 -inf"), 11, "not a finite number");
  expect_read_error("nan41.msh", with_line(good_41, 23, "0 NaN 0"), 23, "not a finite number");
}

TEST(GmshErrors, UndefinedNodeTag)
{
  expect_read_error("undefined.msh", with_line(good_22, 21, "4 4 2 4 1 3 7 8 13"), 21, "refers to node 13");
  expect_read_error("undefined41.msh", with_line(good_41, 39, "105 20 30 40 60"), 39, "refers to node 60");
}

TEST(GmshErrors, DuplicateNodeTag)
{
  expect_read_error("duplicate.msh", with_line(good_22, 13, "7 0 0 1"), 13, "node tag 7 is defined twice");
}

TEST(GmshErrors, BinaryFileWithoutItsByteOrderMark)
{
  // An ASCII file that says it is binary: where the byte order mark 1 should be, there is text.
  expect_read_error("binary22.msh", with_line(good_22, 2, "2.2 1 8"), 0, "byte order mark");
  expect_read_error("binary41.msh", with_line(good_41, 2, "4.1 1 8"), 0, "byte order mark");
  expect_read_error("type2.msh", with_line(good_22, 2, "2.2 2 8"), 2, "file type 2 is not valid");
  expect_read_error("size4.msh", with_line(good_22, 2, "2.2 0 4"), 2, "data size 4 is not supported");
}

TEST(GmshErrors, UnsupportedVersion)
{
  expect_read_error("v3.msh", with_line(good_22, 2, "3.0 0 8"), 2, "version 3.0 is not supported");
}

TEST(GmshErrors, MissingFile)
{
  const fs::path p = tmp_dir() / "does_not_exist.msh";
  std::ostringstream warnings;
  expect_error([&] { IO::read_gmsh(p.string(), warnings); }, p, 0, "cannot open");
}

TEST(GmshErrors, EmptyFile)
{
  expect_read_error("empty.msh", "", 0, "empty");
  expect_read_error("blank.msh", "\n  \n", 0, "empty");
}

TEST(GmshErrors, NotGmsh)
{
  expect_read_error("not_gmsh.msh", with_line(good_22, 1, "MeshVersionFormatted 2"), 1, "not a Gmsh mesh file");
}

TEST(GmshErrors, MissingEndMarkers)
{
  // $EndNodes gone: the next section header stands where it belongs.
  expect_read_error("no_end_nodes.msh", without_line(good_22, 15), 15, "'$EndNodes'");
  // $EndElements gone: the file ends where it was expected, after line 23.
  expect_read_error("no_end_elements.msh", without_line(good_22, 24), 23, "'$EndElements'");
  // An unknown section never closed.
  expect_read_error("no_end_comments.msh", without_line(good_41, 6), 6, "'$EndComments' is missing");
}

TEST(GmshErrors, GarbageTokens)
{
  expect_read_error("garbage_coord.msh", with_line(good_22, 11, "7 1 zero 0"), 11, "found 'zero'");
  expect_read_error("garbage_tail.msh", with_line(good_22, 11, "7 1 0 0 x"), 11, "unexpected 'x'");
  expect_read_error("extra_node.msh", with_line(good_22, 21, "4 4 2 4 1 3 7 8 12 40"), 21, "unexpected '40'");
  expect_read_error("garbage_section.msh", with_line(good_22, 16, "Elements"), 16, "expected a section header");
  expect_read_error("garbage_entity.msh", with_line(good_41, 12, "9 0 0 0 1 1 1 1 seven 1 5"), 12, "found 'seven'");
}

TEST(GmshErrors, BlockCountsDoNotMatch41)
{
  // Header announces 6 nodes, the blocks hold 5.
  expect_read_error("nodes41.msh", with_line(good_41, 15, "2 6 10 50"), 15, "announces 6 nodes, but its blocks hold 5");
  // A block longer than the header allows.
  expect_read_error("block41.msh", with_line(good_41, 30, "5 5 101 106"), 40, "more than the 5 elements");
}

TEST(GmshErrors, ChecksOfTheMeshNameTheLine)
{
  // The second tetrahedron repeats the first: check_and_orient names its line.
  expect_read_error("repeated.msh", with_line(good_22, 22, "5 4 2 5 1 7 3 8 12"), 22, "repeats tetrahedron 1");
  expect_read_error("repeated41.msh", with_line(good_41, 39, "105 30 10 20 40"), 39, "repeats tetrahedron 1");
}

TEST(Vtu, RegularTetrahedron)
{
  // A regular tetrahedron (every dihedral angle acos(1/3)) and a right-angled one.
  Tet_mesh m;
  m.points = {Point(1, 1, 1), Point(1, -1, -1), Point(-1, -1, 1), Point(-1, 1, -1), Point(2, 2, 2)};
  m.tets = {{0, 1, 2, 3}, {0, 1, 3, 4}};
  m.tet_labels = {0, 6};
  m.triangles = {{0, 1, 2}};
  m.triangle_labels = {9};
  const fs::path p = tmp_dir() / "regular.vtu";
  IO::write_vtu(p.string(), m, false);
  const std::string text = read_text(p);

  EXPECT_NE(text.find("NumberOfPoints=\"5\" NumberOfCells=\"3\""), std::string::npos);
  // Tags balance: each opened tag is closed in order.
  std::vector<std::string> open;
  for(std::size_t i = text.find('<'); i != std::string::npos; i = text.find('<', i + 1))
  {
    const std::size_t end = text.find('>', i);
    ASSERT_NE(end, std::string::npos);
    const std::string tag = text.substr(i + 1, end - i - 1);
    if(tag[0] == '?' || tag.back() == '/') continue;
    const std::string name = tag.substr(tag[0] == '/', tag.find_first_of(" ", 0) - (tag[0] == '/'));
    if(tag[0] == '/')
    {
      ASSERT_FALSE(open.empty()) << tag;
      EXPECT_EQ(open.back(), name);
      open.pop_back();
    }
    else
      open.push_back(name);
  }
  EXPECT_TRUE(open.empty());

  auto values = [&](const std::string& name, const std::string& type) {
    const std::size_t at = text.find("Name=\"" + name + "\"");
    EXPECT_NE(at, std::string::npos) << name;
    const std::size_t open_end = text.find('>', at);
    const std::size_t start = text.rfind('<', at);
    EXPECT_NE(text.substr(start, at - start).find("type=\"" + type + "\""), std::string::npos) << name;
    std::istringstream in(text.substr(open_end + 1, text.find("</DataArray>", open_end) - open_end - 1));
    return std::vector<double>(std::istream_iterator<double>(in), std::istream_iterator<double>());
  };
  // The tetrahedra, then the boundary triangle with its patch label.
  EXPECT_EQ(values("connectivity", "Int64"), (std::vector<double>{0, 1, 2, 3, 0, 1, 3, 4, 0, 1, 2}));
  EXPECT_EQ(values("offsets", "Int64"), (std::vector<double>{4, 8, 11}));
  EXPECT_EQ(values("types", "UInt8"), (std::vector<double>{10, 10, 5}));
  EXPECT_EQ(values("label", "Int32"), (std::vector<double>{0, 6, 9}));
  EXPECT_EQ(values("dimension", "UInt8"), (std::vector<double>{3, 3, 2}));
  const auto angles = values("min_dihedral_angle", "Float64");
  ASSERT_EQ(angles.size(), 3u);
  EXPECT_EQ(angles[2], -1);
  EXPECT_NEAR(angles[0], 70.5288, 1e-3);
  EXPECT_NEAR(angles[0], std::acos(1.0 / 3.0) * 180.0 / 3.14159265358979323846, 1e-9);
  EXPECT_LT(angles[1], 70.0);

  const std::size_t cell_data = text.find("<CellData");
  ASSERT_NE(cell_data, std::string::npos);
  EXPECT_LT(cell_data, text.find("Name=\"label\""));
  EXPECT_LT(cell_data, text.find("Name=\"min_dihedral_angle\""));
  // Points, bit for bit.
  std::istringstream pts(text.substr(text.find('>', text.find("NumberOfComponents=\"3\"")) + 1));
  for(const Point& q : m.points)
  {
    double x, y, z;
    pts >> x >> y >> z;
    EXPECT_EQ(Point(x, y, z), q);
  }
}

TEST(Cli, ConvertsThroughGmshAndVtu)
{
  const fs::path mesh = tmp_dir() / "cli.mesh", msh = tmp_dir() / "cli.msh", back = tmp_dir() / "cli_back.mesh",
                 vtu = tmp_dir() / "cli.vtu";
  const Tet_mesh m = grid_mesh();
  IO::write_medit(mesh.string(), m);
  std::string output;
  auto run = [&](const fs::path& in, const fs::path& out) {
    return bodt_test::run_bodt("convert " + in.string() + " " + out.string(), output);
  };
  ASSERT_EQ(run(mesh, msh), 0);
  ASSERT_EQ(run(msh, back), 0);
  ASSERT_EQ(run(back, vtu), 0);
  std::ostringstream warnings;
  expect_same_mesh_content(m, IO::read_medit(back.string(), warnings));
  // 162 tetrahedra, 18 triangles, 3 edges, 8 corners.
  EXPECT_NE(read_text(vtu).find("NumberOfCells=\"191\""), std::string::npos);
  ASSERT_EQ(run(vtu, back), 0) << output;
  Tet_mesh from_vtu = IO::read_medit(back.string(), warnings);
  EXPECT_EQ(from_vtu.triangle_labels, m.triangle_labels);
  EXPECT_EQ(from_vtu.tet_labels, m.tet_labels);
}

TEST(Gmsh, UntaggedPointElementsAreNotCorners)
{
  const std::string text = "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n4\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n"
                           "$EndNodes\n$Elements\n3\n1 15 2 0 0 1\n2 15 2 0 7 2\n3 4 2 1 1 1 2 3 4\n$EndElements\n";
  std::ostringstream warnings;
  const Tet_mesh m = IO::read_gmsh(write_file("points.msh", text).string(), warnings);
  EXPECT_EQ(m.corners, (std::vector<int>{1}));   // only node 2, on geometric point 7
}
