// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_BODT_3_INTERNAL_TOPOLOGY_CONTRACTION_PASS_H
#define CGAL_BODT_3_INTERNAL_TOPOLOGY_CONTRACTION_PASS_H

#include <CGAL/BODT_3/Smoothing_options.h>
#include <CGAL/BODT_3/Smoothing_result.h>
#include <CGAL/BODT_3/internal/Topology/Edge_contraction.h>
#include <CGAL/BODT_3/internal/Topology/flip_pass.h>
#include <CGAL/BODT_3/internal/Topology/replace_cells.h>
#include <CGAL/BODT_3/internal/Utilities/Attempt_history.h>

#include <CGAL/Real_timer.h>

#include <cstddef>
#include <optional>
#include <vector>

namespace CGAL {
namespace BODT_3 {
namespace internal {

/// One edge-contraction pass: the cells a flip pass with options `opt` would
/// select (`flip_selection_quality` below `opt.quality_threshold`), worst first by
/// `measure`, each get the best contraction of one of their vertices onto another
/// (`Edge_contraction`), if it raises the worst mesh cell around the removed
/// vertex; new cells below the threshold are tried in turn. `may_remove(v)` says
/// which vertices may go (by their classification); at most `budget` go.
///
/// One thread: the order depends on the mesh alone (ties by `vertex_id`), so the
/// result does not depend on the threads of the rest of the run. Every accepted
/// contraction removes a vertex, so the pass ends.
///
/// `removed` receives the ids (`vertex_id`, taken before the vertex goes) of the
/// removed vertices, `touched` the vertices of every created cell. `history`
/// (optional) skips cells tried in vain whose neighbourhood has not changed;
/// `start` (optional, as for `flip_pass`) are the cells the pass may start from,
/// taken over; by default every finite cell is measured.
template <class Adapter, class May_remove, class Vertex_id>
Contraction_stats contraction_pass(Adapter& adapter, const Flip_options& opt, const Dihedral_bounds& bounds,
                                   Quality_measure measure, std::size_t budget, const May_remove& may_remove,
                                   const Vertex_id& vertex_id, std::vector<int>& removed,
                                   std::vector<typename Adapter::Vertex_handle>& touched, Attempt_history* history,
                                   std::vector<Flip_candidate<typename Adapter::Cell_handle>>* start = nullptr)
{
  using Cell_handle = typename Adapter::Cell_handle;
  using Vertex_handle = typename Adapter::Vertex_handle;
  using Candidate = Flip_candidate<Cell_handle>;
  CGAL::Real_timer timer;
  timer.start();
  Contraction_stats stats;
  const Flip_context<Adapter> ctx(adapter, bounds, opt.flip_outside, measure);
  auto& tr = adapter.triangulation();

  auto candidate = [&](Cell_handle c) -> std::optional<Candidate> {
    if(!ctx.flippable(adapter.region(c))) return std::nullopt;
    const double q = ctx.quality(c);
    if(!(flip_selection_quality(measure, q, ctx.point(c->vertex(0)), ctx.point(c->vertex(1)),
                                ctx.point(c->vertex(2)), ctx.point(c->vertex(3))) < opt.quality_threshold))
      return std::nullopt;
    return Candidate::of(c, q, vertex_id);
  };
  std::vector<Candidate> first;
  if(start)
  {
    first.swap(*start);
    first.erase(std::remove_if(first.begin(), first.end(), [&](const Candidate& m) { return !candidate(m.cell); }),
                first.end());
  }
  else
    for(auto c = tr.finite_cells_begin(); c != tr.finite_cells_end(); ++c)
      if(const std::optional<Candidate> e = candidate(c)) first.push_back(*e);
  Candidate_queue<Candidate> queue(std::move(first));

  const Edge_contraction<Adapter> contraction;
  Flip<Adapter> best, proposal;
  std::vector<Cell_handle> created;
  while(!queue.empty() && stats.contractions < budget)
  {
    const Candidate e = queue.pop();
    if(history && !history->worth_trying(e.ids)) continue;
    if(!e.still_there(tr, vertex_id)) continue;
    best.clear();
    for(int i = 0; i < 4; ++i)
    {
      const Vertex_handle u = e.cell->vertex(i);
      if(!may_remove(u)) continue;
      for(int j = 0; j < 4; ++j)
      {
        if(j == i) continue;
        const double at_least = best.improves() ? best.new_worst : -std::numeric_limits<double>::infinity();
        if(contraction(ctx, u, e.cell->vertex(j), proposal, at_least) && proposal.improves() &&
           proposal.new_worst > best.new_worst)
          std::swap(best, proposal);
      }
    }
    const int removed_id = best.improves() ? vertex_id(best.removed) : -1;
    created.clear();
    if(!best.improves() ||
       !replace_cells(adapter, best.old_cells, best.new_cells, best.new_facets, &created, nullptr, {best.removed}))
    {
      if(history) history->record_failure(e.ids);
      continue;
    }
    ++stats.contractions;
    if(best.boundary) ++stats.boundary_contractions;
    removed.push_back(removed_id);
    if(history) ++history->clock;
    for(Cell_handle n : created)
      for(int k = 0; k < 4; ++k)
      {
        touched.push_back(n->vertex(k));
        if(history && !tr.is_infinite(n->vertex(k))) history->star_changed(vertex_id(n->vertex(k)));
      }
    for(Cell_handle n : created)
      if(!tr.is_infinite(n))
        if(const std::optional<Candidate> c = candidate(n)) queue.push(*c);
  }
  stats.seconds = timer.time();
  return stats;
}

} // namespace internal
} // namespace BODT_3
} // namespace CGAL

#endif // CGAL_BODT_3_INTERNAL_TOPOLOGY_CONTRACTION_PASS_H
