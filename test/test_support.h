// Helpers shared by the tests: scratch files, running the `bodt` tool, editing
// mesh text line by line, and a conforming grid of tetrahedra.
#ifndef BODT_TEST_SUPPORT_H
#define BODT_TEST_SUPPORT_H

#include <CGAL/BODT_3/Tet_mesh.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cstdint>
#include <cstring>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <vector>

namespace bodt_test {

namespace fs = std::filesystem;

/// A mesh from points and tetrahedra given in any orientation (each turned
/// positive), every tetrahedron labelled 1 unless `labels` says otherwise.
inline CGAL::BODT_3::Tet_mesh make_mesh(const std::vector<CGAL::BODT_3::Tet_mesh::Point>& points,
                                        std::vector<std::array<int, 4>> tets, std::vector<int> labels = {})
{
  CGAL::BODT_3::Tet_mesh m;
  m.points = points;
  m.vertex_refs.assign(points.size(), 0);
  for(auto& t : tets)
    if(CGAL::orientation(points[t[0]], points[t[1]], points[t[2]], points[t[3]]) == CGAL::NEGATIVE)
      std::swap(t[2], t[3]);
  m.tets = tets;
  m.tet_labels = labels.empty() ? std::vector<int>(tets.size(), 1) : labels;
  return m;
}

/// The running test's own scratch folder (under BODT_TEST_TMP), or a sub-folder
/// of it, created. One folder per test, because ctest runs the tests of one
/// executable in parallel.
inline fs::path tmp_dir(const std::string& sub = "")
{
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  const std::string test = info ? std::string(info->test_suite_name()) + "." + info->name() : "no_test";
  std::string folder;
  for(char ch : test) folder += (std::isalnum(static_cast<unsigned char>(ch)) || ch == '.') ? ch : '_';
  const fs::path d = fs::absolute(fs::path(BODT_TEST_TMP) / folder / sub);
  fs::create_directories(d);
  return d;
}

inline fs::path write_file(const std::string& name, const std::string& text)
{
  const fs::path p = tmp_dir() / name;
  std::ofstream(p, std::ios::binary) << text;
  return p;
}

inline std::string read_text(const fs::path& p)
{
  std::ifstream in(p, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

/// `text` with its line number `line` (1-based) replaced.
inline std::string with_line(const std::string& text, int line, const std::string& replacement)
{
  std::istringstream in(text);
  std::string out, l;
  for(int n = 1; std::getline(in, l); ++n) out += (n == line ? replacement : l) + "\n";
  return out;
}

inline std::string without_line(const std::string& text, int line)
{
  std::istringstream in(text);
  std::string out, l;
  for(int n = 1; std::getline(in, l); ++n)
    if(n != line) out += l + "\n";
  return out;
}

/// The first `line` lines of `text`.
inline std::string truncate_after_line(const std::string& text, int line)
{
  std::istringstream in(text);
  std::string out, l;
  for(int n = 1; n <= line && std::getline(in, l); ++n) out += l + "\n";
  return out;
}

inline std::string shell_quoted(const std::string& s) { return "'" + s + "'"; }
inline std::string shell_quoted(const fs::path& p) { return shell_quoted(p.string()); }

/// Runs the tool with `args`; returns its exit status (128 + signal if it was
/// killed) and fills `output` with what it printed on stdout and stderr.
inline int run_bodt(const std::string& args, std::string& output, const fs::path& dir = tmp_dir())
{
  const fs::path log = dir / "bodt_output.txt";
  const int status =
      std::system((std::string(BODT_BINARY) + " " + args + " > " + shell_quoted(log.string()) + " 2>&1").c_str());
  output = read_text(log);
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

/// What every supported format keeps: points bit for bit, tetrahedra, triangles and
/// edges with their labels, corners.
inline void expect_same_mesh_content(const CGAL::BODT_3::Tet_mesh& a, const CGAL::BODT_3::Tet_mesh& b)
{
  ASSERT_EQ(a.points.size(), b.points.size());
  for(std::size_t i = 0; i < a.points.size(); ++i)
    for(int c = 0; c < 3; ++c)
    {
      std::uint64_t x, y;
      const double ax = a.points[i][c], bx = b.points[i][c];
      std::memcpy(&x, &ax, sizeof x);
      std::memcpy(&y, &bx, sizeof y);
      EXPECT_EQ(x, y) << "vertex " << i << ", coordinate " << c;
    }
  EXPECT_EQ(a.tets, b.tets);
  EXPECT_EQ(a.tet_labels, b.tet_labels);
  EXPECT_EQ(a.triangles, b.triangles);
  EXPECT_EQ(a.triangle_labels, b.triangle_labels);
  EXPECT_EQ(a.edges, b.edges);
  EXPECT_EQ(a.edge_labels, b.edge_labels);
  EXPECT_EQ(a.corners, b.corners);
}

/// Index of grid point (i, j, k) in `cube_grid(n, ...)`.
inline int grid_index(int n, int i, int j, int k) { return (k * (n + 1) + j) * (n + 1) + i; }

/// The box [0, n]^3 of unit cubes, each split into the six tetrahedra around its
/// main diagonal (paths from corner (0,0,0) to (1,1,1) along the axes), which
/// makes a conforming mesh; every tetrahedron is positively oriented and labelled
/// `label(i, j, k)` after its cube.
template <class Label>
CGAL::BODT_3::Tet_mesh cube_grid(int n, Label label)
{
  CGAL::BODT_3::Tet_mesh m;
  for(int k = 0; k <= n; ++k)
    for(int j = 0; j <= n; ++j)
      for(int i = 0; i <= n; ++i) m.points.emplace_back(i, j, k);
  m.vertex_refs.assign(m.points.size(), 0);
  for(int k = 0; k < n; ++k)
    for(int j = 0; j < n; ++j)
      for(int i = 0; i < n; ++i)
      {
        std::array<int, 3> axes{0, 1, 2};
        do
        {
          std::array<int, 3> c{i, j, k};
          std::array<int, 4> t{};
          t[0] = grid_index(n, c[0], c[1], c[2]);
          for(int s = 0; s < 3; ++s)
          {
            ++c[axes[s]];
            t[s + 1] = grid_index(n, c[0], c[1], c[2]);
          }
          if(CGAL::orientation(m.points[t[0]], m.points[t[1]], m.points[t[2]], m.points[t[3]]) != CGAL::POSITIVE)
            std::swap(t[2], t[3]);
          m.tets.push_back(t);
          m.tet_labels.push_back(label(i, j, k));
        } while(std::next_permutation(axes.begin(), axes.end()));
      }
  return m;
}

/// Two `cube_grid(n, ...)` grids, the second moved by `shift` (whole cubes), sharing
/// the points they have in common: with a shift of (n, n, 0) they share an edge of
/// the box, with (n, n, n) a corner, and no triangulation can hold them.
inline CGAL::BODT_3::Tet_mesh touching_grids(int n, const std::array<int, 3>& shift)
{
  CGAL::BODT_3::Tet_mesh m = cube_grid(n, [](int, int, int) { return 1; });
  const CGAL::BODT_3::Tet_mesh second = m;
  std::vector<int> number;
  for(const auto& p : second.points)
  {
    const CGAL::BODT_3::Tet_mesh::Point moved(p.x() + shift[0], p.y() + shift[1], p.z() + shift[2]);
    const auto at = std::find(m.points.begin(), m.points.end(), moved);
    number.push_back(static_cast<int>(at - m.points.begin()));
    if(at == m.points.end())
    {
      m.points.push_back(moved);
      m.vertex_refs.push_back(0);
    }
  }
  for(const auto& t : second.tets)
  {
    m.tets.push_back({number[t[0]], number[t[1]], number[t[2]], number[t[3]]});
    m.tet_labels.push_back(1);
  }
  return m;
}

} // namespace bodt_test

#endif // BODT_TEST_SUPPORT_H
