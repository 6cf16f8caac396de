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
#include <CGAL/BODT_3/internal/Utilities/Candidate_queue.h>
#include <CGAL/BODT_3/internal/Utilities/Id_tuple_map.h>
#include <CGAL/BODT_3/internal/Utilities/Thread_workers.h>
#include <CGAL/BODT_3/internal/Utilities/prefetch.h>

#include <CGAL/Real_timer.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <vector>

namespace CGAL {
namespace BODT_3 {
namespace internal {

/// The quality by which a flip pass selects its cells, given the cell's quality
/// `q` by the pass's measure: the minimum dihedral sine, which is `q` when that is
/// the measure. With the largest angle as the measure, a cell with a small angle
/// is selected too: a flat cell often goes only with its neighbours.
template <class Point>
double flip_selection_quality(Quality_measure measure, double q, const Point& p0, const Point& p1, const Point& p2,
                              const Point& p3)
{
  if(measure == Quality_measure::min_dihedral_sine) return q;
  return min_dihedral_sine(p0, p1, p2, p3);
}

/// A cell a flip pass will try, as it was when it was queued: its quality by the
/// pass's measure, its vertex ids sorted (the key of the attempt history, and
/// what breaks ties, so that the order depends on the mesh alone) and its handle.
/// 32 bytes, half a `Candidate_cell` (which keeps the vertex handles as well): on
/// a Mesh_3 mesh nearly every cell is queued in the largest-angle phase's first pass.
template <class Cell_handle>
struct Flip_candidate
{
  double quality;
  std::array<int, 4> ids;   // sorted
  Cell_handle cell;

  /// The candidate of cell `c`, of quality `quality`; `vertex_id(v)` gives the ids.
  template <class Vertex_id>
  static Flip_candidate of(Cell_handle c, double quality, const Vertex_id& vertex_id)
  {
    Flip_candidate e{quality, {}, c};
    for(int k = 0; k < 4; ++k) e.ids[k] = vertex_id(c->vertex(k));
    std::sort(e.ids.begin(), e.ids.end());
    return e;
  }

  /// "Tried after": the worse cell goes first, ties by ids, so that a max-heap
  /// pops the worst first.
  bool operator<(const Flip_candidate& o) const
  {
    if(quality != o.quality) return quality > o.quality;
    return ids > o.ids;
  }

  /// Whether the cell is still in triangulation `tr` with the same vertices: a
  /// flip may have replaced it, and a new cell may live where it was.
  template <class Tr, class Vertex_id>
  bool still_there(const Tr& tr, const Vertex_id& vertex_id) const
  {
    if(!tr.tds().cells().is_used(cell)) return false;
    std::array<int, 4> now;
    for(int k = 0; k < 4; ++k)
    {
      if(tr.is_infinite(cell->vertex(k))) return false;
      now[k] = vertex_id(cell->vertex(k));
    }
    std::sort(now.begin(), now.end());
    return same_ids(now, ids);
  }
};

/// One topology pass: the cells whose quality is below the threshold
/// (`flip_selection_quality`), worst first by `measure`, each get the best of the
/// edge removals of their six edges and the multi-face removals rooted at their
/// four faces, if it raises the worst quality (by `measure`) of the cells it
/// replaces; new cells below the threshold are tried in turn. Every accepted flip
/// strictly raises the worst cell of its region, so the pass ends.
///
/// The cells are taken in rounds: the next `round_size` cells worth trying, in
/// the queue's order, are evaluated concurrently on the triangulation as it is
/// when the round starts (the dynamic programs and the candidate cells' qualities
/// are where the time goes; nothing is written), then their flips are applied in
/// the same order on one thread. A flip whose cells an earlier flip of the round
/// replaced, or a cell whose neighbourhood an earlier flip changed, goes back into
/// the queue. The order depends only on the mesh (ties are broken by `vertex_id`,
/// stable ids of the vertices) and the round size, never on the threads: the same
/// input gives the same output on any number of threads.
template <class Adapter>
class Flip_pass
{
public:
  using Vertex_handle = typename Adapter::Vertex_handle;
  using Cell_handle = typename Adapter::Cell_handle;
  using Candidate = Flip_candidate<Cell_handle>;

  /// Cells evaluated together: enough to keep two to eight threads busy, few
  /// enough that a round's flips seldom meet (measured in doc/scaling.md).
  static constexpr std::size_t round_size = 256;

  Flip_pass(Adapter& adapter, const Flip_options& opt, const Dihedral_bounds& bounds, Quality_measure measure,
            int threads)
    : adapter_(adapter), opt_(opt), measure_(measure), ctx_(adapter, bounds, opt.flip_outside, measure),
      evaluators_(threads)
  {}

  /// Runs the pass; see `flip_pass` for the arguments.
  template <class Vertex_id>
  Topology_stats operator()(const Vertex_id& vertex_id, std::vector<Vertex_handle>& touched,
                            Attempt_history* history, std::vector<Candidate>* start)
  {
    CGAL::Real_timer timer;
    timer.start();
    Candidate_queue<Candidate> queue = start_queue(vertex_id, start, history);
    Topology_stats stats;
    const std::size_t max_flips = 4 * adapter_.tds().number_of_cells() + 16;   // O(1), unlike counting finite cells
    std::vector<Candidate> round;
    while(!queue.empty() && stats.total() < max_flips)
    {
      round.clear();
      while(!queue.empty() && round.size() < round_size)
      {
        const Candidate e = queue.pop();
        // The history first: it does not read the cell, which is anywhere in memory.
        if(history && !history->worth_trying(e.ids)) continue;
        if(e.still_there(adapter_.triangulation(), vertex_id)) round.push_back(e);   // else replaced since queued
      }
      evaluate(round, vertex_id);
      const Flip_count round_start = flips_done_;
      for(std::size_t k = 0; k < round.size() && stats.total() < max_flips; ++k)
      {
        Evaluation& ev = evaluations_[k];
        if(touched_since(round_start, ev.neighbourhood))
        {
          queue.push(round[k]);   // judged on cells an earlier flip of the round replaced
          continue;
        }
        record_useless(ev, round_start);
        if(!ev.best.improves())
        {
          if(history) history->record_failure(round[k].ids);
          continue;
        }
        if(!apply(ev.best))
        {
          if(history) history->record_failure(round[k].ids);
          continue;
        }
        count(ev.best, stats);
        if(history) ++history->clock;
        ++flips_done_;
        mark_touched(vertex_id, touched, history);
        for(Cell_handle n : created_)
          if(!adapter_.triangulation().is_infinite(n))
            if(const std::optional<Candidate> c = candidate(n, vertex_id)) queue.push(*c);
      }
    }
    stats.seconds = timer.time();
    return stats;
  }

private:
  // Flips done in the pass, at most `max_flips`: 32 bits keep the maps of what
  // was found useless at 12 and 16 bytes a slot (up to a billion cells).
  using Flip_count = std::uint32_t;

  // What evaluating one cell found: its best flip, the edges and faces found
  // useless, and the ids of the vertices whose stars it read (its own and the
  // apexes across its faces).
  struct Evaluation
  {
    Flip<Adapter> best;
    std::vector<std::array<int, 2>> useless_edges;
    std::vector<std::array<int, 3>> useless_faces;
    std::array<int, 8> neighbourhood;
  };

  // A thread's scratch space for evaluations.
  struct Evaluator
  {
    Edge_removal<Adapter> edge_removal;
    Multi_face_removal<Adapter> face_removal;
    Flip<Adapter> candidate;
  };

  // The candidate of cell c, if it is flippable and below the threshold.
  template <class Vertex_id>
  std::optional<Candidate> candidate(Cell_handle c, const Vertex_id& vertex_id) const
  {
    if(!ctx_.flippable(adapter_.region(c))) return std::nullopt;
    const double q = ctx_.quality(c);
    const double selection = flip_selection_quality(measure_, q, ctx_.point(c->vertex(0)), ctx_.point(c->vertex(1)),
                                                    ctx_.point(c->vertex(2)), ctx_.point(c->vertex(3)));
    if(!(selection < opt_.quality_threshold)) return std::nullopt;
    return Candidate::of(c, q, vertex_id);
  }

  // The starting cells: those given, taken over (on a mesh where nearly every
  // cell is one, a copy would be the largest array of the pass), or every finite
  // cell measured. The maps the pass fills get their room now rather than by
  // growing (each growth copied a map into new pages, and the last set the peak
  // memory of the run): on Mesh_3 outputs of `eight.off` and `fandisk.off` the
  // large passes found about 1.5 edges and 2.2 faces useless per starting cell,
  // and the largest-angle phase's first pass failed at 96% of its cells. Room is
  // made for 2 edges, 3 faces and one failure per starting cell.
  template <class Vertex_id>
  Candidate_queue<Candidate> start_queue(const Vertex_id& vertex_id, std::vector<Candidate>* given,
                                         Attempt_history* history)
  {
    CGAL_precondition(!given || measure_ == Quality_measure::min_dihedral_sine ||
                      measure_ == Quality_measure::largest_dihedral_angle);
    std::vector<Candidate> start;
    if(given)
    {
      // The given cells that the pass selects, judged in parallel and kept in order.
      start.swap(*given);
      std::vector<char> selected(start.size());
      evaluators_.for_each(0, static_cast<int>(start.size()), [&](Evaluator&, int k) {
        const Candidate& m = start[static_cast<std::size_t>(k)];
        CGAL_assertion(ctx_.flippable(adapter_.region(m.cell)));
        const Cell_handle c = m.cell;
        selected[static_cast<std::size_t>(k)] =
            flip_selection_quality(measure_, m.quality, ctx_.point(c->vertex(0)), ctx_.point(c->vertex(1)),
                                   ctx_.point(c->vertex(2)), ctx_.point(c->vertex(3))) < opt_.quality_threshold;
      }, 1024);
      std::size_t kept = 0;
      for(std::size_t k = 0; k < start.size(); ++k)
        if(selected[k]) start[kept++] = start[k];
      start.resize(kept);
    }
    else
    {
      auto& tr = adapter_.triangulation();
      for(auto c = tr.finite_cells_begin(); c != tr.finite_cells_end(); ++c)
        if(const std::optional<Candidate> e = candidate(c, vertex_id)) start.push_back(*e);
    }
    const int threads = evaluators_.threads();
    useless_edges_.reserve(2 * start.size(), threads);
    useless_faces_.reserve(3 * start.size(), threads);
    if(history) history->failed.reserve(history->failed.size() + start.size(), threads);
    return Candidate_queue<Candidate>(std::move(start));
  }

  // Every cell of the round evaluated on the triangulation as it is now, concurrently.
  template <class Vertex_id>
  void evaluate(const std::vector<Candidate>& round, const Vertex_id& vertex_id)
  {
    if(evaluations_.size() < round.size()) evaluations_.resize(round.size());
    evaluators_.for_each(0, static_cast<int>(round.size()), [&](Evaluator& w, int k) {
      find_best_flip(round[k].cell, vertex_id, w, evaluations_[k]);
    }, 1);
  }

  // The best improving flip of cell c: edge removals of its six edges, multi-face
  // removals at its four faces. Within the pass geometry is fixed, so an edge or a
  // face found useless stays so until a flip touches its vertices.
  template <class Vertex_id>
  void find_best_flip(Cell_handle c, const Vertex_id& vertex_id, Evaluator& w, Evaluation& ev) const
  {
    w.edge_removal.max_ring = opt_.max_ring;
    w.face_removal.max_faces = opt_.max_faces;
    ev.best.clear();
    ev.useless_edges.clear();
    ev.useless_faces.clear();
    std::array<int, 4> id;   // the ids of c's vertices in c's order: looked up once
    for(int k = 0; k < 4; ++k) id[k] = vertex_id(c->vertex(k));
    // What the evaluation reads first lies anywhere in memory: the maps' slots of
    // c's edges and faces, and c's neighbours, where the walks around the edges
    // and the face removals start. Asked for together, they load together.
    for(int i = 0; i < 4; ++i)
    {
      prefetch(c->neighbor(i));
      for(int j = i + 1; j < 4; ++j) useless_edges_.prefetch({std::min(id[i], id[j]), std::max(id[i], id[j])});
      std::array<int, 3> face;
      for(int k = 0, m = 0; k < 4; ++k)
        if(k != i) face[m++] = id[k];
      std::sort(face.begin(), face.end());
      useless_faces_.prefetch(face);
    }
    ev.neighbourhood.fill(-1);
    std::copy(id.begin(), id.end(), ev.neighbourhood.begin());
    Flip<Adapter>& candidate = w.candidate;
    auto consider = [&]() {
      if(candidate.improves() && candidate.new_worst > ev.best.new_worst) std::swap(ev.best, candidate);
    };
    for(int i = 0; i < 4; ++i)
      for(int j = i + 1; j < 4; ++j)
      {
        const std::array<int, 2> key{std::min(id[i], id[j]), std::max(id[i], id[j])};
        const Flip_count* known = useless_edges_.find(key);
        if(known && still_useless(*known, {id[i], id[j]})) continue;
        // Only the best proposal for this cell counts: what cannot beat the best so
        // far is cut short, and then says nothing about the edge's own worth.
        const double at_least = ev.best.improves() ? ev.best.new_worst : -std::numeric_limits<double>::infinity();
        if(w.edge_removal(ctx_, c, i, j, candidate, at_least) && candidate.improves())
          consider();
        else if(!ev.best.improves() || candidate.old_worst >= at_least)
          ev.useless_edges.push_back(key);
      }
    for(int i = 0; i < 4; ++i)
    {
      const Cell_handle n = c->neighbor(i);
      const Vertex_handle apex = n->vertex(n->index(c));
      if(adapter_.triangulation().is_infinite(apex)) continue;
      // The face's ids, sorted: its two apexes need not be part of the key, since
      // another cell across it would be new, and its making touched the face's vertices.
      std::array<int, 3> key;
      for(int k = 0, m = 0; k < 4; ++k)
        if(k != i) key[m++] = id[k];
      std::sort(key.begin(), key.end());
      const int apex_id = vertex_id(apex);
      ev.neighbourhood[4 + i] = apex_id;
      const Flip_count* known = useless_faces_.find(key);
      if(known && still_useless(*known, {id[0], id[1], id[2], id[3], apex_id})) continue;
      // A removal that cannot beat the best so far is not checked for validity;
      // it then says nothing about the face's own worth, and is not recorded.
      const double at_least = ev.best.improves() ? ev.best.new_worst : -std::numeric_limits<double>::infinity();
      if(w.face_removal(ctx_, c, i, candidate, at_least) && candidate.improves())
        consider();
      else
        ev.useless_faces.push_back(key);
    }
  }

  // Marks what an evaluation found useless, as of the state it was judged on.
  void record_useless(const Evaluation& ev, Flip_count when)
  {
    for(const auto& key : ev.useless_edges) useless_edges_.assign(key, when);
    for(const auto& key : ev.useless_faces) useless_faces_.assign(key, when);
  }

  // The round's flips are checked against each other (`touched_since`), so the
  // cells are there; replace_cells still refuses, changing nothing, a change it
  // cannot make, and then the cell counts as tried in vain.
  bool apply(const Flip<Adapter>& flip)
  {
    created_.clear();
    return replace_cells(adapter_, flip.old_cells, flip.new_cells, flip.new_facets, &created_);
  }

  static void count(const Flip<Adapter>& flip, Topology_stats& stats)
  {
    switch(flip.kind)
    {
    case Flip_kind::flip_2_3: ++stats.flips_2_3; break;
    case Flip_kind::flip_3_2: ++stats.flips_3_2; break;
    case Flip_kind::edge_removal: ++stats.edge_removals; break;
    case Flip_kind::multi_face_removal: ++stats.multi_face_removals; break;
    case Flip_kind::edge_contraction: break;   // not a flip pass's: contraction_pass counts them
    }
    if(flip.boundary) ++stats.boundary_flips;
  }

  // The vertices of the created cells: their stars changed. Each goes into
  // `touched` once per pass (the first time it is touched): a vertex may be in
  // hundreds of flips of a pass, and the list was the pass's largest after its maps.
  template <class Vertex_id>
  void mark_touched(const Vertex_id& vertex_id, std::vector<Vertex_handle>& touched, Attempt_history* history)
  {
    for(Cell_handle n : created_)
      for(int k = 0; k < 4; ++k)
      {
        if(adapter_.triangulation().is_infinite(n->vertex(k))) continue;
        const int id = vertex_id(n->vertex(k));
        if(id >= static_cast<int>(touched_at_.size())) touched_at_.resize(id + 1, 0);
        if(touched_at_[id] == 0) touched.push_back(n->vertex(k));
        touched_at_[id] = flips_done_;
        if(history) history->star_changed(id);
      }
  }

  // Whether a flip touched a vertex with one of these ids after `when` flips.
  // Every cell an evaluation of cell c reads holds a vertex of c or the apex
  // across one of c's faces (the rings of c's edges, the cells between the two
  // apexes of a face removal), and a flip that replaces a cell touches all of
  // that cell's vertices: an evaluation none of whose vertices was touched since
  // it was made still holds.
  template <class Ids>
  bool touched_since(Flip_count when, const Ids& ids) const
  {
    for(int id : ids)
      if(id >= 0 && id < static_cast<int>(touched_at_.size()) && touched_at_[id] > when) return true;
    return false;
  }

  bool still_useless(Flip_count when, std::initializer_list<int> ids) const { return !touched_since(when, ids); }

  Adapter& adapter_;
  const Flip_options& opt_;
  Quality_measure measure_;
  const Flip_context<Adapter> ctx_;
  Thread_workers<Evaluator> evaluators_;
  std::vector<Evaluation> evaluations_;
  std::vector<Cell_handle> created_;
  Id_tuple_map<2, Flip_count> useless_edges_;
  Id_tuple_map<3, Flip_count> useless_faces_;
  std::vector<Flip_count> touched_at_;          // per vertex id: flips done when a flip last touched it
  Flip_count flips_done_ = 0;
};

/// One flip pass (`Flip_pass`) on the triangulation behind `adapter`, on
/// `threads` threads (as `Smoothing_options::threads`; the result does not depend on it).
///
/// `touched` receives the finite vertices of the cells created, each once.
/// `history` (optional) lets the pass skip cells tried in vain before whose
/// neighbourhood has not changed since. `candidates` (optional, with the minimum
/// dihedral sine or the largest angle as measure) are the cells the pass may start
/// from, flippable and measured; it takes them over (leaving the vector empty)
/// and starts from those below the threshold (the caller may know them without
/// measuring every cell, or choose where to work). By default every finite cell
/// is measured.
template <class Adapter, class Vertex_id>
Topology_stats flip_pass(Adapter& adapter, const Flip_options& opt, const Dihedral_bounds& bounds,
                         const Vertex_id& vertex_id, std::vector<typename Adapter::Vertex_handle>& touched,
                         Attempt_history* history = nullptr,
                         Quality_measure measure = Quality_measure::min_dihedral_sine,
                         std::vector<Flip_candidate<typename Adapter::Cell_handle>>* candidates = nullptr,
                         int threads = 1)
{
  return Flip_pass<Adapter>(adapter, opt, bounds, measure, threads)(vertex_id, touched, history, candidates);
}

} // namespace internal
} // namespace BODT_3
} // namespace CGAL

#endif // CGAL_BODT_3_INTERNAL_TOPOLOGY_FLIP_PASS_H
