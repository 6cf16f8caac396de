// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The Mesh_3-generated inputs (small sizes): size, orientation, a closed boundary
// of the expected topology, features, volume, determinism; and the random sphere.
#include "inputs/generated_inputs.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <utility>
#include <vector>

namespace {

using namespace bodt_inputs;

using Vertex_handle = Tr::Vertex_handle;
using Cell_handle = Tr::Cell_handle;
using Triangle = std::array<Vertex_handle, 3>;

constexpr double pi = 3.14159265358979323846;

Point bare_point(const Tr& tr, Vertex_handle v)
{
  return tr.geom_traits().construct_point_3_object()(v->point());
}

std::array<Point, 4> bare_points(const Tr& tr, Cell_handle c)
{
  return {bare_point(tr, c->vertex(0)), bare_point(tr, c->vertex(1)),
          bare_point(tr, c->vertex(2)), bare_point(tr, c->vertex(3))};
}

std::vector<Cell_handle> cells_in_complex(const C3t3& c3t3)
{
  std::vector<Cell_handle> cells;
  for(auto it = c3t3.cells_in_complex_begin(); it != c3t3.cells_in_complex_end(); ++it)
    cells.push_back(it);
  return cells;
}

double volume(const Tr& tr, Cell_handle c)
{
  const std::array<Point, 4> p = bare_points(tr, c);
  return CGAL::volume(p[0], p[1], p[2], p[3]);
}

double volume_of_subdomain(const C3t3& c3t3, int label)
{
  double sum = 0.;
  for(Cell_handle c : cells_in_complex(c3t3))
    if(c3t3.subdomain_index(c) == label)
      sum += volume(c3t3.triangulation(), c);
  return sum;
}

double volume_of_complex(const C3t3& c3t3)
{
  double sum = 0.;
  for(Cell_handle c : cells_in_complex(c3t3))
    sum += volume(c3t3.triangulation(), c);
  return sum;
}

// Midpoint rule on a grid over the domain's bounding box: a reference volume for
// shapes without a closed form.
double quadrature_volume(const Mesh_domain& domain, double step)
{
  const CGAL::Bbox_3 box = domain.bbox();
  const auto is_in = domain.is_in_domain_object();
  const int nx = int(std::ceil((box.xmax() - box.xmin()) / step));
  const int ny = int(std::ceil((box.ymax() - box.ymin()) / step));
  const int nz = int(std::ceil((box.zmax() - box.zmin()) / step));
  long inside = 0;
  for(int i = 0; i < nx; ++i)
    for(int j = 0; j < ny; ++j)
      for(int k = 0; k < nz; ++k)
        if(is_in(Point(box.xmin() + (i + 0.5) * step, box.ymin() + (j + 0.5) * step,
                       box.zmin() + (k + 0.5) * step)))
          ++inside;
  return inside * step * step * step;
}

// Facets between a cell of the complex and a cell outside it, oriented as seen
// from the inside cell.
std::vector<Triangle> boundary_facets(const C3t3& c3t3)
{
  std::vector<Triangle> facets;
  for(Cell_handle c : cells_in_complex(c3t3))
    for(int i = 0; i < 4; ++i)
      if(!c3t3.is_in_complex(c->neighbor(i)))
      {
        EXPECT_TRUE(c3t3.is_in_complex(c, i));
        facets.push_back({c->vertex((i + 1) & 3), c->vertex((i + 2) & 3), c->vertex((i + 3) & 3)});
      }
  return facets;
}

struct Surface_topology
{
  bool every_edge_has_two_facets = true;
  bool every_vertex_link_is_a_cycle = true;
  long euler_characteristic = 0;
};

Surface_topology topology(const std::vector<Triangle>& facets)
{
  using Edge = std::pair<Vertex_handle, Vertex_handle>;
  const auto edge = [](Vertex_handle a, Vertex_handle b) { return a < b ? Edge(a, b) : Edge(b, a); };

  std::map<Edge, int> edge_facets;
  std::map<Vertex_handle, std::map<Vertex_handle, std::vector<Vertex_handle>>> links;
  for(const Triangle& t : facets)
    for(int k = 0; k < 3; ++k)
    {
      ++edge_facets[edge(t[k], t[(k + 1) % 3])];
      auto& link = links[t[k]];
      link[t[(k + 1) % 3]].push_back(t[(k + 2) % 3]);
      link[t[(k + 2) % 3]].push_back(t[(k + 1) % 3]);
    }

  Surface_topology result;
  for(const auto& ef : edge_facets)
    if(ef.second != 2)
      result.every_edge_has_two_facets = false;

  // A closed 2-manifold: the link of each vertex is one cycle.
  for(const auto& vl : links)
  {
    const auto& link = vl.second;
    if(std::any_of(link.begin(), link.end(), [](const auto& n) { return n.second.size() != 2; }))
    {
      result.every_vertex_link_is_a_cycle = false;
      continue;
    }
    const Vertex_handle start = link.begin()->first;
    Vertex_handle previous = start, current = link.at(start)[0];
    std::size_t length = 1;
    while(current != start && length <= link.size())
    {
      const auto& next = link.at(current);
      const Vertex_handle following = (next[0] == previous) ? next[1] : next[0];
      previous = current;
      current = following;
      ++length;
    }
    if(length != link.size())
      result.every_vertex_link_is_a_cycle = false;
  }

  result.euler_characteristic =
    long(links.size()) - long(edge_facets.size()) + long(facets.size());
  return result;
}

long expected_euler_characteristic(Shape shape)
{
  switch(shape)
  {
  case Shape::torus: return 0;
  case Shape::genus2: return -2;
  default: return 2;
  }
}

double squared_distance_to_polylines(const Point& p, const std::vector<Polyline>& polylines)
{
  double best = std::numeric_limits<double>::infinity();
  for(const Polyline& polyline : polylines)
    for(std::size_t i = 0; i + 1 < polyline.size(); ++i)
      best = (std::min)(best, CGAL::squared_distance(K::Segment_3(polyline[i], polyline[i + 1]), p));
  return best;
}

bool is_polyline_endpoint(const Point& p, const std::vector<Polyline>& polylines)
{
  return std::any_of(polylines.begin(), polylines.end(), [&](const Polyline& polyline) {
    return p == polyline.front() || p == polyline.back();
  });
}

// Everything that must be reproduced: vertices (point, dimension) in order, and
// the cells of the complex with their subdomain.
struct Mesh_signature
{
  std::vector<Point> points;
  std::vector<int> dimensions;
  std::vector<std::array<std::size_t, 5>> cells;

  bool operator==(const Mesh_signature& other) const
  {
    return points == other.points && dimensions == other.dimensions && cells == other.cells;
  }
};

Mesh_signature signature(const C3t3& c3t3)
{
  const Tr& tr = c3t3.triangulation();
  Mesh_signature s;
  std::map<Vertex_handle, std::size_t> index;
  for(Vertex_handle v : tr.finite_vertex_handles())
  {
    index.emplace(v, s.points.size());
    s.points.push_back(bare_point(tr, v));
    s.dimensions.push_back(c3t3.in_dimension(v));
  }
  for(Cell_handle c : cells_in_complex(c3t3))
    s.cells.push_back({index.at(c->vertex(0)), index.at(c->vertex(1)), index.at(c->vertex(2)),
                       index.at(c->vertex(3)), std::size_t(c3t3.subdomain_index(c))});
  return s;
}

class GeneratedInput : public ::testing::TestWithParam<Shape>
{
};

TEST_P(GeneratedInput, SmallSizeHasAFewThousandCells)
{
  const Generated_mesh mesh = make_input(GetParam(), Size::small);
  EXPECT_EQ(mesh.name, name(GetParam()));
  ASSERT_NE(mesh.domain, nullptr);
  EXPECT_GE(mesh.c3t3.number_of_cells_in_complex(), 2000u);
  EXPECT_LE(mesh.c3t3.number_of_cells_in_complex(), 6000u);
}

TEST_P(GeneratedInput, CellsArePositivelyOriented)
{
  const Generated_mesh mesh = make_input(GetParam(), Size::small);
  std::size_t bad = 0;
  for(Cell_handle c : cells_in_complex(mesh.c3t3))
  {
    const std::array<Point, 4> p = bare_points(mesh.c3t3.triangulation(), c);
    if(CGAL::orientation(p[0], p[1], p[2], p[3]) != CGAL::POSITIVE)
      ++bad;
  }
  EXPECT_EQ(bad, 0u);
}

TEST_P(GeneratedInput, BoundaryIsAClosedSurfaceOfTheExpectedTopology)
{
  const Generated_mesh mesh = make_input(GetParam(), Size::small);
  const std::vector<Triangle> facets = boundary_facets(mesh.c3t3);
  ASSERT_FALSE(facets.empty());
  const Surface_topology t = topology(facets);
  EXPECT_TRUE(t.every_edge_has_two_facets);
  EXPECT_TRUE(t.every_vertex_link_is_a_cycle);
  EXPECT_EQ(t.euler_characteristic, expected_euler_characteristic(GetParam()));
}

TEST_P(GeneratedInput, VolumeIsCloseToTheDomainVolume)
{
  const Shape shape = GetParam();
  const Generated_mesh mesh = make_input(shape, Size::small);
  const double v = volume_of_complex(mesh.c3t3);
  switch(shape)
  {
  case Shape::sphere:
  case Shape::two_subdomains:
    EXPECT_NEAR(v, 4. * pi / 3., 0.03 * 4. * pi / 3.);
    break;
  case Shape::torus:
    EXPECT_NEAR(v, 2. * pi * pi * 1. * 0.4 * 0.4, 0.03 * 2. * pi * pi * 0.16);
    break;
  case Shape::genus2:
  {
    const double reference = quadrature_volume(*mesh.domain, 0.02);
    EXPECT_NEAR(v, reference, 0.03 * reference);
    break;
  }
  case Shape::sharp_part:
    // [0,2]x[0,1]x[0,1], minus the notch (0.5), minus the chamfer prism (0.0625).
    EXPECT_NEAR(v, 1.4375, 1e-6 * 1.4375);
    break;
  }
}

TEST_P(GeneratedInput, SameCallGivesTheSameMesh)
{
  const Generated_mesh first = make_input(GetParam(), Size::small);
  const Generated_mesh second = make_input(GetParam(), Size::small);
  const Mesh_signature a = signature(first.c3t3), b = signature(second.c3t3);
  EXPECT_FALSE(a.cells.empty());
  EXPECT_TRUE(a == b);
}

TEST_P(GeneratedInput, FeatureVerticesLieOnTheFeaturePolylines)
{
  const Shape shape = GetParam();
  const Generated_mesh mesh = make_input(shape, Size::small);
  const std::vector<Polyline> polylines = feature_polylines(shape);
  const Tr& tr = mesh.c3t3.triangulation();

  std::size_t on_curves = 0, on_corners = 0;
  for(Vertex_handle v : tr.finite_vertex_handles())
  {
    const Point p = bare_point(tr, v);
    const int dimension = mesh.c3t3.in_dimension(v);
    if(dimension == 1)
    {
      ++on_curves;
      EXPECT_LE(std::sqrt(squared_distance_to_polylines(p, polylines)), 1e-12) << p;
    }
    else if(dimension == 0)
    {
      ++on_corners;
      EXPECT_TRUE(is_polyline_endpoint(p, polylines)) << p;
    }
  }

  if(shape == Shape::sharp_part || shape == Shape::two_subdomains)
    EXPECT_GT(on_curves, 0u);
  else
  {
    EXPECT_TRUE(polylines.empty());
    EXPECT_EQ(on_curves + on_corners, 0u);
  }
}

INSTANTIATE_TEST_SUITE_P(All, GeneratedInput, ::testing::ValuesIn(all_shapes()),
                         [](const ::testing::TestParamInfo<Shape>& info) { return name(info.param); });

TEST(GeneratedInputs, NamesAreDistinct)
{
  std::set<std::string> names;
  for(Shape shape : all_shapes())
    names.insert(name(shape));
  EXPECT_EQ(names.size(), 5u);
}

TEST(GeneratedInputs, SharpPartPolylinesAreTheEdgesOfThePolyhedron)
{
  // A prism over a 7-gon: 21 edges, 14 corners, each corner on 3 edges.
  const std::vector<Polyline> polylines = feature_polylines(Shape::sharp_part);
  ASSERT_EQ(polylines.size(), 21u);
  std::map<Point, int> corner_edges;
  for(const Polyline& polyline : polylines)
  {
    ASSERT_EQ(polyline.size(), 2u);
    ++corner_edges[polyline.front()];
    ++corner_edges[polyline.back()];
  }
  EXPECT_EQ(corner_edges.size(), 14u);
  for(const auto& ce : corner_edges)
    EXPECT_EQ(ce.second, 3) << ce.first;
}

TEST(GeneratedInputs, SharpPartCornersAreMeshVertices)
{
  const Generated_mesh mesh = make_input(Shape::sharp_part, Size::small);
  const Tr& tr = mesh.c3t3.triangulation();
  std::set<Point> corners;
  for(Vertex_handle v : tr.finite_vertex_handles())
    if(mesh.c3t3.in_dimension(v) == 0)
      corners.insert(bare_point(tr, v));
  EXPECT_EQ(corners.size(), 14u);
}

TEST(GeneratedInputs, TwoSubdomainsHaveBothLabelsAndAnInterface)
{
  const Generated_mesh mesh = make_input(Shape::two_subdomains, Size::small);
  const C3t3& c3t3 = mesh.c3t3;
  const Tr& tr = c3t3.triangulation();

  std::set<int> labels;
  std::size_t interface_facets = 0;
  double max_interface_z = 0.;
  for(Cell_handle c : cells_in_complex(c3t3))
  {
    labels.insert(c3t3.subdomain_index(c));
    for(int i = 0; i < 4; ++i)
    {
      const Cell_handle n = c->neighbor(i);
      // Each interface facet once, from the lower cell.
      if(c3t3.subdomain_index(c) == 1 && c3t3.is_in_complex(n) && c3t3.subdomain_index(n) == 2)
      {
        ++interface_facets;
        EXPECT_TRUE(c3t3.is_in_complex(c, i));
        for(int k = 1; k < 4; ++k)
          max_interface_z = (std::max)(max_interface_z,
                                       std::abs(bare_point(tr, c->vertex((i + k) & 3)).z()));
      }
    }
  }
  EXPECT_EQ(labels, (std::set<int>{1, 2}));
  EXPECT_GT(interface_facets, 0u);
  // The interface vertices are on the plane z = 0 up to the bisection error.
  EXPECT_LT(max_interface_z, 1e-5);

  const double half = 2. * pi / 3.;
  EXPECT_NEAR(volume_of_subdomain(c3t3, 1), half, 0.03 * half);
  EXPECT_NEAR(volume_of_subdomain(c3t3, 2), half, 0.03 * half);
}

TEST(RandomSphereInput, HasTheRequestedPointsOnTheUnitSphere)
{
  const Delaunay dt = make_random_sphere();
  EXPECT_EQ(dt.number_of_vertices(), 642u);
  EXPECT_TRUE(dt.is_valid());
  for(const Point& p : dt.points())
    EXPECT_NEAR(std::sqrt(CGAL::squared_distance(p, Point(CGAL::ORIGIN))), 1., 1e-12) << p;
  EXPECT_EQ(make_random_sphere(Size::small).number_of_vertices(), 642u);
}

TEST(RandomSphereInput, IsDeterministicAndSeeded)
{
  const auto points = [](const Delaunay& dt) {
    return std::vector<Point>(dt.points_begin(), dt.points_end());
  };
  const auto cells = [](const Delaunay& dt) {
    std::map<Delaunay::Vertex_handle, std::size_t> index;
    for(Delaunay::Vertex_handle v : dt.finite_vertex_handles())
      index.emplace(v, index.size());
    std::vector<std::array<std::size_t, 4>> result;
    for(Delaunay::Cell_handle c : dt.finite_cell_handles())
      result.push_back({index.at(c->vertex(0)), index.at(c->vertex(1)),
                        index.at(c->vertex(2)), index.at(c->vertex(3))});
    return result;
  };

  const Delaunay a = make_random_sphere(642, 7), b = make_random_sphere(642, 7);
  EXPECT_EQ(points(a), points(b));
  EXPECT_EQ(cells(a), cells(b));
  EXPECT_NE(points(a), points(make_random_sphere(642, 8)));
}

TEST(PaperRandomSphere, HasNoDihedralAngleBelowThePapersInputAndKeepsItsPoints)
{
  const Generated_mesh mesh = make_paper_random_sphere();
  const Tr& tr = mesh.c3t3.triangulation();
  EXPECT_EQ(tr.number_of_vertices(), 729u);
  EXPECT_EQ(mesh.c3t3.number_of_cells_in_complex(), tr.number_of_finite_cells());
  double smallest = 180.;
  for(Cell_handle c : cells_in_complex(mesh.c3t3))
  {
    const std::array<Point, 4> p = bare_points(tr, c);
    ASSERT_EQ(CGAL::orientation(p[0], p[1], p[2], p[3]), CGAL::POSITIVE);
    static const int edge[6][4] = {{0, 1, 2, 3}, {0, 2, 1, 3}, {0, 3, 1, 2}, {1, 2, 0, 3}, {1, 3, 0, 2}, {2, 3, 0, 1}};
    for(const auto& e : edge)
      smallest = (std::min)(smallest, std::abs(CGAL::approximate_dihedral_angle(p[e[0]], p[e[1]], p[e[2]], p[e[3]])));
  }
  EXPECT_GE(smallest, 5.86);

  // The boundary is the hull of the 642 points on the unit sphere, a closed sphere.
  const std::vector<Triangle> facets = boundary_facets(mesh.c3t3);
  EXPECT_EQ(facets.size(), 2u * 642u - 4u);
  const Surface_topology t = topology(facets);
  EXPECT_TRUE(t.every_edge_has_two_facets);
  EXPECT_EQ(t.euler_characteristic, 2);
  for(const Triangle& f : facets)
    for(Vertex_handle v : f)
      EXPECT_NEAR(std::sqrt(CGAL::squared_distance(bare_point(tr, v), Point(CGAL::ORIGIN))), 1., 1e-12);

  // Built from a Tet_mesh, not by Mesh_3: each facet of the complex has its
  // circumcenter as surface center on both sides (CGAL's Lloyd reads them).
  for(auto f = mesh.c3t3.facets_in_complex_begin(); f != mesh.c3t3.facets_in_complex_end(); ++f)
  {
    const Point p[3] = {bare_point(tr, f->first->vertex((f->second + 1) & 3)),
                        bare_point(tr, f->first->vertex((f->second + 2) & 3)),
                        bare_point(tr, f->first->vertex((f->second + 3) & 3))};
    const auto mirror = tr.mirror_facet(*f);
    for(const Point& center : {f->first->get_facet_surface_center(f->second),
                               mirror.first->get_facet_surface_center(mirror.second)})
    {
      EXPECT_NEAR(CGAL::squared_distance(center, p[0]), CGAL::squared_distance(center, p[1]), 1e-12);
      EXPECT_NEAR(CGAL::squared_distance(center, p[0]), CGAL::squared_distance(center, p[2]), 1e-12);
      EXPECT_LT(CGAL::squared_distance(center, K::Plane_3(p[0], p[1], p[2])), 1e-24);
    }
  }
}

TEST(PaperRandomSphere, IsDeterministicAndSeeded)
{
  const Mesh_signature a = signature(make_paper_random_sphere(3).c3t3);
  EXPECT_FALSE(a.cells.empty());
  EXPECT_TRUE(a == signature(make_paper_random_sphere(3).c3t3));
  EXPECT_FALSE(a == signature(make_paper_random_sphere(4).c3t3));
}

} // namespace
