// Vertex insertion: the shapes of bad tetrahedra on constructed tetrahedra; edge
// and facet splits with their labels (subdomains, patches, curves, vertex
// dimensions), volume and validity, and their undo; the budget; and the pipeline
// with insertion over CGAL-meshed inputs and through a file mesh.
#include "c3t3_checks.h"
#include "test_support.h"
#include "delaunay_cells.h"
#include "inputs/generated_inputs.h"

#include <CGAL/BODT_3/internal/Insertion/Bad_tet_shape.h>
#include <CGAL/BODT_3/internal/Insertion/Cavity_insertion.h>
#include <CGAL/BODT_3/Tet_mesh_conversion.h>
#include <CGAL/BODT_3/internal/Insertion/Vertex_insertion.h>
#include <CGAL/BODT_3/mesh_quality.h>
#include <CGAL/BODT_3/smooth.h>

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <set>
#include <vector>

namespace BODT = CGAL::BODT_3;
using BODT::internal::Bad_tet_shape;
using BODT::Tet_mesh;
using Point = Tet_mesh::Point;
using File_c3t3 = BODT::Tet_mesh_c3t3;
using Vertex_handle = File_c3t3::Vertex_handle;
using Adapter = BODT::internal::C3t3_adapter<File_c3t3>;

using bodt_test::bare;
using bodt_test::expect_valid;

namespace {

CGAL::BODT_3::internal::Bad_tet_shape shape_of(Point a, Point b, Point c, Point d)
{
  if(CGAL::orientation(a, b, c, d) != CGAL::POSITIVE) std::swap(c, d);
  BODT::Bad_tet_options opt;
  opt.small_angle = 45;   // loose bounds: the shapes, not their badness, are under test
  opt.large_angle = 135;
  return BODT::internal::classify_bad_tet(a, b, c, d, opt).shape;
}

using bodt_test::make_mesh;

// What a split and its undo must keep or restore.
struct State
{
  std::map<int, double> volume;
  std::map<int, double> patch_area;
  std::set<std::array<Point, 4>> cells;   // sorted points, in the complex
  std::size_t vertices = 0, facets = 0, edges = 0;
};

State state(const File_c3t3& c3t3)
{
  State s;
  for(auto c = c3t3.cells_in_complex_begin(); c != c3t3.cells_in_complex_end(); ++c)
  {
    std::array<Point, 4> p = {bare(c3t3, c->vertex(0)), bare(c3t3, c->vertex(1)), bare(c3t3, c->vertex(2)),
                              bare(c3t3, c->vertex(3))};
    s.volume[c3t3.subdomain_index(c)] += CGAL::volume(p[0], p[1], p[2], p[3]);
    std::sort(p.begin(), p.end());
    s.cells.insert(p);
  }
  for(auto f = c3t3.facets_in_complex_begin(); f != c3t3.facets_in_complex_end(); ++f)
    s.patch_area[c3t3.surface_patch_index(*f)] += std::sqrt(c3t3.triangulation().triangle(*f).squared_area());
  s.vertices = c3t3.triangulation().number_of_vertices();
  s.facets = c3t3.number_of_facets_in_complex();
  for(auto e = c3t3.edges_in_complex_begin(); e != c3t3.edges_in_complex_end(); ++e) ++s.edges;
  return s;
}

void expect_same_volumes(const State& a, const State& b)
{
  ASSERT_EQ(a.volume.size(), b.volume.size());
  for(const auto& kv : a.volume) EXPECT_NEAR(b.volume.at(kv.first), kv.second, 1e-12 * std::abs(kv.second));
  ASSERT_EQ(a.patch_area.size(), b.patch_area.size());
  for(const auto& kv : a.patch_area) EXPECT_NEAR(b.patch_area.at(kv.first), kv.second, 1e-12 * kv.second);
}

// Six tets around the axis edge (0, 1) of a hexagonal bipyramid, in two subdomains
// (1 above y = 0, 2 below), with the outer faces labelled by the file as patches.
Tet_mesh bipyramid()
{
  std::vector<Point> p = {Point(0, 0, -1), Point(0, 0, 1)};
  for(int k = 0; k < 6; ++k) p.emplace_back(std::cos(k * 3.14159265358979323846 / 3), std::sin(k * 3.14159265358979323846 / 3), 0.1 * (k % 2));
  std::vector<std::array<int, 4>> t;
  std::vector<int> labels;
  for(int k = 0; k < 6; ++k)
  {
    t.push_back({0, 1, 2 + k, 2 + (k + 1) % 6});
    labels.push_back(k < 3 ? 1 : 2);
  }
  return make_mesh(p, t, labels);
}

} // namespace

TEST(BadTetShape, EachShapeOnAConstructedTetrahedron)
{
  // Good: the regular tetrahedron.
  EXPECT_EQ(shape_of(Point(1, 1, 1), Point(1, -1, -1), Point(-1, 1, -1), Point(-1, -1, 1)), CGAL::BODT_3::internal::Bad_tet_shape::good);
  // One short edge a b over the middle of c d: a wedge; beyond its end: a spike.
  EXPECT_EQ(shape_of(Point(-0.05, 0, 0.5), Point(0.05, 0, 0.5), Point(0, -1, 0), Point(0, 1, 0)), CGAL::BODT_3::internal::Bad_tet_shape::wedge);
  EXPECT_EQ(shape_of(Point(-0.05, 2, 0.5), Point(0.05, 2, 0.5), Point(0, -1, 0), Point(0, 1, 0)), CGAL::BODT_3::internal::Bad_tet_shape::spike);
  // Two short edges sharing b: bent at b, a spear; nearly straight, a splinter.
  EXPECT_EQ(shape_of(Point(0, 0, 0), Point(0.22, 0.14, 0), Point(0.44, 0, 0), Point(0.22, 0.05, 1.1)),
            CGAL::BODT_3::internal::Bad_tet_shape::spear);
  EXPECT_EQ(shape_of(Point(0, 0, 0), Point(0.25, 0.02, 0), Point(0.5, 0, 0.03), Point(0.25, 0.3, 1.5)),
            CGAL::BODT_3::internal::Bad_tet_shape::splinter);
  // Two opposite short edges: a spindle.
  EXPECT_EQ(shape_of(Point(0, 0, 0), Point(0.1, 0.05, 0), Point(0, 0.1, 1.5), Point(0.08, 0, 1.5)),
            CGAL::BODT_3::internal::Bad_tet_shape::spindle);
  // Three short edges around a face (a thin base, far apex): a spire.
  EXPECT_EQ(shape_of(Point(0, 0, 0), Point(0.2, 0, 0), Point(0.1, 0.01, 0), Point(0.05, 0.05, 1.5)),
            CGAL::BODT_3::internal::Bad_tet_shape::spire);
  // Flat, no short edge: a vertex over the inside of its face, a cap; over an edge of
  // it, a spade; two crossing edges, a sliver.
  EXPECT_EQ(shape_of(Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0), Point(0.3, 0.3, 0.05)), CGAL::BODT_3::internal::Bad_tet_shape::cap);
  EXPECT_EQ(shape_of(Point(0, 0, 0), Point(1, 0, 0), Point(0.5, 0.9, 0), Point(0.5, -0.02, 0.03)),
            CGAL::BODT_3::internal::Bad_tet_shape::spade);
  EXPECT_EQ(shape_of(Point(1, 0, 0.05), Point(0, 1, -0.05), Point(-1, 0, 0.05), Point(0, -1, -0.05)),
            CGAL::BODT_3::internal::Bad_tet_shape::sliver);
}

TEST(BadTetShape, WhereToSplit)
{
  BODT::Bad_tet_options opt;
  opt.small_angle = 30;
  opt.large_angle = 150;
  // A cap over (0.3, 0.3) of its face: the barycentric coordinates of that point.
  Point a(0, 0, 0), b(1, 0, 0), c(0, 1, 0), d(0.3, 0.3, 0.05);
  if(CGAL::orientation(a, b, c, d) != CGAL::POSITIVE) std::swap(a, b);
  const auto cap = BODT::internal::classify_bad_tet(a, b, c, d, opt);
  ASSERT_EQ(cap.shape, CGAL::BODT_3::internal::Bad_tet_shape::cap);
  EXPECT_EQ(cap.vertex, 3);
  const Point p[3] = {a, b, c};
  double x = 0, y = 0, s = 0;
  for(int k = 0; k < 3; ++k)
  {
    x += cap.bary[k] * p[k].x();
    y += cap.bary[k] * p[k].y();
    s += cap.bary[k];
  }
  EXPECT_NEAR(x / s, 0.3, 1e-12);
  EXPECT_NEAR(y / s, 0.3, 1e-12);
  // A sliver: its crossing edges meet halfway along both.
  const auto sliver = BODT::internal::classify_bad_tet(Point(1, 0, 0.05), Point(-1, 0, 0.05), Point(0, 1, -0.05),
                                             Point(0, -1, -0.05), opt);
  ASSERT_EQ(sliver.shape, CGAL::BODT_3::internal::Bad_tet_shape::sliver);
  EXPECT_NEAR(sliver.t[0], 0.5, 1e-12);
  EXPECT_NEAR(sliver.t[1], 0.5, 1e-12);
}

// An edge inside one subdomain: every cell around it splits in two, the volume
// stays, the new vertex is interior (dimension 3); undone, all comes back.
TEST(Splits, InteriorEdgeAndItsUndo)
{
  std::vector<Point> p = {Point(0, 0, -1), Point(0, 0, 1)};
  for(int k = 0; k < 5; ++k) p.emplace_back(std::cos(k * 1.2566370614359172), std::sin(k * 1.2566370614359172), 0);
  std::vector<std::array<int, 4>> t;
  for(int k = 0; k < 5; ++k) t.push_back({0, 1, 2 + k, 2 + (k + 1) % 5});
  File_c3t3 c3t3;
  std::vector<Vertex_handle> h;
  BODT::tet_mesh_to_c3t3(make_mesh(p, t), c3t3, "test", &h);
  const State before = state(c3t3);
  Adapter adapter(c3t3, false);
  File_c3t3::Cell_handle c;
  int i, j;
  ASSERT_TRUE(c3t3.triangulation().tds().is_edge(h[0], h[1], c, i, j));
  BODT::internal::Split_record<Adapter> r;
  ASSERT_TRUE(BODT::internal::split_edge(adapter, c, i, j, Point(0, 0, 0.2), r));
  expect_valid(c3t3);
  const State after = state(c3t3);
  expect_same_volumes(before, after);
  EXPECT_EQ(after.cells.size(), 10u);
  EXPECT_EQ(after.vertices, before.vertices + 1);
  EXPECT_EQ(c3t3.in_dimension(r.vertex), 3);
  EXPECT_TRUE(r.boundary.empty());
  BODT::internal::undo_split(adapter, r);
  expect_valid(c3t3);
  const State undone = state(c3t3);
  EXPECT_EQ(undone.cells, before.cells);
  EXPECT_EQ(undone.vertices, before.vertices);
  EXPECT_EQ(undone.facets, before.facets);
}

// A boundary edge of the bipyramid: splitting it keeps both subdomains' volumes,
// and its two boundary facets become four with their patch.
TEST(Splits, BoundaryEdgeKeepsPatchesAndVolumes)
{
  File_c3t3 c3t3;
  std::vector<Vertex_handle> h;
  BODT::tet_mesh_to_c3t3(bipyramid(), c3t3, "test", &h);
  const State before = state(c3t3);
  Adapter adapter(c3t3, false);
  File_c3t3::Cell_handle c;
  int i, j;
  // An edge on the outer boundary, within subdomain 1 (edge (0, 2) would be on the interface too).
  ASSERT_TRUE(c3t3.triangulation().tds().is_edge(h[0], h[3], c, i, j));
  const Point mid = CGAL::midpoint(bare(c3t3, h[0]), bare(c3t3, h[3]));
  BODT::internal::Split_record<Adapter> r;
  ASSERT_TRUE(BODT::internal::split_edge(adapter, c, i, j, mid, r));
  expect_valid(c3t3);
  const State after = state(c3t3);
  expect_same_volumes(before, after);
  EXPECT_EQ(after.facets, before.facets + 2);   // its two boundary facets became four
  EXPECT_EQ(c3t3.in_dimension(r.vertex), 2);
  EXPECT_EQ(r.boundary.size(), 2u);
  BODT::internal::undo_split(adapter, r);
  expect_valid(c3t3);
  EXPECT_EQ(state(c3t3).cells, before.cells);
  EXPECT_EQ(state(c3t3).facets, before.facets);
}

// A curve edge splits into two edges of the same curve; the new vertex is on the
// curve (dimension 1), and the mesh written back lists the halves in its place.
TEST(Splits, CurveEdgeBecomesTwoAndTheFileFollows)
{
  Tet_mesh mesh = bipyramid();
  mesh.edges = {{0, 2}, {0, 3}};
  mesh.edge_labels = {7, 8};
  mesh.ridges = {0};
  File_c3t3 c3t3;
  std::vector<Vertex_handle> h;
  BODT::tet_mesh_to_c3t3(mesh, c3t3, "test", &h);
  Adapter adapter(c3t3, false);
  File_c3t3::Cell_handle c;
  int i, j;
  ASSERT_TRUE(c3t3.triangulation().tds().is_edge(h[0], h[2], c, i, j));
  const int curve = c3t3.curve_index(h[0], h[2]);
  BODT::internal::Split_record<Adapter> r;
  ASSERT_TRUE(BODT::internal::split_edge(adapter, c, i, j, CGAL::midpoint(bare(c3t3, h[0]), bare(c3t3, h[2])), r));
  expect_valid(c3t3);
  EXPECT_EQ(c3t3.in_dimension(r.vertex), 1);
  EXPECT_FALSE(c3t3.is_in_complex(h[0], h[2]));
  EXPECT_EQ(c3t3.curve_index(h[0], r.vertex), curve);
  EXPECT_EQ(c3t3.curve_index(r.vertex, h[2]), curve);

  Tet_mesh out = mesh;
  BODT::update_tet_mesh(out, c3t3, h);
  ASSERT_EQ(out.points.size(), mesh.points.size() + 1);
  const int e = static_cast<int>(mesh.points.size());
  EXPECT_EQ(out.points[e], CGAL::midpoint(mesh.points[0], mesh.points[2]));
  ASSERT_EQ(out.edges.size(), 3u);
  EXPECT_EQ(out.edges[0], (std::array<int, 2>{0, e}));
  EXPECT_EQ(out.edges[1], (std::array<int, 2>{e, 2}));
  EXPECT_EQ(out.edges[2], (std::array<int, 2>{0, 3}));
  EXPECT_EQ(out.edge_labels, (std::vector<int>{7, 7, 8}));
  EXPECT_EQ(out.ridges, (std::vector<int>{0, 1}));
  EXPECT_EQ(out.tets.size(), mesh.tets.size() + 2);   // the two cells around (0, 2) became four

  BODT::internal::undo_split(adapter, r);
  expect_valid(c3t3);
  EXPECT_TRUE(c3t3.is_in_complex(h[0], h[2]));
  EXPECT_EQ(c3t3.curve_index(h[0], h[2]), curve);
}

// A facet: its two cells become six; a boundary facet becomes three of its patch.
TEST(Splits, InteriorAndBoundaryFacets)
{
  for(bool interface : {true, false})
  {
    SCOPED_TRACE(interface ? "interface facet" : "boundary facet");
    File_c3t3 c3t3;
    std::vector<Vertex_handle> h;
    BODT::tet_mesh_to_c3t3(bipyramid(), c3t3, "test", &h);
    const State before = state(c3t3);
    Adapter adapter(c3t3, false);
    // The interface facet (0, 1, 5) between subdomains 1 and 2; the boundary facet (0, 2, 3).
    File_c3t3::Cell_handle c;
    int i, j, k;
    const Vertex_handle a = h[0], b = interface ? h[1] : h[2], d = interface ? h[5] : h[3];
    ASSERT_TRUE(c3t3.triangulation().tds().is_facet(a, b, d, c, i, j, k));
    const int f = 6 - i - j - k;
    const Point p((bare(c3t3, a).x() + bare(c3t3, b).x() + bare(c3t3, d).x()) / 3,
                  (bare(c3t3, a).y() + bare(c3t3, b).y() + bare(c3t3, d).y()) / 3,
                  (bare(c3t3, a).z() + bare(c3t3, b).z() + bare(c3t3, d).z()) / 3);
    BODT::internal::Split_record<Adapter> r;
    ASSERT_TRUE(BODT::internal::split_facet(adapter, c, f, p, r));
    expect_valid(c3t3);
    const State after = state(c3t3);
    expect_same_volumes(before, after);
    EXPECT_EQ(after.facets, before.facets + 2);
    EXPECT_EQ(c3t3.in_dimension(r.vertex), 2);
    EXPECT_EQ(after.cells.size(), before.cells.size() + (interface ? 4u : 2u));
    BODT::internal::undo_split(adapter, r);
    expect_valid(c3t3);
    EXPECT_EQ(state(c3t3).cells, before.cells);
    EXPECT_EQ(state(c3t3).facets, before.facets);
  }
}

// A split that would make a cell inside out is refused and changes nothing.
TEST(Splits, AnInvertingPointIsRefused)
{
  File_c3t3 c3t3;
  std::vector<Vertex_handle> h;
  BODT::tet_mesh_to_c3t3(bipyramid(), c3t3, "test", &h);
  const State before = state(c3t3);
  Adapter adapter(c3t3, false);
  File_c3t3::Cell_handle c;
  int i, j;
  ASSERT_TRUE(c3t3.triangulation().tds().is_edge(h[0], h[1], c, i, j));
  BODT::internal::Split_record<Adapter> r;
  EXPECT_FALSE(BODT::internal::split_edge(adapter, c, i, j, Point(3, 0, 0), r));   // far off the edge
  expect_valid(c3t3);
  EXPECT_EQ(state(c3t3).cells, before.cells);
  EXPECT_EQ(state(c3t3).vertices, before.vertices);
}

// Insertion in an optimized cavity (Cavity_insertion.h), at the worst cells of a
// Delaunay triangulation of random points cut into two subdomains by a plane
// (the file's interface facets between them): each proposal's cavity lies in its
// cell's subdomain and holds no facet of the complex; every cone over the
// cavity's boundary is positively oriented (exactly), within the mesh's extreme
// angles, and the cones' volumes add up to the cavity's (they tile it); the cones
// compare better, worst first, than the cells they replace. Then the pass
// inserts them: a valid complex, each subdomain's volume and each patch's area
// the same, one vertex per insertion, and a better worst cell.
// One insertion pass in cavity mode on `c3t3` (no history, every cell measured),
// with the vertices numbered in the triangulation's order.
BODT::Insertion_stats cavity_pass(File_c3t3& c3t3, const BODT::internal::Dihedral_bounds& bounds,
                                  const BODT::Insertion_options& opt, int threads)
{
  Adapter adapter(c3t3, false);
  auto motion = [](Vertex_handle) { return BODT::internal::Vertex_motion<Vertex_handle>{}; };
  std::map<Vertex_handle, int> ids;
  for(auto v = c3t3.triangulation().finite_vertices_begin(); v != c3t3.triangulation().finite_vertices_end(); ++v)
    ids.emplace(v, static_cast<int>(ids.size()));
  auto vertex_id = [&](Vertex_handle v) {
    const auto it = ids.find(v);
    return it == ids.end() ? -1 : it->second;
  };
  std::vector<BODT::internal::Added_vertex<Vertex_handle>> added;
  std::vector<Vertex_handle> touched;
  return BODT::internal::insertion_pass(adapter, opt, bounds, BODT::Quality_measure::min_dihedral_sine,
                                        BODT::Tensor_voting_options(), 100, false, motion, vertex_id, added, touched,
                                        nullptr, nullptr, nullptr, nullptr, threads);
}

TEST(CavityInsertion, ConesTileTheCavityWithinItsSubdomainAndRaiseTheWorst)
{
  const bodt_test::Delaunay_cells d(400);
  std::vector<int> labels;
  for(const auto& c : d.cells)
  {
    double x = 0;
    for(int v : c) x += d.points[static_cast<std::size_t>(v)].x() / 4;
    labels.push_back(x < 0.5 ? 1 : 2);
  }
  File_c3t3 c3t3;
  BODT::tet_mesh_to_c3t3(make_mesh(d.points, d.cells, labels), c3t3, "test");
  const State before = state(c3t3);
  ASSERT_EQ(before.volume.size(), 2u);
  Adapter adapter(c3t3, false);
  auto cp = c3t3.triangulation().geom_traits().construct_point_3_object();
  auto pt = [&](Vertex_handle v) { return cp(v->point()); };
  BODT::internal::Dihedral_bounds bounds;
  std::vector<std::pair<double, File_c3t3::Cell_handle>> cells;
  for(auto c = c3t3.cells_in_complex_begin(); c != c3t3.cells_in_complex_end(); ++c)
  {
    bounds.include(pt(c->vertex(0)), pt(c->vertex(1)), pt(c->vertex(2)), pt(c->vertex(3)));
    cells.emplace_back(BODT::internal::min_dihedral_sine(pt(c->vertex(0)), pt(c->vertex(1)), pt(c->vertex(2)),
                                                         pt(c->vertex(3))),
                       c);
  }
  std::sort(cells.begin(), cells.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  const double worst_before = cells.front().first;
  BODT::internal::Cavity_insertion<Adapter> cavity(adapter, bounds, BODT::Quality_measure::min_dihedral_sine);
  int found = 0;
  for(std::size_t k = 0; k < 30; ++k)
  {
    const auto c = cells[k].second;
    BODT::internal::Cavity_insertion<Adapter>::Proposal p;
    const bool has = cavity(c, p);
    // What the pass relies on to run searches ahead: an insertion elsewhere
    // replaces its cavity's cells and changes its neighbours' adjacency, so a
    // search is judged on cells it read, which holds its cavities' cells and
    // their neighbours, found in the sorted list by the same test the pass uses.
    using Search = BODT::internal::Cavity_insertion<Adapter>;
    EXPECT_TRUE(std::is_sorted(p.read.begin(), p.read.end(), Search::by_address));
    EXPECT_TRUE(Search::reads_any(p.read, {c}));
    if(!has) continue;
    ++found;
    for(const auto& x : p.cavity)
      for(int i = 0; i < 4; ++i)
      {
        EXPECT_TRUE(Search::reads_any(p.read, {x}));
        EXPECT_TRUE(Search::reads_any(p.read, {x->neighbor(i)}));
      }
    std::vector<File_c3t3::Cell_handle> elsewhere;   // cells no search from c looks at
    for(auto y = c3t3.cells_in_complex_begin(); y != c3t3.cells_in_complex_end() && elsewhere.size() < 4; ++y)
      if(!std::binary_search(p.read.begin(), p.read.end(), File_c3t3::Cell_handle(y), Search::by_address))
        elsewhere.push_back(y);
    std::sort(elsewhere.begin(), elsewhere.end(), Search::by_address);
    EXPECT_FALSE(Search::reads_any(p.read, elsewhere));
    double cavity_volume = 0, cones_volume = 0;
    std::vector<double> cones;
    for(const auto& x : p.cavity)
    {
      EXPECT_EQ(c3t3.subdomain_index(x), c3t3.subdomain_index(c));
      cavity_volume += CGAL::volume(pt(x->vertex(0)), pt(x->vertex(1)), pt(x->vertex(2)), pt(x->vertex(3)));
      for(int i = 0; i < 4; ++i)
      {
        const bool inner = std::find(p.cavity.begin(), p.cavity.end(), x->neighbor(i)) != p.cavity.end();
        if(inner)
        {
          EXPECT_FALSE(c3t3.is_in_complex(x, i)) << "a facet of the complex inside the cavity";
          continue;
        }
        std::array<Point, 4> q = {pt(x->vertex(0)), pt(x->vertex(1)), pt(x->vertex(2)), pt(x->vertex(3))};
        q[static_cast<std::size_t>(i)] = p.point;
        EXPECT_EQ(CGAL::orientation(q[0], q[1], q[2], q[3]), CGAL::POSITIVE);
        const double sine = BODT::internal::min_dihedral_sine(q[0], q[1], q[2], q[3]);
        EXPECT_TRUE(bounds.contains(q[0], q[1], q[2], q[3], sine));
        cones_volume += CGAL::volume(q[0], q[1], q[2], q[3]);
        cones.push_back(sine);
      }
    }
    EXPECT_NEAR(cones_volume, cavity_volume, 1e-12 * cavity_volume);
    std::vector<double> after = p.after, old = p.before;
    std::sort(cones.begin(), cones.end());
    std::sort(after.begin(), after.end());
    EXPECT_EQ(cones, after);
    EXPECT_GT(BODT::internal::compare_worst_first(after, old), 0);
  }
  EXPECT_GT(found, 0) << "no cavity found: the checks would not reach it";

  BODT::Insertion_options opt;
  opt.cavity = true;
  opt.quality_threshold = 0.5;
  const auto stats = cavity_pass(c3t3, bounds, opt, 1);
  EXPECT_GT(stats.cavity_insertions, 0u);
  EXPECT_EQ(stats.vertices_added, stats.cavity_insertions);
  expect_valid(c3t3);
  const State after = state(c3t3);
  expect_same_volumes(before, after);
  EXPECT_EQ(after.vertices, before.vertices + stats.cavity_insertions);
  EXPECT_EQ(after.facets, before.facets);
  std::vector<double> qualities_before, qualities_after;
  for(const auto& c : cells) qualities_before.push_back(c.first);
  for(auto c = c3t3.cells_in_complex_begin(); c != c3t3.cells_in_complex_end(); ++c)
    qualities_after.push_back(BODT::internal::min_dihedral_sine(pt(c->vertex(0)), pt(c->vertex(1)),
                                                                pt(c->vertex(2)), pt(c->vertex(3))));
  EXPECT_GE(*std::min_element(qualities_after.begin(), qualities_after.end()), worst_before);
  EXPECT_GT(BODT::internal::compare_worst_first(qualities_after, qualities_before), 0);
}

// The cavity pass runs its searches ahead on the threads, in rounds of one cell
// per thread, and uses a search only if no cell it read was replaced meanwhile:
// on 1, 2 and 4 threads the same cells, at the same points, in the same order.
TEST(CavityInsertion, SamePassOnAnyNumberOfThreads)
{
  const bodt_test::Delaunay_cells d(600);
  std::vector<int> labels;
  for(const auto& c : d.cells)
  {
    double y = 0;
    for(int v : c) y += d.points[static_cast<std::size_t>(v)].y() / 4;
    labels.push_back(y < 0.4 ? 1 : 3);
  }
  const Tet_mesh mesh = make_mesh(d.points, d.cells, labels);
  using Cell_points = std::array<std::array<double, 3>, 4>;
  auto run = [&](int threads, std::size_t& insertions) {
    File_c3t3 c3t3;
    BODT::tet_mesh_to_c3t3(mesh, c3t3, "test");
    auto cp = c3t3.triangulation().geom_traits().construct_point_3_object();
    BODT::internal::Dihedral_bounds bounds;
    for(auto c = c3t3.cells_in_complex_begin(); c != c3t3.cells_in_complex_end(); ++c)
      bounds.include(cp(c->vertex(0)->point()), cp(c->vertex(1)->point()), cp(c->vertex(2)->point()),
                     cp(c->vertex(3)->point()));
    BODT::Insertion_options opt;
    opt.cavity = true;
    opt.quality_threshold = 0.5;
    opt.max_cavity_attempts = 40;
    insertions = cavity_pass(c3t3, bounds, opt, threads).cavity_insertions;
    expect_valid(c3t3);
    std::vector<std::pair<int, Cell_points>> cells;
    for(auto c = c3t3.cells_in_complex_begin(); c != c3t3.cells_in_complex_end(); ++c)
    {
      Cell_points q;
      for(int k = 0; k < 4; ++k)
      {
        const Point x = cp(c->vertex(k)->point());
        q[static_cast<std::size_t>(k)] = {x.x(), x.y(), x.z()};
      }
      std::sort(q.begin(), q.end());
      cells.emplace_back(c3t3.subdomain_index(c), q);
    }
    std::sort(cells.begin(), cells.end());
    return cells;
  };
  std::size_t one = 0;
  const auto on_one = run(1, one);
  EXPECT_GT(one, 1u) << "too few insertions for rounds to meet";
  for(int threads : {2, 4})
  {
    std::size_t n = 0;
    EXPECT_EQ(run(threads, n), on_one) << threads << " threads";
    EXPECT_EQ(n, one);
  }
}

// The pipeline with insertion over CGAL-meshed inputs: within the budget, every
// subdomain's volume kept, no inverted cell, a valid complex, corners where they
// were, curve edges forming the same curves, and better than the input.
class InsertionPipeline : public ::testing::TestWithParam<bodt_inputs::Shape>
{};

TEST_P(InsertionPipeline, KeepsLabelsVolumesAndValidity)
{
  using namespace bodt_inputs;
  const Generated_mesh input = make_input(GetParam(), Size::small);
  C3t3 c3t3 = input.c3t3;
  const auto before = BODT::mesh_quality(c3t3);
  auto cp = c3t3.triangulation().geom_traits().construct_point_3_object();
  std::set<Point> corners;
  for(auto v = c3t3.vertices_in_complex_begin(); v != c3t3.vertices_in_complex_end(); ++v)
    corners.insert(cp(v->point()));
  std::size_t curve_edges_before = 0;
  for(auto e = c3t3.edges_in_complex_begin(); e != c3t3.edges_in_complex_end(); ++e) ++curve_edges_before;

  const std::size_t n = c3t3.triangulation().number_of_vertices();
  const auto r = BODT::smooth(c3t3, BODT::Smoothing_options());
  const auto after = BODT::mesh_quality(c3t3);

  EXPECT_LE(r.insertion.vertices_added, static_cast<std::size_t>(std::ceil(0.05 * double(n))));
  EXPECT_EQ(c3t3.triangulation().number_of_vertices(), n + r.insertion.vertices_added);
  EXPECT_TRUE(c3t3.triangulation().tds().is_valid());
  EXPECT_TRUE(c3t3.is_valid());
  std::size_t bad = 0;
  for(auto c = c3t3.triangulation().finite_cells_begin(); c != c3t3.triangulation().finite_cells_end(); ++c)
    if(CGAL::orientation(cp(c->vertex(0)->point()), cp(c->vertex(1)->point()), cp(c->vertex(2)->point()),
                         cp(c->vertex(3)->point())) != CGAL::POSITIVE)
      ++bad;
  EXPECT_EQ(bad, 0u);
  for(const auto& kv : before.volume_per_subdomain)
    EXPECT_NEAR(after.volume_per_subdomain.at(kv.first), kv.second, 1e-10 * kv.second);
  std::set<Point> corners_after;
  for(auto v = c3t3.vertices_in_complex_begin(); v != c3t3.vertices_in_complex_end(); ++v)
    corners_after.insert(cp(v->point()));
  EXPECT_EQ(corners_after, corners);
  // A curve split at a new vertex has one more edge; curve vertices stay on curves.
  std::size_t curve_edges = 0;
  for(auto e = c3t3.edges_in_complex_begin(); e != c3t3.edges_in_complex_end(); ++e)
  {
    ++curve_edges;
    EXPECT_LE(c3t3.in_dimension(e->first->vertex(e->second)), 1);
    EXPECT_LE(c3t3.in_dimension(e->first->vertex(e->third)), 1);
  }
  EXPECT_GE(curve_edges, curve_edges_before);
  EXPECT_LE(curve_edges, curve_edges_before + r.insertion.vertices_added);
  EXPECT_GE(after.min_dihedral_deg, before.min_dihedral_deg);
  EXPECT_LE(after.max_dihedral_deg, before.max_dihedral_deg);
}

INSTANTIATE_TEST_SUITE_P(All, InsertionPipeline, ::testing::ValuesIn(bodt_inputs::all_shapes()),
                         [](const ::testing::TestParamInfo<bodt_inputs::Shape>& info) {
                           return bodt_inputs::name(info.param);
                         });

// The budget caps the vertices added; 0 adds none.
TEST(InsertionBudget, CapsTheVerticesAdded)
{
  using namespace bodt_inputs;
  const Generated_mesh input = make_input(Shape::genus2, Size::small);
  std::size_t unlimited = 0;
  for(long long budget : {-1LL, 0LL, 3LL})
  {
    C3t3 c3t3 = input.c3t3;
    BODT::Smoothing_options opt;
    opt.max_vertex_insertions = budget;
    const auto r = BODT::smooth(c3t3, opt);
    if(budget < 0)
    {
      // The default budget: at most 5% of the input's vertices.
      unlimited = r.insertion.vertices_added;
      EXPECT_LE(double(unlimited), 0.05 * double(input.c3t3.triangulation().number_of_vertices()));
    }
    else
      EXPECT_LE(r.insertion.vertices_added, static_cast<std::size_t>(budget));
    if(budget == 0) { EXPECT_EQ(r.insertion.vertices_added, 0u); }
  }
  EXPECT_GT(unlimited, 3u) << "the small genus-2 mesh needs insertions; the test loses its point otherwise";
}
