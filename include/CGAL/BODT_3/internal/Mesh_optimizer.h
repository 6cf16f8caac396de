// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_BODT_3_INTERNAL_MESH_OPTIMIZER_H
#define CGAL_BODT_3_INTERNAL_MESH_OPTIMIZER_H

#include <CGAL/BODT_3/Smoothing_options.h>
#include <CGAL/BODT_3/Smoothing_result.h>
#include <CGAL/BODT_3/internal/Smoothing/Smoothing_sweep.h>
#include <CGAL/BODT_3/internal/Utilities/Thread_workers.h>
#include <CGAL/BODT_3/internal/Mesh/Flat_view.h>
#include <CGAL/BODT_3/internal/Classification/Vertex_classification.h>
#include <CGAL/BODT_3/internal/Topology/flip_pass.h>
#include <CGAL/BODT_3/internal/Insertion/insertion_pass.h>
#include <CGAL/BODT_3/internal/Quality/tet_quality.h>

#include <CGAL/Real_timer.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace BODT_3 {

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
  Classification_options copt;
  copt.move_boundary = opt.moving_vertices == Moving_vertices::ALL;
  copt.preserve_features = opt.preserve_features;
  copt.tensor_voting = opt.tensor_voting;
  return copt;
}

/// The pipeline of the paper's Fig. 1 on the triangulation behind `labels`
/// (Mesh_labels.h): the vertices are classified once (`classify(view, options)`
/// gives a `Vertex_classification` by view id), then each iteration runs a
/// smoothing sweep (unless `moving_vertices` is NONE), a topology pass (if
/// `topology_optimization`), max-min steps and an insertion pass. The flat view the
/// sweeps use is re-read after a pass that changed cells. Every decision compares
/// the cells concerned, worst first, by the phase's measure, within the extreme
/// angles the phase started from, so the mesh never ends worse than it started.
/// A phase stops after `max_iteration_number` iterations (0:
/// `unlimited_iteration_cap`), at the time limit, at convergence (no vertex moved
/// by more than `convergence` of its local size and no flip; with no iteration
/// limit and no convergence given, `unlimited_convergence`), or when an iteration
/// changed nothing. The main phase decides by `quality_measure`; with
/// `largest_angle_phase`, a phase by the largest dihedral angle and a last one by
/// `quality_measure` follow, without insertion; the last one takes max-min steps
/// at every cell below the flip threshold.
template <class Labels, class Classify, class Visitor>
Smoothing_result optimize_mesh(Labels& labels, const Classify& classify, const Smoothing_options& opt,
                               Visitor&& visitor)
{
  CGAL::Real_timer timer;
  timer.start();

  Flat_view<Labels> view(labels, opt.threads);
  auto& mesh = view.mesh();

  Vertex_classification cls = classify(view, classification_options(opt));
  if(opt.moving_vertices == Moving_vertices::NONE) std::fill(cls.kind.begin(), cls.kind.end(), Vertex_kind::fixed);

  Smoothing_result result;
  // Adds the time since the last call to `phase`.
  double lap = 0;
  auto charge = [&](double& phase) {
    const double now = timer.time();
    phase += now - lap;
    lap = now;
  };
  result.interior_vertices = cls.count(Vertex_kind::interior);
  result.surface_vertices = cls.count(Vertex_kind::surface);
  result.feature_vertices = cls.count(Vertex_kind::feature);
  result.fixed_vertices = cls.count(Vertex_kind::fixed);
  result.non_manifold_vertices = cls.non_manifold;
  result.used_tensor_voting = cls.used_tensor_voting;
  visitor.after_classification(result);

  // Whole-mesh scans run in blocks of cells, merged in block order: the same
  // result on any number of threads.
  Thread_workers<char> workers(opt.threads);
  auto cell_blocks = [&mesh] { return block_count(mesh.cells.size()); };
  auto for_cell_blocks = [&](const auto& f) {
    workers.for_blocks(mesh.cells.size(), [&](char&, int b, std::size_t begin, std::size_t end) {
      for(std::size_t c = begin; c < end; ++c)
        if(mesh.in_mesh[c]) f(b, c);
    });
  };
  // The extreme angles of the mesh now: no phase ends with a smaller smallest or a
  // larger largest angle than it started with.
  auto extreme_angles = [&]() {
    std::vector<Dihedral_bounds> block_bounds(cell_blocks(), Dihedral_bounds::empty());
    for_cell_blocks([&](int b, std::size_t c) {
      const auto& q = mesh.cells[c];
      block_bounds[b].include(mesh.points[q[0]], mesh.points[q[1]], mesh.points[q[2]], mesh.points[q[3]]);
    });
    Dihedral_bounds all = Dihedral_bounds::empty();
    for(const Dihedral_bounds& b : block_bounds) all.include(b);
    return all;
  };
  Dihedral_bounds bounds = extreme_angles();

  // Every step that may change a subdomain's volume is paid from one budget for
  // the run (Volume_budget.h); NODT, which does not keep the volume, has none.
  Volume_budget volume_budget =
      opt.smoothing_method == Smoothing_method::NODT ? Volume_budget() : Volume_budget::of(mesh, opt.threads);
  // Each phase has its options (its measure) and its sweep.
  Smoothing_options popt = opt;
  std::optional<Smoothing_sweep<typename Flat_view<Labels>::Kernel>> sweep;
  sweep.emplace(mesh, cls, popt, bounds, &volume_budget);
  auto vertex_id = [&view](typename Labels::Vertex_handle v) { return view.index(v); };
  std::vector<typename Labels::Vertex_handle> touched;
  std::vector<int> changed;
  Attempt_history history;
  history.retries_after_moves = opt.flips.retries_after_moves;
  std::vector<typename Labels::Cell_handle> candidates;
  std::vector<std::size_t> changed_at(mesh.number_of_vertices(), 0);   // per vertex: when it last moved or flipped
  std::vector<std::size_t> new_star_at(mesh.number_of_vertices(), 0);  // per vertex: when its star last changed

  // Insertion: its budget, and how existing vertices move, by their view id.
  using Vertex_handle = typename Labels::Vertex_handle;
  std::size_t budget = opt.max_vertex_insertions >= 0
                           ? static_cast<std::size_t>(opt.max_vertex_insertions)
                           : static_cast<std::size_t>(std::floor(0.05 * double(mesh.number_of_vertices())));
  if(!opt.vertex_insertion || opt.moving_vertices == Moving_vertices::NONE) budget = 0;
  Attempt_history insertion_history;
  std::vector<Added_vertex<Vertex_handle>> added;
  auto motion = [&](Vertex_handle v) {
    const int id = view.index(v);
    Vertex_motion<Vertex_handle> m;
    m.kind = cls.kind[id];
    if(cls.curve_neighbors[id][0] >= 0)
    {
      m.a = view.vertices()[cls.curve_neighbors[id][0]];
      m.b = view.vertices()[cls.curve_neighbors[id][1]];
    }
    return m;
  };
  // The last change within one edge of each vertex, for a pass's history.
  auto stamp_regions = [&](Attempt_history& h) {
    h.region_stamp.resize(mesh.number_of_vertices());
    h.topology_stamp.resize(mesh.number_of_vertices());
    workers.for_each(0, static_cast<int>(mesh.number_of_vertices()), [&](char&, int v) {
      std::size_t stamp = changed_at[v], star = new_star_at[v];
      for(int k = mesh.incidence_begin[v]; k < mesh.incidence_begin[v + 1]; ++k)
        for(int u : mesh.incidences[k].face)
        {
          stamp = std::max(stamp, changed_at[u]);
          star = std::max(star, new_star_at[u]);
        }
      h.region_stamp[v] = stamp;
      h.topology_stamp[v] = star;
    }, 4096);
  };
  // After the triangulation changed: re-read it, classify new vertices, mark stars changed.
  auto reread = [&]() {
    view.refresh();
    view.read_points();
    cls.kind.resize(mesh.number_of_vertices(), Vertex_kind::fixed);
    cls.curve_neighbors.resize(mesh.number_of_vertices(), {-1, -1});
    for(const auto& a : added)
    {
      const int id = view.index(a.vertex);
      cls.kind[id] = a.kind;
      if(a.a == Vertex_handle()) continue;
      // A split curve edge a b: the new vertex sits between them on the curve.
      const int ia = view.index(a.a), ib = view.index(a.b);
      cls.curve_neighbors[id] = {ia, ib};
      for(auto [end, other] : {std::pair<int, int>{ia, ib}, std::pair<int, int>{ib, ia}})
        for(int& n : cls.curve_neighbors[end])
          if(n == other) n = id;
    }
    changed.clear();
    for(auto v : touched)
      if(!labels.triangulation().is_infinite(v)) changed.push_back(view.index(v));
    changed_at.resize(mesh.number_of_vertices(), history.clock);
    new_star_at.resize(mesh.number_of_vertices(), history.clock);
    for(int v : changed) changed_at[v] = new_star_at[v] = history.clock;
    sweep->refresh(changed);
    charge(result.phases.reread);
  };

  // With the guard on, the sweep knows every mesh cell's minimum dihedral sine:
  // the passes start from the cells below their thresholds.
  auto guard_knows = [&popt] {
    return popt.quality_guard && popt.quality_measure == Quality_measure::min_dihedral_sine;
  };
  // The mesh cells the guard measured below a threshold, as `make(c)` gives them,
  // in cell order.
  auto collect_below = [&](double threshold, auto& out, const auto& make) {
    std::vector<std::decay_t<decltype(out)>> found(static_cast<std::size_t>(cell_blocks()));
    for_cell_blocks([&](int b, std::size_t c) {
      if(sweep->cell_quality(static_cast<int>(c)) < threshold) found[static_cast<std::size_t>(b)].push_back(make(c));
    });
    out.clear();
    for(const auto& f : found) out.insert(out.end(), f.begin(), f.end());
  };
  // For the flip pass, measured again from the flat points in each cell's vertex
  // order, as the pass would measure them; for the insertion pass, the cells.
  using Measured = Measured_cell<typename Labels::Cell_handle, Vertex_handle>;
  std::vector<Measured> measured;
  auto measure = [&](std::size_t c) {
    const auto& q = mesh.cells[c];
    Measured m{view.cells()[c], {}, q, 0.0};
    for(int k = 0; k < 4; ++k) m.vertices[k] = view.vertices()[q[k]];
    m.quality = tet_quality(popt.quality_measure, mesh.points[q[0]], mesh.points[q[1]], mesh.points[q[2]],
                            mesh.points[q[3]]);
    return m;
  };
  auto cell = [&](std::size_t c) { return view.cells()[c]; };

  const bool unlimited = opt.max_iteration_number == 0;
  const double convergence = unlimited && opt.convergence == 0 ? unlimited_convergence : opt.convergence;
  std::size_t it = 0;
  bool out_of_time = false;
  std::vector<char> moved;   // vertices moved in some phase
  // One phase: at most `last` iterations with the options `popt`, until an
  // iteration changes nothing or converges. Returns how it ended.
  auto run_phase = [&](std::size_t phase) {
    Mesh_optimization_return_code code = MAX_ITERATION_NUMBER_REACHED;
    const std::size_t last = popt.max_iteration_number == 0 ? unlimited_iteration_cap : popt.max_iteration_number;
    for(std::size_t k = 1; k <= last; ++k)
    {
      Iteration_stats stats;
      stats.iteration = ++it;
      stats.phase = phase;
      if(popt.moving_vertices != Moving_vertices::NONE)
      {
        const double start = timer.time();
        sweep->forget_moves();
        sweep->run(stats);
        view.write_back();
        ++history.clock;
        for(int v : sweep->moved()) changed_at[v] = history.clock;
        stats.sweep_seconds = timer.time() - start;
        charge(result.phases.sweeps);
      }
      if(popt.topology_optimization)
      {
        const double start = timer.time();   // the pass's cost includes finding where to start
        history.pass = it;
        stamp_regions(history);
        touched.clear();
        added.clear();
        // Cells outside the mesh are not measured by the guard: a pass that flips them scans.
        const bool known = guard_knows() && !popt.flips.flip_outside;
        if(known) collect_below(popt.flips.quality_threshold, measured, measure);
        stats.topology = flip_pass(labels, popt.flips, bounds, vertex_id, touched, &history, popt.quality_measure,
                                   known ? &measured : nullptr);
        stats.topology.seconds = timer.time() - start;
        charge(result.phases.flips);
        if(stats.topology.total() > 0) reread();
      }
      if(popt.moving_vertices != Moving_vertices::NONE && popt.max_min_threshold > 0)
      {
        // After the flips, which remove most flat tetrahedra better than moves can.
        sweep->forget_moves();
        sweep->raise_worst(popt.max_min_threshold, stats);
        view.write_back();
        ++history.clock;
        for(int v : sweep->moved()) changed_at[v] = history.clock;
        charge(result.phases.max_min);
      }
      if(budget > 0 && popt.vertex_insertion)
      {
        const double start = timer.time();
        touched.clear();
        added.clear();
        insertion_history.pass = it;
        insertion_history.clock = history.clock;
        stamp_regions(insertion_history);
        if(guard_knows()) collect_below(popt.insertion.quality_threshold, candidates, cell);
        stats.insertion = insertion_pass(labels, popt.insertion, bounds, popt.quality_measure, popt.tensor_voting,
                                         budget, popt.moving_vertices == Moving_vertices::ALL, motion, vertex_id,
                                         added, touched, &insertion_history, guard_knows() ? &candidates : nullptr,
                                         &volume_budget);
        stats.insertion.seconds = timer.time() - start;
        budget -= stats.insertion.vertices_added;
        history.clock = insertion_history.clock;
        charge(result.phases.insertion);
        if(stats.insertion.vertices_added > 0 || stats.insertion.undone > 0) reread();
      }
      result.topology += stats.topology;
      result.insertion += stats.insertion;
      stats.seconds = timer.time();
      result.iterations = it;
      visitor.after_iteration(stats);
      const bool flipped = stats.topology.total() > 0 || stats.insertion.vertices_added > 0;
      if(stats.moved == 0 && !flipped) { code = CANT_IMPROVE_ANYMORE; break; }
      if(convergence > 0 && stats.max_relative_move < convergence && !flipped)
      {
        code = CONVERGENCE_REACHED;
        break;
      }
      if(opt.time_limit > 0 && timer.time() >= opt.time_limit)
      {
        out_of_time = true;
        code = TIME_LIMIT_REACHED;
        break;
      }
    }
    moved.resize(mesh.number_of_vertices(), 0);
    for(std::size_t v = 0; v < moved.size(); ++v) moved[v] |= sweep->has_moved(static_cast<int>(v));
    return code;
  };
  // A new phase: its options, the extreme angles it starts from, its sweep; the
  // cells that failed to flip by the last phase's measure may flip by this one's.
  auto start_phase = [&](const Smoothing_options& next) {
    sweep.reset();
    popt = next;
    bounds = extreme_angles();
    history.failed.clear();
    sweep.emplace(mesh, cls, popt, bounds, &volume_budget);
    charge(result.phases.setup);
  };

  charge(result.phases.setup);
  result.code = run_phase(0);
  // Not for NODT, the paper's baseline: a new sweep would project onto the boundary
  // the phase starts from, no longer the input's.
  if(opt.largest_angle_phase && opt.smoothing_method != Smoothing_method::NODT && !out_of_time)
  {
    // The measure above treats an angle and its supplement alike, so angles
    // between its worst and the largest one are left alone: lower them with the
    // largest angle as the measure, then let the minimum sine use what that freed.
    Smoothing_options lower = opt;
    lower.quality_measure = Quality_measure::largest_dihedral_angle;
    lower.vertex_insertion = false;
    // Max-min steps where an angle is above the threshold; flips also where one is
    // below its supplement (the flip pass selects by sine), since a flat cell often
    // goes only with its neighbours.
    lower.max_min_threshold = largest_angle_quality(opt.largest_angle_threshold);
    lower.flips.quality_threshold = dihedral_sine(opt.largest_angle_threshold);
    start_phase(lower);
    run_phase(1);
    if(!out_of_time)
    {
      Smoothing_options polish = opt;
      polish.vertex_insertion = false;
      // Max-min steps at every cell the flip pass works on (not only the worst ones):
      // the phase before pressed many cells down to the smallest angle it started from.
      if(polish.max_min_threshold > 0 && polish.quality_measure == Quality_measure::min_dihedral_sine)
        polish.max_min_threshold = std::max(polish.max_min_threshold, polish.flips.quality_threshold);
      start_phase(polish);
      run_phase(2);
    }
  }
  if(out_of_time) result.code = TIME_LIMIT_REACHED;
  result.moved_vertices = static_cast<std::size_t>(std::count(moved.begin(), moved.end(), 1));
  result.seconds = timer.time();
  return result;
}

} // namespace BODT_3
} // namespace CGAL

#endif // CGAL_BODT_3_INTERNAL_MESH_OPTIMIZER_H
