// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
#include "cli/commands.h"

#include <CGAL/BODT_3/IO/html_report.h>
#include <CGAL/BODT_3/IO/mesh_io.h>
#include <CGAL/BODT_3/IO/write_atomically.h>
#include <CGAL/BODT_3/mesh_quality.h>
#include <CGAL/BODT_3/smooth.h>

#include <cmath>
#include <cstdio>
#include <iostream>
#include <sstream>

namespace bodt_cli {

namespace BODT = CGAL::BODT_3;

namespace {

const char* const smooth_help =
    "usage: bodt smooth IN -o OUT [options]\n\n"
    "Improves the dihedral angles of a tetrahedral mesh by B-ODT smoothing: interior\n"
    "vertices move by ODT, boundary and interface vertices on their tangent plane,\n"
    "feature vertices along their feature; corners stay. The connectivity, the volume\n"
    "of every subdomain, and the labels are kept, no tetrahedron is inverted, and by\n"
    "default no move may lower the smallest or raise the largest dihedral angle around\n"
    "its vertex. Prints the quality before and after. OUT (.mesh, .msh, .vtu) is written\n"
    "to a temporary file and renamed.\n\n"
    "  -o, --output OUT     output mesh (required)\n"
    "  --iterations N       number of sweeps (default 20, as in the paper)\n"
    "  --method bodt|odt    bodt: all vertices (default); odt: interior vertices only\n"
    "  --no-features        no feature preservation: every boundary vertex uses Algorithm 2\n"
    "  --no-guard           accept every valid move, even one that worsens the worst angles\n"
    "  --time-limit S       stop after S seconds\n"
    "  --report R.json      write a JSON report: before/after quality, time, moves\n"
    "  --html R.html        write a self-contained HTML page: quality table and\n"
    "                       dihedral-angle histograms before and after, for a browser\n"
    "  --quiet              no progress or summary on stderr\n";

std::size_t parse_count(const std::string& s, const char* what)
{
  std::size_t pos = 0;
  long long v = -1;
  try { v = std::stoll(s, &pos); } catch(...) {}
  if(pos != s.size() || v < 0 || v > 1000000) throw Usage_error(std::string(what) + " must be an integer from 0 to 1000000");
  return static_cast<std::size_t>(v);
}

double parse_seconds(const std::string& s)
{
  std::size_t pos = 0;
  double v = -1;
  try { v = std::stod(s, &pos); } catch(...) {}
  if(pos != s.size() || !(v >= 0)) throw Usage_error("--time-limit must be a non-negative number of seconds");
  return v;
}

const char* code_name(CGAL::Mesh_optimization_return_code c)
{
  switch(c)
  {
  case CGAL::MAX_ITERATION_NUMBER_REACHED: return "max_iteration_number_reached";
  case CGAL::TIME_LIMIT_REACHED: return "time_limit_reached";
  case CGAL::CONVERGENCE_REACHED: return "convergence_reached";
  case CGAL::CANT_IMPROVE_ANYMORE: return "cant_improve_anymore";
  default: return "other";
  }
}

// Progress on stderr once a run has lasted a second: long runs show life, short ones stay quiet.
struct Progress_visitor
{
  bool quiet;
  void after_classification(const BODT::Smoothing_result& r) const
  {
    if(quiet) return;
    std::cerr << "bodt smooth: " << r.interior_vertices << " interior, " << r.surface_vertices << " surface, "
              << r.feature_vertices << " feature and " << r.fixed_vertices << " fixed vertices"
              << (r.used_tensor_voting ? " (features by tensor voting)" : "") << "\n";
  }
  void after_iteration(const BODT::Iteration_stats& s) const
  {
    if(quiet || s.seconds < 1.0) return;
    std::fprintf(stderr,
                 "bodt smooth: iteration %zu: %zu vertices moved, %zu refused (%zu would invert a cell, %zu would "
                 "worsen the worst angle), %.1f s\n",
                 s.iteration, s.moved, s.refused, s.refused_inverting_mesh_cell + s.refused_inverting_outside_cell,
                 s.refused_worsening_quality, s.seconds);
  }
};

} // namespace

int smooth(const std::vector<std::string>& argv)
{
  Arguments args(argv);
  if(args.flag("--help") || args.flag("-h"))
  {
    std::cout << smooth_help;
    return 0;
  }
  std::string output, value, report_path;
  if(!args.option("-o", output)) args.option("--output", output);
  BODT::Smoothing_options opt;
  if(args.option("--iterations", value)) opt.max_iteration_number = parse_count(value, "--iterations");
  if(args.option("--method", value))
  {
    if(value == "odt") opt.moving_vertices = BODT::Moving_vertices::INTERIOR;
    else if(value != "bodt") throw Usage_error("--method must be bodt or odt");
  }
  if(args.flag("--no-features")) opt.preserve_features = false;
  if(args.flag("--no-guard")) opt.quality_guard = false;
  if(args.option("--time-limit", value)) opt.time_limit = parse_seconds(value);
  args.option("--report", report_path);
  std::string html_path;
  args.option("--html", html_path);
  const bool quiet = args.flag("--quiet");
  const auto files = args.positionals();
  if(files.size() != 1) throw Usage_error("expected exactly one input mesh");
  if(output.empty()) throw Usage_error("the output file is missing (-o OUT)");
  namespace IO = BODT::IO;
  if(IO::format_of(output) == IO::Mesh_format::unknown)
    throw Usage_error("cannot tell the output format from '" + output + "'");

  BODT::Tet_mesh mesh = IO::read_mesh(files[0]);
  const BODT::Quality_report before = BODT::mesh_quality(mesh);
  if(before.inverted_tets > 0)
    throw std::runtime_error(files[0] + ": " + std::to_string(before.inverted_tets) +
                             " tetrahedra of the mesh are flat; smoothing needs a valid mesh");
  const BODT::Smoothing_result result = BODT::smooth(mesh, opt, Progress_visitor{quiet});
  const BODT::Quality_report after = BODT::mesh_quality(mesh);
  IO::write_mesh(output, mesh);

  double max_subdomain_change = 0;
  for(const auto& kv : before.volume_per_subdomain)
  {
    const auto it = after.volume_per_subdomain.find(kv.first);
    const double v1 = it == after.volume_per_subdomain.end() ? 0.0 : it->second;
    max_subdomain_change = std::max(max_subdomain_change, std::abs(v1 - kv.second) / std::abs(kv.second));
  }
  const double volume_change = (after.volume - before.volume) / before.volume;

  char line[256];
  std::printf("%-22s %12s %12s\n", "", "before", "after");
  std::printf("%-22s %12.2f %12.2f\n", "min dihedral (deg)", before.min_dihedral_deg, after.min_dihedral_deg);
  std::printf("%-22s %12.2f %12.2f\n", "max dihedral (deg)", before.max_dihedral_deg, after.max_dihedral_deg);
  std::printf("%-22s %12zu %12zu\n", "tets below 10 deg", before.tets_below_small, after.tets_below_small);
  std::printf("%-22s %12zu %12zu\n", "tets above 170 deg", before.tets_above_large, after.tets_above_large);
  std::printf("%-22s %12.4f %12.4f\n", "mean radius ratio", before.mean_radius_ratio, after.mean_radius_ratio);
  std::printf("%-22s %12zu %12zu\n", "inverted or flat tets", before.inverted_tets, after.inverted_tets);
  std::snprintf(line, sizeof line, "%zu sweeps (%s), %zu of %zu vertices moved, %.2f s; volume change %.2e\n",
                result.iterations, code_name(result.code), result.moved_vertices, mesh.points.size(), result.seconds,
                volume_change);
  std::cout << line;

  if(!report_path.empty())
  {
    std::ostringstream js;
    char num[64];
    auto f = [&](double x) { std::snprintf(num, sizeof num, "%.17g", x); return std::string(num); };
    js << "{\"input\": \"" << files[0] << "\", \"output\": \"" << output << "\", \"method\": \""
       << (opt.moving_vertices == BODT::Moving_vertices::ALL ? "bodt" : "odt") << "\", \"features\": "
       << (opt.preserve_features ? "true" : "false") << ", \"quality_guard\": " << (opt.quality_guard ? "true" : "false")
       << ",\n \"before\": " << BODT::to_json(before) << ",\n \"after\": " << BODT::to_json(after)
       << ",\n \"seconds\": " << f(result.seconds) << ", \"iterations\": " << result.iterations
       << ", \"return_code\": \"" << code_name(result.code) << "\", \"moved_vertices\": " << result.moved_vertices
       << ", \"volume_change\": " << f(after.volume - before.volume) << ", \"relative_volume_change\": "
       << f(volume_change) << ", \"max_relative_subdomain_volume_change\": " << f(max_subdomain_change)
       << ",\n \"vertices\": {\"interior\": " << result.interior_vertices << ", \"surface\": " << result.surface_vertices
       << ", \"feature\": " << result.feature_vertices << ", \"fixed\": " << result.fixed_vertices
       << ", \"non_manifold\": " << result.non_manifold_vertices << ", \"tensor_voting\": "
       << (result.used_tensor_voting ? "true" : "false") << "}}\n";
    BODT::write_atomically(report_path, [&](std::ostream& out) { out << js.str(); });
  }

  if(!html_path.empty())
  {
    std::string method = opt.moving_vertices == BODT::Moving_vertices::ALL ? "bodt" : "odt";
    if(!opt.preserve_features) method += ", no feature preservation";
    if(!opt.quality_guard) method += ", no quality guard";
    char seconds[32], change[32];
    std::snprintf(seconds, sizeof seconds, "%.2f s", result.seconds);
    std::snprintf(change, sizeof change, "%.2e", volume_change);
    const std::vector<BODT::Report_entry> run = {
        {"method", method},
        {"iterations", std::to_string(result.iterations) + " (" + code_name(result.code) + ")"},
        {"time", seconds},
        {"moved vertices", std::to_string(result.moved_vertices) + " of " + std::to_string(mesh.points.size())},
        {"relative volume change", change},
        {"output", output}};
    const std::string page = BODT::html_report(files[0], before, after, run);
    BODT::write_atomically(html_path, [&](std::ostream& out) { out << page; });
  }
  return 0;
}

} // namespace bodt_cli
