// Topology optimization: the quality measure against a brute-force computation,
// each flip kind on a constructed configuration (labels, volume, validity, the
// better configuration chosen, exact coplanarity refused when off by one ulp,
// curve edges and interfaces kept), and a property test of the whole pipeline over
// CGAL-meshed inputs with features and two subdomains.
#include "c3t3_checks.h"
#include "inputs/generated_inputs.h"

#include <CGAL/BODT_3/Tet_mesh_conversion.h>
#include <CGAL/BODT_3/internal/Quality/dihedral_angles.h>
#include <CGAL/BODT_3/internal/Topology/flip_pass.h>
#include <CGAL/BODT_3/mesh_quality.h>
#include <CGAL/BODT_3/internal/Quality/tet_quality.h>
#include <CGAL/bodt_optimize_mesh_3.h>

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

// A mesh from points and tets given in any orientation; every tet labelled `label`
// unless `labels` says otherwise.
Tet_mesh make_mesh(const std::vector<Point>& points, std::vector<std::array<int, 4>> tets,
                   std::vector<int> labels = {})
{
  Tet_mesh m;
  m.points = points;
  m.vertex_refs.assign(points.size(), 0);
  for(auto& t : tets)
    if(CGAL::orientation(points[t[0]], points[t[1]], points[t[2]], points[t[3]]) == CGAL::NEGATIVE)
      std::swap(t[2], t[3]);
  m.tets = tets;
  m.tet_labels = labels.empty() ? std::vector<int>(tets.size(), 1) : labels;
  return m;
}

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

TEST(Quality_measure, MatchesTheSinesOfTheDihedralAngles)
{
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1, 1);
  int checked = 0;
  for(int i = 0; i < 2000; ++i)
  {
    Point p[4];
    for(auto& x : p) x = Point(u(rng), u(rng), u(rng));
    if(CGAL::orientation(p[0], p[1], p[2], p[3]) != CGAL::POSITIVE) std::swap(p[2], p[3]);
    if(CGAL::orientation(p[0], p[1], p[2], p[3]) != CGAL::POSITIVE) continue;
    EXPECT_NEAR(BODT::internal::min_dihedral_sine(p[0], p[1], p[2], p[3]), brute_min_sine(p[0], p[1], p[2], p[3]), 1e-9);
    // Negatively oriented: -1, whatever the shape.
    EXPECT_EQ(BODT::internal::min_dihedral_sine(p[0], p[1], p[3], p[2]), -1);
    ++checked;
  }
  EXPECT_GT(checked, 1900);
  Point r[4] = {Point(1, 1, 1), Point(1, -1, -1), Point(-1, 1, -1), Point(-1, -1, 1)};
  if(CGAL::orientation(r[0], r[1], r[2], r[3]) != CGAL::POSITIVE) std::swap(r[2], r[3]);
  EXPECT_NEAR(BODT::internal::min_dihedral_sine(r[0], r[1], r[2], r[3]), std::sqrt(8.0) / 3, 1e-15);
  // A flat tetrahedron has quality 0 or is refused.
  EXPECT_LE(BODT::internal::min_dihedral_sine(Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0), Point(1, 1, 0)), 0);
}

TEST(Quality_measure, BoundsAgreeWithTheAngles)
{
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1, 1);
  BODT::internal::Dihedral_bounds bounds = BODT::internal::Dihedral_bounds::empty();
  // Bounds from a few tets, then every tet is inside iff its angles are.
  std::vector<std::array<Point, 4>> tets;
  while(tets.size() < 300)
  {
    std::array<Point, 4> p;
    for(auto& x : p) x = Point(u(rng), u(rng), u(rng));
    if(CGAL::orientation(p[0], p[1], p[2], p[3]) != CGAL::POSITIVE) std::swap(p[2], p[3]);
    if(CGAL::orientation(p[0], p[1], p[2], p[3]) == CGAL::POSITIVE) tets.push_back(p);
  }
  double lo = 180, hi = 0;
  for(std::size_t i = 0; i < 20; ++i)
  {
    bounds.include(tets[i][0], tets[i][1], tets[i][2], tets[i][3]);
    const auto mm = BODT::internal::min_max_dihedral_angle(tets[i][0], tets[i][1], tets[i][2], tets[i][3]);
    lo = std::min(lo, mm.first);
    hi = std::max(hi, mm.second);
  }
  int inside = 0;
  for(const auto& t : tets)
  {
    const auto mm = BODT::internal::min_max_dihedral_angle(t[0], t[1], t[2], t[3]);
    const bool expected = mm.first >= lo - 1e-9 && mm.second <= hi + 1e-9;
    const bool clearly = mm.first >= lo + 1e-9 && mm.second <= hi - 1e-9;
    const bool got = bounds.contains(t[0], t[1], t[2], t[3], BODT::internal::min_dihedral_sine(t[0], t[1], t[2], t[3]));
    if(clearly)
    {
      EXPECT_TRUE(got);
    }
    if(!expected)
    {
      EXPECT_FALSE(got);
    }
    inside += got ? 1 : 0;
  }
  EXPECT_GT(inside, 20);
  EXPECT_LT(inside, 300);
}

TEST(Quality_measure, WorstFirstComparison)
{
  std::vector<double> a = {0.5, 0.1, 0.9}, b = {0.2, 0.1};
  EXPECT_EQ(BODT::internal::compare_worst_first(a, b), 1);   // 0.1 ties, then 0.5 > 0.2
  std::vector<double> c = {0.3}, d = {0.4, 0.9};
  EXPECT_EQ(BODT::internal::compare_worst_first(c, d), -1);
  std::vector<double> e = {0.3, 0.8}, f = {0.3};
  EXPECT_EQ(BODT::internal::compare_worst_first(e, f), 0);
}

// Edge removal, the 3-2 flip among them: the ring around an axis edge, for
// several heights; the pass ends in the better of the two configurations.
// When a cell whose flips failed is tried again: not before its wait (1, 2, 4, 8
// passes after 1, 2, 3, 4 failures), and only once something within one edge of it
// changed since the failure; after `retries_after_moves` failures, only a new
// connectivity counts, moves alone do not.
TEST(Flips, FailedCellsAreRetriedAfterTheirWaitAndAChange)
{
  BODT::internal::Attempt_history h;
  h.retries_after_moves = 1;
  h.region_stamp.assign(10, 0);
  h.topology_stamp.assign(10, 0);
  const std::array<int, 4> cell{1, 2, 3, 4};
  EXPECT_TRUE(h.worth_trying(cell));   // never tried
  h.pass = 1;
  h.clock = 5;
  h.record_failure(cell);
  h.pass = 2;
  EXPECT_FALSE(h.worth_trying(cell));   // nothing changed
  h.region_stamp[7] = 6;                // a vertex that is not the cell's
  EXPECT_FALSE(h.worth_trying(cell));
  h.region_stamp[3] = 6;                // a vertex within one edge moved
  EXPECT_TRUE(h.worth_trying(cell));
  h.clock = 7;
  h.record_failure(cell);               // second failure, at pass 2: wait 2
  h.region_stamp[2] = 8;
  h.topology_stamp[2] = 8;
  h.pass = 3;
  EXPECT_FALSE(h.worth_trying(cell));   // within the wait
  h.pass = 4;
  h.topology_stamp[2] = 0;
  EXPECT_FALSE(h.worth_trying(cell));   // moves alone no longer count
  h.star_changed(4);                    // a flip gave vertex 4 a new star, at clock 7
  EXPECT_FALSE(h.worth_trying(cell));   // not after the failure
  h.clock = 9;
  h.star_changed(4);
  EXPECT_TRUE(h.worth_trying(cell));
  EXPECT_EQ(h.region_stamp[4], 9u);
}

TEST(Flips, EdgeRemovalChoosesTheBetterConfiguration)
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
TEST(Flips, MultiFaceRemovalChoosesTheBetterConfiguration)
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
TEST(Flips, NothingAcrossAnInterface)
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
TEST(Flips, CurveEdgesStay)
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
TEST(Flips, CoplanarBoundaryFacetsFlipAndOneUlpOffDoesNot)
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

// The pipeline over CGAL-meshed inputs: the boundary changes only by coplanar flips
// (same area per patch, every new facet coplanar with a facet it replaced), every
// subdomain keeps its volume, every curve edge stays, no cell is inverted, and the
// mesh ends better than it started.
class Pipeline_properties : public ::testing::TestWithParam<bodt_inputs::Shape>
{};

TEST_P(Pipeline_properties, FlipsKeepSurfaceVolumeCurvesAndValidity)
{
  using namespace bodt_inputs;
  const Generated_mesh input = make_input(GetParam(), Size::small);
  for(auto moving : {BODT::Moving_vertices::NONE, BODT::Moving_vertices::ALL})
  {
    SCOPED_TRACE(moving == BODT::Moving_vertices::NONE ? "flips alone" : "B-ODT + flips");
    C3t3 c3t3 = input.c3t3;
    std::vector<std::pair<Point, Point>> curves;
    auto cp = c3t3.triangulation().geom_traits().construct_point_3_object();
    for(auto e = c3t3.edges_in_complex_begin(); e != c3t3.edges_in_complex_end(); ++e)
      curves.emplace_back(cp(e->first->vertex(e->second)->point()), cp(e->first->vertex(e->third)->point()));
    const auto before = BODT::mesh_quality(c3t3);
    std::map<std::pair<int, int>, double> area_before;
    std::set<std::pair<std::array<Point, 3>, std::pair<int, int>>> facets_before;
    for(auto f = c3t3.facets_in_complex_begin(); f != c3t3.facets_in_complex_end(); ++f)
    {
      const auto t = c3t3.triangulation().triangle(*f);
      area_before[c3t3.surface_patch_index(*f)] += std::sqrt(t.squared_area());
      facets_before.insert({sorted_points(t[0], t[1], t[2]), c3t3.surface_patch_index(*f)});
    }

    BODT::Smoothing_options opt;
    opt.moving_vertices = moving;
    opt.vertex_insertion = false;
    const auto r = BODT::smooth(c3t3, opt);
    EXPECT_GT(r.topology.total(), 0u);
    const auto after = BODT::mesh_quality(c3t3);

    EXPECT_TRUE(c3t3.triangulation().tds().is_valid());
    EXPECT_TRUE(c3t3.is_valid());
    EXPECT_EQ(after.inverted_tets, 0u);
    std::size_t bad = 0;
    for(auto c = c3t3.triangulation().finite_cells_begin(); c != c3t3.triangulation().finite_cells_end(); ++c)
      if(CGAL::orientation(cp(c->vertex(0)->point()), cp(c->vertex(1)->point()), cp(c->vertex(2)->point()),
                           cp(c->vertex(3)->point())) != CGAL::POSITIVE)
        ++bad;
    EXPECT_EQ(bad, 0u) << "inverted or flat cells outside the complex";
    ASSERT_EQ(after.volume_per_subdomain.size(), before.volume_per_subdomain.size());
    for(const auto& kv : before.volume_per_subdomain)
      EXPECT_NEAR(after.volume_per_subdomain.at(kv.first), kv.second, 1e-10 * kv.second);
    std::map<std::pair<int, int>, double> area_after;
    for(auto f = c3t3.facets_in_complex_begin(); f != c3t3.facets_in_complex_end(); ++f)
      area_after[c3t3.surface_patch_index(*f)] += std::sqrt(c3t3.triangulation().triangle(*f).squared_area());
    if(moving == BODT::Moving_vertices::NONE)
    {
      ASSERT_EQ(area_after.size(), area_before.size());
      for(const auto& kv : area_before) EXPECT_NEAR(area_after.at(kv.first), kv.second, 1e-12 * kv.second);
      // A facet that is new lies in the plane of an old one of its patch it shares an edge with.
      std::map<std::pair<Point, Point>, std::vector<std::pair<std::array<Point, 3>, std::pair<int, int>>>> by_edge;
      for(const auto& f : facets_before)
        for(int k = 0; k < 3; ++k) by_edge[std::minmax(f.first[k], f.first[(k + 1) % 3])].push_back(f);
      std::size_t new_facets = 0;
      for(auto f = c3t3.facets_in_complex_begin(); f != c3t3.facets_in_complex_end(); ++f)
      {
        const auto t = c3t3.triangulation().triangle(*f);
        const auto key = std::make_pair(sorted_points(t[0], t[1], t[2]), c3t3.surface_patch_index(*f));
        if(facets_before.count(key)) continue;
        ++new_facets;
        bool coplanar = false;
        for(int k = 0; k < 3 && !coplanar; ++k)
          for(const auto& old : by_edge[std::minmax(key.first[k], key.first[(k + 1) % 3])])
            for(const Point& x : old.first)
              coplanar = coplanar || (old.second == key.second &&
                                      CGAL::orientation(key.first[0], key.first[1], key.first[2], x) == CGAL::COPLANAR &&
                                      std::find(key.first.begin(), key.first.end(), x) == key.first.end());
        EXPECT_TRUE(coplanar) << "a boundary facet that is not coplanar with the one it replaced";
      }
      EXPECT_EQ(new_facets > 0, r.topology.boundary_flips > 0);
    }
    // Every curve edge is still an edge of the complex, between the same points
    // (flips alone) or with its endpoints on their curve (smoothing moves them).
    std::size_t curve_edges = 0;
    for(auto e = c3t3.edges_in_complex_begin(); e != c3t3.edges_in_complex_end(); ++e) ++curve_edges;
    EXPECT_EQ(curve_edges, curves.size());
    if(moving == BODT::Moving_vertices::NONE)
    {
      std::set<std::pair<Point, Point>> now;
      for(auto e = c3t3.edges_in_complex_begin(); e != c3t3.edges_in_complex_end(); ++e)
      {
        const Point a = cp(e->first->vertex(e->second)->point()), b = cp(e->first->vertex(e->third)->point());
        now.insert(std::minmax(a, b));
      }
      for(const auto& e : curves) EXPECT_TRUE(now.count(std::minmax(e.first, e.second)));
    }
    EXPECT_GE(after.min_dihedral_deg, before.min_dihedral_deg);
    EXPECT_LE(after.max_dihedral_deg, before.max_dihedral_deg);
    EXPECT_GT(after.min_dihedral_deg, before.min_dihedral_deg + 1.0);
  }
}

INSTANTIATE_TEST_SUITE_P(All, Pipeline_properties, ::testing::ValuesIn(bodt_inputs::all_shapes()),
                         [](const ::testing::TestParamInfo<bodt_inputs::Shape>& info) {
                           return bodt_inputs::name(info.param);
                         });

// Same input, same options: same points and same cells, flips included.
TEST(Pipeline, SameInputSameOutput)
{
  using namespace bodt_inputs;
  const Generated_mesh input = make_input(Shape::two_subdomains, Size::small);
  C3t3 a = input.c3t3, b = input.c3t3;
  CGAL::bodt_optimize_mesh_3(a);
  CGAL::bodt_optimize_mesh_3(b);
  const Tet_mesh ma = BODT::c3t3_to_tet_mesh(a), mb = BODT::c3t3_to_tet_mesh(b);
  EXPECT_EQ(ma.points, mb.points);
  EXPECT_EQ(ma.tets, mb.tets);
  EXPECT_EQ(ma.triangles, mb.triangles);
}

// What lets the flip pass evaluate a round of cells concurrently and apply their
// flips one after the other: every cell an evaluation of cell c reads or would
// replace holds a vertex of c or the apex across one of c's faces (the pass's
// `neighbourhood`), so an evaluation none of whose neighbourhood a flip touched
// since is still right. Checked on every proposal of every cell of a Mesh_3
// mesh with features and two subdomains, each measure, before and after a
// flipped state; and the whole pipeline gives the same cells on 1, 2 and 4
// threads with every pass at work (flips, max-min steps, insertion, all phases).
TEST(Flips, EvaluationsStayWithinTheCellsNeighbourhood)
{
  using namespace bodt_inputs;
  using Adapter = BODT::internal::C3t3_adapter<C3t3>;
  const Generated_mesh input = make_input(Shape::two_subdomains, Size::small);
  for(const auto measure : {BODT::Quality_measure::min_dihedral_sine, BODT::Quality_measure::largest_dihedral_angle})
  {
    C3t3 c3t3 = input.c3t3;
    Adapter adapter(c3t3);
    const BODT::internal::Dihedral_bounds any;   // default: every angle allowed, so more proposals
    const BODT::internal::Flip_context<Adapter> ctx(adapter, any, false, measure);
    BODT::internal::Edge_removal<Adapter> edge_removal;
    BODT::internal::Multi_face_removal<Adapter> face_removal;
    BODT::internal::Flip<Adapter> flip;
    std::size_t proposals = 0, improving = 0;
    auto& tr = c3t3.triangulation();
    for(auto c = tr.finite_cells_begin(); c != tr.finite_cells_end(); ++c)
    {
      std::set<C3t3::Vertex_handle> neighbourhood;
      for(int k = 0; k < 4; ++k)
      {
        neighbourhood.insert(c->vertex(k));
        neighbourhood.insert(c->neighbor(k)->vertex(c->neighbor(k)->index(c)));
      }
      auto check = [&](const char* what) {
        ++proposals;
        if(flip.improves()) ++improving;
        for(const auto& old : flip.old_cells)
        {
          bool inside = false;
          for(int k = 0; k < 4; ++k) inside = inside || neighbourhood.count(old->vertex(k)) > 0;
          ASSERT_TRUE(inside) << what << " reads a cell with no vertex of the cell's neighbourhood";
        }
      };
      for(int i = 0; i < 4; ++i)
      {
        for(int j = i + 1; j < 4; ++j)
          if(edge_removal(ctx, c, i, j, flip)) check("edge removal");
        if(!tr.is_infinite(c->neighbor(i)->vertex(c->neighbor(i)->index(c))) && face_removal(ctx, c, i, flip))
          check("multi-face removal");
      }
    }
    EXPECT_GT(proposals, 1000u);
    EXPECT_GT(improving, 10u) << "no flip to make: the check would not reach the pass's real cases";
  }
}

TEST(Pipeline, SameCellsOnAnyNumberOfThreadsWithEveryPassAtWork)
{
  using namespace bodt_inputs;
  struct Counts
  {
    std::size_t flips = 0, max_min = 0, inserted = 0, phases = 0;
  };
  struct Counting
  {
    Counts* counts;
    void after_classification(const BODT::Smoothing_result&) {}
    void after_iteration(const BODT::Iteration_stats& s)
    {
      counts->flips += s.topology.total();
      counts->max_min += s.max_min_moves;
      counts->inserted += s.insertion.vertices_added;
      counts->phases = std::max<std::size_t>(counts->phases, static_cast<std::size_t>(s.phase) + 1);
    }
  };
  // Features and two subdomains; handles, where insertion finds work; sharp edges and corners.
  for(Shape shape : {Shape::two_subdomains, Shape::genus2, Shape::sharp_part})
  {
    SCOPED_TRACE(name(shape));
    const Generated_mesh input = make_input(shape, Size::small);
    Tet_mesh reference;
    Counts counts;
    for(int threads : {1, 2, 4})
    {
      C3t3 c3t3 = input.c3t3;
      Counts now;
      CGAL::bodt_optimize_mesh_3(c3t3, CGAL::parameters::number_of_threads = threads,
                                 CGAL::parameters::progress_visitor = Counting{&now});
      const Tet_mesh m = BODT::c3t3_to_tet_mesh(c3t3);
      if(threads == 1)
      {
        reference = m;
        counts = now;
        continue;
      }
      EXPECT_TRUE(m.points == reference.points) << threads << " threads";
      EXPECT_TRUE(m.tets == reference.tets) << threads << " threads";
      EXPECT_TRUE(m.triangles == reference.triangles) << threads << " threads";
    }
    EXPECT_GT(counts.flips, 0u);
    EXPECT_GT(counts.max_min, 0u);
    EXPECT_EQ(counts.phases, 3u);
    if(shape == Shape::genus2) { EXPECT_GT(counts.inserted, 0u); }
  }
}

// The largest-angle measure is 1 + the cosine of the largest dihedral angle: it
// orders tetrahedra by their largest angle, is 0 for a flat one with an angle of
// 180 degrees, and -1 for a negatively oriented one.
TEST(Quality_measure, LargestAngleMeasureOrdersByTheLargestAngle)
{
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<std::pair<double, double>> measured;   // (largest angle, measure)
  while(measured.size() < 1000)
  {
    Point p[4];
    for(auto& x : p) x = Point(u(rng), u(rng), u(rng));
    if(CGAL::orientation(p[0], p[1], p[2], p[3]) != CGAL::POSITIVE) std::swap(p[2], p[3]);
    if(CGAL::orientation(p[0], p[1], p[2], p[3]) != CGAL::POSITIVE) continue;
    const double q = BODT::internal::tet_quality(BODT::Quality_measure::largest_dihedral_angle, p[0], p[1], p[2], p[3]);
    const double largest = BODT::internal::min_max_dihedral_angle(p[0], p[1], p[2], p[3]).second;
    EXPECT_NEAR(q, 1 + std::cos(largest * 3.14159265358979323846 / 180), 1e-9);
    EXPECT_EQ(BODT::internal::tet_quality(BODT::Quality_measure::largest_dihedral_angle, p[0], p[1], p[3], p[2]), -1);
    measured.emplace_back(largest, q);
  }
  std::sort(measured.begin(), measured.end());
  for(std::size_t i = 1; i < measured.size(); ++i)
  {
    if(measured[i].first > measured[i - 1].first + 1e-6)
    {
      EXPECT_LT(measured[i].second, measured[i - 1].second);
    }
  }
  // A flat tetrahedron, its fourth vertex just above the opposite face: angles near 180 degrees.
  const double flat = BODT::internal::tet_quality(BODT::Quality_measure::largest_dihedral_angle, Point(0, 0, 0), Point(2, 0, 0),
                                        Point(0, 2, 0), Point(0.5, 0.5, 1e-9));
  EXPECT_GE(flat, 0);
  EXPECT_LT(flat, 1e-6);
}

// The largest-angle phase (on by default) starts where the main phase ends: it
// lowers the largest angle without lowering the smallest, keeps every
// subdomain's volume and the vertex count, and inverts nothing.
TEST(Pipeline, LargestAnglePhaseLowersTheLargestAngle)
{
  using namespace bodt_inputs;
  for(Shape shape : {Shape::torus, Shape::two_subdomains})
  {
    SCOPED_TRACE(name(shape));
    const Generated_mesh input = make_input(shape, Size::small);
    C3t3 without = input.c3t3, with = input.c3t3;
    BODT::Smoothing_options opt;
    opt.largest_angle_phase = false;
    BODT::smooth(without, opt);
    opt.largest_angle_phase = true;
    struct Phases
    {
      std::set<std::size_t>* seen;
      void after_classification(const BODT::Smoothing_result&) const {}
      void after_iteration(const BODT::Iteration_stats& s) const { seen->insert(s.phase); }
    };
    std::set<std::size_t> seen;
    BODT::smooth(with, opt, Phases{&seen});
    EXPECT_EQ(seen, (std::set<std::size_t>{0, 1, 2}));
    const auto a = BODT::mesh_quality(without), b = BODT::mesh_quality(with);
    EXPECT_EQ(b.inverted_tets, 0u);
    EXPECT_TRUE(with.triangulation().tds().is_valid());
    EXPECT_EQ(b.num_vertices, a.num_vertices);
    EXPECT_GE(b.min_dihedral_deg, a.min_dihedral_deg);
    EXPECT_LT(b.max_dihedral_deg, a.max_dihedral_deg - 1.0);
    ASSERT_EQ(b.volume_per_subdomain.size(), a.volume_per_subdomain.size());
    for(const auto& kv : a.volume_per_subdomain)
      EXPECT_NEAR(b.volume_per_subdomain.at(kv.first), kv.second, 1e-10 * kv.second);
  }
}
