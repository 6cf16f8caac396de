// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_BODT_3_SMOOTHING_RESULT_H
#define CGAL_BODT_3_SMOOTHING_RESULT_H

#include <CGAL/Mesh_optimization_return_code.h>

#include <cstddef>
#include <tuple>

namespace CGAL {
namespace BODT_3 {
namespace internal {

// Adds every counter `Stats::counters()` lists of `from` to `to`.
template <class Stats>
void add_counters(Stats& to, const Stats& from)
{
  std::apply([&](auto... member) { ((to.*member += from.*member), ...); }, Stats::counters());
}

} // namespace internal

/// What a flip pass did: accepted flips by kind.
struct Topology_stats
{
  std::size_t flips_2_3 = 0;             // a face removed, an edge created (multi-face removal of one face)
  std::size_t flips_3_2 = 0;             // an edge of three tetrahedra removed
  std::size_t edge_removals = 0;         // an edge of four or more tetrahedra removed
  std::size_t multi_face_removals = 0;   // two or more faces removed, an edge created
  std::size_t boundary_flips = 0;        // of the above, those that flip exactly coplanar boundary or interface facets
  double seconds = 0;                    // the pass, with the search for the cells it starts from

  std::size_t total() const { return flips_2_3 + flips_3_2 + edge_removals + multi_face_removals; }
  static constexpr auto counters()
  {
    using S = Topology_stats;
    return std::make_tuple(&S::flips_2_3, &S::flips_3_2, &S::edge_removals, &S::multi_face_removals,
                           &S::boundary_flips, &S::seconds);
  }
  Topology_stats& operator+=(const Topology_stats& o)
  {
    internal::add_counters(*this, o);
    return *this;
  }
};

/// What an insertion pass did: kept insertions by the kind of tetrahedron split.
struct Insertion_stats
{
  std::size_t spade_splits = 0;     // an edge split at the projection of the opposite vertex
  std::size_t wedge_splits = 0;     // the long edge split at the projection of the short edge's middle
  std::size_t cap_splits = 0;       // a face split at the projection of the opposite vertex
  std::size_t sliver_splits = 0;    // both opposite edges split (two vertices)
  std::size_t ear_splits = 0;       // a boundary ear's inner edge split at its middle (`ear_splits`)
  std::size_t cavity_insertions = 0;   // an interior vertex in an optimized cavity (`cavity_insertion`)
  std::size_t undone = 0;           // insertions tried and undone, since they did not improve
  std::size_t vertices_added = 0;
  double seconds = 0;               // the pass, with the search for the cells it starts from

  static constexpr auto counters()
  {
    using S = Insertion_stats;
    return std::make_tuple(&S::spade_splits, &S::wedge_splits, &S::cap_splits, &S::sliver_splits, &S::ear_splits, &S::cavity_insertions, &S::undone,
                           &S::vertices_added, &S::seconds);
  }
  Insertion_stats& operator+=(const Insertion_stats& o)
  {
    internal::add_counters(*this, o);
    return *this;
  }
};

/// What an edge-contraction pass did.
struct Contraction_stats
{
  std::size_t contractions = 0;            // vertices removed, each moved onto a neighbour
  std::size_t boundary_contractions = 0;   // of which on a flat part of the boundary or of an interface
  double seconds = 0;                      // the pass, with the search for the cells it starts from

  static constexpr auto counters()
  {
    using S = Contraction_stats;
    return std::make_tuple(&S::contractions, &S::boundary_contractions, &S::seconds);
  }
  Contraction_stats& operator+=(const Contraction_stats& o)
  {
    internal::add_counters(*this, o);
    return *this;
  }
};

/// What one sweep did, as reported to visitors.
struct Iteration_stats
{
  std::size_t iteration = 0;          // 1-based, counted through the phases
  std::size_t phase = 0;              // 0: main; 1: largest angle; 2: minimum sine again (largest_angle_phase); 3: worst cells (worst_cell_phase)
  std::size_t moved = 0;              // vertices that moved
  std::size_t shortened = 0;          // of which by a shortened step
  std::size_t refused = 0;            // vertices with a move that was refused entirely
  // Why their full-length move was refused:
  std::size_t refused_inverting_mesh_cell = 0;
  std::size_t refused_inverting_outside_cell = 0;   // a finite cell outside the mesh (C3T3)
  std::size_t refused_breaking_hull = 0;
  std::size_t refused_changing_volume = 0;        // beyond the volume budget (Volume_budget.h)
  std::size_t refused_worsening_quality = 0;
  std::size_t refused_leaving_surface = 0;        // beyond `max_boundary_distance` of the input's surface
  std::size_t max_min_moves = 0;      // vertices moved by the max-min fallback
  std::size_t max_min_searches = 0;   // vertices it searched (not those whose search found no step and nothing changed since)
  double max_relative_move = 0;       // largest move / local size
  Topology_stats topology;            // the flip pass after the sweep
  Contraction_stats contraction;      // the edge-contraction pass after the max-min steps
  Insertion_stats insertion;          // the insertion pass that ends the iteration
  double sweep_seconds = 0;           // time of the sweep alone
  double max_min_seconds = 0;         // of the max-min steps
  double reread_seconds = 0;          // of re-reading the flat view after the flips and the insertion
  double seconds = 0;                 // since the start of the smoothing
};

/// Where the time of a run went, wall seconds per phase.
struct Phase_seconds
{
  double conversion = 0;   // mesh arrays to triangulation and back (smoothing a `Tet_mesh` only)
  double setup = 0;        // flat view, classification, sweep set-up
  double sweeps = 0;
  double flips = 0;
  double max_min = 0;      // max-min steps
  double contraction = 0;  // edge contractions
  double insertion = 0;
  double reread = 0;       // the flat view re-read after a connectivity change
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
  std::size_t crack_vertices = 0;     // fixed: a coincident twin, or on a crack face (mesh files only)
  std::size_t embedded_triangles = 0; // file triangles inside one subdomain, kept (mesh files only)
  bool used_tensor_voting = false;
  Topology_stats topology;            // summed over the iterations
  Contraction_stats contraction;      // summed over the iterations
  Insertion_stats insertion;          // summed over the iterations
  Phase_seconds phases;
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

#endif // CGAL_BODT_3_SMOOTHING_RESULT_H
