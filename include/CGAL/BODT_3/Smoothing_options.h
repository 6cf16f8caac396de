// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_BODT_3_SMOOTHING_OPTIONS_H
#define CGAL_BODT_3_SMOOTHING_OPTIONS_H

#include <CGAL/BODT_3/Tensor_voting.h>

#include <CGAL/Mesh_optimization_return_code.h>

#include <cstddef>

namespace CGAL {
namespace BODT_3 {

/// Which vertices move.
enum class Moving_vertices
{
  ALL,        // B-ODT: interior, boundary, interface and feature vertices
  INTERIOR    // the original ODT: interior vertices only (the paper's baseline)
};

struct Smoothing_options
{
  std::size_t max_iteration_number = 20;   // the paper's 20 sweeps; 0 means no limit
  double time_limit = 0;                   // seconds; 0 means no limit
  /// Stop when no vertex moved by more than this fraction of its local size
  /// (cube root of the mean volume of its cells) in a sweep; 0 disables the test.
  double convergence = 0;
  Moving_vertices moving_vertices = Moving_vertices::ALL;
  bool preserve_features = true;           // false: Algorithm 2 for every boundary vertex
  bool quality_guard = true;               // refuse moves that worsen the star's extreme angles
  Tensor_voting_options tensor_voting;
};

/// What one sweep did, as reported to visitors.
struct Iteration_stats
{
  std::size_t iteration = 0;          // 1-based
  std::size_t moved = 0;              // vertices that moved
  std::size_t shortened = 0;          // of which by a shortened step
  std::size_t refused = 0;            // vertices with a move that was refused entirely
  // Why their full-length move was refused:
  std::size_t refused_inverting_mesh_cell = 0;
  std::size_t refused_inverting_outside_cell = 0;   // a finite cell outside the mesh (C3T3)
  std::size_t refused_breaking_hull = 0;
  std::size_t refused_worsening_quality = 0;
  double max_relative_move = 0;       // largest move / local size
  double seconds = 0;                 // since the start of the smoothing
};

/// The outcome of a smoothing run.
struct Smoothing_result
{
  Mesh_optimization_return_code code = MESH_OPTIMIZATION_UNKNOWN_ERROR;
  std::size_t iterations = 0;
  std::size_t moved_vertices = 0;     // distinct vertices that moved at least once
  std::size_t interior_vertices = 0;
  std::size_t surface_vertices = 0;
  std::size_t feature_vertices = 0;
  std::size_t fixed_vertices = 0;
  std::size_t non_manifold_vertices = 0;
  bool used_tensor_voting = false;
  double seconds = 0;
};

/// A visitor that does nothing; a user visitor provides the same two functions.
struct Null_smoothing_visitor
{
  void after_classification(const Smoothing_result&) {}
  void after_iteration(const Iteration_stats&) {}
};

} // namespace BODT_3
} // namespace CGAL

#endif // CGAL_BODT_3_SMOOTHING_OPTIONS_H
