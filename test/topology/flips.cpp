// Topology optimization on constructed configurations: each flip kind through
// the flip pass (labels, volume, validity, the better configuration chosen, exact
// coplanarity refused when off by one ulp, curve edges and interfaces kept), and
// Edge_removal and Multi_face_removal called directly (their proposals against a
// brute-force search, then applied: validity by exact orientation, exact volumes,
// labels, the worst cell raised). The flips over CGAL-meshed inputs, through the
// whole pipeline, are tested in pipeline/smoothing.cpp.
#include "c3t3_checks.h"
#include "test_support.h"
#include "exact_volumes.h"

#include <CGAL/BODT_3/Tet_mesh_conversion.h>
#include <CGAL/BODT_3/internal/Quality/dihedral_angles.h>
#include <CGAL/BODT_3/internal/Topology/Edge_contraction.h>
#include <CGAL/BODT_3/internal/Topology/Edge_removal.h>
#include <CGAL/BODT_3/internal/Topology/Multi_face_removal.h>
#include <CGAL/BODT_3/internal/Topology/flip_pass.h>
#include <CGAL/BODT_3/internal/Topology/replace_cells.h>
#include <CGAL/BODT_3/internal/Quality/tet_quality.h>

#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Random.h>

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <map>
#include <random>
#include <set>
#include <vector>

namespace BODT = CGAL::BODT_3;
using BODT::Tet_mesh;
using Point = Tet_mesh::Point;
using File_c3t3 = BODT::Tet_mesh_c3t3;
using Vertex_handle = File_c3t3::Vertex_handle;

using bodt_test::bare;
using bodt_test::expect_valid;

namespace {

constexpr double kPi = 3.14159265358979323846;

// The minimum sine of the six dihedral angles, from the angles themselves.
double brute_min_sine(const Point& a, const Point& b, const Point& c, const Point& d)
{
  double q = 2;
  for(double deg : BODT::internal::dihedral_angles(a, b, c, d)) q = std::min(q, std::sin(deg * kPi / 180));
  return q;
}

using bodt_test::make_mesh;

double worst_of(const std::vector<Point>& p, const std::vector<std::array<int, 4>>& tets)
{
  double q = 2;
  for(const auto& t : tets) q = std::min(q, brute_min_sine(p[t[0]], p[t[1]], p[t[2]], p[t[3]]));
  return q;
}

struct Built
{
  File_c3t3 c3t3;
  std::vector<Vertex_handle> handles;
};

void build(const Tet_mesh& m, Built& b) { BODT::tet_mesh_to_c3t3(m, b.c3t3, "test", &b.handles); }

// One flip pass over every cell of the mesh (quality threshold 1).
BODT::Topology_stats flip_all(File_c3t3& c3t3)
{
  BODT::internal::C3t3_adapter<File_c3t3> adapter(c3t3);
  std::map<Vertex_handle, int> ids;
  for(auto v = c3t3.triangulation().finite_vertices_begin(); v != c3t3.triangulation().finite_vertices_end(); ++v)
    ids.emplace(v, static_cast<int>(ids.size()));
  BODT::Flip_options opt;
  opt.quality_threshold = 1.0;
  std::vector<Vertex_handle> touched;
  return BODT::internal::flip_pass(adapter, opt, BODT::internal::Dihedral_bounds(), [&](Vertex_handle v) { return ids.at(v); },
                         touched);
}

// What flips must keep, and the quality they must raise.
struct Snapshot
{
  std::map<int, double> volume;                        // per subdomain
  std::map<int, double> patch_area;                    // per surface patch
  std::set<std::pair<std::array<Point, 3>, int>> facets;   // sorted points, patch
  double worst = 2;                                    // minimum dihedral sine of the mesh cells
  std::size_t cells = 0;
};

std::array<Point, 3> sorted_points(Point a, Point b, Point c)
{
  std::array<Point, 3> t = {a, b, c};
  std::sort(t.begin(), t.end());
  return t;
}

Snapshot snapshot(const File_c3t3& c3t3)
{
  Snapshot s;
  for(auto c = c3t3.cells_in_complex_begin(); c != c3t3.cells_in_complex_end(); ++c)
  {
    const Point p[4] = {bare(c3t3, c->vertex(0)), bare(c3t3, c->vertex(1)), bare(c3t3, c->vertex(2)),
                        bare(c3t3, c->vertex(3))};
    s.volume[c3t3.subdomain_index(c)] += CGAL::volume(p[0], p[1], p[2], p[3]);
    s.worst = std::min(s.worst, brute_min_sine(p[0], p[1], p[2], p[3]));
    ++s.cells;
  }
  for(auto f = c3t3.facets_in_complex_begin(); f != c3t3.facets_in_complex_end(); ++f)
  {
    Point p[3];
    for(int k = 0, m = 0; k < 4; ++k)
      if(k != f->second) p[m++] = bare(c3t3, f->first->vertex(k));
    const int patch = c3t3.surface_patch_index(*f);
    s.patch_area[patch] += std::sqrt(CGAL::squared_area(p[0], p[1], p[2]));
    s.facets.insert({sorted_points(p[0], p[1], p[2]), patch});
  }
  return s;
}

void expect_kept(const Snapshot& before, const Snapshot& after, bool same_facets = true)
{
  ASSERT_EQ(before.volume.size(), after.volume.size());
  for(const auto& kv : before.volume)
    EXPECT_NEAR(after.volume.at(kv.first), kv.second, 1e-14 * std::abs(kv.second)) << "subdomain " << kv.first;
  for(const auto& kv : before.patch_area)
    EXPECT_NEAR(after.patch_area.at(kv.first), kv.second, 1e-12 * kv.second) << "patch " << kv.first;
  if(same_facets)
  {
    EXPECT_EQ(before.facets, after.facets);
  }
}

// Cells (u, v, r_k, r_{k+1}) around the axis edge u v of a ring of m points on the
// unit circle at z = 0, with u and v at heights -h and +h.
std::vector<Point> ring_points(int m, double h)
{
  std::vector<Point> p = {Point(0, 0, -h), Point(0, 0, h)};
  for(int k = 0; k < m; ++k) p.emplace_back(std::cos(2 * kPi * k / m), std::sin(2 * kPi * k / m), 0);
  return p;
}
std::vector<std::array<int, 4>> around_edge(int m)
{
  std::vector<std::array<int, 4>> t;
  for(int k = 0; k < m; ++k) t.push_back({0, 1, 2 + k, 2 + (k + 1) % m});
  return t;
}
// The same region as a fan triangulation of the ring with both apexes.
std::vector<std::array<int, 4>> fan(int m)
{
  std::vector<std::array<int, 4>> t;
  for(int k = 1; k + 1 < m; ++k)
  {
    t.push_back({1, 2, 2 + k, 2 + k + 1});
    t.push_back({0, 2, 2 + k, 2 + k + 1});
  }
  return t;
}

} // namespace

// Edge removal, the 3-2 flip among them: the ring around an axis edge, for
// several heights; the pass ends in the better of the two configurations.
TEST(FlipPass, EdgeRemovalChoosesTheBetterConfiguration)
{
  for(int m : {3, 4, 5, 6, 7})
    for(double h : {0.15, 0.4, 0.8, 1.5, 3.0})
    {
      SCOPED_TRACE("ring " + std::to_string(m) + ", height " + std::to_string(h));
      const auto p = ring_points(m, h);
      Built b;
      build(make_mesh(p, around_edge(m)), b);
      const Snapshot before = snapshot(b.c3t3);
      const auto stats = flip_all(b.c3t3);
      expect_valid(b.c3t3);
      const Snapshot after = snapshot(b.c3t3);
      expect_kept(before, after);
      const bool removed = !b.c3t3.triangulation().tds().is_edge(b.handles[0], b.handles[1]);
      if(worst_of(p, fan(m)) > before.worst + 1e-9) { EXPECT_TRUE(removed); }   // a better one exists
      if(removed)
      {
        EXPECT_GT(after.worst, before.worst);
        EXPECT_EQ(after.cells, 2u * (m - 2));
        EXPECT_GE(m == 3 ? stats.flips_3_2 : stats.edge_removals, 1u);
      }
      else
        EXPECT_EQ(after.worst, before.worst);
    }
}

// Multi-face removal, the 2-3 flip among them: the ring triangulated, with an apex on
// each side; where the cells around a new axis edge are better, the faces go.
TEST(FlipPass, MultiFaceRemovalChoosesTheBetterConfiguration)
{
  int created = 0;
  BODT::Topology_stats all;
  for(int m : {3, 4, 5})
    for(double h : {0.1, 0.2, 0.4, 0.8, 1.5})
    {
      SCOPED_TRACE("ring " + std::to_string(m) + ", height " + std::to_string(h));
      const auto p = ring_points(m, h);
      Built b;
      build(make_mesh(p, fan(m)), b);
      const Snapshot before = snapshot(b.c3t3);
      const auto stats = flip_all(b.c3t3);
      expect_valid(b.c3t3);
      const Snapshot after = snapshot(b.c3t3);
      expect_kept(before, after);
      const bool made = b.c3t3.triangulation().tds().is_edge(b.handles[0], b.handles[1]);
      if(made)
      {
        ++created;
        // Every flip raises the worst cell of the cells it replaces; the mesh's worst
        // rises too unless a cell as bad stays outside them, as in the symmetric ring
        // 4 at height 1.5.
        EXPECT_GE(after.worst, before.worst);
        EXPECT_EQ(after.cells, static_cast<std::size_t>(m));
        if(m == 3) { EXPECT_EQ(stats.flips_2_3, 1u); }
      }
      all += stats;
      // The pass ends at least as well as both configurations it can reach.
      if(worst_of(p, around_edge(m)) > before.worst + 1e-9)
      {
        EXPECT_GE(after.worst, worst_of(p, around_edge(m)) - 1e-9);
      }
    }
  EXPECT_GT(created, 3);
  EXPECT_GT(all.flips_2_3, 0u);
  EXPECT_GT(all.multi_face_removals, 0u);
}

// A flip never crosses an interface: the same ring, cells of two subdomains.
TEST(FlipPass, NothingAcrossAnInterface)
{
  const int m = 4;
  const auto p = ring_points(m, 3.0);   // edge removal would help (see above)
  ASSERT_GT(worst_of(p, fan(m)), worst_of(p, around_edge(m)));
  Built b;
  build(make_mesh(p, around_edge(m), {1, 1, 2, 2}), b);
  const Snapshot before = snapshot(b.c3t3);
  const auto stats = flip_all(b.c3t3);
  expect_valid(b.c3t3);
  expect_kept(before, snapshot(b.c3t3));
  EXPECT_EQ(stats.total(), 0u);
  EXPECT_TRUE(b.c3t3.triangulation().tds().is_edge(b.handles[0], b.handles[1]));
}

// A curve edge is never removed.
TEST(FlipPass, CurveEdgesStay)
{
  const int m = 5;
  const auto p = ring_points(m, 3.0);
  ASSERT_GT(worst_of(p, fan(m)), worst_of(p, around_edge(m)));
  Tet_mesh mesh = make_mesh(p, around_edge(m));
  mesh.edges.push_back({0, 1});
  mesh.edge_labels.push_back(1);
  Built b;
  build(mesh, b);
  const auto stats = flip_all(b.c3t3);
  expect_valid(b.c3t3);
  EXPECT_EQ(stats.flips_3_2 + stats.edge_removals, 0u);
  EXPECT_TRUE(b.c3t3.is_in_complex(b.handles[0], b.handles[1]));
}

namespace {

// Two thin boundary triangles (a, b, c) and (a, c, d) in the plane z = 0 (or d
// lifted by `dz`), under an apex x, and (when `below`) a second subdomain with
// apex y under the plane. The diagonal b d is much better than a c.
Tet_mesh coplanar_pair(double dz, bool below)
{
  std::vector<Point> p = {Point(-1, 0, 0), Point(0, -0.3, 0), Point(1, 0, 0), Point(0, 0.3, dz), Point(0.05, 0.02, 0.6),
                          Point(-0.05, 0.03, -0.6)};
  std::vector<std::array<int, 4>> t = {{0, 1, 2, 4}, {0, 2, 3, 4}};
  std::vector<int> labels = {1, 1};
  if(below)
  {
    t.push_back({0, 1, 2, 5});
    t.push_back({0, 2, 3, 5});
    labels.push_back(2);
    labels.push_back(2);
  }
  return make_mesh(p, t, labels);
}

} // namespace

// On the boundary: the 2-2 flip of two exactly coplanar facets of one patch (4-4
// with the infinite cells beyond), which keeps the surface; refused when one point
// is off the plane by one ulp.
TEST(FlipPass, CoplanarBoundaryFacetsFlipAndOneUlpOffDoesNot)
{
  for(bool below : {false, true})
  {
    SCOPED_TRACE(below ? "interface between two subdomains" : "boundary");
    Built b;
    build(coplanar_pair(0, below), b);
    const Snapshot before = snapshot(b.c3t3);
    const auto stats = flip_all(b.c3t3);
    expect_valid(b.c3t3);
    const Snapshot after = snapshot(b.c3t3);
    expect_kept(before, after, false);
    EXPECT_GE(stats.boundary_flips, 1u);
    EXPECT_GT(after.worst, before.worst);
    EXPECT_FALSE(b.c3t3.triangulation().tds().is_edge(b.handles[0], b.handles[2]));   // a c gone
    EXPECT_TRUE(b.c3t3.triangulation().tds().is_edge(b.handles[1], b.handles[3]));    // b d made
    // The interface or boundary now holds (a, b, d) and (b, c, d) instead.
    std::size_t in_plane = 0;
    for(const auto& f : after.facets)
      if(f.first[0].z() == 0 && f.first[1].z() == 0 && f.first[2].z() == 0) ++in_plane;
    EXPECT_EQ(in_plane, 2u);

    const double ulp = std::nextafter(0.0, 1.0);
    Built off;
    build(coplanar_pair(ulp, below), off);
    ASSERT_NE(CGAL::orientation(Point(-1, 0, 0), Point(0, -0.3, 0), Point(1, 0, 0), Point(0, 0.3, ulp)),
              CGAL::COPLANAR);
    const Snapshot off_before = snapshot(off.c3t3);
    const auto off_stats = flip_all(off.c3t3);
    expect_valid(off.c3t3);
    expect_kept(off_before, snapshot(off.c3t3));
    EXPECT_EQ(off_stats.boundary_flips, 0u);
    EXPECT_TRUE(off.c3t3.triangulation().tds().is_edge(off.handles[0], off.handles[2]));
  }
}

// ---------------------------------------------------------------------------
// Edge_removal and Multi_face_removal called directly, on the ring configurations:
// the proposal (its cells, its worst cell against a brute-force search), then
// `replace_cells` with it, and what must hold after: validity by CGAL's exact
// orientation, every subdomain's volume exactly, labels and complex facets kept,
// the replaced region's worst cell raised.

namespace {

using Adapter = BODT::internal::C3t3_adapter<File_c3t3>;
using Context = BODT::internal::Flip_context<Adapter>;
using Flip = BODT::internal::Flip<Adapter>;
using Cell_handle = File_c3t3::Cell_handle;
using bodt_test::Exact;
using bodt_test::exact_subdomain_volumes;

// The labels of the complex's cells, as a multiset per subdomain.
std::map<int, std::size_t> cells_per_subdomain(const File_c3t3& c3t3)
{
  std::map<int, std::size_t> n;
  for(auto c = c3t3.cells_in_complex_begin(); c != c3t3.cells_in_complex_end(); ++c) ++n[c3t3.subdomain_index(c)];
  return n;
}

// The new cells of a proposal: each finite one positively oriented (exact
// predicate); returns their worst quality by the brute-force measure.
double check_new_cells(const File_c3t3& c3t3, const Flip& flip)
{
  double worst = 2;
  for(const auto& n : flip.new_cells)
  {
    const Point p[4] = {bare(c3t3, n.vertices[0]), bare(c3t3, n.vertices[1]), bare(c3t3, n.vertices[2]),
                        bare(c3t3, n.vertices[3])};
    EXPECT_EQ(CGAL::orientation(p[0], p[1], p[2], p[3]), CGAL::POSITIVE);
    worst = std::min(worst, brute_min_sine(p[0], p[1], p[2], p[3]));
  }
  return worst;
}

double worst_of_cells(const File_c3t3& c3t3, const std::vector<Cell_handle>& cells)
{
  double worst = 2;
  for(const Cell_handle& c : cells)
    worst = std::min(worst, brute_min_sine(bare(c3t3, c->vertex(0)), bare(c3t3, c->vertex(1)), bare(c3t3, c->vertex(2)),
                                           bare(c3t3, c->vertex(3))));
  return worst;
}

// Applies the proposal and checks what flips must keep: validity, every
// subdomain's volume exactly, its number of cells by the flip's count, the
// complex's facets (unless the flip adds some), the replaced region's worst cell
// raised to the proposal's, and the mesh's worst cell not lowered.
void apply_and_check(Built& b, Adapter& adapter, const Flip& flip, bool same_facets = true)
{
  const Snapshot before = snapshot(b.c3t3);
  const auto volumes = exact_subdomain_volumes(b.c3t3);
  const auto counts = cells_per_subdomain(b.c3t3);
  const double old_region = worst_of_cells(b.c3t3, flip.old_cells);
  EXPECT_NEAR(old_region, flip.old_worst, 1e-9);
  std::vector<Cell_handle> created;
  ASSERT_TRUE(BODT::internal::replace_cells(adapter, flip.old_cells, flip.new_cells, flip.new_facets, &created));
  ASSERT_EQ(created.size(), flip.new_cells.size());
  expect_valid(b.c3t3);
  const Snapshot after = snapshot(b.c3t3);
  expect_kept(before, after, same_facets);
  EXPECT_TRUE(exact_subdomain_volumes(b.c3t3) == volumes) << "a subdomain's exact volume changed";
  std::size_t total = 0, total_before = 0;
  for(const auto& kv : cells_per_subdomain(b.c3t3))
  {
    EXPECT_TRUE(counts.count(kv.first)) << "a new label " << kv.first;
    total += kv.second;
  }
  for(const auto& kv : counts) total_before += kv.second;
  EXPECT_EQ(total + flip.old_cells.size(), total_before + flip.new_cells.size());
  const double new_region = worst_of_cells(b.c3t3, created);
  EXPECT_GT(new_region, old_region);
  EXPECT_NEAR(new_region, flip.new_worst, 1e-9);
  EXPECT_GE(after.worst, before.worst);
}

// Every triangulation of the polygon a .. c (indices into the ring), by brute force.
std::vector<std::vector<std::array<int, 3>>> triangulations(int a, int c)
{
  if(c - a < 2) return {{}};
  std::vector<std::vector<std::array<int, 3>>> all;
  for(int b = a + 1; b < c; ++b)
    for(const auto& left : triangulations(a, b))
      for(const auto& right : triangulations(b, c))
      {
        auto t = left;
        t.insert(t.end(), right.begin(), right.end());
        t.push_back({a, b, c});
        all.push_back(t);
      }
  return all;
}

// The best worst cell of the cells (r_a, r_b, r_c, v) and (r_c, r_b, r_a, u) over
// every triangulation of the ring whose cells are all positively oriented (exact
// predicate): what edge removal must find (-1 if none is valid).
double best_ring_triangulation(const std::vector<Point>& p, int m)
{
  double best = -1;
  for(const auto& t : triangulations(0, m - 1))
  {
    double worst = 2;
    for(const auto& x : t)
    {
      const Point &a = p[2 + x[0]], &b = p[2 + x[1]], &c = p[2 + x[2]];
      if(CGAL::orientation(a, b, c, p[1]) != CGAL::POSITIVE || CGAL::orientation(c, b, a, p[0]) != CGAL::POSITIVE)
        worst = -1;
      else
        worst = std::min({worst, brute_min_sine(a, b, c, p[1]), brute_min_sine(c, b, a, p[0])});
    }
    best = std::max(best, worst);
  }
  return best;
}

// ring_points(m, h) made irregular: the ring's points moved along the circle, in
// and out, and up and down (seeded), so that one triangulation is the best.
std::vector<Point> irregular_ring_points(int m, double h, CGAL::Random& rng)
{
  std::vector<Point> p = {Point(0, 0, -h), Point(0, 0, h)};
  for(int k = 0; k < m; ++k)
  {
    const double a = 2 * kPi * (k + rng.get_double(-0.25, 0.25)) / m, r = rng.get_double(0.7, 1.3);
    p.emplace_back(r * std::cos(a), r * std::sin(a), rng.get_double(-0.05, 0.05));
  }
  return p;
}

Cell_handle cell_of(const File_c3t3& c3t3, Vertex_handle a, Vertex_handle b, Vertex_handle c, Vertex_handle d)
{
  Cell_handle cell;
  int i, j, k, l;
  EXPECT_TRUE(c3t3.triangulation().tds().is_cell(a, b, c, d, cell, i, j, k, l));
  return cell;
}

Cell_handle cell_of_edge(const File_c3t3& c3t3, Vertex_handle a, Vertex_handle b, int& i, int& j)
{
  Cell_handle c;
  EXPECT_TRUE(c3t3.triangulation().tds().is_edge(a, b, c, i, j));
  return c;
}

} // namespace

// The 3-2 flip: the three cells around an edge become the two on its ring's triangle.
TEST(EdgeRemoval, RemovesEdgeOfThreeRing)
{
  const auto p = ring_points(3, 1.0);
  ASSERT_GT(worst_of(p, fan(3)), worst_of(p, around_edge(3)) + 0.05);
  Built b;
  build(make_mesh(p, around_edge(3)), b);
  Adapter adapter(b.c3t3, false);
  const Context ctx(adapter, BODT::internal::Dihedral_bounds(), false);
  int i, j;
  const Cell_handle c = cell_of_edge(b.c3t3, b.handles[0], b.handles[1], i, j);
  Flip flip;
  ASSERT_TRUE(BODT::internal::Edge_removal<Adapter>()(ctx, c, i, j, flip));
  EXPECT_EQ(flip.kind, BODT::internal::Flip_kind::flip_3_2);
  EXPECT_FALSE(flip.boundary);
  EXPECT_EQ(flip.old_cells.size(), 3u);
  EXPECT_EQ(flip.new_cells.size(), 2u);
  EXPECT_TRUE(flip.new_facets.empty());
  EXPECT_TRUE(flip.improves());
  EXPECT_NEAR(flip.old_worst, worst_of(p, around_edge(3)), 1e-9);
  EXPECT_NEAR(flip.new_worst, worst_of(p, fan(3)), 1e-9);
  EXPECT_NEAR(check_new_cells(b.c3t3, flip), flip.new_worst, 1e-9);
  apply_and_check(b, adapter, flip);
  EXPECT_FALSE(b.c3t3.triangulation().tds().is_edge(b.handles[0], b.handles[1]));
  EXPECT_EQ(b.c3t3.number_of_cells_in_complex(), 2u);
}

// Rings of 4 to 7 cells at several heights, regular and irregular: the proposal's
// worst cell is the best over every triangulation of the ring (brute force), the
// removed cells' worst is the old one, and an improving proposal, applied, keeps
// validity, volume and labels.
TEST(EdgeRemoval, FindsTheBestTriangulationOfTheRing)
{
  CGAL::Random rng(29);
  int improved = 0, improved_irregular = 0, declined = 0;
  for(bool irregular : {false, true})
    for(int m : {4, 5, 6, 7})
      for(double h : {0.15, 0.4, 0.8, 1.5, 2.0, 3.0, 5.0})
      {
        SCOPED_TRACE(std::string(irregular ? "irregular " : "") + "ring " + std::to_string(m) + ", height " +
                     std::to_string(h));
        const auto p = irregular ? irregular_ring_points(m, h, rng) : ring_points(m, h);
        Built b;
        build(make_mesh(p, around_edge(m)), b);
        expect_valid(b.c3t3);
        Adapter adapter(b.c3t3, false);
        const Context ctx(adapter, BODT::internal::Dihedral_bounds(), false);
        int i, j;
        const Cell_handle c = cell_of_edge(b.c3t3, b.handles[0], b.handles[1], i, j);
        Flip flip;
        const bool proposed = BODT::internal::Edge_removal<Adapter>()(ctx, c, i, j, flip);
        const double old_worst = worst_of(p, around_edge(m)), best = best_ring_triangulation(p, m);
        if(best > old_worst + 1e-9)
        {
          ASSERT_TRUE(proposed);
          EXPECT_EQ(flip.kind, BODT::internal::Flip_kind::edge_removal);
          EXPECT_EQ(flip.old_cells.size(), static_cast<std::size_t>(m));
          EXPECT_EQ(flip.new_cells.size(), 2u * (m - 2));
          EXPECT_NEAR(flip.old_worst, old_worst, 1e-9);
          EXPECT_NEAR(flip.new_worst, best, 1e-9);
          EXPECT_NEAR(check_new_cells(b.c3t3, flip), flip.new_worst, 1e-9);
          ASSERT_TRUE(flip.improves());
          apply_and_check(b, adapter, flip);
          EXPECT_FALSE(b.c3t3.triangulation().tds().is_edge(b.handles[0], b.handles[1]));
          ++(irregular ? improved_irregular : improved);
        }
        else if(best < old_worst - 1e-9)
        {
          EXPECT_TRUE(!proposed || !flip.improves());
          ++declined;
        }
      }
  EXPECT_GE(improved, 5);
  EXPECT_GE(improved_irregular, 5);
  EXPECT_GE(declined, 20);
}

// Two subdomains meeting on the exactly planar interface y = 0 through the edge:
// both sides are triangulated apart with the chord r_0 r_2, whose two facets enter
// the complex; the interface keeps its area and each subdomain its exact volume.
// With r_2 off the plane by one ulp, nothing is proposed.
TEST(EdgeRemoval, FlipsAnExactlyPlanarInterfaceAndKeepsBothVolumes)
{
  const double h = 3.0;
  const std::vector<Point> p = {Point(0, 0, -h), Point(0, 0, h), Point(1, 0, 0), Point(0, 1, 0), Point(-1, 0, 0),
                                Point(0, -1, 0)};
  ASSERT_EQ(CGAL::orientation(p[0], p[1], p[2], p[4]), CGAL::COPLANAR);
  ASSERT_GT(worst_of(p, fan(4)), worst_of(p, around_edge(4)) + 0.05);
  Built b;
  build(make_mesh(p, around_edge(4), {1, 1, 2, 2}), b);
  Adapter adapter(b.c3t3, false);
  const Context ctx(adapter, BODT::internal::Dihedral_bounds(), false);
  int i, j;
  const Cell_handle c = cell_of_edge(b.c3t3, b.handles[0], b.handles[1], i, j);
  Flip flip;
  ASSERT_TRUE(BODT::internal::Edge_removal<Adapter>()(ctx, c, i, j, flip));
  EXPECT_TRUE(flip.boundary);
  EXPECT_EQ(flip.kind, BODT::internal::Flip_kind::edge_removal);
  EXPECT_EQ(flip.old_cells.size(), 4u);
  EXPECT_EQ(flip.new_cells.size(), 4u);
  ASSERT_EQ(flip.new_facets.size(), 2u);
  EXPECT_TRUE(flip.improves());
  EXPECT_NEAR(check_new_cells(b.c3t3, flip), flip.new_worst, 1e-9);
  // Each new cell takes the subdomain of a cell on its side of the interface.
  for(const auto& n : flip.new_cells)
  {
    double y = 0;
    for(const auto& v : n.vertices) y += bare(b.c3t3, v).y();
    EXPECT_EQ(b.c3t3.subdomain_index(flip.old_cells[n.region_of]), y > 0 ? 1 : 2);
  }
  const auto facets_before = snapshot(b.c3t3).facets;
  apply_and_check(b, adapter, flip, false);
  EXPECT_TRUE(b.c3t3.triangulation().tds().is_edge(b.handles[2], b.handles[4]));
  // The interface is still the square u r_0 v r_2, now as (u, r_0, r_2) and (v, r_0, r_2).
  std::size_t interface_facets = 0;
  for(const auto& f : snapshot(b.c3t3).facets)
    if(f.first[0].y() == 0 && f.first[1].y() == 0 && f.first[2].y() == 0)
    {
      ++interface_facets;
      EXPECT_FALSE(facets_before.count(f));
    }
  EXPECT_EQ(interface_facets, 2u);

  auto off = p;
  off[4] = Point(-1, std::nextafter(0.0, 1.0), 0);
  ASSERT_NE(CGAL::orientation(off[0], off[1], off[2], off[4]), CGAL::COPLANAR);
  Built o;
  build(make_mesh(off, around_edge(4), {1, 1, 2, 2}), o);
  Adapter off_adapter(o.c3t3, false);
  const Context off_ctx(off_adapter, BODT::internal::Dihedral_bounds(), false);
  const Cell_handle oc = cell_of_edge(o.c3t3, o.handles[0], o.handles[1], i, j);
  EXPECT_FALSE(BODT::internal::Edge_removal<Adapter>()(off_ctx, oc, i, j, flip));
}

// A curve edge is never proposed for removal, however much it would help.
TEST(EdgeRemoval, RefusesACurveEdge)
{
  const auto p = ring_points(5, 3.0);
  for(bool curve : {false, true})
  {
    Tet_mesh mesh = make_mesh(p, around_edge(5));
    if(curve)
    {
      mesh.edges.push_back({0, 1});
      mesh.edge_labels.push_back(1);
    }
    Built b;
    build(mesh, b);
    Adapter adapter(b.c3t3, false);
    const Context ctx(adapter, BODT::internal::Dihedral_bounds(), false);
    int i, j;
    const Cell_handle c = cell_of_edge(b.c3t3, b.handles[0], b.handles[1], i, j);
    Flip flip;
    const bool proposed = BODT::internal::Edge_removal<Adapter>()(ctx, c, i, j, flip);
    if(curve) { EXPECT_FALSE(proposed); }
    else { EXPECT_TRUE(proposed && flip.improves()); }
  }
}

// The 2-3 flip: two cells on a face become three around the new edge of their apexes.
TEST(MultiFaceRemoval, TwoThreeFlipOfOneFace)
{
  const auto p = ring_points(3, 0.2);
  ASSERT_GT(worst_of(p, around_edge(3)), worst_of(p, fan(3)) + 0.05);
  Built b;
  build(make_mesh(p, fan(3)), b);
  Adapter adapter(b.c3t3, false);
  const Context ctx(adapter, BODT::internal::Dihedral_bounds(), false);
  ASSERT_FALSE(b.c3t3.triangulation().tds().is_edge(b.handles[0], b.handles[1]));
  const Cell_handle c = cell_of(b.c3t3, b.handles[1], b.handles[2], b.handles[3], b.handles[4]);
  ASSERT_NE(c, Cell_handle());
  Flip flip;
  ASSERT_TRUE(BODT::internal::Multi_face_removal<Adapter>()(ctx, c, c->index(b.handles[1]), flip));
  EXPECT_EQ(flip.kind, BODT::internal::Flip_kind::flip_2_3);
  EXPECT_EQ(flip.old_cells.size(), 2u);
  EXPECT_EQ(flip.new_cells.size(), 3u);
  EXPECT_TRUE(flip.new_facets.empty());
  EXPECT_TRUE(flip.improves());
  EXPECT_NEAR(flip.old_worst, worst_of(p, fan(3)), 1e-9);
  EXPECT_NEAR(flip.new_worst, worst_of(p, around_edge(3)), 1e-9);
  EXPECT_NEAR(check_new_cells(b.c3t3, flip), flip.new_worst, 1e-9);
  EXPECT_NEAR(worst_of_cells(b.c3t3, flip.old_cells), flip.old_worst, 1e-9);
  apply_and_check(b, adapter, flip);
  EXPECT_TRUE(b.c3t3.triangulation().tds().is_edge(b.handles[0], b.handles[1]));
  EXPECT_EQ(b.c3t3.number_of_cells_in_complex(), 3u);
}

// Flat rings of 4 and 5 triangulated as fans: the removal of faces of the sandwich
// creates the axis edge; k faces removed give k + 2 cells for 2 k, the proposal is
// at least as good as removing them all (the cells around the axis edge), and
// applied it keeps validity, volume and labels.
TEST(MultiFaceRemoval, RemovesTheSandwichOfAFlatRing)
{
  for(int m : {4, 5})
    for(double h : {0.1, 0.2})
    {
      SCOPED_TRACE("ring " + std::to_string(m) + ", height " + std::to_string(h));
      const auto p = ring_points(m, h);
      ASSERT_GT(worst_of(p, around_edge(m)), worst_of(p, fan(m)) + 0.01);
      Built b;
      build(make_mesh(p, fan(m)), b);
      Adapter adapter(b.c3t3, false);
      const Context ctx(adapter, BODT::internal::Dihedral_bounds(), false);
      // The root: the fan's middle face, under the apex v.
      const int k = (m - 1) / 2;
      const Cell_handle c = cell_of(b.c3t3, b.handles[1], b.handles[2], b.handles[2 + k], b.handles[2 + k + 1]);
      ASSERT_NE(c, Cell_handle());
      Flip flip;
      ASSERT_TRUE(BODT::internal::Multi_face_removal<Adapter>()(ctx, c, c->index(b.handles[1]), flip));
      // Removing one face of a ring of 4 would make a flat cell (u, v, r_0, r_2).
      if(m == 4) { EXPECT_EQ(flip.kind, BODT::internal::Flip_kind::multi_face_removal); }
      ASSERT_GE(flip.new_cells.size(), 3u);
      EXPECT_EQ(flip.old_cells.size(), 2 * (flip.new_cells.size() - 2));
      EXPECT_TRUE(flip.improves());
      EXPECT_GE(flip.new_worst, worst_of(p, around_edge(m)) - 1e-9);
      EXPECT_NEAR(flip.old_worst, worst_of_cells(b.c3t3, flip.old_cells), 1e-9);
      EXPECT_NEAR(check_new_cells(b.c3t3, flip), flip.new_worst, 1e-9);
      apply_and_check(b, adapter, flip);
      EXPECT_TRUE(b.c3t3.triangulation().tds().is_edge(b.handles[0], b.handles[1]));
    }
}

// A face between two subdomains is never removed.
TEST(MultiFaceRemoval, RefusesAFaceBetweenTwoSubdomains)
{
  const auto p = ring_points(3, 0.2);
  for(bool two : {false, true})
  {
    Built b;
    build(make_mesh(p, fan(3), two ? std::vector<int>{1, 2} : std::vector<int>{}), b);
    Adapter adapter(b.c3t3, false);
    const Context ctx(adapter, BODT::internal::Dihedral_bounds(), false);
    const Cell_handle c = cell_of(b.c3t3, b.handles[1], b.handles[2], b.handles[3], b.handles[4]);
    ASSERT_NE(c, Cell_handle());
    Flip flip;
    const bool proposed = BODT::internal::Multi_face_removal<Adapter>()(ctx, c, c->index(b.handles[1]), flip);
    if(two) { EXPECT_FALSE(proposed); }
    else { EXPECT_TRUE(proposed && flip.improves()); }
  }
}

// Edge contraction, constructed: the Delaunay tetrahedra of `points` (generic
// but for the square's corners), all of subdomain `label`.
std::vector<std::array<int, 4>> delaunay_tets(const std::vector<Point>& points)
{
  using K = CGAL::Kernel_traits<Point>::Kernel;
  CGAL::Delaunay_triangulation_3<K> dt;
  std::map<Point, int> index;
  for(std::size_t i = 0; i < points.size(); ++i)
  {
    dt.insert(points[i]);
    index[points[i]] = static_cast<int>(i);
  }
  std::vector<std::array<int, 4>> tets;
  for(auto c = dt.finite_cells_begin(); c != dt.finite_cells_end(); ++c)
    tets.push_back({index.at(c->vertex(0)->point()), index.at(c->vertex(1)->point()),
                    index.at(c->vertex(2)->point()), index.at(c->vertex(3)->point())});
  return tets;
}

// Applies a contraction and checks what it must keep: validity, every
// subdomain's exact volume, the complex's facets (or, with an interface in the
// plane, each patch's area), the vertex gone, and the worst cell raised.
void contract_and_check(Built& b, Adapter& adapter, const Flip& flip, Vertex_handle u, bool same_facets)
{
  const Snapshot before = snapshot(b.c3t3);
  const auto volumes = exact_subdomain_volumes(b.c3t3);
  const std::size_t vertices = b.c3t3.triangulation().number_of_vertices();
  EXPECT_NEAR(worst_of_cells(b.c3t3, flip.old_cells), flip.old_worst, 1e-9);
  EXPECT_NEAR(check_new_cells(b.c3t3, flip), flip.new_worst, 1e-9);
  std::vector<Cell_handle> created;
  ASSERT_TRUE(BODT::internal::replace_cells(adapter, flip.old_cells, flip.new_cells, flip.new_facets, &created,
                                            nullptr, {u}));
  expect_valid(b.c3t3);
  EXPECT_EQ(b.c3t3.triangulation().number_of_vertices(), vertices - 1);
  const Snapshot after = snapshot(b.c3t3);
  expect_kept(before, after, same_facets);
  EXPECT_TRUE(exact_subdomain_volumes(b.c3t3) == volumes) << "a subdomain's exact volume changed";
  EXPECT_GT(worst_of_cells(b.c3t3, created), flip.old_worst);
  EXPECT_GE(after.worst, before.worst);
}

// An interior vertex next to another makes flat cells; contracted onto it, they
// go, the cube keeps its exact volume and its boundary facets. Not along an
// edge of a curve, and never onto a vertex it shares no edge with (the link
// condition fails: the star would fold over the rest).
TEST(EdgeContraction, RemovesAnInteriorVertexAndKeepsTheExactVolumeAndTheBoundary)
{
  std::vector<Point> p;
  for(double x : {-1.0, 1.0})
    for(double y : {-1.0, 1.0})
      for(double z : {-1.0, 1.0}) p.emplace_back(x + 0.01 * y, y + 0.02 * z, z + 0.03 * x);
  p.emplace_back(0.11, 0.07, -0.13);   // w: 8
  p.emplace_back(0.16, 0.09, -0.10);   // u: 9, close to w
  p.emplace_back(-0.4, 0.35, 0.3);     // 10
  const auto tets = delaunay_tets(p);
  for(bool curve : {false, true})
  {
    SCOPED_TRACE(curve ? "u w on a curve" : "u inside");
    Tet_mesh mesh = make_mesh(p, tets);
    if(curve)
    {
      mesh.edges.push_back({8, 9});
      mesh.edge_labels.push_back(1);
    }
    Built b;
    build(mesh, b);
    Adapter adapter(b.c3t3, false);
    const Context ctx(adapter, BODT::internal::Dihedral_bounds(), false);
    const Vertex_handle u = b.handles[9], w = b.handles[8];
    ASSERT_TRUE(b.c3t3.triangulation().tds().is_edge(u, w));
    Flip flip;
    const bool proposed = BODT::internal::Edge_contraction<Adapter>()(ctx, u, w, flip);
    if(curve)
    {
      EXPECT_FALSE(proposed);
      continue;
    }
    ASSERT_TRUE(proposed);
    EXPECT_EQ(flip.kind, BODT::internal::Flip_kind::edge_contraction);
    EXPECT_FALSE(flip.boundary);
    EXPECT_EQ(flip.removed, u);
    EXPECT_TRUE(flip.new_facets.empty());
    EXPECT_TRUE(flip.improves());
    // A corner of the cube not joined to u: refused.
    for(int k = 0; k < 8; ++k)
      if(!b.c3t3.triangulation().tds().is_edge(u, b.handles[k]))
      {
        Flip far;
        EXPECT_FALSE(BODT::internal::Edge_contraction<Adapter>()(ctx, u, b.handles[k], far)) << "corner " << k;
      }
    contract_and_check(b, adapter, flip, u, true);
  }
}

// A vertex of an exactly planar interface between two subdomains slides along it
// onto a neighbour in the plane: the facets through it move with it, each
// subdomain keeps its exact volume and the interface its area. Onto a
// neighbour off the plane, nothing is proposed.
TEST(EdgeContraction, SlidesAlongAnExactlyPlanarInterfaceAndKeepsBothVolumes)
{
  std::vector<Point> plane = {Point(-1, -1, 0),    Point(1.02, -0.97, 0), Point(0.98, 1.01, 0), Point(-1.03, 0.99, 0),
                              Point(0.42, -0.31, 0), Point(-0.37, 0.46, 0), Point(0.13, 0.11, 0), Point(0.17, 0.05, 0)};
  const std::vector<Point> top = {Point(0.1, -0.2, 0.9), Point(-0.5, 0.3, 1.1), Point(0.6, 0.5, 0.8)};
  const std::vector<Point> bottom = {Point(-0.2, 0.1, -1.0), Point(0.5, -0.6, -0.9), Point(-0.6, -0.4, -1.2)};
  {
    std::vector<Point> p = plane;
    p.insert(p.end(), top.begin(), top.end());
    const std::size_t n_top = p.size();
    p.insert(p.end(), bottom.begin(), bottom.end());
    // Each side triangulated apart (a Delaunay face on the hull plane is the 2D
    // Delaunay triangulation of its points, the same from both sides).
    auto side = [&](std::size_t begin, std::size_t end) {
      std::vector<Point> q(p.begin(), p.begin() + plane.size());
      q.insert(q.end(), p.begin() + begin, p.begin() + end);
      auto t = delaunay_tets(q);
      for(auto& tet : t)
        for(int& i : tet)
          if(i >= static_cast<int>(plane.size())) i += static_cast<int>(begin - plane.size());
      return t;
    };
    std::vector<std::array<int, 4>> tets = side(plane.size(), n_top);
    std::vector<int> labels(tets.size(), 1);
    const auto below = side(n_top, p.size());
    tets.insert(tets.end(), below.begin(), below.end());
    labels.resize(tets.size(), 2);
    Built b;
    build(make_mesh(p, tets, labels), b);
    expect_valid(b.c3t3);
    Adapter adapter(b.c3t3, false);
    const Context ctx(adapter, BODT::internal::Dihedral_bounds(), false);
    const Vertex_handle u = b.handles[7], w = b.handles[6];
    ASSERT_TRUE(b.c3t3.triangulation().tds().is_edge(u, w));
    Flip flip;
    ASSERT_TRUE(BODT::internal::Edge_contraction<Adapter>()(ctx, u, w, flip));
    EXPECT_TRUE(flip.boundary);
    EXPECT_FALSE(flip.new_facets.empty());
    EXPECT_TRUE(flip.improves());
    for(std::size_t k = plane.size(); k < p.size(); ++k)
      if(b.c3t3.triangulation().tds().is_edge(u, b.handles[k]))
      {
        Flip off;
        EXPECT_FALSE(BODT::internal::Edge_contraction<Adapter>()(ctx, u, b.handles[k], off)) << "apex " << k;
      }
    contract_and_check(b, adapter, flip, u, false);
  }
}
