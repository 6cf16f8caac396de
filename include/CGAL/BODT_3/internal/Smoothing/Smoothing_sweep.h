// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_BODT_3_INTERNAL_SMOOTHING_SMOOTHING_SWEEP_H
#define CGAL_BODT_3_INTERNAL_SMOOTHING_SMOOTHING_SWEEP_H

#include <CGAL/BODT_3/internal/Moves/Boundary_projection.h>
#include <CGAL/BODT_3/internal/Smoothing/Move_guard.h>
#include <CGAL/BODT_3/internal/Moves/Nodt_move.h>
#include <CGAL/BODT_3/internal/Mesh/Flat_mesh.h>
#include <CGAL/BODT_3/Smoothing_options.h>
#include <CGAL/BODT_3/Smoothing_result.h>
#include <CGAL/BODT_3/internal/Classification/Tensor_voting.h>
#include <CGAL/BODT_3/internal/Utilities/Thread_workers.h>
#include <CGAL/BODT_3/internal/Utilities/first_touch.h>
#include <CGAL/BODT_3/internal/Classification/Vertex_classification.h>
#include <CGAL/BODT_3/internal/Moves/Volume_preserving_move.h>
#include <CGAL/BODT_3/internal/Smoothing/sweep_order.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <utility>
#include <vector>

namespace CGAL {
namespace BODT_3 {
namespace internal {

/// Smoothing sweeps over a `Flat_mesh`: every movable vertex, in
/// `sweep_order`, gets its volume-preserving B-ODT move (`Volume_preserving_move`)
/// through `Move_guard` (with NODT, surface vertices get `Nodt_move`, projected on
/// the boundary the mesh had when the sweeps began). After the mesh's cells change (flips, insertion), call
/// `refresh` with the vertices whose stars changed. With a `budget`, moves that may
/// change a subdomain's volume are priced and paid from it (Volume_budget.h); with
/// a `distance` guard, surface vertices stay near the input's surface.
template <class K>
class Smoothing_sweep
{
public:
  using Vector = typename K::Vector_3;

  Smoothing_sweep(Flat_mesh<K>& mesh, const Vertex_classification& classification, const Smoothing_options& opt,
                  const Dihedral_bounds& bounds, Volume_budget* budget = nullptr,
                  const Boundary_distance_guard<K>* distance = nullptr)
    : mesh_(mesh), classification_(classification), opt_(opt),
      guard_(mesh, opt.quality_guard, bounds, opt.quality_measure, opt.threads, budget, distance), budget_(budget),
      workers_(opt.threads), max_min_workers_(opt.threads), dirty_(mesh.number_of_vertices(), 1),
      max_min_failed_(mesh.number_of_vertices(), 0), moved_now_(mesh.number_of_vertices(), 0),
      moved_once_(mesh.number_of_vertices(), 0), cost_(mesh.number_of_vertices(), 0)
  {
    if(opt.smoothing_method == Smoothing_method::NODT) projection_ = std::make_unique<Boundary_projection<K>>(mesh);
    derive();
  }

  /// After the cells of the mesh changed (and `build_incidences` ran), with the
  /// vertices whose stars changed, where the cells went (Flat_view::Cell_moves)
  /// and the vertices that moved outside the sweeps (Move_guard::refresh);
  /// vertices added since are appended to the classification by the caller
  /// before this call.
  template <class Moves>
  void refresh(const std::vector<int>& changed, const Moves& moves, const std::vector<int>& moved)
  {
    dirty_.resize(mesh_.number_of_vertices(), 1);
    max_min_failed_.resize(mesh_.number_of_vertices(), 0);
    moved_now_.resize(mesh_.number_of_vertices(), 0);
    moved_once_.resize(mesh_.number_of_vertices(), 0);
    cost_.resize(mesh_.number_of_vertices(), 0);
    for(int v : changed) dirty_[v] = 1;
    for(int v : changed) max_min_failed_[v] = 0;
    // The dependents' arrays are made again by the next sweep, not here (they keep
    // their pages meanwhile): a phase without sweeps (the worst cells') re-reads
    // after each pass that changes cells and would make them each time for a few
    // lookups.
    derived_ = false;
    for(int v : changed)
      mark_dependents(v);
    wake_max_min(moves, moved);
    guard_.refresh(moves, moved);
  }

  /// While the mesh's incidences are released (a flip pass that reads the
  /// triangulation): the sweep order and the dependents, derived from them, go
  /// too; `refresh`, or `derive` if the cells did not change, makes them again.
  void release_derived()
  {
    order_ = Sweep_order();
    derived_ = false;
    std::vector<int>().swap(dependent_begin_);
    std::vector<int>().swap(dependents_);
  }

  /// One sweep; fills the move counts of `stats`. Colour by colour: vertices of
  /// one colour share no cell and check no hull facet of one another, so their
  /// moves read nothing the others write; they run concurrently (`opt.threads`),
  /// and the result is the same, bit for bit, on any number of threads.
  void run(Iteration_stats& stats)
  {
    if(!derived_) derive();
    if(order_.colour_begin.empty()) order_ = sweep_order(mesh_, movable());
    for(std::size_t k = 0; k + 1 < order_.colour_begin.size(); ++k)
    {
      const int begin = order_.colour_begin[k], end = order_.colour_begin[k + 1];
      if(budget_)
      {
        // The colour's moves that may change a volume share one allowance.
        std::size_t priced = 0;
        for(int i = begin; i < end; ++i)
          priced += dirty_[order_.vertices[i]] && !guard_.keeps_volume(order_.vertices[i]);
        guard_.allow(budget_->allowance(priced));
      }
      workers_.for_each(begin, end, [this](Worker& w, int i) { visit(order_.vertices[i], w); });
      // Then, in the sequential order: what the moves changed, and what they cost.
      for(int i = begin; i < end; ++i)
      {
        const int v = order_.vertices[i];
        if(!moved_now_[v]) continue;
        if(budget_) budget_->spend(cost_[v]);
        moved_now_[v] = 0;
        moved_once_[v] = 1;
        moved_.push_back(v);
        dirty_[v] = 1;
        max_min_failed_[v] = 0;
        mark_dependents(v);
      }
    }
    workers_.each_worker([&stats](Worker& w) {
      const Iteration_stats& c = w.counts;
      stats.moved += c.moved;
      stats.shortened += c.shortened;
      stats.refused += c.refused;
      stats.refused_inverting_mesh_cell += c.refused_inverting_mesh_cell;
      stats.refused_inverting_outside_cell += c.refused_inverting_outside_cell;
      stats.refused_breaking_hull += c.refused_breaking_hull;
      stats.refused_changing_volume += c.refused_changing_volume;
      stats.refused_worsening_quality += c.refused_worsening_quality;
      stats.refused_leaving_surface += c.refused_leaving_surface;
      stats.max_relative_move = std::max(stats.max_relative_move, c.max_relative_move);
      w.counts = Iteration_stats();
    });
  }

  /// The fallback where B-ODT stalls: each movable vertex of a mesh cell whose
  /// quality is below `threshold` takes compass steps (the directions that keep every
  /// subdomain's volume and its feature, `Volume_preserving_move::free_directions`,
  /// both ways, from a fifth of its shortest edge down to a thousandth) that raise
  /// the worst cell of its star, through the guard. Needs the quality guard.
  void raise_worst(double threshold, Iteration_stats& stats)
  {
    if(!opt_.quality_guard) return;
    std::vector<int> vertices;
    for(std::size_t c = 0; c < mesh_.cells.size(); ++c)
      if(mesh_.in_mesh[c] && guard_.cell_quality(static_cast<int>(c)) < threshold)
        vertices.insert(vertices.end(), mesh_.cells[c].begin(), mesh_.cells[c].end());
    std::sort(vertices.begin(), vertices.end());
    vertices.erase(std::unique(vertices.begin(), vertices.end()), vertices.end());
    vertices.erase(std::remove_if(vertices.begin(), vertices.end(),
                                  [this](int v) { return classification_.kind[v] == Vertex_kind::fixed; }),
                   vertices.end());
    // In blocks, in the order of `vertices`: each vertex's search is judged ahead,
    // concurrently, on the mesh as the block starts; then, in order, a search is
    // applied if nothing it read changed since (no vertex it depends on moved, and
    // the budget still allows every step it took), else made again on the mesh as
    // it is. Either way a vertex gets the search the one-by-one order gives it.
    // A vertex whose last search found no step is not searched again until a
    // vertex its search depends on moves or its star changes: the bounds hold for
    // the phase and the budget only shrinks, so it would find none again.
    std::vector<Max_min_search> searches(max_min_block);
    std::vector<char> ahead(max_min_block);
    if(block_of_.size() < mesh_.number_of_vertices()) block_of_.resize(mesh_.number_of_vertices(), no_block);
    for(std::size_t first = 0; first < vertices.size(); first += max_min_block)
    {
      const std::size_t block = blocks_judged_++;
      const int n = static_cast<int>(std::min(max_min_block, vertices.size() - first));
      const double spent = budget_ ? budget_->spent() : 0;
      for(int i = 0; i < n; ++i) ahead[static_cast<std::size_t>(i)] = !max_min_failed_[vertices[first + static_cast<std::size_t>(i)]];
      max_min_workers_.for_each(0, n, [&](Max_min_worker& w, int i) {
        if(ahead[static_cast<std::size_t>(i)])
          search(vertices[first + static_cast<std::size_t>(i)], spent, w, searches[static_cast<std::size_t>(i)]);
      }, 1);
      for(int i = 0; i < n; ++i)
      {
        const int v = vertices[first + static_cast<std::size_t>(i)];
        if(max_min_failed_[v]) continue;
        ++stats.max_min_searches;
        Max_min_search& found = searches[static_cast<std::size_t>(i)];
        if(!ahead[static_cast<std::size_t>(i)] || block_of_[v] == block || !still_affordable(found))
          search(v, budget_ ? budget_->spent() : 0, max_min_again_, found);
        if(found.costs.empty())
        {
          max_min_failed_[v] = 1;
          continue;
        }
        guard_.apply(v, found.position, found.qualities);
        if(budget_)
          for(double cost : found.costs) budget_->spend(cost);
        ++stats.max_min_moves;
        moved_.push_back(v);
        moved_once_[v] = 1;
        dirty_[v] = 1;
        for_each_dependent(v, [this, block](int w) {
          dirty_[w] = 1;
          max_min_failed_[w] = 0;
          block_of_[w] = block;
        });
      }
    }
  }

  /// The quality of cell `c` now (kept up to date by the quality guard; meaningless without it).
  double cell_quality(int c) const { return guard_.cell_quality(c); }

  /// The vertices moved since the last `forget_moves`.
  const std::vector<int>& moved() const { return moved_; }
  void forget_moves() { moved_.clear(); }

  /// Whether vertex `v` moved so far.
  bool has_moved(int v) const { return moved_once_[v] != 0; }

  /// Derives, per vertex, the vertices whose move depends on it (and drops the
  /// sweep order, which the next sweep makes again): a vertex whose last move was
  /// zero, frozen or refused gets the same verdict again until a vertex of its
  /// star, or the far vertex of one of its hull checks, moves; such vertices are
  /// skipped, which changes no result.
  void derive()
  {
    const int nv = static_cast<int>(mesh_.number_of_vertices());
    const std::vector<char> movable = this->movable();
    // The order is made by the next sweep too.
    order_ = Sweep_order();
    // The vertices to revisit when u moves: the movable vertices sharing a cell
    // with u, and those with a hull check whose far vertex is u. Flat (one array
    // for all): derived again by the first sweep after a change of the cells.
    // Counted first, then written, each vertex's on any thread (a stamp array per
    // thread): grown by push_back, the array reached up to twice its size.
    auto for_dependents = [&](std::vector<int>& stamp, int u, const auto& f) {
      if(stamp.empty()) stamp.assign(static_cast<std::size_t>(nv), -1);
      auto add = [&](int w) {
        if(w == u || !movable[w] || stamp[w] == u) return;
        stamp[w] = u;
        f(w);
      };
      for(int k = mesh_.incidence_begin[u]; k < mesh_.incidence_begin[u + 1]; ++k)
        for(int w : mesh_.incidences[k].face) add(w);
      for(int k = mesh_.checked_begin[u]; k < mesh_.checked_begin[u + 1]; ++k) add(mesh_.checked_by[k]);
    };
    dependent_begin_.assign(nv + 1, 0);
    Thread_workers<std::vector<int>>(workers_.threads()).for_each(0, nv, [&](std::vector<int>& stamp, int u) {
      int count = 0;
      for_dependents(stamp, u, [&count](int) { ++count; });
      dependent_begin_[u + 1] = count;
    }, 1024);
    for(int u = 0; u < nv; ++u) dependent_begin_[u + 1] += dependent_begin_[u];
    // With room for a few more: after a pass that changed a few cells, the array
    // keeps its pages (fresh ones cost more than deriving it, on a virtual machine).
    const std::size_t total = static_cast<std::size_t>(dependent_begin_[nv]);
    reserve_fresh(dependents_, with_room(total), workers_.threads());
    dependents_.resize(total);
    Thread_workers<std::vector<int>>(workers_.threads()).for_each(0, nv, [&](std::vector<int>& stamp, int u) {
      int next = dependent_begin_[u];
      for_dependents(stamp, u, [&](int w) { dependents_[next++] = w; });
    }, 1024);
    derived_ = true;
  }

private:
  // The direction of the curve through a feature vertex: the chord of its two
  // curve neighbours, or tensor voting's where the curve is not known (zero for
  // other vertices). The neighbours share a cell with it (the colouring relies on it).
  Vector feature_direction(int v, const Vertex_star<K>& star) const
  {
    if(classification_.kind[v] != Vertex_kind::feature) return Vector(0, 0, 0);
    const auto& nb = classification_.curve_neighbors[v];
    return nb[0] >= 0 ? mesh_.points[nb[1]] - mesh_.points[nb[0]] : tensor_vote(star, opt_.tensor_voting).direction;
  }

  // What one thread keeps: its scratch space and its counts of the sweep.
  struct Worker
  {
    Vertex_star<K> star;
    typename Move_guard<K>::Trial trial;
    Iteration_stats counts;
  };

  // One vertex's move; writes only the vertex, the qualities of its star's cells,
  // its own flags and the worker.
  void visit(int v, Worker& w)
  {
    if(!dirty_[v]) return;
    dirty_[v] = 0;
    Vertex_star<K>& star = w.star;
    Iteration_stats& stats = w.counts;
    const Vertex_kind kind = classification_.kind[v];
    mesh_.gather_star(v, star);
    const bool natural = projection_ && kind == Vertex_kind::surface;
    const Vector X = natural ? Nodt_move()(star) : mover_(star, kind, feature_direction(v, star));
    if(X == CGAL::NULL_VECTOR) return;
    double volume = 0;
    for(const auto& c : star.cells) volume += CGAL::determinant(c.a - star.x0, c.b - star.x0, c.c - star.x0);
    const double size = std::cbrt(volume / 6.0 / static_cast<double>(star.cells.size()));
    // Frozen: too short a move to be worth its cost; a neighbour's move wakes it.
    if(X.squared_length() < opt_.freeze_bound * opt_.freeze_bound * size * size) return;
    const double fraction = natural ? guard_.move(v, X, *projection_, w.trial) : guard_.move(v, X, w.trial);
    if(fraction == 0)
    {
      ++stats.refused;
      using Refusal = typename Move_guard<K>::Refusal;
      switch(w.trial.first_refusal)
      {
      case Refusal::inverts_mesh_cell: ++stats.refused_inverting_mesh_cell; break;
      case Refusal::inverts_outside_cell: ++stats.refused_inverting_outside_cell; break;
      case Refusal::breaks_convex_hull: ++stats.refused_breaking_hull; break;
      case Refusal::changes_volume: ++stats.refused_changing_volume; break;
      case Refusal::worsens_quality: ++stats.refused_worsening_quality; break;
      case Refusal::leaves_surface: ++stats.refused_leaving_surface; break;
      }
      return;
    }
    ++stats.moved;
    if(fraction < 1) ++stats.shortened;
    moved_now_[v] = 1;
    cost_[v] = w.trial.cost;
    stats.max_relative_move = std::max(stats.max_relative_move, fraction * std::sqrt(X.squared_length()) / size);
  }

  // Vertices whose max-min searches are judged together: enough to keep the
  // threads busy, few enough that the searches seldom read what another moved
  // (on eight_0.2M, largest-angle phase, one thread: 17% of the searches made
  // again with 256, 9% with 64, 4% with 16; the steps took 0.72, 0.65 and 0.62 s
  // with 256, 64 and 32, against 0.64 one by one; 0.35 s on two threads with 32).
  static constexpr std::size_t max_min_block = 32;

  // What a vertex's max-min search found: its steps' costs (none: it stays), its
  // last position and the qualities of its star's mesh cells there, and per
  // stretch between steps the largest cost the budget let through.
  struct Max_min_search
  {
    std::vector<double> costs;
    std::vector<double> passed;   // one more than `costs`
    typename K::Point_3 position;
    std::vector<double> qualities;
  };

  // A thread's scratch space for the searches.
  struct Max_min_worker
  {
    Vertex_star<K> star;
    typename Move_guard<K>::Trial trial, best;
  };

  // The max-min search of vertex v, on the mesh as it is, with `spent` of the
  // budget spent, written to `out` and not to the mesh: a compass search along
  // the vertex's free directions, from a fifth of its shortest edge, halving the
  // step when no direction raises the worst cell of its star.
  void search(int v, double spent, Max_min_worker& w, Max_min_search& out) const
  {
    // Each accepted step raises the star's worst cell, but by as little as it
    // likes: with the largest angle as the measure, some vertices zigzag at the
    // smallest step for thousands of steps (the small generated sharp_part). At
    // most this many rounds (a step or a halving) per vertex and call.
    constexpr int max_min_steps = 200;
    using Refusal = typename Move_guard<K>::Refusal;
    out.costs.clear();
    out.passed.assign(1, 0.0);
    Vector dirs[3];
    mesh_.gather_star(v, w.star);
    const int n = mover_.free_directions(w.star, classification_.kind[v], feature_direction(v, w.star), dirs);
    if(n == 0) return;
    double shortest = std::numeric_limits<double>::infinity();
    for(const auto& c : w.star.cells)
      for(const auto* p : {&c.a, &c.b, &c.c}) shortest = std::min(shortest, CGAL::squared_distance(w.star.x0, *p));
    shortest = std::sqrt(shortest);
    typename Move_guard<K>::Vertex_state state{mesh_.points[v], guard_.worst_around(v), 0.0};
    int steps = 0;
    for(double h = 0.2 * shortest; h > 1e-3 * shortest && steps < max_min_steps; ++steps)
    {
      state.allowance = budget_ ? budget_->allowance_at(spent) : guard_.allowance();
      typename K::Point_3 best;
      double best_worst = state.worst;
      for(int d = 0; d < n; ++d)
        for(double sign : {1.0, -1.0})
        {
          const typename K::Point_3 p = state.position + (sign * h) * dirs[d];
          const bool accepted = guard_.accepts_from(v, state, p, w.trial);
          if(accepted || w.trial.last_refusal == Refusal::worsens_quality ||
             w.trial.last_refusal == Refusal::leaves_surface)   // the budget let it through
            out.passed.back() = std::max(out.passed.back(), w.trial.cost);
          if(accepted && Move_guard<K>::accepted_worst(w.trial) > best_worst)
          {
            best_worst = Move_guard<K>::accepted_worst(w.trial);
            best = p;
            std::swap(w.best, w.trial);
          }
        }
      if(best_worst > state.worst)
      {
        state.position = best;
        state.worst = best_worst;
        spent += w.best.cost;
        out.costs.push_back(w.best.cost);
        out.passed.push_back(0.0);
        out.position = best;
        out.qualities = w.best.qualities;
      }
      else
        h *= 0.5;
    }
  }

  // Whether the budget, as spent now, still lets through every step of a search
  // judged ahead (it only shrinks as it is spent: a refused step stays refused).
  bool still_affordable(const Max_min_search& found) const
  {
    if(!budget_) return true;
    double spent = budget_->spent();
    for(std::size_t k = 0; k < found.passed.size(); ++k)
    {
      if(found.passed[k] > budget_->allowance_at(spent)) return false;
      if(k < found.costs.size()) spent += found.costs[k];
    }
    return true;
  }

  std::vector<char> movable() const
  {
    std::vector<char> m(mesh_.number_of_vertices());
    for(std::size_t v = 0; v < m.size(); ++v) m[v] = classification_.kind[v] != Vertex_kind::fixed;
    return m;
  }

  // Before the guard's refresh: a max-min search may find a step again around a
  // vertex moved on the triangulation (an insertion's smoothing), and in a cell
  // the guard measures again (its quality may round otherwise than when `apply`
  // measured it, and the search compares qualities to the last bit).
  template <class Moves>
  void wake_max_min(const Moves& moves, const std::vector<int>& moved)
  {
    if(moves.whole)
    {
      std::fill(max_min_failed_.begin(), max_min_failed_.end(), 0);
      return;
    }
    for(int v : moved)
    {
      max_min_failed_[v] = 0;
      for_each_dependent(v, [this](int w) { max_min_failed_[w] = 0; });
    }
    for(int c : moves.fresh)
      for(int v : mesh_.cells[c]) max_min_failed_[v] = 0;
    for(const auto& q : mesh_.cells)
      if(guard_.moved_since_refresh(q[0]) || guard_.moved_since_refresh(q[1]) || guard_.moved_since_refresh(q[2]) ||
         guard_.moved_since_refresh(q[3]))
        for(int v : q) max_min_failed_[v] = 0;
  }

  void mark_dependents(int v)
  {
    for_each_dependent(v, [this](int w) {
      dirty_[w] = 1;
      max_min_failed_[w] = 0;
    });
  }

  // The vertices whose move depends on v's position (see `derive`), from the
  // derived arrays when they are there, else from the incidences (a vertex may
  // then come more than once).
  template <class F>
  void for_each_dependent(int v, const F& f) const
  {
    if(derived_)
    {
      for(int k = dependent_begin_[v]; k < dependent_begin_[v + 1]; ++k) f(dependents_[k]);
      return;
    }
    auto add = [&](int w) {
      if(w != v && classification_.kind[w] != Vertex_kind::fixed) f(w);
    };
    for(int k = mesh_.incidence_begin[v]; k < mesh_.incidence_begin[v + 1]; ++k)
      for(int w : mesh_.incidences[k].face) add(w);
    for(int k = mesh_.checked_begin[v]; k < mesh_.checked_begin[v + 1]; ++k) add(mesh_.checked_by[k]);
  }

  Flat_mesh<K>& mesh_;
  const Vertex_classification& classification_;
  const Smoothing_options& opt_;
  Move_guard<K> guard_;
  Volume_budget* budget_;   // null: volume not priced
  Thread_workers<Worker> workers_;
  Thread_workers<Max_min_worker> max_min_workers_;
  Max_min_worker max_min_again_;   // for the searches made again, in order
  // Per vertex, the last max-min block (numbered over the run) in which a vertex
  // its search depends on moved.
  static constexpr std::size_t no_block = std::numeric_limits<std::size_t>::max();
  std::vector<std::size_t> block_of_;
  std::size_t blocks_judged_ = 0;
  Volume_preserving_move mover_;
  std::unique_ptr<Boundary_projection<K>> projection_;   // NODT: the input's boundary
  Sweep_order order_;
  std::vector<int> dependent_begin_;   // per vertex, into dependents_
  std::vector<int> dependents_;
  bool derived_ = false;   // whether they are those of the cells now
  std::vector<char> dirty_;
  std::vector<char> max_min_failed_;   // the last max-min search found no step, and nothing it reads changed since
  std::vector<char> moved_now_;   // moved in the colour being swept
  std::vector<char> moved_once_;
  std::vector<double> cost_;   // of each vertex's move in the colour being swept
  std::vector<int> moved_;
};

} // namespace internal
} // namespace BODT_3
} // namespace CGAL

#endif // CGAL_BODT_3_INTERNAL_SMOOTHING_SMOOTHING_SWEEP_H
