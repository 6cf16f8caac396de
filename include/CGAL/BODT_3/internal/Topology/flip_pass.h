// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_BODT_3_INTERNAL_TOPOLOGY_FLIP_PASS_H
#define CGAL_BODT_3_INTERNAL_TOPOLOGY_FLIP_PASS_H

#include <CGAL/BODT_3/Smoothing_options.h>
#include <CGAL/BODT_3/Smoothing_result.h>
#include <CGAL/BODT_3/internal/Topology/Edge_removal.h>
#include <CGAL/BODT_3/internal/Topology/Flip.h>
#include <CGAL/BODT_3/internal/Topology/Multi_face_removal.h>
#include <CGAL/BODT_3/internal/Utilities/Attempt_history.h>
#include <CGAL/BODT_3/internal/Utilities/Candidate_cell.h>
#include <CGAL/BODT_3/internal/Utilities/Id_tuple_map.h>

#include <CGAL/Real_timer.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <functional>
#include <initializer_list>
#include <limits>
#include <queue>
#include <vector>

namespace CGAL {
namespace BODT_3 {
namespace internal {

/// One topology pass: the cells whose minimum dihedral sine is below the quality
/// threshold, worst first by `measure`, each get the best of the edge removals of
/// their six edges and the multi-face removals rooted at their four faces, if it
/// raises the worst quality (by `measure`) of the cells it replaces; new cells
/// below the threshold are tried again. Every accepted flip strictly raises the
/// worst cell of its region, so the pass ends. The order depends only on the mesh
/// (ties are broken by `vertex_id`, stable ids of the vertices), so the same input
/// gives the same output.
template <class Adapter>
class Flip_pass
{
public:
  using Vertex_handle = typename Adapter::Vertex_handle;
  using Cell_handle = typename Adapter::Cell_handle;
  using Candidate = Candidate_cell<Cell_handle, Vertex_handle>;

  Flip_pass(Adapter& adapter, const Flip_options& opt, const Dihedral_bounds& bounds, Quality_measure measure)
    : adapter_(adapter), opt_(opt), measure_(measure), ctx_(adapter, bounds, opt.flip_outside, measure)
  {
    edge_removal_.max_ring = opt.max_ring;
    face_removal_.max_faces = opt.max_faces;
  }

  /// Runs the pass; see `flip_pass` for the arguments.
  template <class Vertex_id>
  Topology_stats operator()(const Vertex_id& vertex_id, std::vector<Vertex_handle>& touched,
                            Attempt_history* history, const std::vector<Candidate>* start)
  {
    CGAL::Real_timer timer;
    timer.start();
    std::priority_queue<Candidate> queue = start_queue(vertex_id, start);
    Topology_stats stats;
    const std::size_t max_flips = 4 * adapter_.tds().number_of_cells() + 16;   // O(1), unlike counting finite cells
    while(!queue.empty() && stats.total() < max_flips)
    {
      const Candidate e = queue.top();
      queue.pop();
      // The history first: it does not read the cell, which is anywhere in memory.
      if(history && !history->worth_trying(e.ids)) continue;
      if(!e.still_there(adapter_.tds())) continue;   // replaced since it was queued
      if(!find_best_flip(e.cell, vertex_id) || !apply_best_flip())
      {
        if(history) history->record_failure(e.ids);
        continue;
      }
      count(stats);
      if(history) ++history->clock;
      ++flips_done_;
      mark_touched(vertex_id, touched, history);
      for(Cell_handle n : created_)
        if(!adapter_.triangulation().is_infinite(n))
          if(const std::optional<Candidate> c = candidate(n, vertex_id)) queue.push(*c);
    }
    stats.seconds = timer.time();
    return stats;
  }

private:
  // The candidate of cell c, if it is flippable and below the threshold (by its sine).
  template <class Vertex_id>
  std::optional<Candidate> candidate(Cell_handle c, const Vertex_id& vertex_id) const
  {
    if(!ctx_.flippable(adapter_.region(c))) return std::nullopt;
    const double q = ctx_.quality(c);
    const double sine = measure_ == Quality_measure::min_dihedral_sine
                            ? q
                            : min_dihedral_sine(ctx_.point(c->vertex(0)), ctx_.point(c->vertex(1)),
                                                ctx_.point(c->vertex(2)), ctx_.point(c->vertex(3)));
    if(!(sine < opt_.quality_threshold)) return std::nullopt;
    return Candidate::of(c, q, vertex_id);
  }

  // The starting cells: those given, or every finite cell measured; a heap in linear time.
  template <class Vertex_id>
  std::priority_queue<Candidate> start_queue(const Vertex_id& vertex_id, const std::vector<Candidate>* given) const
  {
    CGAL_precondition(!given || measure_ == Quality_measure::min_dihedral_sine);
    std::vector<Candidate> start;
    if(given)
    {
      for(const Candidate& m : *given)
      {
        CGAL_assertion(ctx_.flippable(adapter_.region(m.cell)));
        if(m.quality < opt_.quality_threshold) start.push_back(m);
      }
    }
    else
    {
      auto& tr = adapter_.triangulation();
      for(auto c = tr.finite_cells_begin(); c != tr.finite_cells_end(); ++c)
        if(const std::optional<Candidate> e = candidate(c, vertex_id)) start.push_back(*e);
    }
    return std::priority_queue<Candidate>(std::less<Candidate>(), std::move(start));
  }

  // The best improving flip of cell c, in `best_`: edge removals of its six edges,
  // multi-face removals at its four faces. Within the pass geometry is fixed, so an
  // edge or a face found useless stays so until a flip touches its vertices.
  template <class Vertex_id>
  bool find_best_flip(Cell_handle c, const Vertex_id& vertex_id)
  {
    std::array<int, 4> id;   // the ids of c's vertices in c's order: looked up once
    for(int k = 0; k < 4; ++k) id[k] = vertex_id(c->vertex(k));
    best_.clear();
    auto consider = [&]() {
      if(candidate_.improves() && candidate_.new_worst > best_.new_worst) std::swap(best_, candidate_);
    };
    for(int i = 0; i < 4; ++i)
      for(int j = i + 1; j < 4; ++j)
      {
        const std::array<int, 2> key{std::min(id[i], id[j]), std::max(id[i], id[j])};
        const std::size_t* known = useless_edges_.find(key);
        if(known && still_useless(*known, {id[i], id[j]})) continue;
        // Only the best proposal for this cell counts: what cannot beat the best so
        // far is cut short, and then says nothing about the edge's own worth.
        const double at_least = best_.improves() ? best_.new_worst : -std::numeric_limits<double>::infinity();
        if(edge_removal_(ctx_, c, i, j, candidate_, at_least) && candidate_.improves())
          consider();
        else if(!best_.improves() || candidate_.old_worst >= at_least)
          useless_edges_.assign(key, flips_done_);
      }
    for(int i = 0; i < 4; ++i)
    {
      const Cell_handle n = c->neighbor(i);
      const Vertex_handle apex = n->vertex(n->index(c));
      if(adapter_.triangulation().is_infinite(apex)) continue;
      std::array<int, 4> key;   // the face's ids sorted, then the smaller apex
      for(int k = 0, m = 0; k < 4; ++k)
        if(k != i) key[m++] = id[k];
      std::sort(key.begin(), key.begin() + 3);
      const int apex_id = vertex_id(apex);
      key[3] = std::min(apex_id, id[i]);
      const std::size_t* known = useless_faces_.find(key);
      if(known && still_useless(*known, {id[0], id[1], id[2], id[3], apex_id})) continue;
      if(face_removal_(ctx_, c, i, candidate_) && candidate_.improves())
        consider();
      else
        useless_faces_.assign(key, flips_done_);
    }
    return best_.improves();
  }

  bool apply_best_flip()
  {
    created_.clear();
    return replace_cells(adapter_, best_.old_cells, best_.new_cells, best_.new_facets, &created_);
  }

  void count(Topology_stats& stats) const
  {
    switch(best_.kind)
    {
    case Flip_kind::flip_2_3: ++stats.flips_2_3; break;
    case Flip_kind::flip_3_2: ++stats.flips_3_2; break;
    case Flip_kind::edge_removal: ++stats.edge_removals; break;
    case Flip_kind::multi_face_removal: ++stats.multi_face_removals; break;
    }
    if(best_.boundary) ++stats.boundary_flips;
  }

  // The vertices of the created cells: their stars changed.
  template <class Vertex_id>
  void mark_touched(const Vertex_id& vertex_id, std::vector<Vertex_handle>& touched, Attempt_history* history)
  {
    for(Cell_handle n : created_)
      for(int k = 0; k < 4; ++k)
      {
        touched.push_back(n->vertex(k));
        if(adapter_.triangulation().is_infinite(n->vertex(k))) continue;
        const int id = vertex_id(n->vertex(k));
        if(id >= static_cast<int>(touched_at_.size())) touched_at_.resize(id + 1, 0);
        touched_at_[id] = flips_done_;
        if(history) history->star_changed(id);
      }
  }

  // Whether no flip touched the (finite) vertices with these ids since `when`.
  bool still_useless(std::size_t when, std::initializer_list<int> ids) const
  {
    for(int id : ids)
      if(id < static_cast<int>(touched_at_.size()) && touched_at_[id] > when) return false;
    return true;
  }

  Adapter& adapter_;
  const Flip_options& opt_;
  Quality_measure measure_;
  const Flip_context<Adapter> ctx_;
  Edge_removal<Adapter> edge_removal_;
  Multi_face_removal<Adapter> face_removal_;
  Flip<Adapter> candidate_, best_;
  std::vector<Cell_handle> created_;
  Id_tuple_map<2, std::size_t> useless_edges_;
  Id_tuple_map<4, std::size_t> useless_faces_;   // face ids and apex
  std::vector<std::size_t> touched_at_;          // per vertex id: flips done when a flip last touched it
  std::size_t flips_done_ = 0;
};

/// One flip pass (`Flip_pass`) on the triangulation behind `adapter`.
///
/// `touched` receives the vertices of every cell created (with repetitions).
/// `history` (optional) lets the pass skip cells tried in vain before whose
/// neighbourhood has not changed since. `candidates` (optional, with the minimum
/// dihedral sine as measure) are the cells to start from, flippable and measured,
/// a superset of the flippable cells below the threshold (the caller may know
/// them without measuring every cell); by default every finite cell is measured.
/// The result does not depend on which superset is given.
template <class Adapter, class Vertex_id>
Topology_stats flip_pass(Adapter& adapter, const Flip_options& opt, const Dihedral_bounds& bounds,
                         const Vertex_id& vertex_id, std::vector<typename Adapter::Vertex_handle>& touched,
                         Attempt_history* history = nullptr,
                         Quality_measure measure = Quality_measure::min_dihedral_sine,
                         const std::vector<Candidate_cell<typename Adapter::Cell_handle,
                                                          typename Adapter::Vertex_handle>>* candidates = nullptr)
{
  return Flip_pass<Adapter>(adapter, opt, bounds, measure)(vertex_id, touched, history, candidates);
}

} // namespace internal
} // namespace BODT_3
} // namespace CGAL

#endif // CGAL_BODT_3_INTERNAL_TOPOLOGY_FLIP_PASS_H
