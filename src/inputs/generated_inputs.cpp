// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The only translation unit that instantiates make_mesh_3 (it is slow to compile).
#include "inputs/generated_inputs.h"

#include <CGAL/BODT_3/Tet_mesh_conversion.h>
#include <CGAL/BODT_3/internal/Quality/tet_quality.h>
#include <CGAL/Mesh_criteria_3.h>
#include <CGAL/make_mesh_3.h>
#include <CGAL/point_generators_3.h>
#include <CGAL/Random.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <iterator>
#include <limits>
#include <stdexcept>

namespace bodt_inputs {

namespace {

namespace params = CGAL::parameters;

using Mesh_criteria = CGAL::Mesh_criteria_3<Tr>;
using Labeling_function = std::function<int(const Point&)>;

constexpr double pi = 3.14159265358979323846;

// Mesh_3 criteria that vary with the shape and the size; facet_angle and
// cell_radius_edge_ratio are fixed (see `criteria()`).
struct Sizing
{
  double edge_size;
  double facet_size;
  double facet_distance;
  double cell_size;
};

// -- Labeling functions: 0 outside, the subdomain label inside ----------------

int sphere_label(const Point& p)
{
  return p.x() * p.x() + p.y() * p.y() + p.z() * p.z() < 1. ? 1 : 0;
}

// Signed distance to the ring torus of axis z, centered at (cx, 0, 0).
double torus_distance(const Point& p, double cx, double R, double r)
{
  const double dx = p.x() - cx;
  const double q = std::sqrt(dx * dx + p.y() * p.y()) - R;
  return std::sqrt(q * q + p.z() * p.z()) - r;
}

int torus_label(const Point& p)
{
  return torus_distance(p, 0., 1., 0.4) < 0. ? 1 : 0;
}

// Two tori (R = 1, r = 0.4) side by side along x whose core circles do not meet
// but whose tubes overlap around the origin, joined by an exponential smooth
// minimum so that the boundary is smooth. The overlap is a single blob, so the
// solid has two handles (boundary of genus 2).
int genus2_label(const Point& p)
{
  const double k = 0.1;
  const double d1 = torus_distance(p, -1.25, 1., 0.4);
  const double d2 = torus_distance(p, 1.25, 1., 0.4);
  const double d = (std::min)(d1, d2) - k * std::log1p(std::exp(-std::abs(d1 - d2) / k));
  return d < 0. ? 1 : 0;
}

// The profile of the sharp part in the (x, z) plane, extruded along y in [0, 1]:
// the L of [0,2]x[0,1] minus [1,2]x[0.5,1], with the corner (0, 1) chamfered by
// the plane z - x/2 = 3/4 (dihedral angles of about 116.6 and 153.4 degrees).
// Every coordinate is a dyadic rational, so the corners are exact doubles.
const double sharp_profile[][2] = {
  {0., 0.}, {2., 0.}, {2., 0.5}, {1., 0.5}, {1., 1.}, {0.5, 1.}, {0., 0.75}};

int sharp_part_label(const Point& p)
{
  const double x = p.x(), y = p.y(), z = p.z();
  const bool in_block = 0. < x && x < 2. && 0. < y && y < 1. && 0. < z && z < 1.;
  const bool in_notch = x > 1. && z > 0.5;
  const bool beyond_chamfer = z - 0.5 * x > 0.75;
  return in_block && !in_notch && !beyond_chamfer ? 1 : 0;
}

int two_subdomains_label(const Point& p)
{
  if(sphere_label(p) == 0)
    return 0;
  return p.z() < 0. ? 1 : 2;
}

// -- Domains ------------------------------------------------------------------

// The labeled domain seeds a feature-less mesh by shooting segments from the
// center of its bounding box, so every box below is centered inside the domain
// (off-center for the torus, whose hole contains the origin).
std::shared_ptr<Mesh_domain> make_domain(Shape shape)
{
  Labeling_function f;
  CGAL::Bbox_3 box;
  double error = 1e-6;
  switch(shape)
  {
  case Shape::sphere:
    f = sphere_label;
    box = CGAL::Bbox_3(-1.2, -1.2, -1.2, 1.2, 1.2, 1.2);
    break;
  case Shape::torus:
    f = torus_label;
    box = CGAL::Bbox_3(-1.5, -1.5, -0.5, 3.5, 1.5, 0.5);
    break;
  case Shape::genus2:
    f = genus2_label;
    box = CGAL::Bbox_3(-2.8, -1.6, -0.6, 2.8, 1.6, 0.6);
    break;
  case Shape::sharp_part:
    f = sharp_part_label;
    box = CGAL::Bbox_3(-0.3, -0.1, -0.1, 2.1, 1.1, 1.1);
    // Surface points are found by bisection: make it exact enough that they lie
    // on the planar faces.
    error = 1e-10;
    break;
  case Shape::two_subdomains:
    f = two_subdomains_label;
    // Off-center in z so that the seeding center is not on the interface.
    box = CGAL::Bbox_3(-1.2, -1.2, -1.1, 1.2, 1.2, 1.3);
    break;
  }

  auto domain = std::make_shared<Mesh_domain>(params::function = f,
                                              params::bounding_object = box,
                                              params::relative_error_bound = error);
  const std::vector<Polyline> polylines = feature_polylines(shape);
  if(!polylines.empty())
    domain->add_features(polylines.begin(), polylines.end());
  return domain;
}

// -- Criteria -----------------------------------------------------------------

// Measured with bench/inputs_sizes: `small` gives a few thousand cells in the
// complex and `benchmark` about 40,000. The facet distances keep the volume of
// the smooth shapes within about 1.5% of the exact one at the small size.
Sizing sizing(Shape shape, Size size)
{
  const bool small = (size == Size::small);
  switch(shape)
  {
  case Shape::sphere:
    return small ? Sizing{0.135, 0.135, 0.008, 0.17} : Sizing{0.062, 0.062, 0.002, 0.078};
  case Shape::torus:
    return small ? Sizing{0.15, 0.15, 0.008, 0.2} : Sizing{0.056, 0.056, 0.002, 0.075};
  case Shape::genus2:
    return small ? Sizing{0.2, 0.2, 0.01, 0.25} : Sizing{0.08, 0.08, 0.002, 0.1};
  case Shape::sharp_part:
    return small ? Sizing{0.1, 0.1, 0.01, 0.125} : Sizing{0.0445, 0.0445, 0.005, 0.056};
  case Shape::two_subdomains:
    return small ? Sizing{0.14, 0.14, 0.008, 0.175} : Sizing{0.063, 0.063, 0.002, 0.08};
  }
  throw std::invalid_argument("bodt_inputs::sizing: unknown shape");
}

Mesh_criteria criteria(const Sizing& s)
{
  return Mesh_criteria(params::edge_size = s.edge_size,
                       params::facet_angle = 25.,
                       params::facet_size = s.facet_size,
                       params::facet_distance = s.facet_distance,
                       params::cell_radius_edge_ratio = 3.,
                       params::cell_size = s.cell_size);
}

} // namespace

std::vector<Shape> all_shapes()
{
  return {Shape::sphere, Shape::torus, Shape::genus2, Shape::sharp_part,
          Shape::two_subdomains};
}

std::string name(Shape shape)
{
  switch(shape)
  {
  case Shape::sphere: return "sphere";
  case Shape::torus: return "torus";
  case Shape::genus2: return "genus2";
  case Shape::sharp_part: return "sharp_part";
  case Shape::two_subdomains: return "two_subdomains";
  }
  throw std::invalid_argument("bodt_inputs::name: unknown shape");
}

std::vector<Polyline> feature_polylines(Shape shape)
{
  std::vector<Polyline> polylines;
  if(shape == Shape::sharp_part)
  {
    // The part is a prism over `sharp_profile`: each profile edge gives one edge
    // on each cap (y = 0 and y = 1), each profile corner one edge along y.
    const std::size_t n = std::size(sharp_profile);
    for(std::size_t i = 0; i < n; ++i)
    {
      const double* a = sharp_profile[i];
      const double* b = sharp_profile[(i + 1) % n];
      for(double y : {0., 1.})
        polylines.push_back(Polyline{Point(a[0], y, a[1]), Point(b[0], y, b[1])});
      polylines.push_back(Polyline{Point(a[0], 0., a[1]), Point(a[0], 1., a[1])});
    }
  }
  else if(shape == Shape::two_subdomains)
  {
    // The junction circle, closed (first point == last point). The chords are
    // short enough (sagitta below 1e-5) not to matter at the mesh sizes used.
    const int n = 1024;
    Polyline circle;
    for(int i = 0; i < n; ++i)
    {
      const double t = 2. * pi * i / n;
      circle.push_back(Point(std::cos(t), std::sin(t), 0.));
    }
    circle.push_back(circle.front());
    polylines.push_back(circle);
  }
  return polylines;
}

Generated_mesh make_input(Shape shape, Size size, double refinement)
{
  std::shared_ptr<Mesh_domain> domain = make_domain(shape);
  Sizing s = sizing(shape, size);
  s.edge_size /= refinement;
  s.facet_size /= refinement;
  s.facet_distance /= refinement * refinement;
  s.cell_size /= refinement;
  return Generated_mesh{name(shape), domain,
                        CGAL::make_mesh_3<C3t3>(*domain, criteria(s),
                                                params::no_perturb(),
                                                params::no_exude())};
}

Delaunay make_random_sphere(std::size_t n, unsigned seed)
{
  CGAL::Random rng(seed);
  CGAL::Random_points_on_sphere_3<Point> generator(1., rng);
  std::vector<Point> points;
  points.reserve(n);
  std::copy_n(generator, n, std::back_inserter(points));
  return Delaunay(points.begin(), points.end());
}

Delaunay make_random_sphere(Size size)
{
  // Points on a sphere give about 3n finite cells (all vertices are on the hull):
  // 13,300 points give about 40,000 (measured).
  return make_random_sphere(size == Size::small ? 642 : 13300);
}

namespace {

using Indexed_vertex = CGAL::Triangulation_vertex_base_with_info_3<int, K>;
using Indexed_delaunay =
    CGAL::Delaunay_triangulation_3<K, CGAL::Triangulation_data_structure_3<Indexed_vertex>>;

// The paper's Random Sphere input has its smallest dihedral angle at 5.86 degrees:
// the sliver removal below stops there, to start from a comparable mesh.
constexpr double paper_input_min_angle = 5.86;

// How far below the bound a Delaunay triangulation of `points` is: the number of
// cells whose smallest dihedral angle is under it, then the largest cosine of a
// dihedral angle (smaller is better). Compared lexicographically.
struct Sliver_score
{
  std::size_t below = 0;
  double worst_cosine = -1;
  std::array<int, 4> worst_cell{};
  bool operator<(const Sliver_score& o) const
  {
    return below != o.below ? below < o.below : worst_cosine < o.worst_cosine;
  }
};

Sliver_score sliver_score(const Indexed_delaunay& dt, double bound_cosine)
{
  Sliver_score score;
  for(auto c : dt.finite_cell_handles())
  {
    const std::array<double, 6> cosines = CGAL::BODT_3::internal::dihedral_cosines(
        c->vertex(0)->point(), c->vertex(1)->point(), c->vertex(2)->point(), c->vertex(3)->point());
    const double worst = *std::max_element(cosines.begin(), cosines.end());
    if(worst > bound_cosine) ++score.below;
    std::array<int, 4> ids = {c->vertex(0)->info(), c->vertex(1)->info(), c->vertex(2)->info(), c->vertex(3)->info()};
    std::sort(ids.begin(), ids.end());
    // Ties broken by the vertex indices, so that the result does not depend on cell order.
    if(worst > score.worst_cosine || (worst == score.worst_cosine && ids < score.worst_cell))
    {
      score.worst_cosine = worst;
      score.worst_cell = ids;
    }
  }
  return score;
}

Indexed_delaunay triangulate(const std::vector<Point>& points)
{
  std::vector<std::pair<Point, int>> indexed;
  indexed.reserve(points.size());
  for(std::size_t i = 0; i < points.size(); ++i)
    indexed.emplace_back(points[i], static_cast<int>(i));
  return Indexed_delaunay(indexed.begin(), indexed.end());
}

// A sliver removal of our own, because CGAL's perturb_mesh_3 on this input took
// from seconds to over ten minutes from one run to the next (its sets are ordered
// by address). Random trial moves of the worst cell's vertices, kept when they
// lower the number of cells under the bound (or, at equal count, raise the worst
// angle); surface points stay on the unit sphere, inner points inside radius 0.95.
// Every draw comes from `rng` and every choice is by index: same seed, same mesh.
void remove_slivers(std::vector<Point>& points, std::size_t on_sphere, CGAL::Random& rng)
{
  const double bound_cosine = std::cos(paper_input_min_angle * pi / 180);
  Sliver_score score = sliver_score(triangulate(points), bound_cosine);
  const int max_rounds = 5000, trials_per_vertex = 16;
  for(int round = 0; round < max_rounds && score.below > 0; ++round)
  {
    double shortest = std::numeric_limits<double>::infinity();
    for(int i = 0; i < 4; ++i)
      for(int j = i + 1; j < 4; ++j)
        shortest = (std::min)(shortest, std::sqrt(CGAL::squared_distance(points[score.worst_cell[i]],
                                                                         points[score.worst_cell[j]])));
    bool moved = false;
    for(int i = 0; i < 4 && !moved; ++i)
    {
      const std::size_t v = static_cast<std::size_t>(score.worst_cell[i]);
      const Point old = points[v];
      for(int t = 0; t < trials_per_vertex && !moved; ++t)
      {
        const double step = 0.5 * shortest * rng.get_double(0.05, 1.);
        const double dx = rng.get_double(-1, 1), dy = rng.get_double(-1, 1), dz = rng.get_double(-1, 1);
        const double len = std::sqrt(dx * dx + dy * dy + dz * dz);
        if(len < 1e-3) continue;
        Point p(old.x() + step * dx / len, old.y() + step * dy / len, old.z() + step * dz / len);
        const double r = std::sqrt(p.x() * p.x() + p.y() * p.y() + p.z() * p.z());
        if(v < on_sphere)
          p = Point(p.x() / r, p.y() / r, p.z() / r);
        else if(r > 0.95)
          continue;
        points[v] = p;
        const Sliver_score trial = sliver_score(triangulate(points), bound_cosine);
        if(trial < score)
        {
          score = trial;
          moved = true;
        }
        else
          points[v] = old;
      }
    }
    if(!moved) break;   // the worst cell resists every trial: stop rather than loop
  }
}

} // namespace

Generated_mesh make_paper_random_sphere(unsigned seed)
{
  CGAL::Random rng(seed);
  std::vector<Point> points;
  CGAL::Random_points_on_sphere_3<Point> on_sphere(1., rng);
  std::copy_n(on_sphere, 642, std::back_inserter(points));
  // 87 inner points in a ball of radius 0.8 (the paper says "about 90").
  CGAL::Random_points_in_sphere_3<Point> inside(0.8, rng);
  std::copy_n(inside, 87, std::back_inserter(points));
  remove_slivers(points, 642, rng);
  const Indexed_delaunay dt = triangulate(points);

  CGAL::BODT_3::Tet_mesh mesh;
  mesh.points = points;
  mesh.vertex_refs.assign(mesh.points.size(), 0);
  for(auto c : dt.finite_cell_handles())
  {
    mesh.tets.push_back({c->vertex(0)->info(), c->vertex(1)->info(), c->vertex(2)->info(), c->vertex(3)->info()});
    mesh.tet_labels.push_back(1);
  }

  Generated_mesh out{"random_sphere", make_domain(Shape::sphere), C3t3()};
  CGAL::BODT_3::tet_mesh_to_c3t3(mesh, out.c3t3);
  return out;
}

} // namespace bodt_inputs
