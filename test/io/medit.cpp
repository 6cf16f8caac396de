// Medit reading and writing, and every kind of bad input, through the library
// and through the `bodt` command as a user meets it: a clear message naming the
// file and line, a non-zero exit status below 128, and no output file left.
#include <CGAL/BODT_3/IO/medit.h>
#include <CGAL/BODT_3/IO/mesh_io.h>

#include "test_support.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace fs = std::filesystem;
using namespace bodt_test;
using CGAL::BODT_3::Mesh_io_error;
using CGAL::BODT_3::Tet_mesh;
using Point = Tet_mesh::Point;

namespace {

// Two tetrahedra sharing face (2 3 4), in subdomains 1 and 2, with boundary
// triangles, an edge, a corner and a ridge.
const char* const good_mesh =
    "MeshVersionFormatted 2\n"      // line 1
    "Dimension 3\n"                 // 2
    "Vertices\n"                    // 3
    "5\n"                           // 4
    "0 0 0 1\n"                     // 5
    "1 0 0 1\n"                     // 6
    "0 1 0 1\n"                     // 7
    "0 0 1 1\n"                     // 8
    "1 1 1 2\n"                     // 9
    "Tetrahedra\n"                  // 10
    "2\n"                           // 11
    "1 2 3 4 1\n"                   // 12
    "2 3 4 5 2\n"                   // 13
    "Triangles\n"
    "1\n"
    "1 2 3 7\n"
    "Edges\n"
    "1\n"
    "1 2 4\n"
    "Corners\n"
    "1\n"
    "1\n"
    "Ridges\n"
    "1\n"
    "1\n"
    "End\n";

struct Bad_input
{
  std::string name;
  std::string text;          // file content; empty name of missing file below
  long line;                 // expected line in the message (0: none)
  std::string words;         // expected words in the message
};

std::vector<Bad_input> bad_inputs()
{
  const std::string g = good_mesh;
  return {
      {"empty.mesh", "", 0, "empty"},
      {"blank.mesh", "  \n\n", 0, "empty"},
      {"truncated.mesh", truncate_after_line(g, 8), 8, "truncated"},
      {"truncated_tets.mesh", truncate_after_line(g, 12), 12, "truncated"},
      {"count_too_small.mesh", with_line(g, 4, "4"), 9, "count"},
      {"count_too_large.mesh", with_line(g, 11, "3"), 14, "ends after 2 of the 3 tetrahedra"},
      {"nan.mesh", with_line(g, 7, "0 nan 0 1"), 7, "not a finite number"},
      {"inf.mesh", with_line(g, 8, "0 0 inf 1"), 8, "not a finite number"},
      {"huge.mesh", with_line(g, 8, "0 0 1e31 1"), 8, "magnitude above 1e30"},
      {"tiny.mesh",
       with_line(with_line(with_line(with_line(g, 9, "1e-31 1e-31 1e-31 2"), 8, "0 0 1e-31 1"), 7, "0 1e-31 0 1"), 6,
                 "1e-31 0 0 1"),
       0, "smaller than 1e-30"},
      {"index_out_of_range.mesh", with_line(g, 13, "2 3 4 6 2"), 13, "vertex indices run from 1 to 5"},
      {"index_zero.mesh", with_line(g, 13, "0 3 4 5 2"), 13, "vertex 0"},
      {"repeated_tet.mesh", with_line(with_line(g, 11, "3"), 13, "2 3 4 5 2\n3 4 2 5 2"), 14, "repeats tetrahedron 2"},
      {"degenerate_tet.mesh", with_line(g, 13, "2 4 4 5 2"), 13, "uses vertex 4 twice"},
      {"mixed_orientation.mesh", with_line(g, 13, "2 4 3 5 2"), 13, "mixed orientation"},
      // Edited from the bottom up so that line numbers above stay valid.
      {"three_tets_on_a_face.mesh",
       with_line(with_line(with_line(with_line(g, 13, "2 3 4 5 2\n2 3 4 6 2"), 11, "3"), 9, "1 1 1 2\n-1 -1 -1 0"),
                 4, "6"),
       15, "third to share face"},
      // A fourth vertex in the plane z = 0 of vertices 1, 2 and 3, in a tetrahedron labelled 0.
      {"flat_tet_labelled_0.mesh",
       with_line(with_line(with_line(with_line(g, 13, "2 3 4 5 2\n1 2 6 3 0"), 11, "3"), 9, "1 1 1 2\n1 1 0 0"), 4,
                 "6"),
       15, "tetrahedron 3 (1 2 6 3) is flat"},
      {"garbage.mesh", with_line(g, 6, "1 zero 0 1"), 6, "found 'zero'"},
      {"not_medit.mesh", "solid foo\nfacet normal 0 0 1\n", 1, "not a Medit mesh file"},
      {"dimension2.mesh", with_line(g, 2, "Dimension 2"), 2, "2D mesh"},
      {"bad_ridge.mesh", with_line(g, 25, "7"), 25, "Ridges entry 1 refers to edge 7"},
  };
}

} // namespace

TEST(MeditIO, ReadsSectionsAndLabels)
{
  const fs::path p = write_file("good.mesh", good_mesh);
  std::ostringstream warnings;
  const Tet_mesh m = CGAL::BODT_3::IO::read_medit(p.string(), warnings);
  EXPECT_EQ(warnings.str(), "");
  ASSERT_EQ(m.points.size(), 5u);
  EXPECT_EQ(m.points[4], Point(1, 1, 1));
  EXPECT_EQ(m.vertex_refs[4], 2);
  ASSERT_EQ(m.tets.size(), 2u);
  EXPECT_EQ(m.tets[1], (std::array<int, 4>{1, 2, 3, 4}));
  EXPECT_EQ(m.tet_labels, (std::vector<int>{1, 2}));
  EXPECT_EQ(m.triangle_labels, (std::vector<int>{7}));
  ASSERT_EQ(m.edges.size(), 1u);
  EXPECT_EQ(m.edges[0], (std::array<int, 2>{0, 1}));
  EXPECT_EQ(m.edge_labels[0], 4);
  EXPECT_EQ(m.corners, (std::vector<int>{0}));
  EXPECT_EQ(m.ridges, (std::vector<int>{0}));
}

TEST(MeditIO, RoundTripIsExact)
{
  const fs::path p = write_file("good.mesh", good_mesh);
  std::ostringstream warnings;
  Tet_mesh m = CGAL::BODT_3::IO::read_medit(p.string(), warnings);
  m.points[0] = Point(0.1, 1.0 / 3.0, -2.0 / 7.0);     // not representable in few digits
  m.points[4] = Point(1 + 1e-15, 1, 1);
  const fs::path q = tmp_dir() / "roundtrip.mesh";
  CGAL::BODT_3::IO::write_medit(q.string(), m);
  const Tet_mesh r = CGAL::BODT_3::IO::read_medit(q.string(), warnings);
  expect_same_mesh_content(m, r);
  EXPECT_EQ(r.vertex_refs, m.vertex_refs);
  EXPECT_EQ(r.ridges, m.ridges);
}

TEST(MeditIO, NegativelyOrientedMeshIsReorientedWithWarning)
{
  const std::string flipped = with_line(with_line(good_mesh, 12, "1 2 4 3 1"), 13, "2 4 3 5 2");
  const fs::path p = write_file("flipped.mesh", flipped);
  std::ostringstream warnings;
  const Tet_mesh m = CGAL::BODT_3::IO::read_medit(p.string(), warnings);
  EXPECT_NE(warnings.str().find("negatively oriented"), std::string::npos);
  for(const auto& c : m.tets)
    EXPECT_EQ(CGAL::orientation(m.points[c[0]], m.points[c[1]], m.points[c[2]], m.points[c[3]]), CGAL::POSITIVE);
}

TEST(MeditIO, UnknownSectionsAreSkippedWithWarning)
{
  const std::string text = with_line(good_mesh, 10, "MyExtension\n2\n1.5 2.5\nTetrahedra");
  const fs::path p = write_file("unknown_section.mesh", text);
  std::ostringstream warnings;
  const Tet_mesh m = CGAL::BODT_3::IO::read_medit(p.string(), warnings);
  EXPECT_EQ(m.tets.size(), 2u);
  EXPECT_NE(warnings.str().find("unknown section 'MyExtension'"), std::string::npos) << warnings.str();
  EXPECT_NE(warnings.str().find(":10:"), std::string::npos) << warnings.str();
}

TEST(MeditIO, EveryBadInputThrowsWithFileAndLine)
{
  for(const auto& bad : bad_inputs())
  {
    const fs::path p = write_file(bad.name, bad.text);
    std::ostringstream warnings;
    try
    {
      CGAL::BODT_3::IO::read_medit(p.string(), warnings);
      ADD_FAILURE() << bad.name << " was accepted";
    }
    catch(const Mesh_io_error& e)
    {
      const std::string what = e.what();
      EXPECT_NE(what.find(p.string()), std::string::npos) << what;
      if(bad.line > 0)
      {
        EXPECT_EQ(e.line(), bad.line) << bad.name << ": " << what;
      }
      EXPECT_NE(what.find(bad.words), std::string::npos) << bad.name << ": " << what;
    }
  }
}

// Sections laid out one entry per line are read in parallel blocks of rows, any
// other layout token by token: both read the same mesh, and on a bad file both
// report the first defect in file order, with its line, on any number of threads.
TEST(MeditIO, ParallelRowsAndTokensReadTheSame)
{
  // 24,576 tetrahedra: six blocks of rows, and the checks' parts on four threads.
  const Tet_mesh grid = cube_grid(16, [](int i, int, int) { return i < 8 ? 1 : 2; });
  std::ostringstream written;
  CGAL::BODT_3::IO::write_medit(written, grid);
  const std::string rows = written.str();
  std::string tokens = rows;   // the same numbers, one per line
  std::replace(tokens.begin() + static_cast<std::ptrdiff_t>(tokens.find("Vertices")), tokens.end(), ' ', '\n');
  auto read = [](const std::string& name, const std::string& text, int threads) {
    std::ostringstream warnings;
    return CGAL::BODT_3::IO::read_medit(write_file(name, text).string(), warnings, nullptr, threads);
  };
  for(int threads : {1, 2, 4})
  {
    expect_same_mesh_content(read("rows.mesh", rows, threads), grid);
    expect_same_mesh_content(read("tokens.mesh", tokens, threads), grid);
  }

  // Line of tetrahedron t (1-based) and of vertex v in `rows`.
  int tets_at = 0, vertices_at = 0, line = 1;
  for(std::size_t p = 0; p < rows.size(); ++p)
  {
    if(rows.compare(p, 11, "Tetrahedra\n") == 0) tets_at = line + 1;
    if(rows.compare(p, 9, "Vertices\n") == 0) vertices_at = line + 1;
    if(rows[p] == '\n') ++line;
  }
  ASSERT_GT(tets_at, 0);
  auto tet_line = [&](int t) { return tets_at + t; };
  auto tet = [&](int t) {
    const auto& q = grid.tets[static_cast<std::size_t>(t - 1)];
    return std::to_string(q[0] + 1) + " " + std::to_string(q[1] + 1) + " " + std::to_string(q[2] + 1) + " " +
           std::to_string(q[3] + 1) + " 1";
  };
  // Two different flat tetrahedra, in the plane z = 0.
  const std::string flat = "1 2 19 18 1", other_flat = "2 3 20 19 1";
  struct Case { std::string name, text; long line; std::string words; };
  const std::vector<Case> cases = {
      {"late_bad_index.mesh", with_line(rows, tet_line(20000), "1 2 3 99999 1"), tet_line(20000), "refers to vertex 99999"},
      {"bad_coordinate.mesh", with_line(rows, vertices_at + 3000, "1 x 0 0"), vertices_at + 3000, "found 'x'"},
      {"two_repeats.mesh", with_line(with_line(rows, tet_line(20001), tet(3)), tet_line(15000), tet(5)),
       tet_line(15000), "tetrahedron 15000 (" + tet(5).substr(0, tet(5).size() - 2) + ") repeats tetrahedron 5"},
      {"two_flat.mesh", with_line(with_line(rows, tet_line(20000), other_flat), tet_line(12000), flat), tet_line(12000),
       "tetrahedron 12000 (1 2 19 18) is flat"},
  };
  for(const Case& c : cases)
  {
    std::string message[2];
    long at[2] = {0, 0};
    for(int k = 0; k < 2; ++k)
      try
      {
        read(c.name, c.text, k == 0 ? 1 : 4);
        ADD_FAILURE() << c.name << " was accepted";
      }
      catch(const Mesh_io_error& e)
      {
        message[k] = e.what();
        at[k] = e.line();
      }
    EXPECT_EQ(message[0], message[1]) << c.name;
    EXPECT_EQ(at[0], c.line) << c.name << ": " << message[0];
    EXPECT_EQ(at[1], c.line) << c.name << ": " << message[1];
    EXPECT_NE(message[0].find(c.words), std::string::npos) << c.name << ": " << message[0];
  }
}

TEST(MeditIO, MissingFile)
{
  EXPECT_THROW(CGAL::BODT_3::IO::read_medit((tmp_dir() / "does_not_exist.mesh").string()), Mesh_io_error);
}

TEST(CommandLine, BadInputsExitCleanlyAndLeaveNoOutput)
{
  auto inputs = bad_inputs();
  inputs.push_back({"does_not_exist.mesh", "", 0, "cannot open"});
  for(const auto& bad : inputs)
  {
    fs::path p = tmp_dir() / bad.name;
    if(bad.name != "does_not_exist.mesh") p = write_file(bad.name, bad.text);
    const fs::path out = tmp_dir() / ("out_" + bad.name);
    fs::remove(out);
    std::string output;
    const int status = run_bodt("convert " + p.string() + " " + out.string(), output);
    EXPECT_GT(status, 0) << bad.name;
    EXPECT_LT(status, 128) << bad.name;
    EXPECT_NE(output.find(p.string()), std::string::npos) << bad.name << ": " << output;
    EXPECT_NE(output.find(bad.words), std::string::npos) << bad.name << ": " << output;
    if(bad.line > 0)
    {
      EXPECT_NE(output.find(":" + std::to_string(bad.line) + ":"), std::string::npos) << bad.name << ": " << output;
    }
    EXPECT_FALSE(fs::exists(out)) << bad.name;
    for(const auto& f : fs::directory_iterator(tmp_dir()))
      EXPECT_EQ(f.path().string().find(".tmp."), std::string::npos) << f.path();

    const int qstatus = run_bodt("quality " + p.string(), output);
    EXPECT_GT(qstatus, 0) << bad.name;
    EXPECT_LT(qstatus, 128) << bad.name;
  }
}

TEST(CommandLine, FailedWriteKeepsExistingOutput)
{
  const fs::path good = write_file("good.mesh", good_mesh);
  const fs::path bad = write_file("bad.mesh", with_line(good_mesh, 7, "0 nan 0 1"));
  const fs::path out = write_file("existing_output.mesh", "precious");
  std::string output;
  EXPECT_EQ(run_bodt("convert " + bad.string() + " " + out.string(), output), 1);
  std::ifstream in(out);
  std::string content((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_EQ(content, "precious");
  EXPECT_EQ(run_bodt("convert " + good.string() + " " + out.string(), output), 0) << output;
  EXPECT_EQ(CGAL::BODT_3::IO::read_medit(out.string()).tets.size(), 2u);
}

TEST(CommandLine, UsageErrorsExitWithStatusTwo)
{
  std::string output;
  EXPECT_EQ(run_bodt("", output), 2);
  EXPECT_EQ(run_bodt("frobnicate", output), 2);
  EXPECT_EQ(run_bodt("quality", output), 2);
  EXPECT_EQ(run_bodt("quality a.mesh --bogus", output), 2);
  EXPECT_EQ(run_bodt("convert a.mesh out.xyz", output), 2);
  for(const char* cmd : {"quality", "convert"})
  {
    EXPECT_EQ(run_bodt(std::string(cmd) + " --help", output), 0);
    EXPECT_NE(output.find("Usage: bodt " + std::string(cmd)), std::string::npos) << output;
  }
}

TEST(CommandLine, QualityJsonOnGoodMesh)
{
  const fs::path good = write_file("good.mesh", good_mesh);
  std::string output;
  ASSERT_EQ(run_bodt("quality --json " + good.string(), output), 0) << output;
  const nlohmann::json j = nlohmann::json::parse(output);
  EXPECT_EQ(j.at("num_tets"), 2) << output;
  EXPECT_EQ(j.at("inverted_tets"), 0) << output;
}
