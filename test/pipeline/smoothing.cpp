// B-ODT smoothing of CGAL-meshed inputs, 20 iterations: validity by exact
// predicates, volume per subdomain, corners, feature lines, boundary distance,
// quality never lower than the input's nor than the interior-only ODT baseline,
// determinism. Also the paper's random sphere as a Triangulation_3; and the flips
// and the phases through the pipeline (surface, volume, curves and validity kept,
// the same output for the same input and on any number of threads with every pass
// at work, what the flip pass's parallel rounds rely on, the largest-angle phase),
// and the flat view's re-reads after changes against a first read.
#include "inputs/generated_inputs.h"
#include "test_support.h"
#include "../../bench/jittered_grid.h"

#include <CGAL/BODT_3/Tet_mesh_conversion.h>
#include <CGAL/BODT_3/IO/mesh_io.h>
#include <CGAL/BODT_3/boundary_distance.h>
#include <CGAL/BODT_3/mesh_quality.h>
#include <CGAL/BODT_3/smooth.h>
#include <CGAL/BODT_3/internal/Smoothing/sweep_order.h>
#include <CGAL/BODT_3/internal/Insertion/Vertex_insertion.h>
#include <CGAL/BODT_3/internal/Topology/flip_pass.h>
#include <CGAL/bodt_optimize_mesh_3.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Random.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

using namespace bodt_inputs;
namespace BODT = CGAL::BODT_3;

namespace {

// Tolerance on angles: the guard compares cosines, the report uses atan2.
constexpr double kAngleSlack = 1e-9;

template <class Tr>
std::vector<Point> finite_points(const Tr& tr)
{
  auto cp = tr.geom_traits().construct_point_3_object();
  std::vector<Point> out;
  for(auto v = tr.finite_vertices_begin(); v != tr.finite_vertices_end(); ++v) out.push_back(cp(v->point()));
  return out;
}

// Every finite cell positively oriented (exact predicate) and the convex hull
// locally convex at every hull edge: the triangulation is geometrically valid.
template <class Tr>
void expect_valid(const Tr& tr)
{
  ASSERT_TRUE(tr.tds().is_valid());
  auto cp = tr.geom_traits().construct_point_3_object();
  std::size_t bad = 0, reflex = 0;
  for(auto c = tr.finite_cells_begin(); c != tr.finite_cells_end(); ++c)
    if(CGAL::orientation(cp(c->vertex(0)->point()), cp(c->vertex(1)->point()), cp(c->vertex(2)->point()),
                         cp(c->vertex(3)->point())) != CGAL::POSITIVE)
      ++bad;
  for(auto c = tr.all_cells_begin(); c != tr.all_cells_end(); ++c)
  {
    if(!c->has_vertex(tr.infinite_vertex())) continue;
    const int i = c->index(tr.infinite_vertex());
    // Replacing the infinite vertex by a finite neighbour's far vertex must not give
    // a positively oriented cell: the neighbour lies on the inner side of the facet.
    for(int k = 0; k < 4; ++k)
    {
      if(k == i) continue;
      const auto n = c->neighbor(k);
      const auto w = n->vertex(n->index(c));
      if(w == tr.infinite_vertex()) continue;
      Point p[4];
      for(int j = 0; j < 4; ++j) p[j] = j == i ? cp(w->point()) : cp(c->vertex(j)->point());
      if(CGAL::orientation(p[0], p[1], p[2], p[3]) == CGAL::POSITIVE) ++reflex;
    }
  }
  EXPECT_EQ(bad, 0u) << "inverted or flat cells";
  EXPECT_EQ(reflex, 0u) << "reflex convex hull edges";
}

double distance_to_line(const Point& p, const Point& a, const Point& b)
{
  return std::sqrt(CGAL::squared_distance(p, K::Line_3(a, b)));
}

class Smoothing : public ::testing::TestWithParam<Shape>
{};

// Counts the moves refused because their round-off would change a volume too much.
struct Volume_refusals
{
  std::size_t* refused;
  void after_classification(const BODT::Smoothing_result&) const {}
  void after_iteration(const BODT::Iteration_stats& s) const { *refused += s.refused_changing_volume; }
};

// A C3T3's corners, by position, and its number of vertices on feature curves.
struct Feature_census
{
  std::set<Point> corners;
  std::size_t curve_vertices = 0;
};

Feature_census feature_census(const C3t3& c3t3)
{
  const auto& tr = c3t3.triangulation();
  auto cp = tr.geom_traits().construct_point_3_object();
  Feature_census census;
  for(auto v = tr.finite_vertices_begin(); v != tr.finite_vertices_end(); ++v)
  {
    if(c3t3.in_dimension(v) == 0) census.corners.insert(cp(v->point()));
    census.curve_vertices += c3t3.in_dimension(v) == 1;
  }
  return census;
}

// The same points, cells and boundary triangles as the one-thread run's.
void expect_same_mesh(const BODT::Tet_mesh& m, const BODT::Tet_mesh& reference, int threads)
{
  EXPECT_TRUE(m.points == reference.points) << threads << " threads";
  EXPECT_TRUE(m.tets == reference.tets) << threads << " threads";
  EXPECT_TRUE(m.triangles == reference.triangles) << threads << " threads";
}

// No inverted cell, every subdomain's volume to 1e-10, the extreme angles no worse.
void expect_volumes_and_angles_kept(const BODT::Quality_report& before, const C3t3& c3t3)
{
  const auto after = BODT::mesh_quality(c3t3);
  EXPECT_EQ(after.inverted_tets, 0u);
  for(const auto& kv : before.volume_per_subdomain)
    EXPECT_NEAR(after.volume_per_subdomain.at(kv.first), kv.second, 1e-10 * kv.second) << "subdomain " << kv.first;
  EXPECT_GE(after.min_dihedral_deg, before.min_dihedral_deg - kAngleSlack);
  EXPECT_LE(after.max_dihedral_deg, before.max_dihedral_deg + kAngleSlack);
}

// What a run keeps whatever vertices it adds or removes: a valid triangulation,
// every subdomain's volume, the extreme angles, every corner where it was, and
// no vertex of a feature curve lost.
void expect_constraints_kept(const BODT::Quality_report& before, const Feature_census& features, const C3t3& c3t3)
{
  expect_valid(c3t3.triangulation());
  expect_volumes_and_angles_kept(before, c3t3);
  const Feature_census now = feature_census(c3t3);
  EXPECT_TRUE(now.corners == features.corners) << "a corner moved, went or came";
  EXPECT_GE(now.curve_vertices, features.curve_vertices);
}

// Runs `optimize(c3t3, threads)` on copies of `input` with 1, 2 and 4 threads:
// the same mesh on each; returns the one-thread result.
template <class Optimize>
C3t3 on_one_two_and_four_threads(const C3t3& input, const Optimize& optimize)
{
  C3t3 first;
  BODT::Tet_mesh reference;
  for(int threads : {1, 2, 4})
  {
    C3t3 c3t3 = input;
    optimize(c3t3, threads);
    const BODT::Tet_mesh m = BODT::c3t3_to_tet_mesh(c3t3);
    if(threads > 1)
    {
      expect_same_mesh(m, reference, threads);
      continue;
    }
    reference = m;
    first = c3t3;
  }
  return first;
}

} // namespace

TEST_P(Smoothing, TwentyIterationsKeepValidityVolumeFeaturesAndQuality)
{
  const Generated_mesh input = make_input(GetParam(), Size::small);
  C3t3 bodt = input.c3t3;
  C3t3 odt = input.c3t3, bodt_alone = input.c3t3;

  const auto before = BODT::mesh_quality(input.c3t3);
  const auto surface_before = BODT::boundary_triangles(input.c3t3);
  // Insertion adds vertices; insertion/insertion.cpp checks it. Here the points keep their identity.
  std::size_t volume_refusals = 0;
  const auto code = CGAL::bodt_optimize_mesh_3(bodt, CGAL::parameters::vertex_insertion = false,
                                               CGAL::parameters::progress_visitor = Volume_refusals{&volume_refusals});
  EXPECT_TRUE(code == CGAL::MAX_ITERATION_NUMBER_REACHED || code == CGAL::CANT_IMPROVE_ANYMORE);
  // On an ordinary mesh the volume budget refuses nothing: B-ODT's results stay what they were.
  EXPECT_EQ(volume_refusals, 0u);
  // The paper's comparison of the smoothers alone: B-ODT against interior-only ODT.
  CGAL::bodt_optimize_mesh_3(odt, CGAL::parameters::moving_vertices = BODT::Moving_vertices::INTERIOR,
                             CGAL::parameters::vertex_insertion = false,
                             CGAL::parameters::topology_optimization = false);
  CGAL::bodt_optimize_mesh_3(bodt_alone, CGAL::parameters::vertex_insertion = false,
                             CGAL::parameters::topology_optimization = false);
  const auto after = BODT::mesh_quality(bodt);
  const auto after_odt = BODT::mesh_quality(odt);
  const auto after_alone = BODT::mesh_quality(bodt_alone);

  expect_valid(bodt.triangulation());
  expect_valid(odt.triangulation());
  EXPECT_EQ(after.inverted_tets, 0u);

  // Volumes: total and per subdomain.
  EXPECT_NEAR(after.volume, before.volume, 1e-10 * before.volume);
  ASSERT_EQ(after.volume_per_subdomain.size(), before.volume_per_subdomain.size());
  for(const auto& kv : before.volume_per_subdomain)
    EXPECT_NEAR(after.volume_per_subdomain.at(kv.first), kv.second, 1e-10 * kv.second) << "subdomain " << kv.first;

  // Corners to the bit; feature vertices on their feature lines.
  const auto p0 = finite_points(input.c3t3.triangulation());
  const auto p1 = finite_points(bodt.triangulation());
  ASSERT_EQ(p0.size(), p1.size());
  const double L = BODT::largest_bbox_side(surface_before);
  const auto polylines = feature_polylines(GetParam());
  std::size_t i = 0, corners = 0, features = 0, moved = 0;
  for(auto v = input.c3t3.triangulation().finite_vertices_begin();
      v != input.c3t3.triangulation().finite_vertices_end(); ++v, ++i)
  {
    if(p0[i] != p1[i]) ++moved;
    const int dim = input.c3t3.in_dimension(v);
    if(dim == 0)
    {
      EXPECT_EQ(p0[i], p1[i]) << "corner " << i << " moved";
      ++corners;
    }
    if(dim == 1 && GetParam() == Shape::sharp_part)
    {
      // The straight edge the vertex started on.
      double best = 1e300;
      Point a(0, 0, 0), b(0, 0, 0);
      for(const auto& pl : polylines)
        for(std::size_t s = 0; s + 1 < pl.size(); ++s)
        {
          const double d = std::sqrt(CGAL::squared_distance(p0[i], K::Segment_3(pl[s], pl[s + 1])));
          if(d < best) { best = d; a = pl[s]; b = pl[s + 1]; }
        }
      ASSERT_LT(best, 1e-12);
      EXPECT_LE(distance_to_line(p1[i], a, b), 1e-9 * L) << "feature vertex " << i << " left its edge";
      if(p0[i] != p1[i]) ++features;
    }
  }
  EXPECT_GT(moved, p0.size() / 10) << "B-ODT should move many vertices";
  if(GetParam() == Shape::sharp_part)
  {
    EXPECT_GT(corners, 0u);
    EXPECT_GT(features, 0u) << "no feature vertex moved along its edge";
  }

  // Shape: relative Hausdorff distance between the boundary surfaces.
  EXPECT_LT(BODT::relative_hausdorff_distance(surface_before, BODT::boundary_triangles(bodt)), 1e-2);

  // Quality: never worse than the input; the smoothers alone: B-ODT at least as good
  // as ODT; the pipeline (with flips) better than B-ODT alone.
  EXPECT_GE(after.min_dihedral_deg, before.min_dihedral_deg - kAngleSlack);
  EXPECT_LE(after.max_dihedral_deg, before.max_dihedral_deg + kAngleSlack);
  EXPECT_GE(after_odt.min_dihedral_deg, before.min_dihedral_deg - kAngleSlack);
  EXPECT_GE(after_alone.min_dihedral_deg, after_odt.min_dihedral_deg - kAngleSlack);
  EXPECT_GT(after.min_dihedral_deg, after_alone.min_dihedral_deg);
  EXPECT_LT(after.max_dihedral_deg, after_alone.max_dihedral_deg);
  EXPECT_LE(after.tets_below_small, before.tets_below_small);
}

// max_boundary_distance: every surface vertex of the result, old or inserted, and
// every point of a fine sample of its surface triangles, is within the bound of
// the input's surface (exact distance to its triangles), and the input's surface
// (the same sample) within the bound of the result's, the
// volumes, validity and quality are kept, the surface moves less than without the
// bound, and the result is the same on one and two threads.
TEST_P(Smoothing, MaxBoundaryDistanceKeepsTheSurfaceVerticesNearTheInput)
{
  const Generated_mesh input = make_input(GetParam(), Size::small);
  const double bound = 1e-3;
  C3t3 bounded = input.c3t3, two_threads = input.c3t3, free = input.c3t3;
  CGAL::bodt_optimize_mesh_3(bounded, CGAL::parameters::max_boundary_distance = bound,
                             CGAL::parameters::number_of_threads = 1);
  CGAL::bodt_optimize_mesh_3(two_threads, CGAL::parameters::max_boundary_distance = bound,
                             CGAL::parameters::number_of_threads = 2);
  CGAL::bodt_optimize_mesh_3(free);
  EXPECT_EQ(finite_points(bounded.triangulation()), finite_points(two_threads.triangulation()));

  const auto before = BODT::mesh_quality(input.c3t3);
  const auto after = BODT::mesh_quality(bounded);
  expect_valid(bounded.triangulation());
  EXPECT_EQ(after.inverted_tets, 0u);
  for(const auto& kv : before.volume_per_subdomain)
    EXPECT_NEAR(after.volume_per_subdomain.at(kv.first), kv.second, 1e-10 * kv.second) << "subdomain " << kv.first;
  EXPECT_GE(after.min_dihedral_deg, before.min_dihedral_deg - kAngleSlack);
  EXPECT_LE(after.max_dihedral_deg, before.max_dihedral_deg + kAngleSlack);

  const std::vector<K::Triangle_3> surface = BODT::boundary_triangles(input.c3t3);
  const double L = BODT::largest_bbox_side(surface);
  using Primitive = CGAL::AABB_triangle_primitive<K, std::vector<K::Triangle_3>::const_iterator>;
  CGAL::AABB_tree<CGAL::AABB_traits<K, Primitive>> tree(surface.begin(), surface.end());
  auto cp = bounded.triangulation().geom_traits().construct_point_3_object();
  std::size_t surface_vertices = 0;
  double farthest = 0;
  for(auto f = bounded.facets_in_complex_begin(); f != bounded.facets_in_complex_end(); ++f)
    for(int k = 0; k < 4; ++k)
      if(k != f->second)
      {
        ++surface_vertices;
        farthest = (std::max)(farthest, std::sqrt(tree.squared_distance(cp(f->first->vertex(k)->point()))));
      }
  ASSERT_GT(surface_vertices, 0u);
  EXPECT_LE(farthest, bound * L * (1 + 1e-9));
  // And between them: points of every surface triangle, 45 per triangle; and the
  // other way, the input's surface near the result's.
  const std::vector<K::Triangle_3> result = BODT::boundary_triangles(bounded);
  for(const K::Point_3& q : CGAL::BODT_3::internal::grid_points(result, 8))
    farthest = (std::max)(farthest, std::sqrt(tree.squared_distance(q)));
  EXPECT_LE(farthest, bound * L * (1 + 1e-9));
  CGAL::AABB_tree<CGAL::AABB_traits<K, Primitive>> result_tree(result.begin(), result.end());
  double farthest_input = 0;
  for(const K::Point_3& q : CGAL::BODT_3::internal::grid_points(surface, 8))
    farthest_input = (std::max)(farthest_input, std::sqrt(result_tree.squared_distance(q)));
  EXPECT_LE(farthest_input, bound * L * (1 + 1e-9));

  const double with_bound = BODT::relative_hausdorff_distance(surface, BODT::boundary_triangles(bounded));
  const double without = BODT::relative_hausdorff_distance(surface, BODT::boundary_triangles(free));
  if(without > 2 * bound)
  {
    EXPECT_LT(with_bound, without);
  }
}

TEST_P(Smoothing, SameInputSameOutput)
{
  const Generated_mesh input = make_input(GetParam(), Size::small);
  C3t3 a = input.c3t3, b = input.c3t3;
  CGAL::bodt_optimize_mesh_3(a);
  CGAL::bodt_optimize_mesh_3(b);
  EXPECT_EQ(finite_points(a.triangulation()), finite_points(b.triangulation()));
}

// Everything a user gets back, exactly: every vertex position (as hexadecimal
// floats), every cell by vertex numbers with its subdomain, every facet of the
// complex with its patch, in the triangulation's own order.
template <class C3T3>
std::string snapshot(const C3T3& c3t3)
{
  const auto& tr = c3t3.triangulation();
  auto cp = tr.geom_traits().construct_point_3_object();
  std::ostringstream out;
  std::map<typename C3T3::Vertex_handle, int> number;
  char buffer[128];
  for(auto v = tr.finite_vertices_begin(); v != tr.finite_vertices_end(); ++v)
  {
    const auto p = cp(v->point());
    std::snprintf(buffer, sizeof buffer, "%a %a %a %d\n", p.x(), p.y(), p.z(), c3t3.in_dimension(v));
    out << buffer;
    number.emplace(v, static_cast<int>(number.size()));
  }
  for(auto c = c3t3.cells_in_complex_begin(); c != c3t3.cells_in_complex_end(); ++c)
    out << number[c->vertex(0)] << ' ' << number[c->vertex(1)] << ' ' << number[c->vertex(2)] << ' '
        << number[c->vertex(3)] << ' ' << c3t3.subdomain_index(c) << '\n';
  for(auto f = c3t3.facets_in_complex_begin(); f != c3t3.facets_in_complex_end(); ++f)
  {
    std::array<int, 3> t;
    for(int k = 0, m = 0; k < 4; ++k)
      if(k != f->second) t[m++] = number[f->first->vertex(k)];
    std::sort(t.begin(), t.end());
    const auto patch = c3t3.surface_patch_index(*f);
    out << t[0] << ' ' << t[1] << ' ' << t[2] << ' ' << patch.first << ' ' << patch.second << '\n';
  }
  return out.str();
}

// The default pipeline (sweeps, flips, max-min steps, insertion) gives the same
// mesh, bit for bit, on 1, 2 and 4 threads.
TEST_P(Smoothing, SameOutputOnAnyNumberOfThreads)
{
  const Generated_mesh input = make_input(GetParam(), Size::small);
  std::string reference;
  for(int threads : {1, 2, 4})
  {
    C3t3 c3t3 = input.c3t3;
    CGAL::bodt_optimize_mesh_3(c3t3, CGAL::parameters::max_iteration_number = 6,
                               CGAL::parameters::number_of_threads = threads);
    const std::string now = snapshot(c3t3);
    if(threads == 1)
      reference = now;
    else
      EXPECT_TRUE(now == reference) << threads << " threads give another mesh than one thread";
  }
  EXPECT_NE(reference, snapshot(input.c3t3)) << "the pipeline changed nothing: the test would prove nothing";
}

// The sweep's colouring: every movable vertex once, and no two vertices of a
// colour in one cell or in one hull check (what lets them move concurrently).
template <class K>
void expect_valid_colouring(const BODT::internal::Flat_mesh<K>& mesh, const std::vector<char>& movable)
{
  const BODT::internal::Sweep_order order = BODT::internal::sweep_order(mesh, movable);
  std::vector<int> colour(mesh.number_of_vertices(), -1);
  for(std::size_t k = 0; k + 1 < order.colour_begin.size(); ++k)
    for(int i = order.colour_begin[k]; i < order.colour_begin[k + 1]; ++i)
    {
      ASSERT_EQ(colour[order.vertices[i]], -1) << "vertex visited twice";
      colour[order.vertices[i]] = static_cast<int>(k);
    }
  for(std::size_t v = 0; v < movable.size(); ++v) EXPECT_EQ(colour[v] >= 0, movable[v] != 0);
  std::size_t clashes = 0;
  for(const auto& c : mesh.cells)
    for(int i = 0; i < 4; ++i)
      for(int j = i + 1; j < 4; ++j)
        clashes += colour[c[i]] >= 0 && colour[c[i]] == colour[c[j]] ? 1 : 0;
  std::size_t hull_checks = 0;
  for(const auto& h : mesh.hull_checks)
    for(int k = 0; k < 3; ++k, ++hull_checks)
      clashes += colour[h[k]] >= 0 && colour[h[k]] == colour[h[3]] ? 1 : 0;
  EXPECT_EQ(clashes, 0u);
  EXPECT_GT(order.colour_begin.size(), 2u);
}

TEST_P(Smoothing, ColouringSeparatesEveryCellAndHullCheck)
{
  Generated_mesh input = make_input(GetParam(), Size::small);
  BODT::internal::C3t3_adapter<C3t3> adapter(input.c3t3);
  BODT::internal::Flat_view<BODT::internal::C3t3_adapter<C3t3>> view(adapter);
  const auto& mesh = view.mesh();
  // Every vertex movable, and a random half: the colouring holds for any choice.
  CGAL::Random random(static_cast<unsigned>(GetParam()) + 7);
  std::vector<char> all(mesh.number_of_vertices(), 1), half(mesh.number_of_vertices());
  for(char& m : half) m = random.get_bool() ? 1 : 0;
  expect_valid_colouring(mesh, all);
  expect_valid_colouring(mesh, half);
}

INSTANTIATE_TEST_SUITE_P(All, Smoothing, ::testing::ValuesIn(all_shapes()),
                         [](const ::testing::TestParamInfo<Shape>& info) { return name(info.param); });

TEST(RandomSphere, BoundaryVerticesMoveAndTheHullStaysConvex)
{
  Delaunay tr = make_random_sphere();
  const auto before = BODT::mesh_quality(tr);
  const auto surface_before = BODT::boundary_triangles(tr);
  const auto p0 = finite_points(tr);
  const auto code = CGAL::bodt_optimize_mesh_3(tr, CGAL::parameters::max_iteration_number = 20);
  EXPECT_NE(code, CGAL::MESH_OPTIMIZATION_UNKNOWN_ERROR);
  const auto after = BODT::mesh_quality(tr);
  expect_valid(tr);
  EXPECT_NEAR(after.volume, before.volume, 1e-10 * before.volume);
  EXPECT_GE(after.min_dihedral_deg, before.min_dihedral_deg - kAngleSlack);
  EXPECT_LE(after.max_dihedral_deg, before.max_dihedral_deg + kAngleSlack);
  EXPECT_NE(finite_points(tr), p0);
  // Every vertex is on the boundary and moves in its tangent plane, on a coarse
  // sphere: the boundary moves by about 1.2% of the box (measured), under 2%.
  EXPECT_LT(BODT::relative_hausdorff_distance(surface_before, BODT::boundary_triangles(tr)), 2e-2);
}

// A triangulation whose every vertex is on its convex hull: the hull checks
// constrain the colouring, and the result is the same on any number of threads.
TEST(RandomSphere, SameOutputOnAnyNumberOfThreadsAndAValidColouring)
{
  const Delaunay input = make_random_sphere();
  {
    Delaunay tr = input;
    BODT::internal::Triangulation_3_adapter<Delaunay> adapter(tr);
    BODT::internal::Flat_view<BODT::internal::Triangulation_3_adapter<Delaunay>> view(adapter);
    ASSERT_FALSE(view.mesh().hull_checks.empty());
    expect_valid_colouring(view.mesh(), std::vector<char>(view.mesh().number_of_vertices(), 1));
  }
  std::vector<Point> reference;
  for(int threads : {1, 2, 4})
  {
    Delaunay tr = input;
    CGAL::bodt_optimize_mesh_3(tr, CGAL::parameters::max_iteration_number = 6,
                               CGAL::parameters::number_of_threads = threads);
    if(threads == 1)
      reference = finite_points(tr);
    else
      EXPECT_TRUE(finite_points(tr) == reference) << threads << " threads";
  }
  EXPECT_NE(reference, finite_points(input));
}

namespace {

// The view, re-read, holds what a first read of the same triangulation holds.
template <class Adapter>
void expect_first_read(Adapter& adapter, const BODT::internal::Flat_view<Adapter>& view)
{
  Adapter again(adapter);
  const BODT::internal::Flat_view<Adapter> first(again);
  ASSERT_EQ(view.cells(), first.cells());
  const auto& m = view.mesh();
  const auto& f = first.mesh();
  for(std::size_t k = 0; k < m.cells.size(); ++k)
    for(int i = 0; i < 4; ++i)
      ASSERT_EQ(view.vertices()[m.cells[k][i]], first.vertices()[f.cells[k][i]]) << "cell " << k;
  EXPECT_EQ(m.neighbor, f.neighbor);
  EXPECT_EQ(m.in_mesh, f.in_mesh);
  EXPECT_EQ(m.subdomain, f.subdomain);
  EXPECT_EQ(m.hull_checks.size(), f.hull_checks.size());
}

} // namespace

// The re-read after a pass keeps what it can of the last read (Flat_view::read_cells):
// after an insertion that replaces cells and flips that change cells in place
// (CGAL's own 2-3 flips reuse cells), it must give what a first read gives.
TEST(RandomSphere, ReReadAfterChangesIsAFirstRead)
{
  Delaunay tr = make_random_sphere();
  using Adapter = BODT::internal::Triangulation_3_adapter<Delaunay>;
  Adapter adapter(tr);
  BODT::internal::Flat_view<Adapter> view(adapter);
  tr.insert(Point(0.01, 0.02, 0.03));   // while the triangulation is still Delaunay
  int flips = 0;
  for(auto c = tr.finite_cells_begin(); c != tr.finite_cells_end() && flips < 8; ++c)
    for(int i = 0; i < 4 && flips < 8; ++i)
      if(!tr.is_infinite(c->neighbor(i)) && tr.flip(c, i))
      {
        ++flips;
        break;   // the cell may be gone
      }
  ASSERT_GT(flips, 0);
  ASSERT_TRUE(tr.tds().is_valid());   // no longer Delaunay
  view.refresh();
  expect_first_read(adapter, view);
}

namespace {

// Moves some vertices of the view through `guard` (written back), then some on
// the triangulation alone (the view's points stay, so that the re-read finds
// them moved); returns how many of each.
template <class Adapter, class Guard>
std::array<std::size_t, 2> move_some(Adapter& adapter, BODT::internal::Flat_view<Adapter>& view, Guard& guard)
{
  using Vertex_handle = typename Adapter::Vertex_handle;
  const auto& m = view.mesh();
  typename Guard::Trial trial;
  std::array<std::size_t, 2> moved{0, 0};
  auto toward_neighbours = [&](int v) {
    typename Guard::Vector sum(0, 0, 0);
    int n = 0;
    for(int k = m.incidence_begin[v]; k < m.incidence_begin[v + 1]; ++k)
      for(int w : m.incidences[k].face)
      {
        sum = sum + (m.points[w] - m.points[v]);
        ++n;
      }
    return n == 0 ? sum : sum / (10.0 * n);
  };
  const int nv = static_cast<int>(m.number_of_vertices());
  for(int v = 0; v < nv && moved[0] < 20; v += 5)
    if(view.vertices()[v] != Vertex_handle()) moved[0] += guard.move(v, toward_neighbours(v), trial) > 0;
  view.write_back();
  for(int v = 2; v < nv && moved[1] < 20; v += 5)
  {
    if(view.vertices()[v] == Vertex_handle()) continue;
    const auto p = m.points[v] + toward_neighbours(v);
    if(p == m.points[v] || !guard.accepts(v, p, trial)) continue;
    BODT::internal::set_bare_point(adapter.triangulation(), view.vertices()[v], p);
    ++moved[1];
  }
  return moved;
}

// Flip passes (of the cells whose smallest sine is below `threshold`), then
// `splits` edges split (every third split undone), then flips again, each
// after some moves (move_some) and followed by a re-read; returns the flips, the
// splits kept, the re-reads that took only the new cells from the
// triangulation, and the moves through the guard and on the triangulation that
// a re-read followed. After each re-read the move guard, refreshed from the cells'
// moves and the moved vertices, has the qualities (bit for bit) and the
// volume-keeping vertices that a guard made on the mesh then has.
template <class Adapter>
std::array<std::size_t, 5> change_and_reread(Adapter& adapter, BODT::internal::Flat_view<Adapter>& view,
                                             bool flip_outside, double threshold, std::size_t splits)
{
  namespace I = BODT::internal;
  using Vertex_handle = typename Adapter::Vertex_handle;
  using Cell_handle = typename Adapter::Cell_handle;
  using Guard = I::Move_guard<typename I::Flat_view<Adapter>::Kernel>;
  auto& tr = adapter.triangulation();
  auto vertex_id = [&view](Vertex_handle v) { return view.index(v); };
  BODT::Flip_options flips;
  flips.quality_threshold = threshold;
  flips.flip_outside = flip_outside;
  std::array<std::size_t, 5> done{0, 0, 0, 0, 0};
  const I::Volume_budget budget = I::Volume_budget::of(view.mesh());
  Guard guard(view.mesh(), true, I::Dihedral_bounds(), BODT::Quality_measure::min_dihedral_sine, 1, &budget);
  std::array<std::size_t, 2> moves{0, 0};
  std::size_t seen_moved = 0, last_direct = 0;
  auto reread = [&] {
    view.refresh();
    std::vector<int> moved;
    view.read_points(&moved);
    seen_moved += moved.size();
    guard.refresh(view.last_cell_moves(), moved);
    done[2] += view.cells_read() > 0 && view.cells_read() < view.cells().size();
    expect_first_read(adapter, view);
    const Guard fresh(view.mesh(), true, I::Dihedral_bounds(), BODT::Quality_measure::min_dihedral_sine, 1, &budget);
    std::size_t differ = 0;
    for(int c = 0; c < static_cast<int>(view.mesh().cells.size()); ++c)
      differ += guard.cell_quality(c) != fresh.cell_quality(c);
    EXPECT_EQ(differ, 0u) << "cell qualities not those of a whole refresh";
    for(int v = 0; v < static_cast<int>(view.mesh().number_of_vertices()); ++v)
      ASSERT_EQ(guard.keeps_volume(v), fresh.keeps_volume(v)) << "vertex " << v;
    const auto now = move_some(adapter, view, guard);
    moves[0] += now[0];
    moves[1] += now[1];
    last_direct = now[1];
  };
  reread();
  auto flip_and_reread = [&] {
    std::vector<Vertex_handle> touched;
    done[0] += I::flip_pass(adapter, flips, I::Dihedral_bounds(), vertex_id, touched).total();
    reread();
  };
  for(int pass = 0; pass < 3; ++pass) flip_and_reread();
  std::vector<std::pair<Vertex_handle, Vertex_handle>> edges;
  std::size_t n = 0;
  for(auto c = tr.finite_cells_begin(); c != tr.finite_cells_end() && edges.size() < splits; ++c)
    if(n++ % 7 == 0) edges.push_back({c->vertex(0), c->vertex(1)});
  auto cp = tr.geom_traits().construct_point_3_object();
  std::size_t tried = 0;
  for(const auto& [u, v] : edges)
  {
    Cell_handle c;
    int i, j;
    if(!tr.tds().is_edge(u, v, c, i, j)) continue;
    I::Split_record<Adapter> record;
    if(!I::split_edge(adapter, c, i, j, CGAL::midpoint(cp(u->point()), cp(v->point())), record)) continue;
    if(++tried % 3 == 0)
      I::undo_split(adapter, record);
    else
      ++done[1];
  }
  reread();
  for(int pass = 0; pass < 2; ++pass) flip_and_reread();
  EXPECT_EQ(seen_moved, moves[1] - last_direct) << "the re-reads did not find the moves made on the triangulation";
  done[3] = moves[0];
  done[4] = seen_moved;
  return done;
}

// change_and_reread on a view of `adapter` that follows the changes: enough
// flips, splits, re-reads of the new cells alone and moves to have tested something.
template <class Adapter>
void expect_rereads_of_changes(Adapter& adapter, bool flip_outside, double threshold, int splits,
                               std::size_t at_least_splits, std::size_t at_least_moves)
{
  BODT::internal::Flat_view<Adapter> view(adapter);
  view.follow_changes();
  const auto done = change_and_reread(adapter, view, flip_outside, threshold, splits);
  EXPECT_GT(done[0], 10u) << "flips";
  EXPECT_GE(done[1], at_least_splits) << "splits";
  EXPECT_GE(done[2], 2u) << "re-reads of the new cells alone";
  EXPECT_GE(done[3], at_least_moves) << "moves through the guard";
  EXPECT_GE(done[4], at_least_moves) << "moves on the triangulation";
}

} // namespace

// Flat_view::refresh when it follows the changes (re-reading only the cells
// replace_cells logged): after flip passes, edge splits kept and undone, on
// CGAL-meshed inputs with features and two subdomains (with flips outside the
// complex, by its convex hull) and on the paper's random sphere, every re-read
// gives what a first read gives; and the move guard refreshed from the changes
// (Move_guard::refresh with the cells' moves and the moved vertices) what a
// guard made anew gives, bit for bit.
TEST(FlatView, ReReadOfTheLoggedChangesIsAFirstRead)
{
  for(Shape shape : {Shape::two_subdomains, Shape::genus2})
  {
    SCOPED_TRACE(name(shape));
    C3t3 c3t3 = make_input(shape, Size::small).c3t3;
    BODT::internal::C3t3_adapter<C3t3> adapter(c3t3);
    expect_rereads_of_changes(adapter, true, 0.3, 12, 4, 20);
  }
  Delaunay tr = make_random_sphere();
  BODT::internal::Triangulation_3_adapter<Delaunay> adapter(tr);
  // Its vertices are mostly on the convex hull, which the guard keeps convex: few moves.
  expect_rereads_of_changes(adapter, false, 0.05, 4, 1, 0);
}

TEST(Visitor, ReportsEveryIteration)
{
  struct Counting_visitor
  {
    std::size_t* iterations;
    std::size_t* classified;
    std::size_t* all;
    void after_classification(const BODT::Smoothing_result& r) const { *classified = r.interior_vertices; }
    void after_iteration(const BODT::Iteration_stats& s) const
    {
      if(s.phase == 0) *iterations = s.iteration;
      ++*all;
    }
  };
  Generated_mesh input = make_input(Shape::sphere, Size::small);
  std::size_t iterations = 0, classified = 0, all = 0;
  const auto code = CGAL::bodt_optimize_mesh_3(input.c3t3, CGAL::parameters::max_iteration_number = 3,
                                               CGAL::parameters::progress_visitor =
                                                   Counting_visitor{&iterations, &classified, &all});
  EXPECT_EQ(code, CGAL::MAX_ITERATION_NUMBER_REACHED);
  EXPECT_EQ(iterations, 3u);   // the main phase's
  EXPECT_GT(all, 3u);          // then the largest-angle and worst-cell phases', at most 3 each
  EXPECT_LE(all, 12u);
  EXPECT_GT(classified, 0u);
}

TEST(ReturnCodes, ConvergenceAndTimeLimitStopTheSweeps)
{
  struct Counter
  {
    std::size_t* iterations;
    void after_classification(const BODT::Smoothing_result&) const {}
    void after_iteration(const BODT::Iteration_stats& s) const { *iterations = s.iteration; }
  };
  const Generated_mesh input = make_input(Shape::sphere, Size::small);
  std::size_t its = 0;
  C3t3 a = input.c3t3;
  // Every first-sweep move is far below a billion local sizes: converged after one
  // sweep without flips (in each of the three phases with sweeps; the worst-cell
  // phase has none, and ends when the extremes stop improving), and after the
  // first iteration with no flip with them.
  EXPECT_EQ(CGAL::bodt_optimize_mesh_3(a, CGAL::parameters::convergence = 1e9,
                                       CGAL::parameters::topology_optimization = false,
                                       CGAL::parameters::vertex_insertion = false,
                                       CGAL::parameters::worst_cell_phase = false,
                                       CGAL::parameters::progress_visitor = Counter{&its}),
            CGAL::CONVERGENCE_REACHED);
  EXPECT_EQ(its, 3u);
  struct Flip_counter
  {
    std::size_t* iterations;
    std::size_t* last_flips;
    void after_classification(const BODT::Smoothing_result&) const {}
    void after_iteration(const BODT::Iteration_stats& s) const
    {
      *iterations = s.iteration;
      *last_flips = s.topology.total();
    }
  };
  std::size_t last_flips = 1;
  C3t3 a2 = input.c3t3;
  EXPECT_EQ(CGAL::bodt_optimize_mesh_3(a2, CGAL::parameters::convergence = 1e9,
                                       CGAL::parameters::worst_cell_phase = false,
                                       CGAL::parameters::progress_visitor = Flip_counter{&its, &last_flips}),
            CGAL::CONVERGENCE_REACHED);
  EXPECT_GT(its, 1u);
  EXPECT_EQ(last_flips, 0u);
  C3t3 b = input.c3t3;
  EXPECT_EQ(CGAL::bodt_optimize_mesh_3(b, CGAL::parameters::time_limit = 1e-9,
                                       CGAL::parameters::max_iteration_number = 0,
                                       CGAL::parameters::progress_visitor = Counter{&its}),
            CGAL::TIME_LIMIT_REACHED);
  EXPECT_EQ(its, 1u);
}

// NODT (the paper's baseline): surface vertices leave the boundary and come back
// onto the input's boundary triangles; a flat face stays flat.
TEST(Nodt, SurfaceVerticesStayOnTheInputBoundary)
{
  const Generated_mesh input = make_input(Shape::sphere, Size::small);
  C3t3 c3t3 = input.c3t3;
  const std::vector<K::Triangle_3> triangles = BODT::boundary_triangles(input.c3t3);
  using Primitive = CGAL::AABB_triangle_primitive<K, std::vector<K::Triangle_3>::const_iterator>;
  CGAL::AABB_tree<CGAL::AABB_traits<K, Primitive>> tree(triangles.begin(), triangles.end());
  const auto before = BODT::mesh_quality(c3t3);
  BODT::Smoothing_options opt;
  opt.smoothing_method = BODT::Smoothing_method::NODT;
  opt.topology_optimization = false;
  opt.vertex_insertion = false;
  opt.max_min_threshold = 0;
  BODT::smooth(c3t3, opt);
  const auto after = BODT::mesh_quality(c3t3);
  auto cp = c3t3.triangulation().geom_traits().construct_point_3_object();
  std::size_t surface_vertices = 0, moved = 0;
  auto v0 = input.c3t3.triangulation().finite_vertices_begin();
  for(auto v = c3t3.triangulation().finite_vertices_begin(); v != c3t3.triangulation().finite_vertices_end(); ++v, ++v0)
  {
    if(c3t3.in_dimension(v) != 2) continue;
    ++surface_vertices;
    if(cp(v->point()) != cp(v0->point())) ++moved;
    EXPECT_LE(std::sqrt(tree.squared_distance(cp(v->point()))), 1e-12);
  }
  EXPECT_GT(moved, surface_vertices / 2);
  EXPECT_EQ(after.inverted_tets, 0u);
  EXPECT_GE(after.min_dihedral_deg, before.min_dihedral_deg - kAngleSlack);
}

// Found by the smoothing fuzz harness: a two-subdomain mesh with one vertex 4e10
// away. The pipeline kept the volume, but the report measured subdomain 2 as 921
// times larger, because a tetrahedron's volume was computed from its far vertex.
TEST(Volume, FarVertexMeshFromFuzzingKeepsItsMeasuredVolume)
{
  BODT::Tet_mesh m = CGAL::BODT_3::IO::read_mesh(std::string(BODT_FUZZ_FINDINGS) + "/flips_max_min_volume.mesh");
  const auto before = BODT::mesh_quality(m);
  BODT::Smoothing_options opt;
  opt.max_iteration_number = 3;
  // Tensor voting (read since issue 30 whatever the triangle labels) makes ten of its
  // twelve vertices corners, and then nothing moves and nothing flips.
  opt.preserve_features = false;
  const auto r = BODT::smooth(m, opt);
  EXPECT_GT(r.topology.total(), 0u) << "no flip: the test lost its point";
  const auto after = BODT::mesh_quality(m);
  EXPECT_EQ(after.inverted_tets, 0u);
  for(const auto& [label, volume] : before.volume_per_subdomain)
    EXPECT_NEAR(after.volume_per_subdomain.at(label), volume, 1e-10 * volume) << "subdomain " << label;
}

// Found by the smoothing fuzz harness: an interface vertex between a subdomain of
// unit-size cells and one with a vertex 4e10 away. Its move was made perpendicular
// to the normal of the far side, whose direction had lost the near side's digits,
// and the near subdomain lost 7.7% of its volume. Then the far side still changed
// by 3e-8 (relative) through round-off, until moves were paid from the volume
// budget (Volume_budget.h).
TEST(Volume, InterfaceNormalComesFromTheSideWithSmallerFaces)
{
  BODT::Tet_mesh m = CGAL::BODT_3::IO::read_mesh(std::string(BODT_FUZZ_FINDINGS) + "/interface_far_vertex.mesh");
  const auto before = BODT::mesh_quality(m);
  BODT::Smoothing_options opt;
  opt.max_iteration_number = 3;
  BODT::smooth(m, opt);
  const auto after = BODT::mesh_quality(m);
  EXPECT_EQ(after.inverted_tets, 0u);
  EXPECT_NEAR(after.volume_per_subdomain.at(1), before.volume_per_subdomain.at(1),
              1e-10 * before.volume_per_subdomain.at(1));
  EXPECT_NEAR(after.volume_per_subdomain.at(2), before.volume_per_subdomain.at(2),
              1e-10 * before.volume_per_subdomain.at(2));
}

// The volume promise over CGAL-meshed inputs whose features only tensor voting
// finds: each generated input as a file would carry it without its edges, corners
// and triangles, smoothed with the default pipeline (every vertex class moves:
// interior, surface, interface, feature found by voting), every subdomain's volume
// kept to 1e-11 of it (the run's budget), none inverted.
TEST(Volume, KeptWithFeaturesFoundByTensorVoting)
{
  for(Shape shape : {Shape::sharp_part, Shape::two_subdomains, Shape::genus2})
  {
    SCOPED_TRACE(name(shape));
    BODT::Tet_mesh m = BODT::c3t3_to_tet_mesh(make_input(shape, Size::small).c3t3);
    m.edges.clear();
    m.edge_labels.clear();
    m.corners.clear();
    m.required_vertices.clear();
    m.triangles.clear();
    m.triangle_labels.clear();
    const auto before = BODT::mesh_quality(m);
    BODT::Smoothing_options opt;
    opt.max_iteration_number = 10;
    const auto r = BODT::smooth(m, opt);
    EXPECT_TRUE(r.used_tensor_voting);
    EXPECT_GT(r.feature_vertices + r.surface_vertices, 0u);
    EXPECT_GT(r.moved_vertices, m.points.size() / 4);
    const auto after = BODT::mesh_quality(m);
    EXPECT_EQ(after.inverted_tets, 0u);
    for(const auto& [label, volume] : before.volume_per_subdomain)
      EXPECT_NEAR(after.volume_per_subdomain.at(label), volume, 1e-11 * volume) << "subdomain " << label;
  }
}

TEST(Nodt, AFlatFaceStaysFlat)
{
  // A box of 4 x 4 x 4 unit cubes with its vertices jittered inside the faces:
  // every boundary vertex keeps its coordinate on the face it lies in (the box's
  // edges and corners are found by tensor voting and move as in B-ODT).
  BODT::Tet_mesh m = bodt_test::cube_grid(4, [](int, int, int) { return 1; });
  CGAL::Random rng(3);
  for(auto& p : m.points)
  {
    double c[3] = {p.x(), p.y(), p.z()};
    for(double& x : c)
      if(x > 0 && x < 4) x += rng.get_double(-0.2, 0.2);
    p = Point(c[0], c[1], c[2]);
  }
  const BODT::Tet_mesh input = m;
  BODT::Smoothing_options opt;
  opt.smoothing_method = BODT::Smoothing_method::NODT;
  opt.topology_optimization = false;
  opt.vertex_insertion = false;
  opt.max_min_threshold = 0;
  BODT::smooth(m, opt);
  std::size_t moved = 0;
  for(std::size_t i = 0; i < m.points.size(); ++i)
  {
    for(int k = 0; k < 3; ++k)
    {
      const double x0 = input.points[i][k];
      if(x0 == 0 || x0 == 4)
      {
        EXPECT_LE(std::abs(m.points[i][k] - x0), 1e-12) << "vertex " << i;
      }
    }
    if(m.points[i] != input.points[i]) ++moved;
  }
  EXPECT_GT(moved, 0u);
}

// ---------------------------------------------------------------------------
// The flips (and the phases) through the whole pipeline, over CGAL-meshed inputs
// with features and two subdomains (the flips on constructed configurations are
// in topology/flips.cpp).
namespace pipeline_flips {

using Tet_mesh = BODT::Tet_mesh;
using Point = Tet_mesh::Point;
using bodt_inputs::C3t3;

std::array<Point, 3> sorted_points(Point a, Point b, Point c)
{
  std::array<Point, 3> t = {a, b, c};
  std::sort(t.begin(), t.end());
  return t;
}

// The pipeline over CGAL-meshed inputs: the boundary changes only by coplanar flips
// (same area per patch, every new facet coplanar with a facet it replaced), every
// subdomain keeps its volume, every curve edge stays, no cell is inverted, and the
// mesh ends better than it started.
class TopologyPipeline : public ::testing::TestWithParam<bodt_inputs::Shape>
{};

TEST_P(TopologyPipeline, FlipsKeepSurfaceVolumeCurvesAndValidity)
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

INSTANTIATE_TEST_SUITE_P(All, TopologyPipeline, ::testing::ValuesIn(bodt_inputs::all_shapes()),
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
// mesh with features and two subdomains, for each measure.
TEST(FlipPass, EvaluationsStayWithinTheCellsNeighbourhood)
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

// The whole pipeline gives the same cells on 1, 2 and 4 threads with every pass
// at work (flips, max-min steps, insertion, all three phases).
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
    BODT::Tet_mesh reference;
    Counts counts;
    for(int threads : {1, 2, 4})
    {
      C3t3 c3t3 = input.c3t3;
      Counts now;
      CGAL::bodt_optimize_mesh_3(c3t3, CGAL::parameters::number_of_threads = threads,
                                 CGAL::parameters::progress_visitor = Counting{&now});
      const BODT::Tet_mesh m = BODT::c3t3_to_tet_mesh(c3t3);
      if(threads == 1)
      {
        reference = m;
        counts = now;
        continue;
      }
      expect_same_mesh(m, reference, threads);
    }
    EXPECT_GT(counts.flips, 0u);
    EXPECT_GT(counts.max_min, 0u);
    EXPECT_GE(counts.phases, 3u);   // the worst-cell phase runs where the worst cell is above 28 degrees
    if(shape == Shape::genus2) { EXPECT_GT(counts.inserted, 0u); }
  }
}

// Edge contraction on CGAL-meshed inputs with features, corners and two
// subdomains (insertion off, so that every output vertex is an input vertex):
// validity, every subdomain's volume, every corner where it was, every feature
// vertex kept, the extreme angles no worse, the vertex count down by what the
// passes report and at most 5%, and the same cells on 1, 2 and 4 threads.
TEST(Pipeline, EdgeContractionKeepsVolumesFeaturesCornersOnAnyNumberOfThreads)
{
  using namespace bodt_inputs;
  struct Removals
  {
    std::size_t* removed;
    void after_classification(const BODT::Smoothing_result&) {}
    void after_iteration(const BODT::Iteration_stats& s) { *removed += s.contraction.contractions; }
  };
  std::size_t total = 0;
  for(Shape shape : {Shape::two_subdomains, Shape::genus2, Shape::sharp_part, Shape::torus})
  {
    SCOPED_TRACE(name(shape));
    const Generated_mesh input = make_input(shape, Size::small);
    const auto before = BODT::mesh_quality(input.c3t3);
    const auto& tr0 = input.c3t3.triangulation();
    const Feature_census features = feature_census(input.c3t3);
    std::size_t removed = 0;
    const C3t3 c3t3 = on_one_two_and_four_threads(input.c3t3, [&](C3t3& c, int threads) {
      std::size_t count = 0;
      CGAL::bodt_optimize_mesh_3(c, CGAL::parameters::edge_contraction = true,
                                 CGAL::parameters::vertex_insertion = false,
                                 CGAL::parameters::number_of_threads = threads,
                                 CGAL::parameters::progress_visitor = Removals{&count});
      if(threads == 1) removed = count;
    });
    total += removed;
    expect_constraints_kept(before, features, c3t3);
    EXPECT_EQ(c3t3.triangulation().number_of_vertices() + removed, tr0.number_of_vertices());
    EXPECT_LE(removed, tr0.number_of_vertices() / 20);
    EXPECT_EQ(feature_census(c3t3).curve_vertices, features.curve_vertices);   // none removed either
  }
  EXPECT_GT(total, 0u) << "no contraction: the checks would not reach it";
}

// The boundary ears of a C3T3 above `angle` degrees: mesh cells two of whose
// facets face another region (outside or another subdomain), measured at the
// edge those facets share.
template <class C3T3>
std::size_t ears_above(const C3T3& c3t3, double angle)
{
  const auto& tr = c3t3.triangulation();
  auto cp = tr.geom_traits().construct_point_3_object();
  auto region = [&](typename C3T3::Cell_handle c) {
    return c3t3.is_in_complex(c) ? int(c3t3.subdomain_index(c)) : -1;
  };
  std::size_t ears = 0;
  for(auto c = c3t3.cells_in_complex_begin(); c != c3t3.cells_in_complex_end(); ++c)
  {
    std::vector<int> off, on;
    for(int i = 0; i < 4; ++i) (region(c->neighbor(i)) != region(c) ? off : on).push_back(i);
    if(off.size() != 2) continue;
    // The facets opposite off[0] and off[1] meet at the edge of the other two vertices.
    auto p = [&](int i) { return cp(c->vertex(i)->point()); };
    const double a = std::abs(CGAL::approximate_dihedral_angle(p(on[0]), p(on[1]), p(off[0]), p(off[1])));
    ears += a > angle;
  }
  return ears;
}

// Ear splits on CGAL-meshed inputs with curved surfaces, features, corners and two
// subdomains: validity, every subdomain's volume, every corner where it was, no
// feature vertex lost, the extreme angles no worse, at most 5% more vertices, the
// same cells on 1, 2 and 4 threads; and over the inputs, fewer ears above the
// largest-angle threshold than without the option.
TEST(Pipeline, EarSplitsRemoveEarsAndKeepVolumesFeaturesCornersOnAnyNumberOfThreads)
{
  using namespace bodt_inputs;
  struct Ears
  {
    std::size_t* split;
    void after_classification(const BODT::Smoothing_result&) {}
    void after_iteration(const BODT::Iteration_stats& s) { *split += s.insertion.ear_splits; }
  };
  std::size_t total = 0, ears_without = 0, ears_with = 0;
  for(Shape shape : {Shape::torus, Shape::genus2, Shape::two_subdomains, Shape::sharp_part})
  {
    SCOPED_TRACE(name(shape));
    const Generated_mesh input = make_input(shape, Size::small);
    const auto before = BODT::mesh_quality(input.c3t3);
    const auto& tr0 = input.c3t3.triangulation();
    const Feature_census features = feature_census(input.c3t3);
    C3t3 plain = input.c3t3;
    CGAL::bodt_optimize_mesh_3(plain);
    ears_without += ears_above(plain, 120.0);
    std::size_t split = 0;
    const C3t3 c3t3 = on_one_two_and_four_threads(input.c3t3, [&](C3t3& c, int threads) {
      std::size_t count = 0;
      CGAL::bodt_optimize_mesh_3(c, CGAL::parameters::ear_splits = true,
                                 CGAL::parameters::number_of_threads = threads,
                                 CGAL::parameters::progress_visitor = Ears{&count});
      if(threads == 1) split = count;
    });
    total += split;
    ears_with += ears_above(c3t3, 120.0);
    expect_constraints_kept(before, features, c3t3);
    EXPECT_LE(c3t3.triangulation().number_of_vertices(), tr0.number_of_vertices() + tr0.number_of_vertices() / 20 + 1);
  }
  EXPECT_GT(total, 0u) << "no ear split: the checks would not reach it";
  EXPECT_LT(ears_with, ears_without) << ears_with << " ears above 120 degrees with the splits, " << ears_without << " without";
}

// Cavity insertion in the worst-cell phase (`cavity_insertion`, on by default) on CGAL-meshed
// inputs with curved surfaces, features, corners and two subdomains: validity,
// every subdomain's volume, every corner where it was, no feature vertex lost, at
// most 5% more vertices, the same cells on 1, 2 and 4 threads; and the phase
// never undoes what the phases before reached (the extreme angles at least those
// of the run without the worst-cell phase, which ends where that phase starts).
TEST(Pipeline, CavityInsertionKeepsVolumesFeaturesCornersOnAnyNumberOfThreads)
{
  using namespace bodt_inputs;
  struct Cavities
  {
    std::size_t* inserted;
    void after_classification(const BODT::Smoothing_result&) {}
    void after_iteration(const BODT::Iteration_stats& s) { *inserted += s.insertion.cavity_insertions; }
  };
  std::size_t total = 0;
  for(Shape shape : {Shape::torus, Shape::genus2, Shape::two_subdomains, Shape::sharp_part})
  {
    SCOPED_TRACE(name(shape));
    const Generated_mesh input = make_input(shape, Size::small);
    const auto before = BODT::mesh_quality(input.c3t3);
    const auto& tr0 = input.c3t3.triangulation();
    const Feature_census features = feature_census(input.c3t3);
    C3t3 three_phases = input.c3t3;
    CGAL::bodt_optimize_mesh_3(three_phases, CGAL::parameters::worst_cell_phase = false);
    const auto reached = BODT::mesh_quality(three_phases);
    std::size_t inserted = 0;
    const C3t3 c3t3 = on_one_two_and_four_threads(input.c3t3, [&](C3t3& c, int threads) {
      std::size_t count = 0;
      CGAL::bodt_optimize_mesh_3(c, CGAL::parameters::cavity_insertion = true,
                                 CGAL::parameters::number_of_threads = threads,
                                 CGAL::parameters::progress_visitor = Cavities{&count});
      if(threads == 1) inserted = count;
    });
    total += inserted;
    expect_constraints_kept(before, features, c3t3);
    EXPECT_LE(c3t3.triangulation().number_of_vertices(), tr0.number_of_vertices() + tr0.number_of_vertices() / 20 + 1);
    const auto after = BODT::mesh_quality(c3t3);
    EXPECT_GE(after.min_dihedral_deg, reached.min_dihedral_deg);
    EXPECT_LE(after.max_dihedral_deg, reached.max_dihedral_deg);
  }
  EXPECT_GT(total, 0u) << "no cavity insertion: the checks would not reach it";
}

// The worst-cell phase on a mesh the phases before leave above their 30-degree
// thresholds: it raises the smallest angle and never the largest, keeps validity
// and the volume, ends by itself, and gives the same bytes on 1 and 2 threads;
// switched off, the run is the three phases alone.
TEST(Pipeline, WorstCellPhaseRaisesTheWorstCellAboveTheThresholds)
{
  // The benchmark's hard grid: one subdomain, no boundary triangles; the phases
  // before end it with angles above 30 degrees.
  const BODT::Tet_mesh input = bodt_bench::jittered_grid(8, bodt_bench::Grid_kind::hard);
  struct Phases
  {
    std::size_t* worst_iterations;
    void after_classification(const BODT::Smoothing_result&) {}
    void after_iteration(const BODT::Iteration_stats& s) { *worst_iterations += s.phase == 3; }
  };
  BODT::Smoothing_options opt;
  opt.max_iteration_number = 5;
  opt.worst_cell_phase = false;
  BODT::Tet_mesh without = input;
  std::size_t none = 0;
  BODT::smooth(without, opt, Phases{&none});
  EXPECT_EQ(none, 0u);
  opt.worst_cell_phase = true;
  BODT::Tet_mesh with = input, two = input;
  std::size_t iterations = 0;
  BODT::smooth(with, opt, Phases{&iterations});
  opt.threads = 2;
  BODT::smooth(two, opt);
  EXPECT_TRUE(with.points == two.points && with.tets == two.tets);

  const auto before = BODT::mesh_quality(input);
  const auto q0 = BODT::mesh_quality(without);
  const auto q1 = BODT::mesh_quality(with);
  ASSERT_GT(q0.min_dihedral_deg, 30.0) << "the input would not reach the phase's case";
  EXPECT_GE(iterations, 1u);
  EXPECT_LE(iterations, opt.max_iteration_number);
  EXPECT_GT(q1.min_dihedral_deg, q0.min_dihedral_deg + 0.1);
  EXPECT_LE(q1.max_dihedral_deg, q0.max_dihedral_deg);
  EXPECT_EQ(q1.inverted_tets, 0u);
  EXPECT_NEAR(q1.volume, before.volume, 1e-12 * before.volume);
  // Cavity insertion (on by default) may add vertices there, within the budget.
  EXPECT_LE(with.points.size(), input.points.size() + input.points.size() / 20);
}

// Where the phases before leave the worst cell below the last phase's thresholds
// (a Mesh_3 output whose worst cells lie on its curved surface), the worst-cell
// phase without cavity insertion ends before its first iteration: its steps there
// would be the last phase's, and the output is the one without it. (With cavity
// insertion, on by default, the phase runs whatever the worst cell.)
TEST(Pipeline, WorstCellPhaseEndsBelowTheLastPhasesThresholds)
{
  const Generated_mesh input = make_input(Shape::genus2, Size::small);
  struct Phases
  {
    std::size_t* worst_iterations;
    void after_classification(const BODT::Smoothing_result&) {}
    void after_iteration(const BODT::Iteration_stats& s) { *worst_iterations += s.phase == 3; }
  };
  BODT::Smoothing_options opt;
  opt.cavity_insertion = false;
  opt.worst_cell_phase = false;
  C3t3 without = input.c3t3;
  BODT::smooth(without, opt);
  opt.worst_cell_phase = true;
  C3t3 with = input.c3t3;
  std::size_t iterations = 0;
  BODT::smooth(with, opt, Phases{&iterations});

  const auto q = BODT::mesh_quality(without);
  ASSERT_LT(std::min(q.min_dihedral_deg, 180 - q.max_dihedral_deg) + opt.worst_cell_margin, 30.0)
      << "the mesh would not reach the case";
  EXPECT_EQ(iterations, 0u);
  const BODT::Tet_mesh a = BODT::c3t3_to_tet_mesh(without), b = BODT::c3t3_to_tet_mesh(with);
  EXPECT_TRUE(a.points == b.points && a.tets == b.tets);
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
    opt.worst_cell_phase = false;   // the three phases alone
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

} // namespace pipeline_flips
