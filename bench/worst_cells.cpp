// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Where the default pipeline stops: after smoothing a generated input, the cells
// with the smallest and the largest dihedral angles, with how many of their
// vertices and facets lie on the boundary and their shape (Bad_tet_shape.h), and
// the angles of the boundary triangles before and after.
//
//   worst_cells [--only NAME] [--seed S] [--no-insertion] [--no-phase] [--max-min T] [--count K]
//               [--contraction] [--no-cavity] [--write-input FILE.mesh] [--margin DEGREES] [--cavity-attempts N]
#include "inputs/generated_inputs.h"

#include <CGAL/BODT_3/IO/mesh_io.h>
#include <CGAL/BODT_3/Tet_mesh_conversion.h>
#include <CGAL/BODT_3/internal/Insertion/Bad_tet_shape.h>
#include <CGAL/BODT_3/mesh_quality.h>
#include <CGAL/BODT_3/smooth.h>
#include <CGAL/BODT_3/internal/Quality/tet_quality.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

using namespace bodt_inputs;
namespace BODT = CGAL::BODT_3;

namespace {

constexpr double degrees = 180 / 3.14159265358979323846;

// The smallest and largest angles of the boundary triangles.
void surface_angles(const C3t3& c3t3, const char* when)
{
  double lo = 180, hi = 0;
  std::size_t n = 0;
  for(auto it = c3t3.facets_in_complex_begin(); it != c3t3.facets_in_complex_end(); ++it)
  {
    const auto f = *it;
    Point p[3];
    for(int k = 0, j = 0; k < 4; ++k)
      if(k != f.second) p[j++] = f.first->vertex(k)->point().point();
    for(int k = 0; k < 3; ++k)
    {
      const auto u = p[(k + 1) % 3] - p[k], v = p[(k + 2) % 3] - p[k];
      const double a = std::acos(std::clamp(u * v / std::sqrt(u * u * (v * v)), -1.0, 1.0)) * degrees;
      lo = std::min(lo, a);
      hi = std::max(hi, a);
    }
    ++n;
  }
  std::printf("%s: %zu boundary triangles, angles %.2f .. %.2f\n", when, n, lo, hi);
}

void worst(const C3t3& c3t3, std::size_t count)
{
  struct Row
  {
    double lo, hi;
    int on_boundary, boundary_facets;
    BODT::internal::Bad_tet_shape shape;
    std::string edge;   // where the smallest angle is
  };
  // The edge of cell c between vertices i and j: on the surface (in a boundary
  // triangle), with both, one or no vertex on the boundary; how many cells of
  // the mesh it has and the sum of their angles at it. A surface edge with
  // n cells around it has an angle below (its angle in the surface) / n.
  auto describe = [&](C3t3::Triangulation::Cell_handle c, int i, int j) {
    const auto& tr = c3t3.triangulation();
    int ends = (c3t3.in_dimension(c->vertex(i)) < 3) + (c3t3.in_dimension(c->vertex(j)) < 3);
    bool surface = false;
    int n = 0;
    double sum = 0;
    auto circ = tr.incident_cells(c, i, j), done = circ;
    do
    {
      const auto x = circ;
      const int xi = x->index(c->vertex(i)), xj = x->index(c->vertex(j));
      for(int k = 0; k < 4; ++k)
        if(k != xi && k != xj && c3t3.is_in_complex(x, k)) surface = true;
      if(c3t3.is_in_complex(x))
      {
        ++n;
        const auto cs = BODT::internal::dihedral_cosines(x->vertex(0)->point().point(), x->vertex(1)->point().point(),
                                                         x->vertex(2)->point().point(), x->vertex(3)->point().point());
        static const int ends_of[6][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};
        for(int e = 0; e < 6; ++e)
          if((ends_of[e][0] == xi && ends_of[e][1] == xj) || (ends_of[e][0] == xj && ends_of[e][1] == xi))
            sum += std::acos(std::clamp(cs[e], -1.0, 1.0)) * degrees;
      }
    } while(++circ != done);
    auto degree = [&](C3t3::Triangulation::Vertex_handle v) {
      std::vector<C3t3::Triangulation::Cell_handle> star;
      tr.finite_incident_cells(v, std::back_inserter(star));
      return static_cast<std::size_t>(std::count_if(star.begin(), star.end(), [&](auto x) { return c3t3.is_in_complex(x); }));
    };
    char text[160];
    std::snprintf(text, sizeof text, "%s edge, %d on boundary, %d cells, angles sum %.1f; ends %zu, %zu (dim %d, %d; %zu, %zu cells)",
                  surface ? "surface" : "inner", ends, n, sum, std::hash<const void*>()(&*c->vertex(i)) % 100000,
                  std::hash<const void*>()(&*c->vertex(j)) % 100000, c3t3.in_dimension(c->vertex(i)), c3t3.in_dimension(c->vertex(j)), degree(c->vertex(i)), degree(c->vertex(j)));
    return std::string(text);
  };
  std::vector<Row> rows;
  for(auto c = c3t3.cells_in_complex_begin(); c != c3t3.cells_in_complex_end(); ++c)
  {
    const Point a = c->vertex(0)->point().point();
    const Point b = c->vertex(1)->point().point();
    const Point d = c->vertex(2)->point().point();
    const Point e = c->vertex(3)->point().point();
    const auto cs = BODT::internal::dihedral_cosines(a, b, d, e);
    double lo = 180, hi = 0;
    int at = 0;
    for(int e = 0; e < 6; ++e)
    {
      const double ang = std::acos(std::clamp(cs[e], -1.0, 1.0)) * degrees;
      if(ang < lo) at = e;
      lo = std::min(lo, ang);
      hi = std::max(hi, ang);
    }
    static const int ends_of[6][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};
    Row r{lo, hi, 0, 0, BODT::internal::Bad_tet_shape::good, describe(c, ends_of[at][0], ends_of[at][1])};
    for(int k = 0; k < 4; ++k)
    {
      if(c3t3.in_dimension(c->vertex(k)) < 3) ++r.on_boundary;
      if(c3t3.is_in_complex(c, k)) ++r.boundary_facets;
    }
    BODT::Bad_tet_options bo;
    bo.small_angle = 25;
    bo.large_angle = 135;
    r.shape = BODT::internal::classify_bad_tet(a, b, d, e, bo).shape;
    rows.push_back(r);
  }
  auto print = [&](const char* title) {
    std::printf("%s\n", title);
    for(std::size_t i = 0; i < std::min(count, rows.size()); ++i)
      std::printf("  %6.2f %6.2f  boundary vertices %d facets %d  %s; smallest at: %s\n", rows[i].lo, rows[i].hi,
                  rows[i].on_boundary, rows[i].boundary_facets, BODT::internal::name(rows[i].shape),
                  rows[i].edge.c_str());
  };
  std::sort(rows.begin(), rows.end(), [](const Row& x, const Row& y) { return x.lo < y.lo; });
  print("smallest angles:");
  std::sort(rows.begin(), rows.end(), [](const Row& x, const Row& y) { return x.hi > y.hi; });
  print("largest angles:");
}

} // namespace

int main(int argc, char** argv)
{
  std::string only = "random_sphere";
  BODT::Smoothing_options opt;
  opt.threads = 1;
  std::size_t count = 12;
  unsigned seed = 1;
  std::string write_input;   // the generated input, as a Medit file (for bodt smooth, bench/path_spread)
  for(int i = 1; i < argc; ++i)
  {
    if(!std::strcmp(argv[i], "--only") && i + 1 < argc) only = argv[++i];
    else if(!std::strcmp(argv[i], "--no-insertion")) opt.vertex_insertion = false;
    else if(!std::strcmp(argv[i], "--no-phase")) opt.largest_angle_phase = false;
    else if(!std::strcmp(argv[i], "--seed") && i + 1 < argc) seed = static_cast<unsigned>(std::stoul(argv[++i]));
    else if(!std::strcmp(argv[i], "--max-min") && i + 1 < argc) opt.max_min_threshold = std::stod(argv[++i]);
    else if(!std::strcmp(argv[i], "--count") && i + 1 < argc) count = std::stoul(argv[++i]);
    else if(!std::strcmp(argv[i], "--contraction")) opt.edge_contraction = true;
    else if(!std::strcmp(argv[i], "--write-input") && i + 1 < argc) write_input = argv[++i];
    else if(!std::strcmp(argv[i], "--no-cavity")) opt.cavity_insertion = false;
    else if(!std::strcmp(argv[i], "--margin") && i + 1 < argc) opt.worst_cell_margin = std::stod(argv[++i]);
    else if(!std::strcmp(argv[i], "--cavity-attempts") && i + 1 < argc)
      opt.insertion.max_cavity_attempts = std::stoi(argv[++i]);
  }
  Generated_mesh in;
  if(only == "random_sphere") in = make_paper_random_sphere(seed);
  for(Shape s : all_shapes())
    if(name(s) == only) in = make_input(s, Size::benchmark);
  C3t3 c3t3 = in.c3t3;
  if(!write_input.empty()) BODT::IO::write_mesh(write_input, BODT::c3t3_to_tet_mesh(c3t3));
  const auto q0 = BODT::mesh_quality(c3t3);
  std::printf("input: %.2f / %.2f, %zu vertices\n", q0.min_dihedral_deg, q0.max_dihedral_deg,
              c3t3.triangulation().number_of_vertices());
  surface_angles(c3t3, "before");
  const auto r = BODT::smooth(c3t3, opt);
  const auto q = BODT::mesh_quality(c3t3);
  std::printf("after %zu iterations, %.2f s: %.2f / %.2f, %zu vertices\n", r.iterations, r.seconds,
              q.min_dihedral_deg, q.max_dihedral_deg, c3t3.triangulation().number_of_vertices());
  surface_angles(c3t3, "after");
  worst(c3t3, count);
  return 0;
}
