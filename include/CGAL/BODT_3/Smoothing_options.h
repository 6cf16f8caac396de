// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_BODT_3_SMOOTHING_OPTIONS_H
#define CGAL_BODT_3_SMOOTHING_OPTIONS_H

#include <CGAL/BODT_3/Bad_tet_shape.h>
#include <CGAL/BODT_3/Tensor_voting.h>
#include <CGAL/BODT_3/tet_quality.h>

#include <CGAL/Mesh_optimization_return_code.h>

#include <cstddef>

namespace CGAL {
namespace BODT_3 {

/// Which vertices move.
enum class Moving_vertices
{
  ALL,        // B-ODT: interior, boundary, interface and feature vertices
  INTERIOR,   // the original ODT: interior vertices only (the paper's baseline)
  NONE        // no smoothing: topology optimization (and insertion) alone
};

/// How boundary vertices move.
enum class Smoothing_method
{
  BODT,   // on their tangent plane (Algorithms 2 and 3): the volume is kept exactly
  NODT    // Natural ODT (Tournois et al. 2009), projected back on the input boundary: the paper's baseline
};

/// How the topology passes work (see flip_pass.h).
struct Flip_options
{
  /// Cells whose minimum dihedral sine is below this are the ones a pass tries to
  /// improve (0.5: a dihedral angle below 30 or above 150 degrees). Larger values
  /// try more cells and cost more; see doc/manual.md for the measurement.
  double quality_threshold = 0.5;
  /// Also improve cells outside the complex (the padding of a C3T3 to its convex
  /// hull), whose flatness can block boundary vertices.
  bool flip_outside = false;
  int max_ring = 10;    // edge removal: largest ring tried
  int max_faces = 10;   // multi-face removal: largest sandwich explored
  /// A cell whose flips all failed this many times in a row is tried again only
  /// once the connectivity near it changed, no longer when vertices near it merely
  /// moved (flip_pass.h). 1 against no limit: the same extreme angles on the 17
  /// inputs of doc/stages.md, flip passes up to 13% cheaper (genus2).
  std::size_t retries_after_moves = 1;
};

/// How the insertion passes work (see insertion_pass.h).
struct Insertion_options
{
  /// Mesh cells whose minimum dihedral sine is below this (0.34: a dihedral angle
  /// below 20 or above 160 degrees) and that are spades, caps or slivers get split.
  double quality_threshold = 0.34;
  Bad_tet_options shapes;      // short edges and margins; the angle bounds follow the threshold
  int smoothing_rounds = 2;    // local smoothing of the new vertices and the tetrahedron's own
};

/// With `max_iteration_number = 0` (no limit), the pipeline still stops after this
/// many iterations, so that every run ends ...
constexpr std::size_t unlimited_iteration_cap = 1000;
/// ... and, unless `convergence` is given, at this convergence (CGAL's optimizers'
/// default): otherwise smoothing goes on with ever smaller moves.
constexpr double unlimited_convergence = 0.02;

struct Smoothing_options
{
  /// The paper's 20 iterations. 0: until an iteration changes nothing or
  /// `convergence` (default then `unlimited_convergence`) is reached, at most
  /// `unlimited_iteration_cap` iterations (CGAL's optimizers cap 0 the same way).
  std::size_t max_iteration_number = 20;
  double time_limit = 0;                   // seconds; 0 means no limit
  /// Threads of the smoothing sweeps; 0: every core the process may use. The
  /// output does not depend on it (doc/manual.md, "Threads").
  int threads = 0;
  /// Stop when no vertex moved by more than this fraction of its local size
  /// (cube root of the mean volume of its cells) in a sweep; 0 disables the test.
  double convergence = 0;
  Moving_vertices moving_vertices = Moving_vertices::ALL;
  /// NODT moves surface vertices (not feature vertices and corners, which move as
  /// in B-ODT) off the boundary and back onto the input's boundary triangles.
  Smoothing_method smoothing_method = Smoothing_method::BODT;
  bool preserve_features = true;           // false: Algorithm 2 for every boundary vertex
  bool quality_guard = true;               // refuse moves that worsen the star's extreme angles
  /// After each sweep, flips (edge removal, multi-face removal, coplanar boundary
  /// flips) wherever they improve the worst tetrahedron they touch (paper, Fig. 1).
  bool topology_optimization = true;
  Flip_options flips;
  /// What decides every change (tet_quality.h); the default is justified in doc/manual.md.
  Quality_measure quality_measure = Quality_measure::min_dihedral_sine;
  /// After each sweep, the vertices of mesh cells below this quality (by
  /// `quality_measure`) take max-min compass steps (Smoothing_sweep::raise_worst);
  /// 0 turns the fallback off.
  double max_min_threshold = 0.34;
  /// After the iterations above, a phase decided by the largest dihedral angle
  /// of each tetrahedron (`Quality_measure::largest_dihedral_angle`), within the
  /// smallest and largest angles the mesh then has: flips and max-min steps at the
  /// cells with an angle above `largest_angle_threshold`, and the sweeps; then a
  /// phase decided by `quality_measure` again, without insertion, whose max-min
  /// steps (with the minimum sine as measure) work on every cell below the flip
  /// threshold `flips.quality_threshold` if that is above `max_min_threshold`
  /// (not with NODT). Each runs at most
  /// `max_iteration_number` iterations (counted in the result's `iterations`).
  /// The minimum sine is the same for an angle and its supplement, so it leaves the
  /// angles between its worst and 180 degrees minus that alone; doc/manual.md has
  /// what this phase does to them.
  bool largest_angle_phase = true;
  double largest_angle_threshold = 120;   // degrees
  /// Vertex insertion at spades, caps and slivers (paper, Sec. 2.3).
  bool vertex_insertion = true;
  Insertion_options insertion;
  /// At most this many vertices are inserted; a negative value means 5% of the
  /// input's vertices.
  long long max_vertex_insertions = -1;
  Tensor_voting_options tensor_voting;
};

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
  Topology_stats& operator+=(const Topology_stats& o)
  {
    flips_2_3 += o.flips_2_3;
    flips_3_2 += o.flips_3_2;
    edge_removals += o.edge_removals;
    multi_face_removals += o.multi_face_removals;
    boundary_flips += o.boundary_flips;
    seconds += o.seconds;
    return *this;
  }
};

/// What an insertion pass did: kept insertions by the kind of tetrahedron split.
struct Insertion_stats
{
  std::size_t spade_splits = 0;     // an edge split at the projection of the opposite vertex
  std::size_t cap_splits = 0;       // a face split at the projection of the opposite vertex
  std::size_t sliver_splits = 0;    // both opposite edges split (two vertices)
  std::size_t undone = 0;           // insertions tried and undone, since they did not improve
  std::size_t vertices_added = 0;
  double seconds = 0;               // the pass, with the search for the cells it starts from

  Insertion_stats& operator+=(const Insertion_stats& o)
  {
    spade_splits += o.spade_splits;
    cap_splits += o.cap_splits;
    sliver_splits += o.sliver_splits;
    undone += o.undone;
    vertices_added += o.vertices_added;
    seconds += o.seconds;
    return *this;
  }
};

/// What one sweep did, as reported to visitors.
struct Iteration_stats
{
  std::size_t iteration = 0;          // 1-based, counted through the phases
  std::size_t phase = 0;              // 0: main; 1: largest angle; 2: minimum sine again (largest_angle_phase)
  std::size_t moved = 0;              // vertices that moved
  std::size_t shortened = 0;          // of which by a shortened step
  std::size_t refused = 0;            // vertices with a move that was refused entirely
  // Why their full-length move was refused:
  std::size_t refused_inverting_mesh_cell = 0;
  std::size_t refused_inverting_outside_cell = 0;   // a finite cell outside the mesh (C3T3)
  std::size_t refused_breaking_hull = 0;
  std::size_t refused_changing_volume = 0;        // beyond the volume budget (Volume_budget.h)
  std::size_t refused_worsening_quality = 0;
  std::size_t max_min_moves = 0;      // vertices moved by the max-min fallback
  double max_relative_move = 0;       // largest move / local size
  Topology_stats topology;            // the flip pass after the sweep
  Insertion_stats insertion;          // the insertion pass before the sweep
  double sweep_seconds = 0;           // time of the sweep alone
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

#endif // CGAL_BODT_3_SMOOTHING_OPTIONS_H
