// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
#include "cli/commands.h"
#include "cli/feature_angles.h"
#include "cli/outputs.h"
#include "cli/progress.h"
#include "report/html_report.h"
#include "report/json_report.h"
#include "report/mesh_pictures.h"

#include <CGAL/BODT_3/IO/mesh_io.h>
#include <CGAL/BODT_3/Return_code.h>
#include <CGAL/BODT_3/boundary_distance.h>
#include <CGAL/BODT_3/mesh_quality.h>
#include <CGAL/BODT_3/smooth.h>

#include <array>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <map>
#include <memory>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace bodt_cli {

namespace BODT = CGAL::BODT_3;

namespace {

struct Smooth_options
{
  std::string input, output, format, report, html, cut, method = "bodt";
  BODT::Smoothing_options smoothing;
  bool no_features = false, no_guard = false, no_flips = false, no_insertion = false, quiet = false, json = false;
  bool no_largest_angle_phase = false;
  bool no_boundary_distance = false;
  // Degrees; used only when given (the library's ratios stay otherwise, bit for bit).
  double feature_angle = 0, corner_angle = 0;
  bool feature_angle_given = false, corner_angle_given = false;
};

// The input's boundary, kept through the run for the distance after it: each
// point once and the triangles as index triples: a third of the memory of the
// triangles themselves, which were a part of the run's peak.
struct Kept_surface
{
  std::vector<BODT::Tet_mesh::Point> points;
  std::vector<std::array<int, 3>> triangles;

  explicit Kept_surface(const BODT::Boundary_triangles& t)
  {
    std::map<BODT::Tet_mesh::Point, int> index;
    triangles.reserve(t.size());
    for(const auto& tri : t)
    {
      std::array<int, 3> ids;
      for(int k = 0; k < 3; ++k)
      {
        const auto it = index.emplace(tri[k], static_cast<int>(points.size())).first;
        if(it->second == static_cast<int>(points.size())) points.push_back(tri[k]);
        ids[k] = it->second;
      }
      triangles.push_back(ids);
    }
  }

  BODT::Boundary_triangles triangles_again() const
  {
    BODT::Boundary_triangles out;
    out.reserve(triangles.size());
    for(const auto& t : triangles) out.emplace_back(points[t[0]], points[t[1]], points[t[2]]);
    return out;
  }
};

std::string printf_string(const char* fmt, double x)
{
  char buf[64];
  std::snprintf(buf, sizeof buf, fmt, x);
  return buf;
}

// A CLI11 check of --feature-angle and --corner-angle: the ratios they map to run
// over (0, 1], the angles over (0, 90] (feature_angles.h).
std::string check_feature_angle(const std::string& text)
{
  char* end = nullptr;
  const double x = std::strtod(text.c_str(), &end);
  if(text.empty() || *end != '\0' || !(x > 0 && x <= 90)) return "an angle in degrees above 0 and at most 90";
  return std::string();
}

std::string check_cut_plane(const std::string& text)
{
  try
  {
    bodt_report::parse_cut_plane(text);
    return std::string();
  }
  catch(const std::invalid_argument& e)
  {
    return e.what();
  }
}

// How the run found features, for the page.
std::string features_text(const Smooth_options& o, const BODT::Smoothing_result& result)
{
  const BODT::Tensor_voting_options& tv = o.smoothing.tensor_voting;
  if(!o.smoothing.preserve_features) return "not preserved (--no-features)";
  if(!result.used_tensor_voting)
    return o.smoothing.moving_vertices == BODT::Moving_vertices::ALL ? "the mesh's own (edges, corners, patches)"
                                                                      : "boundary vertices do not move";
  return "by tensor voting: feature angle " + printf_string("%.2f", angle_of_edge_ratio(tv.edge_ratio)) +
         " deg, corner angle " + printf_string("%.2f", angle_of_corner_ratio(tv.corner_ratio)) + " deg";
}

const char* const smooth_description =
    "Improves the dihedral angles of a tetrahedral mesh. Each sweep moves the vertices\n"
    "(interior vertices by ODT, boundary and interface vertices on their tangent plane,\n"
    "feature vertices along their feature; corners stay), then flips, and inserts\n"
    "vertices at spades, caps and slivers. The volume of every subdomain and the labels\n"
    "are kept, no tetrahedron is inverted, and by default no move may lower the smallest\n"
    "or raise the largest dihedral angle around its vertex. Prints the quality before\n"
    "and after. Every output path is checked before the work starts; outputs are written\n"
    "to a temporary file and renamed, and the reports appear only with the mesh.";

void print_table(const BODT::Quality_report& before, const BODT::Quality_report& after,
                 const BODT::Smoothing_result& result, std::size_t vertices,
                 double boundary_distance, double bound)
{
  std::printf("%-28s %12s %12s\n", "", "before", "after");
  std::printf("%-28s %12.2f %12.2f\n", "min dihedral (deg)", before.min_dihedral_deg, after.min_dihedral_deg);
  std::printf("%-28s %12.2f %12.2f\n", "max dihedral (deg)", before.max_dihedral_deg, after.max_dihedral_deg);
  if(before.min_boundary_triangle_angle_deg >= 0 && after.min_boundary_triangle_angle_deg >= 0)
    std::printf("%-28s %12.2f %12.2f\n", "min boundary triangle (deg)", before.min_boundary_triangle_angle_deg,
                after.min_boundary_triangle_angle_deg);
  std::printf("%-28s %12zu %12zu\n", "tets below 10 deg", before.tets_below_small, after.tets_below_small);
  std::printf("%-28s %12zu %12zu\n", "tets above 170 deg", before.tets_above_large, after.tets_above_large);
  std::printf("%-28s %12zu %12zu\n", "bad tets: interior", before.bad_tets_interior, after.bad_tets_interior);
  std::printf("%-28s %12zu %12zu\n", "  touching the boundary", before.bad_tets_touching_boundary,
              after.bad_tets_touching_boundary);
  std::printf("%-28s %12zu %12zu\n", "  all vertices on boundary", before.bad_tets_all_vertices_on_boundary,
              after.bad_tets_all_vertices_on_boundary);
  std::printf("%-28s %12.4f %12.4f\n", "mean radius ratio", before.mean_radius_ratio, after.mean_radius_ratio);
  std::printf("%-28s %12zu %12zu\n", "tetrahedra", before.num_tets, after.num_tets);
  std::printf("%-28s %12zu %12zu\n", "inverted or flat tets", before.inverted_tets, after.inverted_tets);
  std::printf("%zu sweeps (%s), %zu of %zu vertices moved, %zu flips, %zu vertices inserted, %zu removed, %.2f s; "
              "volume change %.2e\n",
              result.iterations, BODT::to_string(result.code), result.moved_vertices, vertices,
              result.topology.total(), result.insertion.vertices_added, result.contraction.contractions, result.seconds,
              (after.volume - before.volume) / before.volume);
  if(boundary_distance >= 0)   // negative: not measured
    std::printf("boundary and interfaces moved by %.2e of the bounding box (symmetric Hausdorff distance; %s)\n",
                boundary_distance, bound > 0 ? printf_string("bound %.1e", bound).c_str() : "no bound");
}

int run_smooth(Smooth_options o)
{
  BODT::Smoothing_options& opt = o.smoothing;
  if(o.method == "odt") opt.moving_vertices = BODT::Moving_vertices::INTERIOR;
  else if(o.method == "flips") opt.moving_vertices = BODT::Moving_vertices::NONE;
  else if(o.method == "nodt") opt.smoothing_method = BODT::Smoothing_method::NODT;
  opt.preserve_features = !o.no_features;
  opt.quality_guard = !o.no_guard;
  opt.topology_optimization = !o.no_flips;
  opt.vertex_insertion = !o.no_insertion;
  opt.largest_angle_phase = !o.no_largest_angle_phase;
  if(o.method == "flips" && o.no_flips)
    throw Usage_error("--method flips with --no-flips would change nothing");
  if((o.feature_angle_given || o.corner_angle_given) && o.no_features)
    throw Usage_error("--feature-angle and --corner-angle say how features are found; --no-features keeps none");
  if(o.feature_angle_given) opt.tensor_voting.edge_ratio = edge_ratio_of_angle(o.feature_angle);
  if(o.corner_angle_given) opt.tensor_voting.corner_ratio = corner_ratio_of_angle(o.corner_angle);
  std::optional<bodt_report::Cut_plane> cut;
  if(!o.cut.empty()) cut = bodt_report::parse_cut_plane(o.cut);

  // Everything that can be refused is refused before the work starts.
  check_input_path(o.input);
  check_output_paths(o.input, {{"-o", o.output}, {"--report", o.report}, {"--html", o.html}});
  const Output_format format = choose_output_format(o.output, o.format);

  // Wall seconds of the phases around the smoothing, for the report.
  auto clock = std::chrono::steady_clock::now();
  auto lap = [&clock]() {
    const auto now = std::chrono::steady_clock::now();
    const double s = std::chrono::duration<double>(now - clock).count();
    clock = now;
    return s;
  };
  std::ostringstream silenced;
  BODT::IO::Mesh_file_format input_format;
  BODT::Tet_mesh mesh = BODT::IO::read_mesh(o.input, input_format, o.quiet ? silenced : std::cerr, opt.threads);
  const double read_seconds = lap();
  const BODT::IO::Mesh_file_format output_format = format.resolve(o.output, input_format);
  BODT::Quality_options measures;
  measures.threads = opt.threads;
  const BODT::Quality_report before = BODT::mesh_quality(mesh, measures);
  double quality_seconds = lap();
  if(before.inverted_tets > 0)
    throw std::runtime_error(o.input + ": " + std::to_string(before.inverted_tets) +
                             " tetrahedra of the mesh are flat; smoothing needs a valid mesh");
  if(cut && !bodt_report::plane_meets_mesh(*cut, mesh))
    throw Usage_error("--cut " + o.cut + ": the plane misses the mesh");
  // The page draws the input beside the result.
  std::optional<BODT::Tet_mesh> input;
  if(!o.html.empty()) input = mesh;
  // The input's surface is kept only for measuring how far the run moved it.
  const Kept_surface surface_before(o.no_boundary_distance ? BODT::Boundary_triangles()
                                                          : BODT::boundary_triangles(mesh, opt.threads));
  double distance_seconds = lap();
  Progress progress(o.quiet, opt);
  const BODT::Smoothing_result result = BODT::smooth(mesh, opt, progress);
  progress.finish();
  const double smoothing_seconds = lap();
  const BODT::Quality_report after = BODT::mesh_quality(mesh, measures);
  quality_seconds += lap();
  // Negative: not measured. Sampled at the corners and side midpoints of every
  // triangle, a third of the time of doc/results.md's finer grid (6 per side),
  // which read up to 4% higher on the shared meshes and the same on most.
  const double boundary_distance =
      o.no_boundary_distance ? -1.0
                             : BODT::relative_hausdorff_distance(surface_before.triangles_again(),
                                                                 BODT::boundary_triangles(mesh, opt.threads),
                                                                 opt.threads, 2);
  distance_seconds += lap();
  if((o.feature_angle_given || o.corner_angle_given) && !result.used_tensor_voting && !o.quiet)
    std::cerr << "bodt smooth: --feature-angle and --corner-angle were not used: "
              << (opt.moving_vertices == BODT::Moving_vertices::ALL
                      ? "the mesh carries the dimension of every vertex"
                      : "boundary vertices do not move with --method " + o.method)
              << "\n";

  // The reports are made in memory and staged, so that a failure writing the mesh leaves no report.
  Staged_files side_files;
  nlohmann::json report;
  if(!o.report.empty() || o.json)
  {
    report = BODT::smoothing_report(opt, result, progress.iterations(), before, after);
    report["bodt_version"] = BODT_VERSION;
    report["input"] = o.input;
    report["output"] = o.output;
    report["output_format"] = BODT::IO::format_name(output_format);
    if(boundary_distance >= 0) report["boundary_distance"] = boundary_distance;
    // The mesh is written after the report is made: its time is not here.
    report["process_seconds"] = {{"read", read_seconds},
                                 {"quality_before_and_after", quality_seconds},
                                 {"boundary_distance", distance_seconds},
                                 {"smoothing", smoothing_seconds}};
    if(!o.report.empty()) side_files.stage(o.report, report.dump(1) + "\n");
  }
  if(!o.html.empty())
  {
    std::string method = o.method;
    if(!opt.preserve_features) method += ", no feature preservation";
    if(!opt.quality_guard) method += ", no quality guard";
    if(!opt.topology_optimization) method += ", no flips";
    if(!opt.vertex_insertion) method += ", no insertion";
    const std::vector<BODT::Report_entry> run = {
        {"method", method},
        {"iterations", std::to_string(result.iterations) + " (" + BODT::to_string(result.code) + ")"},
        {"time", printf_string("%.2f s", result.seconds)},
        {"moved vertices", std::to_string(result.moved_vertices) + " of " + std::to_string(mesh.points.size())},
        {"flips", std::to_string(result.topology.total())},
        {"inserted vertices", std::to_string(result.insertion.vertices_added)},
        {"relative volume change", printf_string("%.2e", (after.volume - before.volume) / before.volume)},
        {"boundary distance", boundary_distance >= 0
                                  ? printf_string("%.2e of the bounding box (symmetric Hausdorff)", boundary_distance)
                                  : "not measured (--no-boundary-distance)"},
        {"features", features_text(o, result)},
        {"output", o.output}};
    bodt_report::Picture_options pictures;
    pictures.feature_angle = angle_of_edge_ratio(opt.tensor_voting.edge_ratio);
    pictures.cut = cut;
    pictures.threads = opt.threads;
    side_files.stage(o.html, BODT::html_report(o.input, before, after, run,
                                               bodt_report::mesh_pictures_html(*input, mesh, pictures)));
  }
  write_output(o.output, mesh, output_format, opt.threads);
  side_files.commit();
  // Standard output holds the JSON alone, for scripts; messages stay on stderr.
  if(o.json)
    std::cout << report.dump() << "\n";
  else if(!o.quiet)
    print_table(before, after, result, mesh.points.size(), boundary_distance,
                opt.smoothing_method == BODT::Smoothing_method::BODT &&
                        opt.moving_vertices == BODT::Moving_vertices::ALL
                    ? opt.max_boundary_distance
                    : 0.0);
  return 0;
}

} // namespace

Command add_smooth(CLI::App& command)
{
  auto o = std::make_shared<Smooth_options>();
  command.footer(smooth_description);
  command.add_option("input", o->input, "input mesh (.mesh, .meshb, .msh, .vtu, .vtk, .node)")->required();
  command.add_option("-o,--output", o->output,
                     "output mesh; its format follows the name, in the input's variant when it is the same format")
      ->required();
  command.add_option("--format", o->format,
                     std::string("output format whatever the name: ") + BODT::IO::format_names())
      ->check(CLI::Validator(check_format_name, "FORMAT"));
  command.add_option("--iterations", o->smoothing.max_iteration_number,
                     "number of sweeps (default 20, as in the paper); 0: until a sweep changes nothing or "
                     "--convergence is reached, at most 1000")
      ->check(CLI::Range(0, 1000000));
  command.add_option("--time-limit", o->smoothing.time_limit, "stop after the sweep that passes S seconds")
      ->check(CLI::NonNegativeNumber);
  command.add_option("--convergence", o->smoothing.convergence,
                     "stop when no vertex moved by more than this fraction of its local size (default 0: off)")
      ->check(CLI::NonNegativeNumber);
  command.add_option("--freeze-bound", o->smoothing.freeze_bound,
                     "a vertex whose move is shorter than this fraction of its local size stays put until a "
                     "neighbour moves (default 0.0003; 0: every vertex moves every time)")
      ->check(CLI::NonNegativeNumber);
  command.add_option("--max-boundary-distance", o->smoothing.max_boundary_distance,
                     "refuse any step that takes the boundary or an interface farther than D from the input's, "
                     "or the input's farther than D from them, D relative to the largest side of its bounding "
                     "box (default 0: no bound)")
      ->check(CLI::NonNegativeNumber);
  command.add_option("--method", o->method,
                     "bodt: every vertex moves (default); odt: interior vertices only; flips: no vertex moves, "
                     "flips alone; nodt: surface vertices by Natural ODT, projected back on the input boundary "
                     "(the paper's baseline; the volume is not kept)")
      ->check(CLI::IsMember({"bodt", "odt", "flips", "nodt"}));
  command.add_flag("--no-features", o->no_features, "no feature preservation: every boundary vertex on its plane");
  command.add_flag("--no-guard", o->no_guard, "accept every valid move, even one that worsens the worst angles");
  command.add_flag("--no-flips", o->no_flips, "no topology optimization (flips)");
  command.add_flag("--no-insertion", o->no_insertion, "no vertex insertion");
  command.add_flag("--ear-splits,!--no-ear-splits", o->smoothing.ear_splits,
                   "in the main and the largest-angle phases, split boundary ears: a tetrahedron whose two boundary "
                   "faces meet at an angle above --largest-angle-threshold, which no move or flip lowers, gets a "
                   "vertex on its opposite edge where that improves the tetrahedra around (default: off; a lower "
                   "largest angle on curved surfaces, sometimes a lower smallest one: doc/manual.md)");
  command.add_flag("--worst-cell-phase,!--no-worst-cell-phase", o->smoothing.worst_cell_phase,
                   "a final phase raising the worst cells: max-min steps and flips at the tetrahedra within 2 "
                   "degrees of the worst, until the extreme angles stop improving (default: on)");
  command.add_flag("--cavity-insertion,!--no-cavity-insertion", o->smoothing.cavity_insertion,
                   "in the worst-cell phase, insert interior vertices at the worst tetrahedra, each in a cavity "
                   "grown and a place searched for the best worst tetrahedron (default: on)");
  command.add_flag("--contraction,!--no-contraction", o->smoothing.edge_contraction,
                   "edge contraction: remove vertices inside a subdomain or on a flat part of the surface where "
                   "that raises the worst tetrahedron around them (default: off)");
  command.add_option("--max-removals", o->smoothing.max_vertex_removals,
                     "remove at most N vertices by edge contraction (default -1: 5% of the input's vertices)")
      ->check(CLI::Range(-1LL, 1000000000LL));
  command.add_option("--max-insertions", o->smoothing.max_vertex_insertions,
                     "insert at most N vertices (default -1: 5% of the input's vertices)")
      ->check(CLI::Range(-1LL, 1000000000LL));
  command.add_option("--max-min-threshold", o->smoothing.max_min_threshold,
                     "max-min steps at the vertices whose worst tetrahedron has a dihedral sine below S "
                     "(default 0.34, about 20 degrees; 0: off)")
      ->check(CLI::Range(0., 1.));
  command.add_flag("--no-boundary-distance", o->no_boundary_distance,
                   "do not measure how far the boundary and interfaces moved (the symmetric Hausdorff distance "
                   "printed and reported; about 7% of a one-thread run on a large mesh)");
  command.add_flag("--no-largest-angle-phase", o->no_largest_angle_phase,
                   "no final phase lowering the largest angles (decided by the largest dihedral angle, then by "
                   "the minimum sine again)");
  command.add_option("--largest-angle-threshold", o->smoothing.largest_angle_threshold,
                     "that phase flips and takes max-min steps at tetrahedra with a dihedral angle above D degrees "
                     "(default 120)")
      ->check(CLI::Range(0., 180.));
  command.add_option("--threads", o->smoothing.threads,
                     "threads of the reading, quality reports, smoothing and writing (default 0: every core); the output does not depend on it")
      ->check(CLI::Range(0, 4096));
  CLI::Option* feature_angle =
      command
          .add_option("--feature-angle", o->feature_angle,
                      "in a mesh with no feature information (edges, corners, surface patches), tensor voting takes "
                      "as features the edges where the surface turns by more than DEG degrees, in (0, 90] "
                      "(default " + printf_string("%.2f", angle_of_edge_ratio(BODT::Tensor_voting_options().edge_ratio)) +
                      ", the library's feature_edge_ratio 0.05); larger: fewer features, more vertices free to move")
          ->check(CLI::Validator(check_feature_angle, "DEG"));
  CLI::Option* corner_angle =
      command
          .add_option("--corner-angle", o->corner_angle,
                      "... and as corners the vertices where three sides meet with normals more than DEG degrees "
                      "apart, in (0, 90] (default " +
                      printf_string("%.2f", angle_of_corner_ratio(BODT::Tensor_voting_options().corner_ratio)) +
                      ", the library's feature_corner_ratio 0.05; a cube corner: 90)")
          ->check(CLI::Validator(check_feature_angle, "DEG"));
  command.add_option("--report", o->report, "write a JSON report: options, every sweep, quality before and after");
  CLI::Option* html =
      command.add_option("--html", o->html,
                         "write a self-contained HTML page: quality table, subdomain volumes, the dihedral-angle "
                         "histograms before and after on one axis, and pictures of the surface and of a cut before "
                         "and after, cells coloured by their smallest dihedral angle, the worst ones ringed");
  command
      .add_option("--cut", o->cut,
                  "the plane of the page's cut: x=V, y=V, z=V or PX,PY,PZ,NX,NY,NZ (a point and a normal; default: "
                  "through the input's worst tetrahedron, facing the surface pictures' viewer)")
      ->check(CLI::Validator(check_cut_plane, "PLANE"))
      ->needs(html);
  command.add_flag("--json", o->json,
                   "print the report (what --report writes) on standard output as one line of JSON, instead of the "
                   "table");
  command.add_flag("-q,--quiet", o->quiet, "print nothing but errors");
  return [o, feature_angle, corner_angle]() {
    o->feature_angle_given = feature_angle->count() > 0;
    o->corner_angle_given = corner_angle->count() > 0;
    return run_smooth(*o);
  };
}

} // namespace bodt_cli
