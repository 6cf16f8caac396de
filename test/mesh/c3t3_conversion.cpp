// Conversions between Tet_mesh and Mesh_complex_3_in_triangulation_3: round trips
// of Mesh_3 inputs compared by point (cells, labels, facets, curve edges, corners,
// vertex dimensions), validity of the rebuilt triangulation, smoothing a converted
// mesh, integral surface patch indices, meshes no triangulation can hold, and the
// shared third-party meshes.
#include "inputs/generated_inputs.h"
#include "test_support.h"

#include <CGAL/BODT_3/Tet_mesh_conversion.h>
#include <CGAL/BODT_3/IO/read_mesh_into_c3t3.h>
#include <CGAL/BODT_3/mesh_quality.h>
#include <CGAL/BODT_3/smooth.h>
#include <CGAL/bodt_optimize_mesh_3.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

using namespace bodt_inputs;
namespace BODT = CGAL::BODT_3;
using BODT::Mesh_io_error;
using BODT::Tet_mesh;

namespace {

// A C3T3 whose surface patch index is an int, as with
// Polyhedral_mesh_domain_with_features_3: file triangle labels can then be kept.
struct Int_patch_domain
{
  using R = K;
  using Point_3 = K::Point_3;
  using Subdomain_index = int;
  using Surface_patch_index = int;
  using Curve_index = int;
  using Corner_index = int;
  using Index = int;
  using Has_features = CGAL::Tag_true;
};
using Int_tr = CGAL::Mesh_triangulation_3<Int_patch_domain>::type;
using Int_c3t3 = CGAL::Mesh_complex_3_in_triangulation_3<Int_tr, int, int>;

template <class C3T3>
Point bare(const C3T3& c3t3, typename C3T3::Vertex_handle v)
{
  return c3t3.triangulation().geom_traits().construct_point_3_object()(v->point());
}

template <class C3T3>
std::vector<Point> finite_points(const C3T3& c3t3)
{
  std::vector<Point> out;
  for(auto v = c3t3.triangulation().finite_vertices_begin(); v != c3t3.triangulation().finite_vertices_end(); ++v)
    out.push_back(bare(c3t3, v));
  return out;
}

template <std::size_t N>
std::array<Point, N> sorted(std::array<Point, N> a)
{
  std::sort(a.begin(), a.end());
  return a;
}

// What a complex holds, keyed by points so that two complexes on the same points
// compare whatever their vertex and cell order.
template <class C3T3>
struct Complex_content
{
  std::map<std::array<Point, 4>, int> cells;
  std::map<std::array<Point, 3>, typename C3T3::Surface_patch_index> facets;
  std::map<std::array<Point, 2>, int> edges;
  std::set<Point> corners;
  std::map<Point, int> dimension;   // of the vertices of cells in the complex

  explicit Complex_content(const C3T3& c3t3)
  {
    for(auto c = c3t3.cells_in_complex_begin(); c != c3t3.cells_in_complex_end(); ++c)
    {
      std::array<Point, 4> p;
      for(int k = 0; k < 4; ++k)
      {
        p[k] = bare(c3t3, c->vertex(k));
        dimension[p[k]] = c3t3.in_dimension(c->vertex(k));
      }
      cells.emplace(sorted(p), c3t3.subdomain_index(c));
    }
    for(auto f = c3t3.facets_in_complex_begin(); f != c3t3.facets_in_complex_end(); ++f)
    {
      std::array<Point, 3> p;
      for(int k = 0, m = 0; k < 4; ++k)
        if(k != f->second) p[m++] = bare(c3t3, f->first->vertex(k));
      facets.emplace(sorted(p), c3t3.surface_patch_index(*f));
    }
    for(auto e = c3t3.edges_in_complex_begin(); e != c3t3.edges_in_complex_end(); ++e)
      edges.emplace(sorted(std::array<Point, 2>{bare(c3t3, e->first->vertex(e->second)),
                                                bare(c3t3, e->first->vertex(e->third))}),
                    c3t3.curve_index(*e));
    for(auto v = c3t3.vertices_in_complex_begin(); v != c3t3.vertices_in_complex_end(); ++v)
      corners.insert(bare(c3t3, v));
  }
};

// Vertices of dimension 1 to 3 whose index is not that of a curve edge, complex
// facet or complex cell around them (of that dimension).
template <class C3T3>
std::size_t vertices_with_a_foreign_index(const C3T3& c3t3)
{
  using Index = typename C3T3::Triangulation::Vertex::Index;
  const auto& tr = c3t3.triangulation();
  std::size_t foreign = 0;
  for(auto v = tr.finite_vertices_begin(); v != tr.finite_vertices_end(); ++v)
  {
    std::vector<Index> around;
    const int d = c3t3.in_dimension(v);
    if(d == 3)
    {
      std::vector<typename C3T3::Cell_handle> cells;
      tr.incident_cells(v, std::back_inserter(cells));
      for(const auto& c : cells)
        if(c3t3.is_in_complex(c)) around.push_back(Index(c3t3.subdomain_index(c)));
    }
    else if(d == 2)
    {
      std::vector<typename C3T3::Facet> facets;
      tr.incident_facets(v, std::back_inserter(facets));
      for(const auto& f : facets)
        if(c3t3.is_in_complex(f)) around.push_back(Index(c3t3.surface_patch_index(f)));
    }
    else if(d == 1)
    {
      std::vector<typename C3T3::Edge> edges;
      tr.incident_edges(v, std::back_inserter(edges));
      for(const auto& e : edges)
        if(c3t3.is_in_complex(e)) around.push_back(Index(c3t3.curve_index(e)));
    }
    if(d == 0 || (d == 3 && around.empty())) continue;   // corners are numbered anew; outside vertices have none
    if(std::find(around.begin(), around.end(), v->index()) == around.end()) ++foreign;
  }
  return foreign;
}

// Every finite cell positively oriented, and the data structure valid but for the
// Euler relation, which reads `C - F + E - V = -genus` (infinite vertex included)
// when the outside of a solid whose boundary has that genus is closed by one
// infinite vertex.
template <class Tr>
void expect_valid(const Tr& tr, int boundary_genus)
{
  const auto& tds = tr.tds();
  if(boundary_genus == 0)
  {
    EXPECT_TRUE(tds.is_valid());
  }
  std::size_t invalid = 0;
  for(auto c = tds.cells_begin(); c != tds.cells_end(); ++c)
    if(!tds.is_valid(c)) ++invalid;
  for(auto v = tds.vertices_begin(); v != tds.vertices_end(); ++v)
    if(!tds.is_valid(v)) ++invalid;
  EXPECT_EQ(invalid, 0u);
  const long euler = static_cast<long>(tds.number_of_cells()) - static_cast<long>(tds.number_of_facets()) +
                     static_cast<long>(tds.number_of_edges()) - static_cast<long>(tds.number_of_vertices());
  EXPECT_EQ(euler, -boundary_genus);

  auto cp = tr.geom_traits().construct_point_3_object();
  std::size_t not_positive = 0;
  for(auto c = tr.finite_cells_begin(); c != tr.finite_cells_end(); ++c)
    if(CGAL::orientation(cp(c->vertex(0)->point()), cp(c->vertex(1)->point()), cp(c->vertex(2)->point()),
                         cp(c->vertex(3)->point())) != CGAL::POSITIVE)
      ++not_positive;
  EXPECT_EQ(not_positive, 0u);
}

int boundary_genus(Shape shape)
{
  return shape == Shape::torus ? 1 : shape == Shape::genus2 ? 2 : 0;
}

// Triangles of `m` with their labels, each rotated to start at its smallest vertex
// (so that orientation counts).
std::map<std::array<int, 3>, int> oriented_triangles(const Tet_mesh& m)
{
  std::map<std::array<int, 3>, int> out;
  for(std::size_t f = 0; f < m.triangles.size(); ++f)
  {
    auto t = m.triangles[f];
    std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
    out.emplace(t, m.triangle_labels[f]);
  }
  return out;
}

class RoundTrip : public ::testing::TestWithParam<Shape>
{};

} // namespace

TEST_P(RoundTrip, KeepsPointsCellsFacetsEdgesCornersAndDimensions)
{
  const Generated_mesh input = make_input(GetParam(), Size::small);
  const C3t3& c0 = input.c3t3;
  const Tet_mesh m1 = BODT::c3t3_to_tet_mesh(c0);

  // Every cell and feature of the complex is written; only vertices of no cell of the
  // complex are left out, and the others keep their order.
  EXPECT_EQ(m1.tets.size(), c0.number_of_cells_in_complex());
  EXPECT_EQ(m1.triangles.size(), c0.number_of_facets_in_complex());
  EXPECT_EQ(m1.edges.size(), c0.number_of_edges_in_complex());
  EXPECT_EQ(m1.corners.size(), c0.number_of_vertices_in_complex());
  EXPECT_LE(m1.points.size(), c0.triangulation().number_of_vertices());
  {
    const std::vector<Point> all = finite_points(c0);
    std::size_t j = 0;
    for(const Point& p : all)
      if(j < m1.points.size() && p == m1.points[j]) ++j;
    EXPECT_EQ(j, m1.points.size()) << "the written points are not the triangulation's, in order";
    std::vector<char> used(m1.points.size(), 0);
    for(const auto& t : m1.tets)
      for(int v : t) used[v] = 1;
    EXPECT_EQ(std::count(used.begin(), used.end(), 0), 0) << "a written vertex is in no tetrahedron";
  }
  if(GetParam() == Shape::sharp_part || GetParam() == Shape::two_subdomains)
  {
    EXPECT_GT(m1.edges.size(), 0u);
  }
  if(GetParam() == Shape::sharp_part)
  {
    EXPECT_GT(m1.corners.size(), 0u);
  }

  // Triangles point out of the complex cell on their side (the smaller label's, between two).
  {
    std::map<std::array<int, 3>, std::vector<std::size_t>> tets_of_face;
    for(std::size_t t = 0; t < m1.tets.size(); ++t)
      for(int i = 0; i < 4; ++i)
      {
        std::array<int, 3> f;
        for(int k = 0, m = 0; k < 4; ++k)
          if(k != i) f[m++] = m1.tets[t][k];
        std::sort(f.begin(), f.end());
        tets_of_face[f].push_back(t);
      }
    std::size_t wrong = 0;
    for(const auto& tri : m1.triangles)
    {
      std::array<int, 3> key = tri;
      std::sort(key.begin(), key.end());
      const auto& ts = tets_of_face.at(key);
      std::size_t inner = ts[0];
      if(ts.size() == 2 && m1.tet_labels[ts[1]] < m1.tet_labels[ts[0]]) inner = ts[1];
      int apex = -1;
      for(int v : m1.tets[inner])
        if(v != tri[0] && v != tri[1] && v != tri[2]) apex = v;
      if(CGAL::orientation(m1.points[tri[0]], m1.points[tri[1]], m1.points[tri[2]], m1.points[apex]) !=
         CGAL::NEGATIVE)
        ++wrong;
    }
    EXPECT_EQ(wrong, 0u) << "triangles whose normal points into their cell";
  }

  C3t3 c1;
  BODT::tet_mesh_to_c3t3(m1, c1);
  const auto& tr1 = c1.triangulation();
  expect_valid(tr1, boundary_genus(GetParam()));
  EXPECT_EQ(finite_points(c1), m1.points);   // bit-exact, same order
  EXPECT_EQ(tr1.number_of_finite_cells(), m1.tets.size());

  EXPECT_EQ(c1.number_of_cells_in_complex(), c0.number_of_cells_in_complex());
  EXPECT_EQ(c1.number_of_facets_in_complex(), c0.number_of_facets_in_complex());
  EXPECT_EQ(c1.number_of_edges_in_complex(), c0.number_of_edges_in_complex());
  EXPECT_EQ(c1.number_of_vertices_in_complex(), c0.number_of_vertices_in_complex());

  // Same content as Mesh_3's complex: Labeled_mesh_domain_3's surface patch index is
  // the ordered pair of subdomains, so it is rebuilt exactly; so are curve indices.
  const Complex_content<C3t3> k0(c0), k1(c1);
  EXPECT_TRUE(k1.cells == k0.cells);
  EXPECT_TRUE(k1.facets == k0.facets);
  EXPECT_TRUE(k1.edges == k0.edges);
  EXPECT_TRUE(k1.corners == k0.corners);
  EXPECT_TRUE(k1.dimension == k0.dimension) << "a vertex's in_dimension changed";
  EXPECT_EQ(vertices_with_a_foreign_index(c1), 0u);

  // Second round: the same file, up to the order of the facets and the numbering of
  // the patches.
  const Tet_mesh m2 = BODT::c3t3_to_tet_mesh(c1);
  EXPECT_EQ(m2.points, m1.points);
  EXPECT_EQ(m2.tets, m1.tets);
  EXPECT_EQ(m2.tet_labels, m1.tet_labels);
  const auto t1 = oriented_triangles(m1), t2 = oriented_triangles(m2);
  ASSERT_EQ(t2.size(), t1.size());
  std::map<int, int> patch_map;
  std::size_t other_triangle = 0;
  for(const auto& t : t1)
  {
    const auto it = t2.find(t.first);
    if(it == t2.end() || patch_map.emplace(t.second, it->second).first->second != it->second) ++other_triangle;
  }
  EXPECT_EQ(other_triangle, 0u);
  std::set<int> images;
  for(const auto& p : patch_map) images.insert(p.second);
  EXPECT_EQ(images.size(), patch_map.size()) << "two patches merged";
  auto edge_set = [](const Tet_mesh& m) {
    std::set<std::pair<std::array<int, 2>, int>> s;
    for(std::size_t e = 0; e < m.edges.size(); ++e)
      s.emplace(std::array<int, 2>{std::min(m.edges[e][0], m.edges[e][1]), std::max(m.edges[e][0], m.edges[e][1])},
                m.edge_labels[e]);
    return s;
  };
  EXPECT_EQ(edge_set(m2), edge_set(m1));
  EXPECT_EQ(std::set<int>(m2.corners.begin(), m2.corners.end()), std::set<int>(m1.corners.begin(), m1.corners.end()));
}

INSTANTIATE_TEST_SUITE_P(All, RoundTrip, ::testing::ValuesIn(all_shapes()),
                         [](const ::testing::TestParamInfo<Shape>& info) { return name(info.param); });

TEST(C3t3Conversion, TwoSubdomainsKeepBothLabelsAndTheirVolumes)
{
  const Generated_mesh input = make_input(Shape::two_subdomains, Size::small);
  const Tet_mesh m = BODT::c3t3_to_tet_mesh(input.c3t3);
  EXPECT_EQ(std::set<int>(m.tet_labels.begin(), m.tet_labels.end()), (std::set<int>{1, 2}));
  C3t3 c;
  BODT::tet_mesh_to_c3t3(m, c);
  std::set<int> labels;
  std::size_t interface = 0;
  for(auto cell = c.cells_in_complex_begin(); cell != c.cells_in_complex_end(); ++cell)
    labels.insert(c.subdomain_index(cell));
  for(auto f = c.facets_in_complex_begin(); f != c.facets_in_complex_end(); ++f)
    if(c.surface_patch_index(*f) == std::make_pair(1, 2)) ++interface;
  EXPECT_EQ(labels, (std::set<int>{1, 2}));
  EXPECT_GT(interface, 0u);
  const auto v0 = BODT::mesh_quality(input.c3t3).volume_per_subdomain;
  const auto v1 = BODT::mesh_quality(c).volume_per_subdomain;
  // The boundary and the interface, as facets of the complex and as faces between labels.
  const double smallest = BODT::mesh_quality(input.c3t3).min_boundary_triangle_angle_deg;
  EXPECT_GT(smallest, 0);
  EXPECT_NEAR(BODT::mesh_quality(m).min_boundary_triangle_angle_deg, smallest, 1e-9);
  EXPECT_NEAR(BODT::mesh_quality(c).min_boundary_triangle_angle_deg, smallest, 1e-9);
  ASSERT_EQ(v1.size(), 2u);
  for(const auto& kv : v0)
    EXPECT_NEAR(v1.at(kv.first), kv.second, 1e-12 * kv.second);
}

TEST(C3t3Conversion, SmoothingAConvertedMeshKeepsTheVolumePerSubdomain)
{
  for(Shape shape : {Shape::two_subdomains, Shape::sharp_part})
  {
    SCOPED_TRACE(name(shape));
    C3t3 c;
    BODT::tet_mesh_to_c3t3(BODT::c3t3_to_tet_mesh(make_input(shape, Size::small).c3t3), c);
    const auto before = BODT::mesh_quality(c);
    const std::vector<Point> p0 = finite_points(c);
    std::vector<Point> corners;
    for(auto v = c.vertices_in_complex_begin(); v != c.vertices_in_complex_end(); ++v) corners.push_back(bare(c, v));
    CGAL::bodt_optimize_mesh_3(c, CGAL::parameters::max_iteration_number = 10);
    const auto after = BODT::mesh_quality(c);
    EXPECT_EQ(after.inverted_tets, 0u);
    ASSERT_EQ(after.volume_per_subdomain.size(), before.volume_per_subdomain.size());
    for(const auto& kv : before.volume_per_subdomain)
      EXPECT_NEAR(after.volume_per_subdomain.at(kv.first), kv.second, 1e-10 * kv.second) << "subdomain " << kv.first;
    const std::vector<Point> p1 = finite_points(c);
    // Insertion (the worst-cell phase's cavities) may add vertices, within its 5%.
    ASSERT_GE(p1.size(), p0.size());
    ASSERT_LE(p1.size(), p0.size() + p0.size() / 20);
    const std::set<Point> now(p1.begin(), p1.end());
    std::size_t moved = 0;
    for(const Point& p : p0) moved += now.count(p) == 0;
    EXPECT_GT(moved, p0.size() / 10);
    for(const Point& p : corners) EXPECT_TRUE(now.count(p)) << "corner " << p << " moved";
  }
}

// A C3T3 handed over with facets in the complex between two cells of one
// subdomain (an embedded surface: the two halves of the cut ball relabelled 1, the
// facets of their interface z = 0 kept): the surface stays where it was (its
// vertices in place, the same area covered), the complex stays valid, the volume
// is kept. Before the fix its vertices moved as interior vertices, by up to 0.1.
TEST(C3t3Conversion, EmbeddedFacetsOfAC3t3StayOnTheirSurface)
{
  Generated_mesh input = make_input(Shape::two_subdomains, Size::small);
  C3t3& c = input.c3t3;
  for(auto cell = c.triangulation().finite_cells_begin(); cell != c.triangulation().finite_cells_end(); ++cell)
    if(c.is_in_complex(cell) && c.subdomain_index(cell) != 1)
    {
      c.remove_from_complex(cell);
      c.add_to_complex(cell, 1);
    }
  auto embedded = [&c](double& area) {
    std::vector<Point> on;
    area = 0;
    for(auto f = c.facets_in_complex_begin(); f != c.facets_in_complex_end(); ++f)
    {
      const auto cell = f->first;
      const auto other = cell->neighbor(f->second);
      if(!c.is_in_complex(cell) || !c.is_in_complex(other)) continue;
      std::array<Point, 3> t;
      for(int k = 0, m = 0; k < 4; ++k)
        if(k != f->second) t[m++] = bare(c, cell->vertex(k));
      area += std::sqrt(CGAL::to_double(CGAL::squared_area(t[0], t[1], t[2])));
      on.insert(on.end(), t.begin(), t.end());
    }
    return on;
  };
  double area0 = 0, area1 = 0;
  const std::vector<Point> on0 = embedded(area0);
  ASSERT_FALSE(on0.empty());
  const std::set<Point> kept(on0.begin(), on0.end());
  double height = 0;   // Mesh_3 puts the interface within about 1e-7 of z = 0
  for(const Point& p : on0) height = std::max(height, std::abs(p.z()));
  const auto before = BODT::mesh_quality(c);
  const std::vector<Point> p0 = finite_points(c);
  CGAL::bodt_optimize_mesh_3(c, CGAL::parameters::max_iteration_number = 10);
  const std::vector<Point> p1 = finite_points(c);
  std::size_t moved = 0;
  for(std::size_t i = 0; i < std::min(p0.size(), p1.size()); ++i) moved += p0[i] != p1[i];
  EXPECT_GT(moved, p0.size() / 10);
  const std::vector<Point> on = embedded(area1);
  for(const Point& p : on)   // its own vertex, or one inserted on one of its facets
    EXPECT_TRUE(kept.count(p) || std::abs(p.z()) <= height) << p;
  EXPECT_NEAR(area1, area0, 1e-9 * area0);
  const auto after = BODT::mesh_quality(c);
  EXPECT_EQ(after.inverted_tets, 0u);
  EXPECT_NEAR(after.volume_per_subdomain.at(1), before.volume_per_subdomain.at(1),
              1e-10 * before.volume_per_subdomain.at(1));
  EXPECT_TRUE(c.triangulation().tds().is_valid());
}

namespace {

// Two tetrahedra sharing face (1 2 3) (0-based), labels 1 and 2, then a third one
// (label 0, outside the complex) on face (0 1 3).
Tet_mesh two_tets_and_outside()
{
  Tet_mesh m;
  m.points = {Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0), Point(0, 0, 1), Point(1, 1, 1), Point(1, -1, 1),
              Point(5, 5, 5)};   // the last point is used by no tetrahedron
  m.vertex_refs.assign(m.points.size(), 0);
  m.tets = {{0, 1, 2, 3}, {1, 3, 2, 4}, {0, 1, 3, 5}};
  for(auto& t : m.tets)
    if(CGAL::orientation(m.points[t[0]], m.points[t[1]], m.points[t[2]], m.points[t[3]]) != CGAL::POSITIVE)
      std::swap(t[2], t[3]);
  m.tet_labels = {1, 2, 0};
  m.triangles = {{0, 1, 2}, {1, 2, 3}, {0, 2, 3}};
  m.triangle_labels = {7, 9, 0};
  m.edges = {{0, 1}, {1, 2}};
  m.edge_labels = {4, 0};
  m.corners = {0};
  m.required_vertices = {1, 6};
  return m;
}

template <class C3T3>
std::string conversion_error(const Tet_mesh& m)
{
  C3T3 c;
  try
  {
    BODT::tet_mesh_to_c3t3(m, c, "hand.mesh");
  }
  catch(const Mesh_io_error& e)
  {
    EXPECT_EQ(e.file(), "hand.mesh");
    return e.message();
  }
  return std::string();
}

} // namespace

TEST(C3t3Conversion, OutsideTetrahedraStayInTheTriangulationOnly)
{
  const Tet_mesh m = two_tets_and_outside();
  C3t3 c;
  BODT::tet_mesh_to_c3t3(m, c);
  const auto& tr = c.triangulation();
  expect_valid(tr, 0);
  EXPECT_EQ(tr.number_of_vertices(), 6u);   // the unused point is left out
  EXPECT_EQ(tr.number_of_finite_cells(), 3u);
  EXPECT_EQ(tr.number_of_cells(), 3u + 8u);  // one infinite cell per boundary face
  EXPECT_EQ(c.number_of_cells_in_complex(), 2u);
  // Boundary of the labelled pair (6 faces) and their interface; the face shared with
  // the outside tetrahedron is a boundary face too.
  EXPECT_EQ(c.number_of_facets_in_complex(), 7u);
  EXPECT_EQ(c.number_of_edges_in_complex(), 2u);
  EXPECT_EQ(c.number_of_vertices_in_complex(), 2u);
  std::map<int, int> dims;
  for(auto v = tr.finite_vertices_begin(); v != tr.finite_vertices_end(); ++v) ++dims[c.in_dimension(v)];
  EXPECT_EQ(dims, (std::map<int, int>{{0, 2}, {1, 1}, {2, 2}, {3, 1}}));   // vertex 5 is only outside
  EXPECT_EQ(vertices_with_a_foreign_index(c), 0u);

  const Tet_mesh back = BODT::c3t3_to_tet_mesh(c);
  EXPECT_EQ(back.points.size(), 5u);
  EXPECT_EQ(back.tets.size(), 2u);
  EXPECT_EQ(back.tet_labels, (std::vector<int>{1, 2}));
  EXPECT_EQ(back.triangles.size(), 7u);
  EXPECT_EQ(back.edges.size(), 2u);
  EXPECT_EQ(back.corners.size(), 2u);
}

TEST(C3t3Conversion, AllLabelsZeroMakeOneSubdomain)
{
  Tet_mesh m = two_tets_and_outside();
  m.tet_labels = {0, 0, 0};
  C3t3 c;
  BODT::tet_mesh_to_c3t3(m, c);
  EXPECT_EQ(c.number_of_cells_in_complex(), 3u);
  for(auto cell = c.cells_in_complex_begin(); cell != c.cells_in_complex_end(); ++cell)
    EXPECT_EQ(c.subdomain_index(cell), 1);
  EXPECT_EQ(c.number_of_facets_in_complex(), 8u);
}

// smooth(Tet_mesh&) frees the file's labels during its run and writes them again
// at the end: labels all 0 stay all 0 (no subdomain is made up), one subdomain
// and an outside keep theirs, and the cell count is the complex's.
TEST(C3t3Conversion, SmoothingAFileMeshWritesItsLabelsAgain)
{
  const Tet_mesh input = BODT::c3t3_to_tet_mesh(make_input(Shape::two_subdomains, Size::small).c3t3);
  std::set<int> file_labels(input.tet_labels.begin(), input.tet_labels.end());
  ASSERT_EQ(file_labels.size(), 2u);
  BODT::Smoothing_options opt;
  opt.max_iteration_number = 2;
  Tet_mesh zero = input;
  std::fill(zero.tet_labels.begin(), zero.tet_labels.end(), 0);
  BODT::smooth(zero, opt);
  EXPECT_EQ(zero.tet_labels.size(), zero.tets.size());
  EXPECT_EQ(std::set<int>(zero.tet_labels.begin(), zero.tet_labels.end()), std::set<int>{0});
  Tet_mesh labelled = input;
  const int outside = *file_labels.begin();
  for(int& l : labelled.tet_labels)
    if(l == outside) l = 0;
  BODT::smooth(labelled, opt);
  EXPECT_EQ(labelled.tet_labels.size(), labelled.tets.size());
  EXPECT_EQ(std::set<int>(labelled.tet_labels.begin(), labelled.tet_labels.end()),
            (std::set<int>{0, *file_labels.rbegin()}));
  // A point no tetrahedron uses has no vertex: it is kept aside while the points are freed.
  Tet_mesh small = two_tets_and_outside();
  BODT::smooth(small, opt);
  ASSERT_EQ(small.points.size(), 7u);
  EXPECT_EQ(small.points[6], Point(5, 5, 5));
  EXPECT_EQ(small.tets.size(), 3u);
}

TEST(C3t3Conversion, IntegralPatchIndicesKeepTheFileLabels)
{
  const Tet_mesh m = two_tets_and_outside();
  Int_c3t3 c;
  BODT::tet_mesh_to_c3t3(m, c);
  expect_valid(c.triangulation(), 0);
  EXPECT_EQ(vertices_with_a_foreign_index(c), 0u);
  std::map<std::set<int>, int> patch;   // by the file's vertex indices (the points are distinct)
  std::map<Point, int> id;
  for(std::size_t i = 0; i < m.points.size(); ++i) id[m.points[i]] = static_cast<int>(i);
  for(auto f = c.facets_in_complex_begin(); f != c.facets_in_complex_end(); ++f)
  {
    std::set<int> key;
    for(int k = 0; k < 4; ++k)
      if(k != f->second) key.insert(id.at(bare(c, f->first->vertex(k))));
    patch[key] = c.surface_patch_index(*f);
  }
  ASSERT_EQ(patch.size(), 7u);
  EXPECT_EQ(patch.at({0, 1, 2}), 7);
  EXPECT_EQ(patch.at({1, 2, 3}), 9);   // the interface, listed
  // Label 0 and unlisted faces: one new index per pair of subdomains, above the labels.
  const int outside_1 = patch.at({0, 2, 3});
  EXPECT_GT(outside_1, 9);
  EXPECT_EQ(patch.at({0, 1, 3}), outside_1);
  const int outside_2 = patch.at({1, 2, 4});
  EXPECT_GT(outside_2, 9);
  EXPECT_NE(outside_2, outside_1);
  EXPECT_EQ(patch.at({2, 3, 4}), outside_2);
  // Curve labels: 4 kept, 0 (meaning "no curve" to the complex) becomes a new one.
  const auto h = [&](int i) {
    for(auto v = c.triangulation().finite_vertices_begin(); v != c.triangulation().finite_vertices_end(); ++v)
      if(bare(c, v) == m.points[i]) return typename Int_tr::Vertex_handle(v);
    return typename Int_tr::Vertex_handle();
  };
  EXPECT_EQ(c.curve_index(h(0), h(1)), 4);
  EXPECT_EQ(c.curve_index(h(1), h(2)), 5);

  // Integral indices are written back as they are.
  const Tet_mesh back = BODT::c3t3_to_tet_mesh(c);
  std::set<int> labels(back.triangle_labels.begin(), back.triangle_labels.end());
  EXPECT_EQ(labels, (std::set<int>{7, 9, outside_1, outside_2}));
  EXPECT_EQ(std::set<int>(back.edge_labels.begin(), back.edge_labels.end()), (std::set<int>{4, 5}));
}

TEST(C3t3Conversion, MeshesNoTriangulationCanHoldThrow)
{
  const std::vector<Point> pts = {Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0), Point(0, 0, 1),
                                  Point(0, 0, -1), Point(1, 1, -1), Point(-1, -1, -1), Point(1, 1, 1),
                                  Point(1, -1, 1)};
  auto make = [&](std::vector<std::array<int, 4>> tets) {
    Tet_mesh m;
    m.points = pts;
    m.vertex_refs.assign(pts.size(), 0);
    for(auto& t : tets)
      if(CGAL::orientation(pts[t[0]], pts[t[1]], pts[t[2]], pts[t[3]]) == CGAL::NEGATIVE) std::swap(t[2], t[3]);
    m.tets = tets;
    m.tet_labels.assign(tets.size(), 1);
    return m;
  };

  // Two tetrahedra sharing only edge (0 1): four boundary faces meet there.
  EXPECT_NE(conversion_error<C3t3>(make({{0, 1, 2, 3}, {0, 1, 4, 6}})).find("not manifold at edge (1 2)"),
            std::string::npos);
  // Sharing only vertex 0.
  const std::string pinched = conversion_error<C3t3>(make({{0, 1, 2, 3}, {0, 4, 5, 6}}));
  EXPECT_NE(pinched.find("not manifold at vertex 1:"), std::string::npos) << pinched;
  // On the same side of their common face (0 1 2).
  EXPECT_NE(conversion_error<C3t3>(make({{0, 1, 2, 3}, {0, 1, 2, 7}})).find("same side of their common face"),
            std::string::npos);
  // Inverted.
  Tet_mesh inverted = make({{0, 1, 2, 3}});
  std::swap(inverted.tets[0][0], inverted.tets[0][1]);
  EXPECT_NE(conversion_error<C3t3>(inverted).find("negatively oriented"), std::string::npos);
  // An Edges entry that is no edge of the tetrahedra.
  Tet_mesh bad_edge = make({{0, 1, 2, 3}, {1, 2, 3, 7}});
  bad_edge.edges = {{0, 7}};
  bad_edge.edge_labels = {1};
  EXPECT_NE(conversion_error<C3t3>(bad_edge).find("Edges entry 1 (1 8) is not an edge"), std::string::npos);
  EXPECT_NE(conversion_error<C3t3>(Tet_mesh()).find("no tetrahedra"), std::string::npos);

  // A failed conversion leaves the complex as it was.
  C3t3 c;
  BODT::tet_mesh_to_c3t3(two_tets_and_outside(), c);
  EXPECT_THROW(BODT::tet_mesh_to_c3t3(bad_edge, c), Mesh_io_error);
  EXPECT_EQ(c.number_of_cells_in_complex(), 2u);
  EXPECT_EQ(c.triangulation().number_of_vertices(), 6u);
}

// The conversion checks and links its cells in parallel: the same complex on any
// number of threads, and the first bad cell in file order reported.
TEST(C3t3Conversion, SameComplexAndSameRefusalOnAnyNumberOfThreads)
{
  const Tet_mesh grid = bodt_test::cube_grid(16, [](int i, int, int) { return i < 8 ? 1 : 2; });
  auto convert = [](const Tet_mesh& m, int threads, BODT::Tet_mesh_c3t3& c) {
    const BODT::internal::Tet_face_matching faces(m.tets, m.points.size(), threads);
    BODT::tet_mesh_to_c3t3(m, c, "grid.mesh", nullptr, &faces);
  };
  BODT::Tet_mesh_c3t3 one, four;
  convert(grid, 1, one);
  convert(grid, 4, four);
  EXPECT_TRUE(four.triangulation().is_valid());
  EXPECT_EQ(four.number_of_cells_in_complex(), grid.tets.size());
  EXPECT_EQ(four.number_of_facets_in_complex(), one.number_of_facets_in_complex());
  bodt_test::expect_same_mesh_content(BODT::c3t3_to_tet_mesh(four), BODT::c3t3_to_tet_mesh(one));

  Tet_mesh inverted = grid;
  for(std::size_t t : {19999u, 8999u}) std::swap(inverted.tets[t][0], inverted.tets[t][1]);
  for(int threads : {1, 4})
  {
    BODT::Tet_mesh_c3t3 c;
    try
    {
      convert(inverted, threads, c);
      ADD_FAILURE() << "an inverted mesh was converted";
    }
    catch(const Mesh_io_error& e)
    {
      EXPECT_EQ(e.message(), "tetrahedron 9000 is negatively oriented; a triangulation needs positively oriented cells");
    }
  }
}

TEST(C3t3Conversion, SeveralBoundaryComponentsAreAccepted)
{
  // Two separate tetrahedra: the infinite vertex's star has two parts, as with
  // CGAL::IO::read_MEDIT; everything else is valid.
  Tet_mesh m;
  m.points = {Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0), Point(0, 0, 1),
              Point(5, 0, 0), Point(6, 0, 0), Point(5, 1, 0), Point(5, 0, 1)};
  m.vertex_refs.assign(m.points.size(), 0);
  m.tets = {{0, 1, 2, 3}, {4, 5, 6, 7}};
  m.tet_labels = {1, 2};
  C3t3 c;
  BODT::tet_mesh_to_c3t3(m, c);
  EXPECT_EQ(c.number_of_cells_in_complex(), 2u);
  EXPECT_EQ(c.number_of_facets_in_complex(), 8u);
  const auto& tds = c.triangulation().tds();
  for(auto cell = tds.cells_begin(); cell != tds.cells_end(); ++cell) EXPECT_TRUE(tds.is_valid(cell));
}

TEST(C3t3Conversion, SharedMeshes)
{
  const std::filesystem::path dir(BODT_SHARED_DATA);
  if(!std::filesystem::exists(dir)) GTEST_SKIP() << "no " << dir;
  std::vector<std::filesystem::path> files;
  for(const auto& entry : std::filesystem::directory_iterator(dir))
    if(entry.path().extension() == ".mesh") files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  std::size_t converted = 0;
  for(const auto& path : files)
  {
    SCOPED_TRACE(path.filename().string());
    std::ostringstream warnings;
    const Tet_mesh m = BODT::IO::read_mesh(path.string(), warnings);
    C3t3 c;
    try
    {
      BODT::read_mesh_into_c3t3(path.string(), c, warnings);
    }
    catch(const Mesh_io_error& e)
    {
      std::cout << "[ c3t3     ] " << path.filename().string() << ": not converted: " << e.what() << "\n";
      EXPECT_EQ(e.file(), path.string());
      EXPECT_TRUE(e.message().find("not manifold") != std::string::npos) << e.what();
      continue;
    }
    catch(const std::exception& e)
    {
      ADD_FAILURE() << "not a Mesh_io_error: " << e.what();
      continue;
    }
    ++converted;
    const bool all_zero = m.all_labels_zero();
    std::size_t labelled = 0;
    std::vector<char> used(m.points.size(), 0);
    for(std::size_t t = 0; t < m.tets.size(); ++t)
    {
      labelled += m.in_mesh(t, all_zero);
      for(int v : m.tets[t]) used[v] = 1;
    }
    const auto& tr = c.triangulation();
    EXPECT_EQ(c.number_of_cells_in_complex(), labelled);
    EXPECT_EQ(tr.number_of_finite_cells(), m.tets.size());
    EXPECT_EQ(tr.number_of_vertices(), static_cast<std::size_t>(std::count(used.begin(), used.end(), 1)));
    std::size_t invalid = 0;
    for(auto cell = tr.tds().cells_begin(); cell != tr.tds().cells_end(); ++cell) invalid += !tr.tds().is_valid(cell);
    EXPECT_EQ(invalid, 0u);
    const auto q0 = BODT::mesh_quality(m), q1 = BODT::mesh_quality(c);
    EXPECT_EQ(q1.num_tets, q0.num_tets);
    EXPECT_NEAR(q1.volume, q0.volume, 1e-12 * q0.volume);
    EXPECT_NEAR(q1.min_boundary_triangle_angle_deg, q0.min_boundary_triangle_angle_deg, 1e-9) << path;
    std::cout << "[ c3t3     ] " << path.filename().string() << ": converted, " << tr.number_of_vertices()
              << " vertices, " << c.number_of_cells_in_complex() << " cells, " << c.number_of_facets_in_complex()
              << " facets, " << c.number_of_edges_in_complex() << " curve edges, "
              << c.number_of_vertices_in_complex() << " corners in the complex\n";
  }
  EXPECT_GT(converted, 0u);
}

// Issue 30: every refusal of the conversion names the file the mesh was read from,
// in every format, through `smooth` as through `read_mesh_into_c3t3` (TetGen: the
// `.ele` file, which holds the tetrahedra). The readers accept these files: only
// the conversion can refuse them. A mesh made in code has no file, and its message
// is the refusal alone.
TEST(C3t3Conversion, EveryRefusalNamesTheFile)
{
  Tet_mesh same_side;
  same_side.points = {Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0), Point(0, 0, 1), Point(0.2, 0.2, 2)};
  same_side.vertex_refs.assign(5, 0);
  same_side.tets = {{0, 1, 2, 3}, {0, 1, 2, 4}};
  same_side.tet_labels = {1, 1};
  // On the cube's face z = 0 the tetrahedra have the diagonal (1 4), not (2 3).
  Tet_mesh not_an_edge = bodt_test::cube_grid(1, [](int, int, int) { return 1; });
  not_an_edge.edges = {{1, 2}};
  not_an_edge.edge_labels = {1};
  struct Case
  {
    std::string name;
    Tet_mesh mesh;
    std::string message;
  };
  const std::vector<Case> cases = {
      {"edge", bodt_test::touching_grids(1, {1, 1, 0}), "the boundary is not manifold at edge"},
      {"vertex", bodt_test::touching_grids(1, {1, 1, 1}), "the mesh is not manifold at vertex"},
      {"same_side", same_side, "lie on the same side of their common face"},
      {"not_an_edge", not_an_edge, "Edges entry 1 (2 3) is not an edge of the tetrahedra"}};
  for(const Case& c : cases)
  {
    // Made in code: no file to name.
    Tet_mesh made = c.mesh;
    try
    {
      BODT::smooth(made, BODT::Smoothing_options());
      ADD_FAILURE() << c.name << " was smoothed";
    }
    catch(const Mesh_io_error& e)
    {
      EXPECT_EQ(e.file(), "");
      EXPECT_EQ(std::string(e.what()), e.message());
      EXPECT_NE(e.message().find(c.message), std::string::npos) << e.what();
    }
    for(const std::string extension : {".mesh", ".meshb", ".msh", ".vtu", ".vtk", ".node"})
    {
      const std::string path = (bodt_test::tmp_dir() / (c.name + extension)).string();
      const std::string named = extension == ".node" ? (bodt_test::tmp_dir() / (c.name + ".ele")).string() : path;
      SCOPED_TRACE(path);
      BODT::IO::write_mesh(path, c.mesh);
      std::ostringstream warnings;
      Tet_mesh read = BODT::IO::read_mesh(path, warnings);
      auto expect_named = [&](const auto& run) {
        try
        {
          run();
          ADD_FAILURE() << "accepted";
        }
        catch(const Mesh_io_error& e)
        {
          EXPECT_EQ(e.file(), named);
          EXPECT_EQ(std::string(e.what()), named + ": " + e.message());
          EXPECT_NE(e.message().find(c.message), std::string::npos) << e.what();
        }
      };
      expect_named([&] { BODT::smooth(read, BODT::Smoothing_options()); });
      expect_named([&] {
        C3t3 c3t3;
        BODT::read_mesh_into_c3t3(path, c3t3, warnings);
      });
    }
  }
}
