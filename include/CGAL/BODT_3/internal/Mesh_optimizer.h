// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_BODT_3_INTERNAL_MESH_OPTIMIZER_H
#define CGAL_BODT_3_INTERNAL_MESH_OPTIMIZER_H

#include <CGAL/BODT_3/Smoothing_options.h>
#include <CGAL/BODT_3/Smoothing_result.h>
#include <CGAL/BODT_3/internal/Classification/Vertex_classification.h>
#include <CGAL/BODT_3/internal/Insertion/insertion_pass.h>
#include <CGAL/BODT_3/internal/Mesh/Flat_view.h>
#include <CGAL/BODT_3/internal/Quality/tet_quality.h>
#include <CGAL/BODT_3/internal/Smoothing/Boundary_distance_guard.h>
#include <CGAL/BODT_3/internal/Smoothing/Smoothing_sweep.h>
#include <CGAL/BODT_3/internal/Smoothing/Volume_budget.h>
#include <CGAL/BODT_3/internal/Topology/contraction_pass.h>
#include <CGAL/BODT_3/internal/Topology/flip_pass.h>
#include <CGAL/BODT_3/internal/Utilities/Attempt_history.h>
#include <CGAL/BODT_3/internal/Utilities/Thread_workers.h>
#include <CGAL/BODT_3/internal/Utilities/id_keys.h>

#include <CGAL/Mesh_optimization_return_code.h>
#include <CGAL/Real_timer.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace BODT_3 {
namespace internal {

/// Classifies the vertices of a view from the features the input knows.
struct Classify_by_hints
{
  const Feature_hints& hints;

  template <class View>
  Vertex_classification operator()(const View& view, const Classification_options& opt) const
  {
    return classify_vertices(view.mesh(), hints, opt);
  }
};

/// How the vertices are classified for a run with options `opt`.
inline Classification_options classification_options(const Smoothing_options& opt)
{
  Classification_options classification;
  classification.move_boundary = opt.moving_vertices == Moving_vertices::ALL;
  classification.preserve_features = opt.preserve_features;
  classification.tensor_voting = opt.tensor_voting;
  return classification;
}

/// A phase of the pipeline: iterations run with its own options (its measure
/// and thresholds), numbered as `Iteration_stats::phase`.
struct Phase
{
  std::size_t number;
  Smoothing_options options;
  /// Its max-min and flip thresholds follow the mesh's worst cell (`worst_cell_phase`).
  bool follows_worst = false;
};

/// The last phase's max-min threshold: at every cell the flip pass works on, not
/// only the worst ones, by the minimum sine (the largest-angle phase before it
/// pressed many cells down to the smallest angle it started from).
inline double last_phase_max_min_threshold(const Smoothing_options& opt)
{
  if(opt.max_min_threshold > 0 && opt.quality_measure == Quality_measure::min_dihedral_sine)
    return std::max(opt.max_min_threshold, opt.flips.quality_threshold);
  return opt.max_min_threshold;
}

/// The phases of a run with options `opt`: the main phase, decided by
/// `quality_measure`; then, with `largest_angle_phase` (not for NODT, the paper's
/// baseline, whose projection would then aim at the boundary the phase starts
/// from rather than the input's), a phase decided by the largest dihedral angle
/// and a last one by `quality_measure` again, both without insertion. The
/// minimum sine treats an angle and its supplement alike, so it leaves the
/// angles between its worst and the largest one alone: the second phase lowers
/// them, the last uses what that freed. With `worst_cell_phase` (and the minimum
/// sine as the measure, the guard on), a fourth follows the mesh's worst cell;
/// with `cavity_insertion`, it inserts vertices there too (Cavity_insertion.h).
inline std::vector<Phase> pipeline_phases(const Smoothing_options& opt)
{
  std::vector<Phase> phases{{0, opt}};
  if(!opt.largest_angle_phase || opt.smoothing_method == Smoothing_method::NODT) return phases;

  // Edge contraction in the last phases only: in the main phase it changed the
  // extreme angles more often, both ways, as the later phases took other paths
  // (doc/manual.md).
  phases[0].options.edge_contraction = false;
  Smoothing_options lower = opt;
  lower.quality_measure = Quality_measure::largest_dihedral_angle;
  // Insertion there only at boundary ears, whose largest angle nothing else lowers.
  lower.vertex_insertion = opt.vertex_insertion && opt.ear_splits;
  lower.insertion.ear_angle = opt.largest_angle_threshold;
  lower.insertion.quality_threshold = 0;   // no bad shapes there
  if(opt.ear_splits) phases[0].options.insertion.ear_angle = opt.largest_angle_threshold;
  lower.edge_contraction = false;
  // Max-min steps where an angle is above the threshold; flips around those
  // cells, where an angle is also below its supplement (the flip pass selects by
  // sine), since a flat cell often goes only with its neighbours.
  lower.max_min_threshold = largest_angle_quality(opt.largest_angle_threshold);
  lower.flips.quality_threshold = dihedral_sine(opt.largest_angle_threshold);
  phases.push_back({1, lower});

  Smoothing_options last = opt;
  last.vertex_insertion = false;
  last.max_min_threshold = last_phase_max_min_threshold(opt);
  phases.push_back({2, last});

  if(opt.worst_cell_phase && opt.quality_measure == Quality_measure::min_dihedral_sine && opt.quality_guard &&
     opt.max_min_threshold > 0)
  {
    Smoothing_options worst = last;
    worst.vertex_insertion = opt.vertex_insertion && opt.cavity_insertion;
    worst.insertion.cavity = true;
    phases.push_back({3, worst, true});
  }
  return phases;
}

/// The pipeline of the paper's Fig. 1 on the triangulation behind `Adapter`
/// (Triangulation_adapter.h). The vertices are classified once; then each phase
/// (`pipeline_phases`) runs iterations of
///
///   sweep -> flips -> max-min steps -> insertion,
///
/// re-reading the flat view the sweeps work on after a step that changed cells.
/// Every decision compares the cells concerned, worst first, by the phase's
/// measure, within the extreme angles the phase started from, so the mesh never
/// ends worse than it started. A phase stops after `max_iteration_number`
/// iterations (0: `unlimited_iteration_cap`), at the time limit, at convergence
/// (no vertex moved by more than `convergence` of its local size and no flip;
/// with no iteration limit and no convergence given, `unlimited_convergence`), or
/// when an iteration changed nothing.
///
/// What the steps share: the flat view and the classification of its vertices,
/// the extreme angles of the phase, one volume budget for the run, and, on one
/// clock, when each vertex last moved or got a new star, which tells the flip and
/// insertion passes which of their earlier failures are worth trying again. The
/// failures are kept per measure through the phases (a flip that failed by a
/// phase's measure fails again in a later phase with the same measure, whose
/// extreme angles are no wider, until something near it changes).
template <class Adapter, class Visitor>
class Mesh_optimizer
{
  using Vertex_handle = typename Adapter::Vertex_handle;
  using Cell_handle = typename Adapter::Cell_handle;
  using View = Flat_view<Adapter>;
  using Candidate = Flip_candidate<Cell_handle>;

public:
  /// `classify(view, options)` gives the `Vertex_classification` of the view's vertices.
  template <class Classify>
  Mesh_optimizer(Adapter& adapter, const Classify& classify, const Smoothing_options& options, Visitor& visitor)
    : adapter_(adapter), options_(options), phase_options_(options), visitor_(visitor), timer_(started_timer()),
      view_(adapter, options.threads), mesh_(view_.mesh()), workers_(options.threads)
  {
    view_.follow_changes();   // every pass changes the cells through replace_cells
    classification_ = classify(view_, classification_options(options));
    if(options.moving_vertices == Moving_vertices::NONE)
      std::fill(classification_.kind.begin(), classification_.kind.end(), Vertex_kind::fixed);
    report_classification();

    // Every step that may change a subdomain's volume is paid from one budget for
    // the run (Volume_budget.h); NODT, which does not keep the volume, has none.
    if(options.smoothing_method != Smoothing_method::NODT) volume_budget_ = Volume_budget::of(mesh_, options.threads);
    // The input's surface, for the bound on how far the surface may go (NODT
    // projects back onto it instead; with boundary vertices fixed it stays).
    if(options.smoothing_method == Smoothing_method::BODT && options.moving_vertices == Moving_vertices::ALL)
      distance_ = Boundary_distance_guard<typename View::Kernel>::of(mesh_, options.max_boundary_distance);
    for(Attempt_history& h : flip_histories_) h.retries_after_moves = options.flips.retries_after_moves;
    changed_at_.assign(mesh_.number_of_vertices(), 0);
    new_star_at_.assign(mesh_.number_of_vertices(), 0);
    insertion_budget_ = options.max_vertex_insertions >= 0
                            ? static_cast<std::size_t>(options.max_vertex_insertions)
                            : static_cast<std::size_t>(std::floor(0.05 * double(mesh_.number_of_vertices())));
    if(!options.vertex_insertion || options.moving_vertices == Moving_vertices::NONE) insertion_budget_ = 0;
    removal_budget_ = options.max_vertex_removals >= 0
                          ? static_cast<std::size_t>(options.max_vertex_removals)
                          : static_cast<std::size_t>(std::floor(0.05 * double(mesh_.number_of_vertices())));
    if(!options.edge_contraction || options.moving_vertices == Moving_vertices::NONE) removal_budget_ = 0;
  }

  /// Runs the phases; the result's code is the main phase's, or the time limit's.
  Smoothing_result run()
  {
    for(const Phase& phase : pipeline_phases(options_))
    {
      if(out_of_time_) break;
      start_phase(phase.options);
      const Mesh_optimization_return_code code = run_phase(phase.number, phase.follows_worst);
      if(phase.number == 0) result_.code = code;
    }
    if(out_of_time_) result_.code = TIME_LIMIT_REACHED;
    for(std::size_t v = 0; v < moved_.size(); ++v)   // of the vertices still there
      result_.moved_vertices += moved_[v] && view_.vertices()[v] != Vertex_handle();
    result_.seconds = timer_.time();
    return result_;
  }

private:
  // A phase's extreme angles, within which it works, and its sweep. The cells
  // that failed to flip by the last phase's measure may flip by this one's.
  void start_phase(const Smoothing_options& options)
  {
    sweep_.reset();
    phase_options_ = options;
    bounds_ = extreme_angles();
    sweep_.emplace(mesh_, classification_, phase_options_, bounds_, &volume_budget_, &distance_);
    charge(result_.phases.setup);
  }

  // At most the phase's iterations, until one changes nothing or converges.
  Mesh_optimization_return_code run_phase(std::size_t phase, bool follows_worst)
  {
    const Smoothing_options& opt = phase_options_;
    const std::size_t last = opt.max_iteration_number == 0 ? unlimited_iteration_cap : opt.max_iteration_number;
    Mesh_optimization_return_code code = MAX_ITERATION_NUMBER_REACHED;
    for(std::size_t k = 1; k <= last; ++k)
    {
      Iteration_stats stats;
      stats.iteration = ++iteration_;
      stats.phase = phase;
      const bool moves = opt.moving_vertices != Moving_vertices::NONE;
      if(follows_worst && !follow_worst(k))
      {
        code = CANT_IMPROVE_ANYMORE;
        break;
      }
      if(moves && !follows_worst) sweep(stats);
      if(opt.topology_optimization) flips(stats);
      if(moves && opt.max_min_threshold > 0) max_min_steps(stats);   // after the flips, which remove most flat cells
      if(removal_budget_ > 0 && opt.edge_contraction) contraction(stats);
      if(insertion_budget_ > 0 && opt.vertex_insertion) insertion(stats);
      report_iteration(stats);
      if(const std::optional<Mesh_optimization_return_code> stop = stop_reason(stats, follows_worst))
      {
        code = *stop;
        break;
      }
    }
    moved_.resize(mesh_.number_of_vertices(), 0);
    for(std::size_t v = 0; v < moved_.size(); ++v) moved_[v] |= sweep_->has_moved(static_cast<int>(v));
    return code;
  }

  // The steps of an iteration.

  // Before iteration k of a phase that follows the worst cell: its thresholds
  // from the mesh's extreme angles now; false (the phase ends) when the
  // iteration before raised neither, or when the thresholds would not be above
  // the last phase's.
  bool follow_worst(std::size_t k)
  {
    const Dihedral_bounds now = extreme_angles();
    const double smallest = std::acos(std::min(1.0, now.cos_smallest())) * 180 / pi;
    const double largest = std::acos(std::max(-1.0, now.cos_largest())) * 180 / pi;
    if(k > 1 && smallest <= worst_smallest_ && largest >= worst_largest_) return false;
    worst_smallest_ = smallest;
    worst_largest_ = largest;
    const double worst = std::min(smallest, 180 - largest);
    Smoothing_options& opt = phase_options_;
    const double threshold = dihedral_sine(std::min(90.0, worst + opt.worst_cell_margin));
    // Below the last phase's own thresholds, its flips and max-min steps already
    // worked on these cells, and without sweeps this phase would repeat them.
    // Insertion there is new work, wherever the worst cell is.
    if(!opt.vertex_insertion && threshold <= last_phase_max_min_threshold(options_)) return false;
    opt.max_min_threshold = threshold;
    opt.flips.quality_threshold = threshold;
    opt.insertion.quality_threshold = threshold;
    return true;
  }

  void sweep(Iteration_stats& stats)
  {
    const double start = timer_.time();
    sweep_->forget_moves();
    sweep_->run(stats);
    view_.write_back();
    stamp_moves();
    stats.sweep_seconds = timer_.time() - start;
    charge(result_.phases.sweeps);
  }

  void flips(Iteration_stats& stats)
  {
    const Smoothing_options& opt = phase_options_;
    const double start = timer_.time();   // the pass's cost includes finding where to start
    Attempt_history& history = flip_history();
    begin_pass(history);
    touched_.clear();
    added_.clear();
    // Cells outside the mesh are not measured by the guard: a pass that flips them scans.
    const bool known = guard_knows() && !opt.flips.flip_outside;
    std::vector<Candidate> measured;   // the pass's starting cells, which it takes over
    if(known && opt.quality_measure == Quality_measure::largest_dihedral_angle)
      collect_around(largest_angle_quality(opt.largest_angle_threshold), measured);
    else if(known)
      collect_below(opt.flips.quality_threshold, measured, [this](std::size_t c) { return measure(c); });
    // The pass reads the triangulation, not the flat view's incidences: they are
    // freed while it holds the most (its maps grow with the cells it tries) and
    // derived again after it (by the re-read if it changed cells). A pass that
    // starts from few cells holds little, and may flip none: it keeps them.
    const bool release = !known || measured.size() > mesh_.cells.size() / 8;
    if(release)
    {
      mesh_.release_incidences();
      sweep_->release_derived();
    }
    stats.topology = flip_pass(adapter_, opt.flips, bounds_, vertex_id(), touched_, &history, opt.quality_measure,
                               known ? &measured : nullptr, options_.threads);
    clock_ = history.clock;
    if(release && stats.topology.total() == 0)
    {
      mesh_.build_incidences();
      sweep_->derive();
    }
    stats.topology.seconds = timer_.time() - start;
    charge(result_.phases.flips);
    if(stats.topology.total() > 0) reread(stats);
  }

  void max_min_steps(Iteration_stats& stats)
  {
    const double start = timer_.time();
    sweep_->forget_moves();
    sweep_->raise_worst(phase_options_.max_min_threshold, stats);
    view_.write_back();
    stamp_moves();
    stats.max_min_seconds = timer_.time() - start;
    charge(result_.phases.max_min);
  }

  // Removes vertices inside a subdomain (and, when boundary vertices move, on
  // flat parts of the surface) where that raises the worst cell around them.
  void contraction(Iteration_stats& stats)
  {
    const Smoothing_options& opt = phase_options_;
    const double start = timer_.time();
    touched_.clear();
    added_.clear();
    begin_pass(contraction_history_);
    const bool known = guard_knows() && !opt.flips.flip_outside;
    std::vector<Candidate> measured;
    if(known) collect_below(opt.flips.quality_threshold, measured, [this](std::size_t c) { return measure(c); });
    const bool surface = opt.moving_vertices == Moving_vertices::ALL;
    auto may_remove = [this, surface](Vertex_handle v) {
      const Vertex_kind kind = classification_.kind[view_.index(v)];
      return kind == Vertex_kind::interior || (surface && kind == Vertex_kind::surface);
    };
    std::vector<int> removed;
    stats.contraction = contraction_pass(adapter_, opt.flips, bounds_, opt.quality_measure, removal_budget_,
                                         may_remove, vertex_id(), removed, touched_, &contraction_history_,
                                         known ? &measured : nullptr);
    stats.contraction.seconds = timer_.time() - start;
    removal_budget_ -= stats.contraction.contractions;
    clock_ = contraction_history_.clock;
    charge(result_.phases.contraction);
    for(int id : removed)
    {
      view_.forget(id);
      classification_.kind[id] = Vertex_kind::fixed;   // no cell: never moves
    }
    if(!removed.empty()) reread(stats);
  }

  void insertion(Iteration_stats& stats)
  {
    const Smoothing_options& opt = phase_options_;
    const double start = timer_.time();
    touched_.clear();
    added_.clear();
    begin_pass(insertion_history_);
    // Ears are found by their facets, not by a quality threshold.
    const bool seeded = guard_knows_sines() && !(opt.insertion.ear_angle > 0);
    if(seeded)
      collect_below(opt.insertion.quality_threshold, insertion_candidates_,
                    [this](std::size_t c) { return view_.cells()[c]; });
    stats.insertion = insertion_pass(adapter_, opt.insertion, bounds_, opt.quality_measure, opt.tensor_voting,
                                     insertion_budget_, opt.moving_vertices == Moving_vertices::ALL,
                                     [this](Vertex_handle v) { return motion_of(v); }, vertex_id(), added_, touched_,
                                     &insertion_history_, seeded ? &insertion_candidates_ : nullptr,
                                     &volume_budget_, &distance_, options_.threads);
    stats.insertion.seconds = timer_.time() - start;
    insertion_budget_ -= stats.insertion.vertices_added;
    clock_ = insertion_history_.clock;
    charge(result_.phases.insertion);
    if(stats.insertion.vertices_added > 0 || stats.insertion.undone > 0) reread(stats);
  }

  // After the triangulation changed: re-read it, classify the new vertices, and
  // mark the stars that changed.
  void reread(Iteration_stats& stats)
  {
    const double start = timer_.time();
    view_.refresh();
    std::vector<int> moved;   // by the pass, on the triangulation
    view_.read_points(&moved);
    classification_.kind.resize(mesh_.number_of_vertices(), Vertex_kind::fixed);
    classification_.curve_neighbors.resize(mesh_.number_of_vertices(), {-1, -1});
    for(const auto& a : added_) classify_added(a);
    std::vector<int> changed;
    for(Vertex_handle v : touched_)
      if(!adapter_.triangulation().is_infinite(v))
        if(const int i = view_.index(v); view_.vertices()[i] != Vertex_handle())   // not removed since
          changed.push_back(i);
    const std::size_t now = clock_;
    std::vector<int> added;
    for(std::size_t v = changed_at_.size(); v < mesh_.number_of_vertices(); ++v) added.push_back(static_cast<int>(v));
    changed_at_.resize(mesh_.number_of_vertices(), now);
    new_star_at_.resize(mesh_.number_of_vertices(), now);
    for(int v : changed) changed_at_[v] = new_star_at_[v] = now;
    raise_stamps(added);
    raise_stamps(changed);
    sweep_->refresh(changed, view_.last_cell_moves(), moved);
    stats.reread_seconds += timer_.time() - start;
    charge(result_.phases.reread);
  }

  // How the phase ends, if it does after this iteration.
  // A phase that follows the worst cell has no sweep: `follow_worst` ends it.
  std::optional<Mesh_optimization_return_code> stop_reason(const Iteration_stats& stats, bool follows_worst)
  {
    const bool changed_cells =
        stats.topology.total() > 0 || stats.insertion.vertices_added > 0 || stats.contraction.contractions > 0;
    const bool unlimited = options_.max_iteration_number == 0;
    const double convergence =
        unlimited && options_.convergence == 0 ? unlimited_convergence : options_.convergence;
    if(!follows_worst && stats.moved == 0 && !changed_cells) return CANT_IMPROVE_ANYMORE;
    if(!follows_worst && convergence > 0 && stats.max_relative_move < convergence && !changed_cells)
      return CONVERGENCE_REACHED;
    if(options_.time_limit > 0 && timer_.time() >= options_.time_limit)
    {
      out_of_time_ = true;
      return TIME_LIMIT_REACHED;
    }
    return std::nullopt;
  }

  // What the steps share.

  // The extreme angles of the mesh now: no phase ends with a smaller smallest or
  // a larger largest angle than it started with. Whole-mesh scans run in blocks
  // of cells, merged in block order: the same result on any number of threads.
  Dihedral_bounds extreme_angles()
  {
    std::vector<Dihedral_bounds> block_bounds(block_count(mesh_.cells.size()), Dihedral_bounds::empty());
    for_mesh_cells([&](int b, std::size_t c) {
      const auto& q = mesh_.cells[c];
      block_bounds[b].include(mesh_.points[q[0]], mesh_.points[q[1]], mesh_.points[q[2]], mesh_.points[q[3]]);
    });
    Dihedral_bounds all = Dihedral_bounds::empty();
    for(const Dihedral_bounds& b : block_bounds) all.include(b);
    return all;
  }

  template <class F>
  void for_mesh_cells(const F& f)
  {
    workers_.for_blocks(mesh_.cells.size(), [&](char&, int b, std::size_t begin, std::size_t end) {
      for(std::size_t c = begin; c < end; ++c)
        if(mesh_.in_mesh[c]) f(b, c);
    });
  }

  // With the guard on, the sweep knows every mesh cell's quality by the phase's
  // measure, so the flip pass can start from the cells where there is something
  // to gain (`collect_below`, `collect_around`) ...
  bool guard_knows() const
  {
    const Quality_measure m = phase_options_.quality_measure;
    return phase_options_.quality_guard &&
           (m == Quality_measure::min_dihedral_sine || m == Quality_measure::largest_dihedral_angle);
  }

  // ... and, with the minimum sine as the measure, the insertion pass too.
  bool guard_knows_sines() const
  {
    return phase_options_.quality_guard && phase_options_.quality_measure == Quality_measure::min_dihedral_sine;
  }

  // The mesh cells the guard measured below `threshold`, as `make(c)` gives them, in cell order.
  template <class T, class Make>
  void collect_below(double threshold, std::vector<T>& out, const Make& make)
  {
    collect([&](std::size_t c) { return sweep_->cell_quality(static_cast<int>(c)) < threshold; }, out, make);
  }

  // The mesh cells for which `keep(c)` holds, as `make(c)` gives them, in cell
  // order. The blocks list indices, and `out` is made at its size from them: on a
  // mesh where nearly every cell is kept, lists of `T` per block and their
  // concatenation, which grows by doubling, would hold it about three times.
  template <class Keep, class T, class Make>
  void collect(const Keep& keep, std::vector<T>& out, const Make& make)
  {
    std::vector<std::vector<int>> found(block_count(mesh_.cells.size()));
    for_mesh_cells([&](int b, std::size_t c) {
      if(keep(c)) found[static_cast<std::size_t>(b)].push_back(static_cast<int>(c));
    });
    std::size_t n = 0;
    for(const auto& f : found) n += f.size();
    std::vector<int> cells;
    cells.reserve(n);
    for(const auto& f : found) cells.insert(cells.end(), f.begin(), f.end());
    out.clear();
    out.resize(n);
    workers_.for_each(0, static_cast<int>(n), [&](char&, int k) { out[k] = make(cells[k]); }, 4096);
  }

  // The mesh cells with a vertex of a cell below `threshold`, measured: where the
  // largest-angle phase's flips start. Only there can a flip help a bad cell,
  // itself or by freeing its vertices for the max-min steps. Of those, only the
  // cells the pass would select by sine (`flip_selection_quality`) are kept: on a
  // Mesh_3 output the vertices of the cells above the threshold touch most cells.
  void collect_around(double threshold, std::vector<Candidate>& out)
  {
    const double selected = phase_options_.flips.quality_threshold;
    std::vector<int> bad;
    collect_below(threshold, bad, [](std::size_t c) { return static_cast<int>(c); });
    std::vector<char> near(mesh_.number_of_vertices(), 0);
    for(int c : bad)
      for(int v : mesh_.cells[c]) near[v] = 1;
    collect([&](std::size_t c) {
      const auto& q = mesh_.cells[c];
      const auto& p = mesh_.points;
      return (near[q[0]] || near[q[1]] || near[q[2]] || near[q[3]]) &&
             min_dihedral_sine(p[q[0]], p[q[1]], p[q[2]], p[q[3]]) < selected;
    }, out, [this](std::size_t c) { return measure(c); });
  }

  // A cell for the flip pass, measured from the flat points in the cell's vertex
  // order, as the pass would measure it, without reading the triangulation.
  Candidate measure(std::size_t c) const
  {
    const auto& q = mesh_.cells[c];
    return Candidate{tet_quality(phase_options_.quality_measure, mesh_.points[q[0]], mesh_.points[q[1]],
                                 mesh_.points[q[2]], mesh_.points[q[3]]),
                     sorted(q), view_.cells()[c]};
  }

  auto vertex_id() const
  {
    return [this](Vertex_handle v) { return view_.index(v); };
  }

  // How an existing vertex moves, for the insertion pass.
  Vertex_motion<Vertex_handle> motion_of(Vertex_handle v) const
  {
    const int id = view_.index(v);
    Vertex_motion<Vertex_handle> m;
    m.kind = classification_.kind[id];
    if(classification_.curve_neighbors[id][0] >= 0)
    {
      m.a = view_.vertices()[classification_.curve_neighbors[id][0]];
      m.b = view_.vertices()[classification_.curve_neighbors[id][1]];
    }
    return m;
  }

  // A vertex the insertion pass added; one on a split curve edge a b sits
  // between them on the curve.
  void classify_added(const Added_vertex<Vertex_handle>& a)
  {
    const int id = view_.index(a.vertex);
    classification_.kind[id] = a.kind;
    if(a.a == Vertex_handle()) return;
    const int ia = view_.index(a.a), ib = view_.index(a.b);
    classification_.curve_neighbors[id] = {ia, ib};
    for(auto [end, other] : {std::pair<int, int>{ia, ib}, std::pair<int, int>{ib, ia}})
      for(int& n : classification_.curve_neighbors[end])
        if(n == other) n = id;
  }

  // The vertices the last sweep or max-min step moved changed now.
  void stamp_moves()
  {
    ++clock_;
    for(int v : sweep_->moved()) changed_at_[v] = clock_;
    raise_stamps(sweep_->moved());
  }

  // Vertices whose stamps rose, for the next `stamp_regions`; past an eighth of
  // the vertices it makes them whole, and the list is dropped (it would grow with
  // each sweep of a run with no pass to stamp for).
  void raise_stamps(const std::vector<int>& vertices)
  {
    if(restamp_all_) return;
    if(raised_.size() + vertices.size() >= mesh_.number_of_vertices() / 8)
    {
      restamp_all_ = true;
      std::vector<int>().swap(raised_);
      return;
    }
    raised_.insert(raised_.end(), vertices.begin(), vertices.end());
  }

  // The flip failures by the phase's measure.
  Attempt_history& flip_history()
  {
    return flip_histories_[phase_options_.quality_measure == Quality_measure::largest_dihedral_angle ? 1 : 0];
  }

  // A pass starts: its history on the run's clock, the pass's number, and when
  // each vertex's neighbourhood last changed. The pass advances the clock at each
  // change it makes; the caller takes the clock back afterwards.
  void begin_pass(Attempt_history& history)
  {
    history.clock = clock_;
    history.pass = iteration_;
    // Every pass stamps its history's vertices again: one pair of arrays, handed
    // from history to history, serves them all.
    if(stamped_ && stamped_ != &history)
    {
      history.region_stamp.swap(stamped_->region_stamp);
      history.topology_stamp.swap(stamped_->topology_stamp);
    }
    stamped_ = &history;
    stamp_regions(history);
  }

  // The last change within one edge of each vertex, for a pass's history. Made
  // whole the first time and after changes at many vertices; else only around
  // the vertices whose stamps rose since: a stamp only rises, and a vertex whose
  // neighbours changed got a new star, stamped now, above every other stamp
  // (the same arrays either way).
  void stamp_regions(Attempt_history& history)
  {
    const std::size_t n = mesh_.number_of_vertices();
    history.region_stamp.resize(n);
    history.topology_stamp.resize(n);
    if(!restamp_all_)
    {
      for(int u : raised_)
      {
        const std::size_t stamp = changed_at_[u], star = new_star_at_[u];
        auto raise = [&](int w) {
          history.region_stamp[w] = std::max(history.region_stamp[w], stamp);
          history.topology_stamp[w] = std::max(history.topology_stamp[w], star);
        };
        raise(u);
        for(int k = mesh_.incidence_begin[u]; k < mesh_.incidence_begin[u + 1]; ++k)
          for(int w : mesh_.incidences[k].face) raise(w);
      }
      raised_.clear();
      return;
    }
    restamp_all_ = false;
    workers_.for_each(0, static_cast<int>(mesh_.number_of_vertices()), [&](char&, int v) {
      std::size_t stamp = changed_at_[v], star = new_star_at_[v];
      for(int k = mesh_.incidence_begin[v]; k < mesh_.incidence_begin[v + 1]; ++k)
        for(int u : mesh_.incidences[k].face)
        {
          stamp = std::max(stamp, changed_at_[u]);
          star = std::max(star, new_star_at_[u]);
        }
      history.region_stamp[v] = stamp;
      history.topology_stamp[v] = star;
    }, 4096);
  }

  void report_classification()
  {
    result_.interior_vertices = classification_.count(Vertex_kind::interior);
    result_.surface_vertices = classification_.count(Vertex_kind::surface);
    result_.feature_vertices = classification_.count(Vertex_kind::feature);
    result_.fixed_vertices = classification_.count(Vertex_kind::fixed);
    result_.non_manifold_vertices = classification_.non_manifold;
    result_.used_tensor_voting = classification_.used_tensor_voting;
    visitor_.after_classification(result_);
  }

  void report_iteration(Iteration_stats& stats)
  {
    result_.topology += stats.topology;
    result_.contraction += stats.contraction;
    result_.insertion += stats.insertion;
    stats.seconds = timer_.time();
    result_.iterations = iteration_;
    visitor_.after_iteration(stats);
  }

  static CGAL::Real_timer started_timer()
  {
    CGAL::Real_timer timer;
    timer.start();
    return timer;
  }

  // Adds the time since the last call to `phase_seconds`.
  void charge(double& phase_seconds)
  {
    const double now = timer_.time();
    phase_seconds += now - lap_;
    lap_ = now;
  }

  Adapter& adapter_;
  const Smoothing_options& options_;
  Smoothing_options phase_options_;
  Visitor& visitor_;
  CGAL::Real_timer timer_;
  double lap_ = 0;
  View view_;
  typename View::Mesh& mesh_;
  Thread_workers<char> workers_;
  Vertex_classification classification_;
  Dihedral_bounds bounds_;
  Volume_budget volume_budget_;   // unlimited for NODT
  Boundary_distance_guard<typename View::Kernel> distance_;   // no bound unless asked, with B-ODT
  std::optional<Smoothing_sweep<typename View::Kernel>> sweep_;
  // The run's clock, advanced at each sweep, max-min step, flip and insertion,
  // and per vertex on it: when it last moved or got a new star, and when its star
  // last changed.
  std::size_t clock_ = 0;
  std::vector<std::size_t> changed_at_, new_star_at_;
  std::array<Attempt_history, 2> flip_histories_;   // by the minimum sine, by the largest angle
  Attempt_history insertion_history_;
  Attempt_history contraction_history_;
  Attempt_history* stamped_ = nullptr;   // the history holding the stamp arrays
  bool restamp_all_ = true;              // the stamps are made whole next time
  std::vector<int> raised_;              // else: vertices whose changed_at_ or new_star_at_ rose since they were made
  std::vector<Cell_handle> insertion_candidates_;    // the insertion pass's
  std::vector<Vertex_handle> touched_;               // vertices whose star the last pass changed
  std::vector<Added_vertex<Vertex_handle>> added_;   // vertices the last insertion pass added
  std::size_t insertion_budget_ = 0;
  std::size_t removal_budget_ = 0;
  std::size_t iteration_ = 0;
  bool out_of_time_ = false;
  double worst_smallest_ = 0, worst_largest_ = 180;   // the extreme angles a worst-cell iteration started from
  std::vector<char> moved_;   // vertices moved in some phase
  Smoothing_result result_;
};

/// Runs the pipeline (`Mesh_optimizer`) on the triangulation behind `adapter`.
template <class Adapter, class Classify, class Visitor>
Smoothing_result optimize_mesh(Adapter& adapter, const Classify& classify, const Smoothing_options& options,
                               Visitor&& visitor)
{
  return Mesh_optimizer<Adapter, std::remove_reference_t<Visitor>>(adapter, classify, options, visitor).run();
}

} // namespace internal
} // namespace BODT_3
} // namespace CGAL

#endif // CGAL_BODT_3_INTERNAL_MESH_OPTIMIZER_H
