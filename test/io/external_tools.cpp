// Files written by the real tools users hold: Gmsh (2.2 and 4.1, ASCII and binary),
// TetGen (region attributes and boundary markers) and meshio (.vtu, .vtk, .msh,
// .mesh, .meshb); and our files read back by Gmsh. Each test skips, saying why, when
// its tool is not installed (scripts/setup.sh installs gmsh, tetgen, python3-meshio).
#include <CGAL/BODT_3/IO/mesh_io.h>

#include "io_test_meshes.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <set>
#include <sstream>
#include <string>

namespace fs = std::filesystem;
using namespace bodt_test;
namespace IO = CGAL::BODT_3::IO;
using CGAL::BODT_3::Tet_mesh;
using F = IO::Mesh_format;

namespace {

bool have(const std::string& command) { return std::system((command + " > /dev/null 2>&1").c_str()) == 0; }

int run(const std::string& command, const fs::path& dir)
{
  const std::string log = (dir / "tool_output.txt").string();
  return std::system(("cd " + shell_quoted(dir) + " && " + command + " > " + shell_quoted(log) + " 2>&1").c_str());
}

std::map<int, double> volume_per_label(const Tet_mesh& m)
{
  std::map<int, double> v;
  for(std::size_t t = 0; t < m.tets.size(); ++t)
  {
    const auto& c = m.tets[t];
    v[m.tet_labels[t]] += CGAL::volume(m.points[c[0]], m.points[c[1]], m.points[c[2]], m.points[c[3]]);
  }
  return v;
}

Tet_mesh read(const fs::path& p, IO::Mesh_file_format& f)
{
  std::ostringstream warnings;
  return IO::read_mesh(p.string(), f, warnings);
}

// Two unit cubes side by side, subdomains 1 and 2, every surface in physical group 10.
const char* const two_boxes_geo =
    "SetFactory(\"OpenCASCADE\");\n"
    "Box(1) = {0, 0, 0, 1, 1, 1};\n"
    "Box(2) = {1, 0, 0, 1, 1, 1};\n"
    "BooleanFragments{ Volume{1}; Delete; }{ Volume{2}; Delete; }\n"
    "Physical Volume(1) = {1};\n"
    "Physical Volume(2) = {2};\n"
    "Physical Surface(10) = Surface{:};\n"
    "Mesh.MeshSizeMax = 0.4;\n";

} // namespace

TEST(RealGmsh, EveryVersionAndEncoding)
{
  if(!have("gmsh --version")) GTEST_SKIP() << "gmsh is not installed (Debian package gmsh)";
  const fs::path dir = tmp_dir();
  write_file("two_boxes.geo", two_boxes_geo);
  std::size_t tets = 0, triangles = 0;
  for(const char* variant : {"msh22", "msh41", "msh22-binary", "msh41-binary"})
  {
    SCOPED_TRACE(variant);
    const IO::Mesh_file_format expected = IO::parse_format_name(variant);
    const std::string out = std::string(variant) + ".msh";
    ASSERT_EQ(run("gmsh -3 two_boxes.geo -format msh" + std::to_string(expected.version) +
                      (expected.binary ? " -bin" : "") + " -o " + out,
                  dir),
              0);
    IO::Mesh_file_format f;
    const Tet_mesh m = read(dir / out, f);
    EXPECT_EQ(f, expected);
    const auto v = volume_per_label(m);
    ASSERT_EQ(v.size(), 2u);
    EXPECT_NEAR(v.at(1), 1.0, 1e-12);
    EXPECT_NEAR(v.at(2), 1.0, 1e-12);
    EXPECT_FALSE(m.triangles.empty());
    EXPECT_EQ(std::set<int>(m.triangle_labels.begin(), m.triangle_labels.end()), std::set<int>{10});
    // The same mesh whatever the file's variant.
    if(tets == 0) { tets = m.tets.size(); triangles = m.triangles.size(); }
    EXPECT_EQ(m.tets.size(), tets);
    EXPECT_EQ(m.triangles.size(), triangles);
  }
}

TEST(RealGmsh, GmshReadsOurFiles)
{
  if(!have("gmsh --version")) GTEST_SKIP() << "gmsh is not installed (Debian package gmsh)";
  const fs::path dir = tmp_dir();
  write_file("two_boxes.geo", two_boxes_geo);
  ASSERT_EQ(run("gmsh -3 two_boxes.geo -format msh41 -o source.msh", dir), 0);
  IO::Mesh_file_format f;
  const Tet_mesh m = read(dir / "source.msh", f);
  for(const char* variant : {"msh22", "msh41", "msh22-binary", "msh41-binary"})
  {
    SCOPED_TRACE(variant);
    const std::string ours = std::string("ours_") + variant + ".msh";
    IO::write_mesh((dir / ours).string(), m, IO::parse_format_name(variant));
    // Gmsh reads ours and writes it again as ASCII 2.2.
    ASSERT_EQ(run("gmsh " + ours + " -0 -format msh22 -o back.msh", dir), 0) << read_text(dir / "tool_output.txt");
    const Tet_mesh back = read(dir / "back.msh", f);
    EXPECT_EQ(back.tets.size(), m.tets.size());
    EXPECT_EQ(back.triangles.size(), m.triangles.size());
    EXPECT_EQ(volume_per_label(back).size(), 2u);
    EXPECT_EQ(back.tet_labels, m.tet_labels);
    EXPECT_EQ(back.triangle_labels, m.triangle_labels);
  }
}

TEST(RealTetgen, RegionAttributesAndBoundaryMarkers)
{
  if(!have("command -v tetgen")) GTEST_SKIP() << "tetgen is not installed (Debian package tetgen)";
  const fs::path dir = tmp_dir();
  // The unit cube, facet markers 1 to 6, one region with attribute 5.
  write_file("cube.poly",
             "8 3 0 0\n1 0 0 0\n2 1 0 0\n3 1 1 0\n4 0 1 0\n5 0 0 1\n6 1 0 1\n7 1 1 1\n8 0 1 1\n"
             "6 1\n1 0 1\n4 1 2 3 4\n1 0 2\n4 5 6 7 8\n1 0 3\n4 1 2 6 5\n1 0 4\n4 2 3 7 6\n"
             "1 0 5\n4 3 4 8 7\n1 0 6\n4 4 1 5 8\n0\n1\n1 0.5 0.5 0.5 5 0.01\n");
  ASSERT_EQ(run("tetgen -pqAa0.01 cube.poly", dir), 0) << read_text(dir / "tool_output.txt");
  IO::Mesh_file_format f;
  std::ostringstream warnings;
  const Tet_mesh m = IO::read_mesh((dir / "cube.1.ele").string(), f, warnings);
  EXPECT_EQ(f.format, F::tetgen);
  EXPECT_EQ(warnings.str(), "");   // TetGen orients its tetrahedra as we do
  const auto v = volume_per_label(m);
  ASSERT_EQ(v.size(), 1u);
  EXPECT_NEAR(v.at(5), 1.0, 1e-12);
  EXPECT_EQ(std::set<int>(m.triangle_labels.begin(), m.triangle_labels.end()), (std::set<int>{1, 2, 3, 4, 5, 6}));
  EXPECT_FALSE(m.edges.empty());
  // Every boundary triangle lies on the face of the cube its marker names.
  for(std::size_t t = 0; t < m.triangles.size(); ++t)
  {
    const int marker = m.triangle_labels[t];
    const int axis = marker <= 2 ? 2 : marker == 3 || marker == 5 ? 1 : 0;
    const double at = marker == 1 || marker == 3 || marker == 6 ? 0.0 : 1.0;
    for(int k = 0; k < 3; ++k) EXPECT_EQ(m.points[m.triangles[t][k]][axis], at) << "triangle " << t;
  }
  // Written by us and read again: the same mesh.
  IO::write_mesh((dir / "ours.node").string(), m);
  expect_same_mesh_content(m, read(dir / "ours.ele", f));
  // TetGen reads our files: refining our mesh keeps the region and the markers.
  ASSERT_EQ(run("tetgen -rqAa0.005 ours", dir), 0) << read_text(dir / "tool_output.txt");
  const Tet_mesh refined = read(dir / "ours.1.ele", f);
  EXPECT_GT(refined.tets.size(), m.tets.size());
  EXPECT_NEAR(volume_per_label(refined).at(5), 1.0, 1e-12);
}

TEST(RealMeshio, EveryFormatMeshioWrites)
{
  if(!have("/usr/bin/python3 -c 'import meshio'"))
    GTEST_SKIP() << "meshio is not installed for /usr/bin/python3 (Debian package python3-meshio)";
  const fs::path dir = tmp_dir();
  const Tet_mesh m = grid_mesh();
  IO::write_mesh((dir / "grid.mesh").string(), m);
  // meshio reads our .mesh and writes each format; Gmsh 4.1 takes one cell type only.
  write_file("convert.py",
             "import meshio\n"
             "m = meshio.read('grid.mesh')\n"
             "ref = m.cell_data['medit:ref']\n"
             "m.cell_data['gmsh:physical'] = ref\n"
             "m.cell_data['gmsh:geometrical'] = ref\n"
             "meshio.write('m.vtu', m)\n"
             "meshio.write('m_ascii.vtu', m, binary=False)\n"
             "meshio.write('m.vtk', m)\n"
             "meshio.write('m_ascii.vtk', m, binary=False)\n"
             "meshio.write('m22.msh', m, file_format='gmsh22', binary=False)\n"
             "meshio.write('m22b.msh', m, file_format='gmsh22', binary=True)\n"
             "del m.cell_data['gmsh:physical'], m.cell_data['gmsh:geometrical']\n"
             "meshio.write('m.mesh', m)\n"
             "meshio.write('m.meshb', m)\n"
             "t = [i for i, c in enumerate(m.cells) if c.type == 'tetra'][0]\n"
             "tets = meshio.Mesh(m.points, [m.cells[t]], cell_data={'gmsh:physical': [ref[t]], 'gmsh:geometrical': [ref[t]]})\n"
             "meshio.write('m41.msh', tets, file_format='gmsh', binary=False)\n"
             "meshio.write('m41b.msh', tets, file_format='gmsh', binary=True)\n");
  ASSERT_EQ(run("/usr/bin/python3 convert.py", dir), 0) << read_text(dir / "tool_output.txt");
  for(const char* name : {"m.vtu", "m_ascii.vtu", "m.vtk", "m_ascii.vtk", "m22.msh", "m22b.msh", "m.mesh", "m.meshb",
                          "m41.msh", "m41b.msh"})
  {
    SCOPED_TRACE(name);
    IO::Mesh_file_format f;
    std::ostringstream warnings;
    Tet_mesh r;
    ASSERT_NO_THROW(r = IO::read_mesh((dir / name).string(), f, warnings));
    // meshio writes binary doubles or 17 significant digits, except in ASCII .vtu (12).
    ASSERT_EQ(r.points.size(), m.points.size());
    const double tolerance = std::string(name) == "m_ascii.vtu" ? 1e-11 : 0.0;
    for(std::size_t i = 0; i < m.points.size(); ++i)
      for(int c = 0; c < 3; ++c) EXPECT_NEAR(r.points[i][c], m.points[i][c], tolerance) << "point " << i;
    EXPECT_EQ(r.tets, m.tets);
    // meshio's Gmsh 4.1 writer puts all tetrahedra in one entity, tag 0: it drops the labels.
    if(std::string(name).find("41") == std::string::npos)
    {
      EXPECT_EQ(r.tet_labels, m.tet_labels);
      EXPECT_EQ(r.triangles, m.triangles);
      EXPECT_EQ(r.triangle_labels, m.triangle_labels);
      EXPECT_EQ(r.edge_labels, m.edge_labels);
    }
  }
}

TEST(RealMeshio, ReadsOurFiles)
{
  if(!have("/usr/bin/python3 -c 'import meshio'"))
    GTEST_SKIP() << "meshio is not installed for /usr/bin/python3 (Debian package python3-meshio)";
  const fs::path dir = tmp_dir();
  const Tet_mesh m = grid_mesh();
  // meshio 5.0 fails on binary legacy 5.1 files with SCALARS (its reader, not the file): not listed.
  const char* const variants[][2] = {{"vtu", "o.vtu"},           {"vtu-ascii", "oa.vtu"}, {"vtk", "o.vtk"},
                                     {"vtk-binary", "ob.vtk"},   {"vtk51", "o51.vtk"},    {"msh22", "o22.msh"},
                                     {"msh22-binary", "o22b.msh"}, {"mesh", "o.mesh"},    {"meshb", "o.meshb"}};
  std::string files;
  for(const auto& v : variants)
  {
    IO::write_mesh((dir / v[1]).string(), m, IO::parse_format_name(v[0]));
    files += std::string(files.empty() ? "" : ", ") + "'" + v[1] + "'";
  }
  // For each file: the number of tetrahedra and triangles, and the sum of their labels.
  write_file("check.py",
             "import meshio\n"
             "results = open('results.txt', 'w')\n"
             "for name in [" + files + "]:\n"
             "    m = meshio.read(name)\n"
             "    key = [k for k in ('label', 'gmsh:physical', 'medit:ref') if k in m.cell_data][0]\n"
             "    count = {'tetra': 0, 'triangle': 0}\n"
             "    total = {'tetra': 0, 'triangle': 0}\n"
             "    for block, labels in zip(m.cells, m.cell_data[key]):\n"
             "        if block.type in count:\n"
             "            count[block.type] += len(block.data)\n"
             "            total[block.type] += int(labels.sum())\n"
             "    print(name, count['tetra'], total['tetra'], count['triangle'], total['triangle'], file=results)\n");
  ASSERT_EQ(run("/usr/bin/python3 check.py", dir), 0) << read_text(dir / "tool_output.txt");
  long tet_sum = 0, triangle_sum = 0;
  for(int l : m.tet_labels) tet_sum += l;
  for(int l : m.triangle_labels) triangle_sum += l;
  std::istringstream out(read_text(dir / "results.txt"));
  std::string name;
  long tets, tsum, triangles, fsum;
  std::size_t lines = 0;
  while(out >> name >> tets >> tsum >> triangles >> fsum)
  {
    SCOPED_TRACE(name);
    ++lines;
    EXPECT_EQ(tets, static_cast<long>(m.tets.size()));
    EXPECT_EQ(tsum, tet_sum);
    EXPECT_EQ(triangles, static_cast<long>(m.triangles.size()));
    EXPECT_EQ(fsum, triangle_sum);
  }
  EXPECT_EQ(lines, sizeof variants / sizeof variants[0]);
}
