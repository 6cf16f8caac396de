// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_BODT_OPTIMIZE_MESH_3_H
#define CGAL_BODT_OPTIMIZE_MESH_3_H

#include <CGAL/BODT_3/smooth.h>

#include <CGAL/Mesh_optimization_return_code.h>
#include <CGAL/boost/parameter.h>

#include <boost/parameter/preprocessor.hpp>

namespace CGAL {

namespace parameters {
CGAL_PRAGMA_DIAG_PUSH
CGAL_IGNORE_BOOST_PARAMETER_NAME_WARNINGS
BOOST_PARAMETER_NAME((moving_vertices, tag) moving_vertices_)
BOOST_PARAMETER_NAME((preserve_features, tag) preserve_features_)
BOOST_PARAMETER_NAME((quality_guard, tag) quality_guard_)
BOOST_PARAMETER_NAME((progress_visitor, tag) progress_visitor_)
BOOST_PARAMETER_NAME((feature_edge_ratio, tag) feature_edge_ratio_)
BOOST_PARAMETER_NAME((feature_corner_ratio, tag) feature_corner_ratio_)
BOOST_PARAMETER_NAME((topology_optimization, tag) topology_optimization_)
BOOST_PARAMETER_NAME((vertex_insertion, tag) vertex_insertion_)
BOOST_PARAMETER_NAME((max_vertex_insertions, tag) max_vertex_insertions_)
CGAL_PRAGMA_DIAG_POP
} // namespace parameters

/// Smooths a tetrahedral mesh in place by boundary-optimized Delaunay triangulation
/// (B-ODT), keeping its connectivity, volume, features and subdomains. `mesh` is a
/// `Mesh_complex_3_in_triangulation_3` (as `make_mesh_3` returns it) or a
/// `Triangulation_3`. Called like `odt_optimize_mesh_3`, without a domain:
///
///   CGAL::bodt_optimize_mesh_3(c3t3, CGAL::parameters::max_iteration_number = 20,
///                                    CGAL::parameters::time_limit = 10);
///
/// Parameters (see doc/manual.md):
///  - `time_limit` (seconds, 0: none), `max_iteration_number` (default 20; 0: none),
///    `convergence` (stop when no vertex moves by more than this fraction of its local
///    size; 0, the default, disables it);
///  - `moving_vertices`: `BODT_3::Moving_vertices::ALL` (B-ODT, default) or `INTERIOR`
///    (the original ODT, the paper's baseline);
///  - `preserve_features` (default true; false uses Algorithm 2 for every boundary vertex);
///  - `quality_guard` (default true: a move that would lower the smallest or raise the
///    largest dihedral angle of its star is shortened, then refused);
///  - `feature_edge_ratio`, `feature_corner_ratio`: tensor voting thresholds (see
///    `BODT_3::Tensor_voting_options`), used where the mesh carries no feature information;
///  - `progress_visitor`: an object with `after_classification(const BODT_3::Smoothing_result&)`
///    and `after_iteration(const BODT_3::Iteration_stats&)`, copied.
/// Returns `MAX_ITERATION_NUMBER_REACHED`, `TIME_LIMIT_REACHED`, `CONVERGENCE_REACHED`, or
/// `CANT_IMPROVE_ANYMORE` when a sweep moved no vertex.
CGAL_PRAGMA_DIAG_PUSH
CGAL_IGNORE_BOOST_PARAMETER_NAME_WARNINGS
BOOST_PARAMETER_FUNCTION(
  (Mesh_optimization_return_code),
  bodt_optimize_mesh_3,
  parameters::tag,
  (required (in_out(c3t3), *))
  (optional
    (time_limit_, *, 0.)
    (max_iteration_number_, *, 20)
    (convergence_, *, 0.)
    (moving_vertices_, *, BODT_3::Moving_vertices::ALL)
    (preserve_features_, *, true)
    (quality_guard_, *, true)
    (feature_edge_ratio_, *, BODT_3::Tensor_voting_options().edge_ratio)
    (feature_corner_ratio_, *, BODT_3::Tensor_voting_options().corner_ratio)
    (topology_optimization_, *, true)
    (vertex_insertion_, *, true)
    (max_vertex_insertions_, *, -1)
    (progress_visitor_, *, BODT_3::Null_smoothing_visitor())))
{
  BODT_3::Smoothing_options options;
  options.time_limit = time_limit_;
  options.max_iteration_number = static_cast<std::size_t>(max_iteration_number_);
  options.convergence = convergence_;
  options.moving_vertices = moving_vertices_;
  options.preserve_features = preserve_features_;
  options.quality_guard = quality_guard_;
  options.tensor_voting.edge_ratio = feature_edge_ratio_;
  options.tensor_voting.corner_ratio = feature_corner_ratio_;
  options.topology_optimization = topology_optimization_;
  options.vertex_insertion = vertex_insertion_;
  options.max_vertex_insertions = max_vertex_insertions_;
  auto visitor = progress_visitor_;
  return BODT_3::smooth(c3t3, options, visitor).code;
}
CGAL_PRAGMA_DIAG_POP

} // namespace CGAL

#endif // CGAL_BODT_OPTIMIZE_MESH_3_H
