// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Every Mesh_3 instantiation of the comparison, in one translation unit because
// each is slow to compile: meshing CGAL's data surfaces, and CGAL's optimizers
// and remesher run on both kinds of Mesh_3 output.
#include "compare/compare.h"

#include <CGAL/Mesh_criteria_3.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Random.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/exude_mesh_3.h>
#include <CGAL/lloyd_optimize_mesh_3.h>
#include <CGAL/make_mesh_3.h>
#include <CGAL/odt_optimize_mesh_3.h>
#include <CGAL/perturb_mesh_3.h>
#include <CGAL/tetrahedral_remeshing.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <stdexcept>
#include <utility>

namespace bodt_compare {

namespace params = CGAL::parameters;

namespace {

// Calls `f(c3t3, domain)` on a Mesh_3 output; the method table never calls a
// CGAL method on anything else.
template <class F>
Run on_mesh_3(Mesh& mesh, F&& f)
{
  if(auto* g = std::get_if<bodt_inputs::Generated_mesh>(&mesh)) return f(g->c3t3, *g->domain);
  if(auto* s = std::get_if<Surface_mesh>(&mesh)) return f(s->c3t3, *s->domain);
  throw std::logic_error("CGAL's mesh optimizers apply to Mesh_3 outputs only");
}

// Mesh_3 criteria for a surface, all proportional to one length `h`, as in the
// generated inputs: facet and feature edge size h, cell size 1.25 h, facet
// distance h / 10.
CGAL::Mesh_criteria_3<Surface_tr> surface_criteria(double h)
{
  return CGAL::Mesh_criteria_3<Surface_tr>(params::edge_size = h, params::facet_angle = 25.,
                                           params::facet_size = h, params::facet_distance = 0.1 * h,
                                           params::cell_radius_edge_ratio = 3., params::cell_size = 1.25 * h);
}

Surface_c3t3 mesh_surface(const Surface_domain& domain, double h)
{
  // Mesh_3 draws from CGAL's default random generator: reset it so that the mesh
  // does not depend on what ran before.
  CGAL::get_default_random() = CGAL::Random(0);
  return CGAL::make_mesh_3<Surface_c3t3>(domain, surface_criteria(h), params::no_perturb(), params::no_exude());
}

std::string file_name(const std::string& path)
{
  const std::size_t slash = path.find_last_of('/');
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

// Mean length of the edges of the cells in the complex, each edge counted once.
template <class C3T3>
double mean_edge_length(const C3T3& c3t3)
{
  const auto& tr = c3t3.triangulation();
  auto cp = tr.geom_traits().construct_point_3_object();
  double sum = 0;
  std::size_t n = 0;
  for(const auto& e : tr.finite_edges())
  {
    auto c = tr.incident_cells(e), done = c;
    bool in_complex = false;
    do in_complex = in_complex || c3t3.is_in_complex(c);
    while(++c != done && !in_complex);
    if(!in_complex) continue;
    sum += std::sqrt(CGAL::squared_distance(cp(e.first->vertex(e.second)->point()),
                                            cp(e.first->vertex(e.third)->point())));
    ++n;
  }
  return n ? sum / double(n) : 0.0;
}

// A closed surface as Mesh_3's domain, with its sharp edges detected, and the
// diagonal of its bounding box.
std::pair<std::shared_ptr<Surface_domain>, double> surface_domain(const std::string& off_path)
{
  std::ifstream in(off_path);
  Polyhedron polyhedron;
  if(!(in >> polyhedron)) throw std::runtime_error(off_path + ": cannot read an OFF surface");
  if(!CGAL::is_closed(polyhedron)) throw std::runtime_error(off_path + ": the surface is not closed");
  // Some of CGAL's data surfaces have quadrilateral and larger faces.
  if(!CGAL::is_triangle_mesh(polyhedron)) CGAL::Polygon_mesh_processing::triangulate_faces(polyhedron);

  const CGAL::Bbox_3 box = CGAL::Polygon_mesh_processing::bbox(polyhedron);
  auto domain = std::make_shared<Surface_domain>(polyhedron);
  domain->detect_features();   // CGAL's default: edges sharper than 60 degrees
  const double diagonal = std::sqrt(CGAL::square(box.xmax() - box.xmin()) + CGAL::square(box.ymax() - box.ymin()) +
                                    CGAL::square(box.zmax() - box.zmin()));
  return {domain, diagonal};
}

// The number of cells falls with h far slower than h^-3 while the surface and
// its features dominate (coarse meshes, thin parts), so h is searched for: secant
// steps on log(cells) against log(h), each step by a factor 0.4 to 2.5, until
// the mesh is within 15% of the target. h stays below a tenth of the diagonal:
// where the features alone need more cells than the target, the coarsest wins.
// The search starts at `h`, which ends as the size of the mesh returned;
// `previous_h` and `previous_cells` are a mesh made before (0: none), for the
// first secant step.
Surface_c3t3 search_size(const Surface_domain& domain, double target, double diagonal, double& h, double previous_h,
                         double previous_cells)
{
  Surface_c3t3 c3t3;
  for(int step = 0;; ++step)
  {
    c3t3 = Surface_c3t3();   // one mesh in memory at a time: they reach gigabytes
    c3t3 = mesh_surface(domain, h);
    const double cells = std::max(1., double(c3t3.number_of_cells_in_complex()));
    if(std::abs(cells / target - 1.) < 0.15 || step == 8) break;
    double slope = 3.;   // cells ~ h^-slope
    if(previous_cells > 0.)
      slope = std::clamp(std::log(cells / previous_cells) / std::log(previous_h / h), 0.5, 4.);
    const double next = std::min(diagonal / 10., h * std::clamp(std::pow(cells / target, 1. / slope), 0.4, 2.5));
    if(next == h) break;
    previous_h = h;
    previous_cells = cells;
    h = next;
  }
  return c3t3;
}

Input surface_mesh_input(const std::string& off_path, std::shared_ptr<Surface_domain> domain, double diagonal, double h,
                         Surface_c3t3 c3t3)
{
  const std::string file = file_name(off_path);
  const std::string stem = file.substr(0, file.rfind('.'));
  char origin[256];
  std::snprintf(origin, sizeof origin,
                "Mesh_3 of `%s` (Polyhedral_mesh_domain_with_features_3, detect_features), h = %.4g, i.e. "
                "%.4g of the bounding box diagonal",
                file.c_str(), h, h / diagonal);
  return Input{stem, origin, Surface_mesh{std::move(domain), std::move(c3t3), h}};
}

} // namespace

const std::vector<Data_surface>& data_surfaces()
{
  static const std::vector<Data_surface> surfaces = {
      {"fandisk.off", "the paper's FanDisk surface"},
      {"double-torus-example.off", "a double torus like the paper's 2Torus (not the same surface)"},
      {"elephant.off", "a smooth organic surface"},
      {"anchor.off", "a CAD part with many sharp edges"}};
  return surfaces;
}

Input surface_input(const std::string& off_path, bodt_inputs::Size size)
{
  return surface_input(off_path, size == bodt_inputs::Size::small ? 4000. : 40000.);
}

Input surface_input(const std::string& off_path, double target_cells)
{
  auto [domain, diagonal] = surface_domain(off_path);
  // Searching from a coarse mesh would make several meshes near the target, each
  // taking minutes at millions of cells. Beyond the benchmark's size, h is
  // calibrated on a mesh of that size, then scaled by the cube root of the ratio
  // of cells (at these sizes the volume's cells outnumber the surface's), and
  // the search goes on from there.
  const double calibration_cells = 40000.;
  double h = diagonal / 15.;
  Surface_c3t3 c3t3 = search_size(*domain, std::min(target_cells, calibration_cells), diagonal, h, 0., 0.);
  const double cells = double(c3t3.number_of_cells_in_complex());
  if(target_cells > calibration_cells && std::abs(cells / target_cells - 1.) >= 0.15)
  {
    const double calibration_h = h;
    h = std::min(diagonal / 10., h * std::cbrt(cells / target_cells));
    c3t3 = search_size(*domain, target_cells, diagonal, h, calibration_h, cells);
  }
  return surface_mesh_input(off_path, domain, diagonal, h, std::move(c3t3));
}

Input surface_input_with_size(const std::string& off_path, double h)
{
  auto [domain, diagonal] = surface_domain(off_path);
  Surface_c3t3 c3t3 = mesh_surface(*domain, h);
  return surface_mesh_input(off_path, domain, diagonal, h, std::move(c3t3));
}

Run cgal_odt(Mesh& mesh, std::size_t iterations)
{
  return on_mesh_3(mesh, [&](auto& c3t3, const auto& domain) {
    // No convergence test and no freezing: every vertex moves in every one of the
    // iterations, as in B-ODT.
    const auto code = CGAL::odt_optimize_mesh_3(c3t3, domain, params::max_iteration_number = int(iterations),
                                                params::convergence = 0., params::freeze_bound = 0.);
    return Run{iterations, outcome_name(code)};
  });
}

Run cgal_lloyd(Mesh& mesh, std::size_t iterations)
{
  return on_mesh_3(mesh, [&](auto& c3t3, const auto& domain) {
    const auto code = CGAL::lloyd_optimize_mesh_3(c3t3, domain, params::max_iteration_number = int(iterations),
                                                  params::convergence = 0., params::freeze_bound = 0.);
    return Run{iterations, outcome_name(code)};
  });
}

Run cgal_perturb_exude(Mesh& mesh, std::size_t)
{
  return on_mesh_3(mesh, [&](auto& c3t3, const auto& domain) {
    // make_mesh_3's defaults: no time limit, and each runs while it improves the
    // smallest dihedral angle (sliver_bound = 0).
    const auto perturbed = CGAL::perturb_mesh_3(c3t3, domain);
    const auto exuded = CGAL::exude_mesh_3(c3t3);
    return Run{0, "perturb: " + outcome_name(perturbed) + ", exude: " + outcome_name(exuded)};
  });
}

Run cgal_remeshing(Mesh& mesh, std::size_t iterations)
{
  return on_mesh_3(mesh, [&](auto& c3t3, const auto&) {
    const double target = mean_edge_length(c3t3);
    CGAL::tetrahedral_isotropic_remeshing(c3t3, target, params::number_of_iterations(iterations));
    char outcome[96];
    std::snprintf(outcome, sizeof outcome, "target edge length %.4g", target);
    // CGAL runs 3 flip-and-smooth iterations after the requested ones.
    return Run{iterations + 3, outcome};
  });
}

} // namespace bodt_compare
