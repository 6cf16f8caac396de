// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The inputs, the table of methods, our methods, and the measurements.
#include "compare/compare.h"

#include <CGAL/BODT_3/IO/mesh_io.h>
#include <CGAL/BODT_3/boundary_distance.h>
#include <CGAL/Random.h>
#include <CGAL/Real_timer.h>
#include <CGAL/Timer.h>
#include <CGAL/bodt_optimize_mesh_3.h>

#include <cmath>
#include <exception>
#include <limits>
#include <type_traits>

namespace bodt_compare {

const char* const original_name = "original";
const char* const odt_interior_name = "ODT (paper's baseline)";
const char* const bodt_no_flips_name = "B-ODT, no flips";
const char* const flips_name = "flips alone";
const char* const nodt_name = "NODT";
const char* const bodt_flips_name = "B-ODT + flips, no insertion";
const char* const bodt_basic_name = "B-ODT basic pipeline";
const char* const bodt_name = "B-ODT pipeline";
const char* const after_perturb_exude_name = "perturb+exude, then B-ODT pipeline";
const char* const cgal_odt_name = "CGAL ODT";
const char* const cgal_odt_perturb_exude_name = "CGAL ODT + perturb+exude";

namespace {

struct Iteration_counter
{
  std::size_t* iterations;
  void after_classification(const BODT::Smoothing_result&) const {}
  void after_iteration(const BODT::Iteration_stats& s) const { *iterations = s.iteration; }
};

// What our pipeline runs: smoothing (which vertices, which method), flips,
// vertex insertion, the max-min fallback, features. The defaults are the defaults
// of `bodt_optimize_mesh_3`.
struct Ours
{
  BODT::Moving_vertices moving = BODT::Moving_vertices::ALL;
  bool flips = true;
  bool insertion = true;
  bool max_min = true;
  bool largest_angle_phase = true;
  bool preserve_features = true;
  BODT::Smoothing_method method = BODT::Smoothing_method::BODT;
};

// One stage alone: no flips, no insertion, no max-min fallback.
Ours smoothing_only(BODT::Moving_vertices moving, BODT::Smoothing_method method = BODT::Smoothing_method::BODT)
{
  Ours o;
  o.moving = moving;
  o.flips = o.insertion = o.max_min = o.largest_angle_phase = false;
  o.method = method;
  return o;
}

// What our functions take: the C3T3 of a Mesh_3 output, the mesh itself otherwise.
template <class M>
auto& target(M& m)
{
  using T = std::remove_const_t<M>;
  if constexpr(std::is_same_v<T, bodt_inputs::Generated_mesh> || std::is_same_v<T, Surface_mesh>)
    return m.c3t3;
  else
    return m;
}

// Our pipeline on any kind of input, through the entry point a user of that
// kind of mesh calls.
Run smooth_ours(Mesh& mesh, std::size_t iterations, const Ours& how)
{
  std::size_t done = 0;
  BODT::Topology_stats flips;
  const auto code = std::visit(
      [&](auto& m) {
        if constexpr(std::is_same_v<std::decay_t<decltype(m)>, BODT::Tet_mesh>)
        {
          BODT::Smoothing_options options;
          options.max_iteration_number = iterations;
          options.moving_vertices = how.moving;
          options.preserve_features = how.preserve_features;
          options.topology_optimization = how.flips;
          options.vertex_insertion = how.insertion;
          options.smoothing_method = how.method;
          if(!how.max_min) options.max_min_threshold = 0;
          options.largest_angle_phase = how.largest_angle_phase;
          options.threads = 1;   // CPU seconds against CGAL's sequential optimizers
          const auto r = BODT::smooth(m, options, Iteration_counter{&done});
          flips = r.topology;
          return r.code;
        }
        else
        {
          struct Counting
          {
            std::size_t* iterations;
            BODT::Topology_stats* flips;
            void after_classification(const BODT::Smoothing_result&) const {}
            void after_iteration(const BODT::Iteration_stats& s) const
            {
              *iterations = s.iteration;
              *flips += s.topology;
            }
          };
          return CGAL::bodt_optimize_mesh_3(target(m), CGAL::parameters::max_iteration_number = iterations,
                                            CGAL::parameters::moving_vertices = how.moving,
                                            CGAL::parameters::preserve_features = how.preserve_features,
                                            CGAL::parameters::topology_optimization = how.flips,
                                            CGAL::parameters::vertex_insertion = how.insertion,
                                            CGAL::parameters::smoothing_method = how.method,
                                            CGAL::parameters::max_min_threshold = how.max_min ? BODT::Smoothing_options().max_min_threshold : 0.,
                                            CGAL::parameters::largest_angle_phase = how.largest_angle_phase,
                                            CGAL::parameters::number_of_threads = 1,
                                            CGAL::parameters::progress_visitor = Counting{&done, &flips});
        }
      },
      mesh);
  Run run{done, outcome_name(code)};
  run.flips = flips;
  return run;
}

BODT::Quality_report quality(const Mesh& mesh)
{
  return std::visit([](const auto& m) { return BODT::mesh_quality(target(m)); }, mesh);
}

BODT::Boundary_triangles boundary(const Mesh& mesh)
{
  return std::visit([](const auto& m) { return BODT::boundary_triangles(target(m)); }, mesh);
}

std::string describe(bodt_inputs::Shape shape)
{
  switch(shape)
  {
  case bodt_inputs::Shape::sphere: return "unit ball";
  case bodt_inputs::Shape::torus: return "ring torus, R = 1, r = 0.4";
  case bodt_inputs::Shape::genus2: return "smooth solid with two handles";
  case bodt_inputs::Shape::sharp_part: return "L-shaped block with a chamfer, sharp edges protected";
  case bodt_inputs::Shape::two_subdomains: return "unit ball cut by z = 0 into two subdomains, junction protected";
  }
  return "";
}

} // namespace

std::string outcome_name(CGAL::Mesh_optimization_return_code code)
{
  switch(code)
  {
  case CGAL::BOUND_REACHED: return "bound_reached";
  case CGAL::TIME_LIMIT_REACHED: return "time_limit_reached";
  case CGAL::CANT_IMPROVE_ANYMORE: return "cant_improve_anymore";
  case CGAL::CONVERGENCE_REACHED: return "convergence_reached";
  case CGAL::MAX_ITERATION_NUMBER_REACHED: return "max_iteration_number_reached";
  case CGAL::ALL_VERTICES_FROZEN: return "all_vertices_frozen";
  default: return "unknown_error";
  }
}

const std::vector<Method>& methods()
{
  using BODT::Moving_vertices;
  static const std::vector<Method> table = {
      {original_name, Family::reference, Applies_to::every_mesh, "the input, unchanged",
       [](Mesh&, std::size_t) { return Run{0, "unchanged"}; }},
      {odt_interior_name, Family::ours, Applies_to::every_mesh,
       "`bodt_optimize_mesh_3`, `moving_vertices = INTERIOR`, no flips, no insertion, no max-min, no largest-angle phase: the original "
       "ODT (Algorithm 1), boundary fixed, connectivity kept",
       [](Mesh& m, std::size_t n) { return smooth_ours(m, n, smoothing_only(Moving_vertices::INTERIOR)); }},
      {flips_name, Family::ours, Applies_to::every_mesh,
       "`bodt_optimize_mesh_3`, `moving_vertices = NONE`, no insertion, no max-min, no largest-angle phase: topology optimization alone "
       "(edge removal, multi-face removal, coplanar boundary flips), no vertex moves",
       [](Mesh& m, std::size_t n) {
         Ours o = smoothing_only(Moving_vertices::NONE);
         o.flips = true;
         return smooth_ours(m, n, o);
       }},
      {nodt_name, Family::ours, Applies_to::every_mesh,
       "`bodt_optimize_mesh_3`, `smoothing_method = NODT`, no flips, no insertion, no max-min, no largest-angle phase: Natural ODT as "
       "the paper compares it (boundary vertices at the centroid plus the normal compensation, projected back onto "
       "the input boundary), connectivity kept",
       [](Mesh& m, std::size_t n) {
         return smooth_ours(m, n, smoothing_only(Moving_vertices::ALL, BODT::Smoothing_method::NODT));
       }},
      {bodt_no_flips_name, Family::ours, Applies_to::every_mesh,
       "`bodt_optimize_mesh_3`, no flips, no insertion, no max-min, no largest-angle phase: B-ODT smoothing alone (Algorithm 2 on "
       "surfaces, Algorithm 3 on feature curves, corners fixed), connectivity kept",
       [](Mesh& m, std::size_t n) { return smooth_ours(m, n, smoothing_only(Moving_vertices::ALL)); }},
      {bodt_flips_name, Family::ours, Applies_to::every_mesh,
       "`bodt_optimize_mesh_3`, `vertex_insertion = false`: B-ODT sweeps, flips, the max-min fallback and the "
       "largest-angle phase, no vertex added",
       [](Mesh& m, std::size_t n) {
         Ours o;
         o.insertion = false;
         return smooth_ours(m, n, o);
       }},
      {bodt_basic_name, Family::ours, Applies_to::every_mesh,
       "`bodt_optimize_mesh_3`, `preserve_features = false`: the default pipeline with Algorithm 2 on every "
       "boundary vertex (feature vertices move like surface vertices)",
       [](Mesh& m, std::size_t n) {
         Ours o;
         o.preserve_features = false;
         return smooth_ours(m, n, o);
       }},
      {bodt_name, Family::ours, Applies_to::every_mesh,
       "`bodt_optimize_mesh_3` with its defaults: each iteration a B-ODT sweep, a flip pass, the max-min "
       "fallback at the stars still below its threshold, and vertex insertion at spades, caps, slivers and "
       "wedges (at most 5% vertices added); then the largest-angle phase (the same steps decided by the largest "
       "dihedral angle, within the extreme angles reached; max-min steps and flips at angles above 120 degrees), "
       "a last phase decided by the minimum sine, and the worst-cell phase (max-min steps and flips at the cells "
       "within 2 degrees of the worst, where that is above 28 degrees)",
       [](Mesh& m, std::size_t n) { return smooth_ours(m, n, Ours{}); }},
      {after_perturb_exude_name, Family::ours, Applies_to::mesh_3_output,
       "CGAL's `perturb_mesh_3` + `exude_mesh_3` as `make_mesh_3` runs them by default, then "
       "`bodt_optimize_mesh_3` with its defaults: what a user gets from `make_mesh_3`'s default output",
       [](Mesh& m, std::size_t n) {
         cgal_perturb_exude(m, n);
         return smooth_ours(m, n, Ours{});
       }},
      {cgal_odt_name, Family::cgal, Applies_to::mesh_3_output,
       "`odt_optimize_mesh_3`, `convergence = 0`, `freeze_bound = 0` (every vertex moves in every iteration)",
       cgal_odt},
      {"CGAL Lloyd", Family::cgal, Applies_to::mesh_3_output,
       "`lloyd_optimize_mesh_3`, `convergence = 0`, `freeze_bound = 0`", cgal_lloyd},
      {"CGAL perturb+exude", Family::cgal, Applies_to::mesh_3_output,
       "`perturb_mesh_3` then `exude_mesh_3` with `make_mesh_3`'s defaults (no time limit, `sliver_bound = 0`: "
       "run while the smallest angle improves); not iterative",
       cgal_perturb_exude},
      {cgal_odt_perturb_exude_name, Family::cgal, Applies_to::mesh_3_output,
       "`odt_optimize_mesh_3` as above, then `perturb_mesh_3` and `exude_mesh_3`: what `make_mesh_3` with "
       "`odt()` gives",
       [](Mesh& m, std::size_t n) {
         const Run odt = cgal_odt(m, n);
         const Run pe = cgal_perturb_exude(m, n);
         return Run{odt.iterations, odt.outcome + "; " + pe.outcome};
       }},
      {"CGAL remeshing", Family::cgal, Applies_to::mesh_3_output,
       "`tetrahedral_isotropic_remeshing` on the C3T3 (features and subdomains kept), target edge length = the "
       "mean edge length of the input mesh; CGAL adds 3 flip-and-smooth iterations to those asked",
       cgal_remeshing},
  };
  return table;
}

double Measurement::seconds_per_iteration() const
{
  return run.iterations ? cpu_seconds / double(run.iterations) : std::numeric_limits<double>::quiet_NaN();
}

double Measurement::throughput() const
{
  return run.iterations && cpu_seconds > 0 ? double(input_tets) * double(run.iterations) / cpu_seconds
                                           : std::numeric_limits<double>::quiet_NaN();
}

const Measurement* Input_result::row(const std::string& method) const
{
  for(const Measurement& m : rows)
    if(m.method == method) return m.applied ? &m : nullptr;
  return nullptr;
}

std::vector<Input> generated_inputs(bodt_inputs::Size size)
{
  std::vector<Input> inputs;
  for(bodt_inputs::Shape shape : bodt_inputs::all_shapes())
  {
    // Mesh_3 draws from CGAL's default random generator: same state, same mesh.
    CGAL::get_default_random() = CGAL::Random(0);
    bodt_inputs::Generated_mesh g = bodt_inputs::make_input(shape, size);
    std::string name = g.name;
    inputs.push_back(Input{name, "Mesh_3 of an implicit function: " + describe(shape), std::move(g)});
  }
  // The paper's size only: the small run stays a quick test input set.
  if(size == bodt_inputs::Size::benchmark)
    inputs.push_back(Input{"random_sphere",
                           "the paper's Random Sphere rebuilt: 642 seeded random points on the unit sphere and 87 "
                           "in the ball of radius 0.8, Delaunay_triangulation_3, then a seeded "
                           "sliver removal of ours (random moves of the worst cell's vertices, surface points kept on "
                           "the sphere) until no dihedral angle is below the paper's input's 5.86 degrees",
                           bodt_inputs::make_paper_random_sphere()});
  bodt_inputs::Delaunay sphere = bodt_inputs::make_random_sphere(size);
  const std::string origin = "Delaunay_triangulation_3 of " + std::to_string(sphere.number_of_vertices()) +
                             " random points on the unit sphere, no inner vertex (a Triangulation_3 input)";
  inputs.push_back(Input{"sphere_points_delaunay", origin, std::move(sphere)});
  return inputs;
}

Input file_input(const std::string& path)
{
  const std::size_t slash = path.find_last_of('/');
  const std::string file = slash == std::string::npos ? path : path.substr(slash + 1);
  return Input{file.substr(0, file.rfind('.')), "the file `" + path + "`", BODT::IO::read_mesh(path)};
}

Input_result compare(const Input& input, const std::vector<Method>& table, const Options& options)
{
  Input_result result;
  result.name = input.name;
  result.origin = input.origin;
  result.before = quality(input.mesh);
  const BODT::Boundary_triangles boundary_before = boundary(input.mesh);
  for(const Method& method : table)
  {
    Measurement row;
    row.method = method.name;
    row.input_tets = result.before.num_tets;
    if(method.applies_to == Applies_to::mesh_3_output && !built_by_mesh_3(input.mesh))
    {
      result.rows.push_back(row);
      continue;
    }
    const std::size_t subdomains = result.before.volume_per_subdomain.size();
    if(method.applies_to == Applies_to::one_subdomain && subdomains > 1)
    {
      row.not_run = std::to_string(subdomains) + " subdomains: " + method.name + " knows no subdomain labels";
      result.rows.push_back(row);
      continue;
    }
    options.log(input.name + ": " + method.name);
    Mesh mesh = input.mesh;
    // A randomized method (the perturber) must not depend on what ran before it.
    CGAL::get_default_random() = CGAL::Random(0);
    CGAL::Timer cpu;
    CGAL::Real_timer wall;
    cpu.start();
    wall.start();
    try
    {
      row.run = method.run(mesh, options.iterations);
    }
    catch(const std::exception& e)
    {
      // An external program is not ours to fix: its failure is a result of the comparison.
      if(method.family != Family::external) throw;
      row.not_run = e.what();
      options.log(input.name + ": " + method.name + " failed: " + row.not_run);
      result.rows.push_back(row);
      continue;
    }
    cpu.stop();
    wall.stop();
    row.applied = true;
    row.cpu_seconds = cpu.time() + row.run.child_cpu_seconds;
    row.wall_seconds = wall.time();
    row.quality = quality(mesh);
    row.vertices_added = static_cast<long long>(row.quality.num_vertices) - static_cast<long long>(result.before.num_vertices);
    row.relative_volume_change = (row.quality.volume - result.before.volume) / result.before.volume;
    row.relative_hausdorff = BODT::relative_hausdorff_distance(boundary_before, boundary(mesh));
    result.rows.push_back(row);
  }
  return result;
}

} // namespace bodt_compare
