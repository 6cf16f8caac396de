// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_BODT_3_SMOOTHING_OPTIONS_H
#define CGAL_BODT_3_SMOOTHING_OPTIONS_H

#include <cstddef>

namespace CGAL {
namespace BODT_3 {

/// The measures the pipeline can decide with. The minimum dihedral sine is the
/// default (doc/manual.md); the others exist so that the choice can be measured
/// (bench/quality_measures.cpp): the smallest dihedral angle alone (what CGAL's
/// perturber and exuder raise), and the radius ratio 3 r / R.
enum class Quality_measure
{
  min_dihedral_sine,
  min_dihedral_angle,
  radius_ratio,
  largest_dihedral_angle
};

/// Thresholds that turn the paper's "mu_0 >> mu_1 ~ mu_2" into numbers: the
/// eigenvalues mu_0 >= mu_1 >= mu_2 of M = sum_i S_i n_i n_i^T (eq. 11) are
/// compared relative to mu_0.
///  - mu_1 / mu_0 <  `edge_ratio`: a smooth surface point (Algorithm 2);
///  - mu_1 / mu_0 >= `edge_ratio` and mu_2 / mu_0 < `corner_ratio`: a point on a
///    feature edge, whose direction is e_2 (Algorithm 3);
///  - mu_2 / mu_0 >= `corner_ratio`: a corner, which does not move.
/// Where two flat sides of equal area meet at a dihedral angle theta, the normals
/// differ by phi = 180 - theta degrees and mu_1 / mu_0 = tan^2(phi / 2): the
/// default edge ratio 0.05 marks edges whose normals turn by more than about 25
/// degrees. The defaults come from the experiment of bench/tensor_voting_thresholds
/// (recorded in doc/manual.md): on the generated inputs they miss no sharp-edge
/// vertex and no corner, and constrain 1% of the smooth-surface vertices.
///
/// With `angle_weighted` (the default) each triangle votes with its angle at the
/// vertex instead of its area S_i: then the two flat sides of a straight edge
/// weigh pi each whatever their triangulation, and the ratio depends on the
/// dihedral angle alone; area weights let one side with slim triangles hide the
/// edge (see the measurements in doc/manual.md).
struct Tensor_voting_options
{
  double edge_ratio = 0.05;
  double corner_ratio = 0.05;
  bool angle_weighted = true;
};

/// The thresholds of the classification of bad tetrahedra (doc/manual.md).
struct Bad_tet_options
{
  double small_angle = 10;     // degrees: a tetrahedron with a smaller dihedral angle is bad ...
  double large_angle = 170;    // ... and one with a larger one
  double short_edge = 0.3;     // an edge shorter than this fraction of the longest is short (below 1/3)
  /// A point "projects inside" a face when its barycentric coordinates there all
  /// exceed this, and inside an edge when its parameter is in (margin, 1 - margin).
  double margin = 0.05;
};

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
  /// Above 0 (degrees), the pass also splits boundary ears whose angle is above this,
  /// before any shape test (`Smoothing_options::ear_splits` sets it in the main and the
  /// largest-angle phases).
  double ear_angle = 0;
  /// Instead of the splits by shape: an interior vertex whose cavity and place are
  /// chosen together (Cavity_insertion.h; `Smoothing_options::cavity_insertion`).
  bool cavity = false;
  int max_cavity_attempts = 16;   // cells tried by a pass, worst first
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
  /// Threads of the sweeps, max-min steps and flip evaluations; 0: every core the process may use. The
  /// output does not depend on it (doc/manual.md, "Threads").
  int threads = 0;
  /// Stop when no vertex moved by more than this fraction of its local size
  /// (cube root of the mean volume of its cells) in a sweep; 0 disables the test.
  double convergence = 0;
  /// A vertex whose move in a sweep is shorter than this fraction of its local
  /// size stays where it is, and is visited again only after a vertex it depends
  /// on moves (CGAL's `freeze_bound`, measured against the local size used by
  /// `convergence`); 0 moves every vertex every time. The default was chosen by
  /// measurement (doc/scaling.md, "Freezing"): the largest bound that left the
  /// hard bench grid's angles as they were (0.001 lowered its smallest by 0.4
  /// degree); 0.0001 saved no more time.
  double freeze_bound = 0.0003;
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
  /// After the last phase (with `largest_angle_phase`, by the minimum sine, not
  /// with NODT), a phase without a fixed threshold: each iteration, the cells
  /// whose minimum dihedral sine is below that of an angle `worst_cell_margin`
  /// degrees above the mesh's worst (its smallest angle, or 180 degrees minus its
  /// largest) take the max-min steps and the flips (and the contractions, with
  /// `edge_contraction`), without sweeps; it ends when an iteration raises
  /// neither extreme angle, and does not start where that threshold would not be
  /// above the last phase's (the worst cell below 28 degrees, with the
  /// defaults): there the last phase's steps already worked. The phases before
  /// stop at fixed thresholds (the flips and the last max-min steps at 30
  /// degrees), so nothing else raises a worst cell above them. Measured in doc/manual.md (section 8, item 7): it raised the
  /// smallest angle of the meshes the phases before leave above 30 degrees by 2.7
  /// to 10.7 degrees, for 1% to 17% more time on the hard grids, and
  /// changed nothing where the worst cell lies on a curved surface.
  bool worst_cell_phase = true;
  /// In degrees. Chosen by measurement (doc/manual.md, section 8, item 7): 1, 2,
  /// 3 and 5 on two hard grids, CGAL's sphere, the hand and the bunny; 2 raised the
  /// smallest angle as much as 5 for a small part of its time on the grids.
  double worst_cell_margin = 2;
  /// In the worst-cell phase (with `vertex_insertion`): an interior vertex at the
  /// worst cells, its cavity and place chosen together (Cavity_insertion.h), kept
  /// where its cells compare better, worst first, than those it replaces. The
  /// phase then starts whatever the worst cell.
  bool cavity_insertion = true;
  /// Vertex insertion at spades, caps and slivers (paper, Sec. 2.3).
  bool vertex_insertion = true;
  /// In the main and the largest-angle phases (with `vertex_insertion`), boundary ears are split:
  /// a cell two of whose facets lie on the boundary of its subdomain, meeting at an
  /// edge where its dihedral angle is above `largest_angle_threshold`. No other cell
  /// of the subdomain shares that edge, so the angle is the surface's own there and
  /// no move or flip of the cell lowers it; a vertex on the opposite edge, smoothed,
  /// splits it in two (`Insertion_pass`, kept only where the cells around improve).
  /// Off by default: it lowers the largest angle where ears bound it, but lowers the
  /// smallest on some meshes and costs time (doc/manual.md, section 9, "Boundary ears").
  bool ear_splits = false;
  Insertion_options insertion;
  /// At most this many vertices are inserted; a negative value means 5% of the
  /// input's vertices.
  long long max_vertex_insertions = -1;
  /// Edge contraction (Edge_contraction.h): a vertex inside a subdomain, or on a
  /// flat part of the boundary or of an interface, is removed by moving it onto a
  /// neighbour where that raises the worst cell around it, at the cells a flip pass
  /// works on, after the max-min steps of the last phase and of the worst-cell
  /// phase (of the only phase without `largest_angle_phase`). Corners and feature vertices never go;
  /// volumes and surfaces stay exactly as they are. Off by default: measured in
  /// doc/manual.md, it helps some meshes and leaves most as they were.
  bool edge_contraction = false;
  /// At most this many vertices are removed; a negative value means 5% of the
  /// input's vertices.
  long long max_vertex_removals = -1;
  /// How far the surface (boundary and interfaces) may go from the input's, as a
  /// fraction of the largest side of the bounding box of the input's surface (like
  /// MMG's -hausd, relative). A move of a surface vertex is refused unless its
  /// surface triangles stay within that distance of the input's surface and the
  /// input's surface stays within it of the mesh's (Boundary_distance_guard.h):
  /// the symmetric Hausdorff distance between the two stays within the bound, up
  /// to rounding, where the surface does not fold within the bound of itself
  /// (doc/manual.md, section 8). 0: no bound (the default: the bound costs angles
  /// and time). With B-ODT only (NODT projects onto the input's surface).
  double max_boundary_distance = 0;
  Tensor_voting_options tensor_voting;
};

} // namespace BODT_3
} // namespace CGAL

#endif // CGAL_BODT_3_SMOOTHING_OPTIONS_H
