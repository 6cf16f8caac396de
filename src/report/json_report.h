// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef BODT_REPORT_JSON_REPORT_H
#define BODT_REPORT_JSON_REPORT_H

// JSON for the quality and smoothing records, built with nlohmann::json (Debian's
// nlohmann-json3-dev), which escapes every string and writes a value that is not
// finite (NaN, infinity) as null: the output is always valid JSON. It belongs to the
// tools (bodt, bodt-compare, the Python module), not to the header-only package; its
// functions stay in namespace CGAL::BODT_3, where nlohmann finds them by
// argument-dependent lookup on the package's types.

#include "cli/feature_angles.h"

#include <CGAL/BODT_3/Return_code.h>
#include <CGAL/BODT_3/Smoothing_options.h>
#include <CGAL/BODT_3/Smoothing_result.h>
#include <CGAL/BODT_3/mesh_quality.h>

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace CGAL {
namespace BODT_3 {

// nlohmann finds these by argument-dependent lookup: `nlohmann::json j = report;`.

inline void to_json(nlohmann::json& j, const Quality_report& r)
{
  char small[32], large[32];
  std::snprintf(small, sizeof small, "tets_below_%gdeg", r.options.small_angle);
  std::snprintf(large, sizeof large, "tets_above_%gdeg", r.options.large_angle);
  nlohmann::json volumes = nlohmann::json::object();
  for(const auto& kv : r.volume_per_subdomain) volumes[std::to_string(kv.first)] = kv.second;
  j = nlohmann::json{{"num_vertices", r.num_vertices},
                     {"num_tets", r.num_tets},
                     {"min_dihedral_deg", r.min_dihedral_deg},
                     {"max_dihedral_deg", r.max_dihedral_deg},
                     {"small_angle_deg", r.options.small_angle},
                     {"large_angle_deg", r.options.large_angle},
                     {small, r.tets_below_small},
                     {large, r.tets_above_large},
                     {"bad_tets",
                      {{"interior", r.bad_tets_interior},
                       {"touching_boundary", r.bad_tets_touching_boundary},
                       {"all_vertices_on_boundary", r.bad_tets_all_vertices_on_boundary}}},
                     {"min_boundary_triangle_angle_deg", r.min_boundary_triangle_angle_deg >= 0
                                                             ? nlohmann::json(r.min_boundary_triangle_angle_deg)
                                                             : nlohmann::json(nullptr)},
                     {"min_radius_ratio", r.min_radius_ratio},
                     {"mean_radius_ratio", r.mean_radius_ratio},
                     {"volume", r.volume},
                     {"volume_per_subdomain", volumes},
                     {"inverted_tets", r.inverted_tets},
                     {"histogram",
                      {{"bin_width_deg", r.histogram.empty() ? 180.0 : 180.0 / static_cast<double>(r.histogram.size())},
                       {"counts", r.histogram}}}};
}

inline void to_json(nlohmann::json& j, const Topology_stats& s)
{
  j = nlohmann::json{{"flips_2_3", s.flips_2_3},
                     {"flips_3_2", s.flips_3_2},
                     {"edge_removals", s.edge_removals},
                     {"multi_face_removals", s.multi_face_removals},
                     {"boundary_flips", s.boundary_flips},
                     {"total", s.total()},
                     {"seconds", s.seconds}};
}

inline void to_json(nlohmann::json& j, const Insertion_stats& s)
{
  j = nlohmann::json{{"spade_splits", s.spade_splits},
                     {"wedge_splits", s.wedge_splits},
                     {"cap_splits", s.cap_splits},
                     {"sliver_splits", s.sliver_splits},
                     {"ear_splits", s.ear_splits},
                     {"cavity_insertions", s.cavity_insertions},
                     {"undone", s.undone},
                     {"vertices_added", s.vertices_added},
                     {"seconds", s.seconds}};
}

inline void to_json(nlohmann::json& j, const Contraction_stats& s)
{
  j = nlohmann::json{{"contractions", s.contractions},
                     {"boundary_contractions", s.boundary_contractions},
                     {"seconds", s.seconds}};
}

inline void to_json(nlohmann::json& j, const Iteration_stats& s)
{
  j = nlohmann::json{{"iteration", s.iteration},
                     {"phase", s.phase},
                     {"moved", s.moved},
                     {"shortened", s.shortened},
                     {"refused", s.refused},
                     {"refused_because",
                      {{"inverting_mesh_cell", s.refused_inverting_mesh_cell},
                       {"inverting_outside_cell", s.refused_inverting_outside_cell},
                       {"breaking_hull", s.refused_breaking_hull},
                       {"changing_volume", s.refused_changing_volume},
                       {"worsening_quality", s.refused_worsening_quality},
                       {"leaving_surface", s.refused_leaving_surface}}},
                     {"max_min_moves", s.max_min_moves},
                     {"max_min_searches", s.max_min_searches},
                     {"max_relative_move", s.max_relative_move},
                     {"topology", s.topology},
                     {"contraction", s.contraction},
                     {"insertion", s.insertion},
                     {"sweep_seconds", s.sweep_seconds},
                     {"max_min_seconds", s.max_min_seconds},
                     {"reread_seconds", s.reread_seconds},
                     {"seconds", s.seconds}};
}

inline void to_json(nlohmann::json& j, const Phase_seconds& p)
{
  j = nlohmann::json{{"conversion", p.conversion}, {"setup", p.setup},     {"sweeps", p.sweeps},
                     {"flips", p.flips},           {"max_min", p.max_min}, {"contraction", p.contraction},
                     {"insertion", p.insertion}, {"reread", p.reread}};
}

inline void to_json(nlohmann::json& j, const Smoothing_result& r)
{
  j = nlohmann::json{{"return_code", to_string(r.code)},
                     {"iterations", r.iterations},
                     {"moved_vertices", r.moved_vertices},
                     {"vertices",
                      {{"interior", r.interior_vertices},
                       {"surface", r.surface_vertices},
                       {"feature", r.feature_vertices},
                       {"fixed", r.fixed_vertices},
                       {"non_manifold", r.non_manifold_vertices},
                       {"on_cracks", r.crack_vertices},
                       {"tensor_voting", r.used_tensor_voting}}},
                     {"embedded_triangles", r.embedded_triangles},
                     {"topology", r.topology},
                     {"contraction", r.contraction},
                     {"insertion", r.insertion},
                     {"phase_seconds", r.phases},
                     {"seconds", r.seconds}};
}

/// The method as the command line spells it (`--method`).
inline const char* method_name(const Smoothing_options& o)
{
  switch(o.moving_vertices)
  {
  case Moving_vertices::ALL: return o.smoothing_method == Smoothing_method::NODT ? "nodt" : "bodt";
  case Moving_vertices::INTERIOR: return "odt";
  case Moving_vertices::NONE: return "flips";
  }
  return "unknown";
}

inline void to_json(nlohmann::json& j, const Smoothing_options& o)
{
  j = nlohmann::json{{"method", method_name(o)},
                     {"max_iteration_number", o.max_iteration_number},
                     {"time_limit", o.time_limit},
                     {"convergence", o.convergence},
                     {"freeze_bound", o.freeze_bound},
                     {"max_boundary_distance", o.max_boundary_distance},
                     {"preserve_features", o.preserve_features},
                     {"quality_guard", o.quality_guard},
                     {"topology_optimization", o.topology_optimization},
                     {"vertex_insertion", o.vertex_insertion},
                     {"ear_splits", o.ear_splits},
                     {"cavity_insertion", o.cavity_insertion},
                     {"max_vertex_insertions", o.max_vertex_insertions},
                     {"edge_contraction", o.edge_contraction},
                     {"worst_cell_phase", o.worst_cell_phase},
                     {"max_vertex_removals", o.max_vertex_removals},
                     {"max_min_threshold", o.max_min_threshold},
                     {"largest_angle_phase", o.largest_angle_phase},
                     {"largest_angle_threshold", o.largest_angle_threshold},
                     {"threads", o.threads},
                     {"flip_quality_threshold", o.flips.quality_threshold},
                     {"insertion_quality_threshold", o.insertion.quality_threshold},
                     {"tensor_voting",
                      {{"edge_ratio", o.tensor_voting.edge_ratio},
                       {"corner_ratio", o.tensor_voting.corner_ratio},
                       {"feature_angle_deg", bodt_cli::angle_of_edge_ratio(o.tensor_voting.edge_ratio)},
                       {"corner_angle_deg", bodt_cli::angle_of_corner_ratio(o.tensor_voting.corner_ratio)},
                       {"angle_weighted", o.tensor_voting.angle_weighted}}}};
}

/// The quality report as one line of JSON (`bodt quality --json`).
inline std::string to_json(const Quality_report& r) { return nlohmann::json(r).dump(); }

/// Everything known about a smoothing run: the options, the result with its totals,
/// every iteration, the quality before and after, and the volume changes (whole
/// mesh, and the largest relative change of a subdomain).
inline nlohmann::json smoothing_report(const Smoothing_options& options, const Smoothing_result& result,
                                       const std::vector<Iteration_stats>& iterations, const Quality_report& before,
                                       const Quality_report& after)
{
  double max_subdomain_change = 0;
  for(const auto& kv : before.volume_per_subdomain)
  {
    const auto it = after.volume_per_subdomain.find(kv.first);
    const double v1 = it == after.volume_per_subdomain.end() ? 0.0 : it->second;
    max_subdomain_change = std::max(max_subdomain_change, std::abs(v1 - kv.second) / std::abs(kv.second));
  }
  nlohmann::json j;
  j["options"] = options;
  j["result"] = result;
  j["per_iteration"] = iterations;
  j["before"] = before;
  j["after"] = after;
  j["volume_change"] = after.volume - before.volume;
  j["relative_volume_change"] = (after.volume - before.volume) / before.volume;
  j["max_relative_subdomain_volume_change"] = max_subdomain_change;
  return j;
}

} // namespace BODT_3
} // namespace CGAL

#endif // BODT_REPORT_JSON_REPORT_H
