// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_BODT_3_INTERNAL_TOPOLOGY_FLIP_PASS_H
#define CGAL_BODT_3_INTERNAL_TOPOLOGY_FLIP_PASS_H

#include <CGAL/BODT_3/internal/Topology/Edge_removal.h>
#include <CGAL/BODT_3/internal/Topology/Flip.h>
#include <CGAL/BODT_3/internal/Utilities/Id_tuple_map.h>
#include <CGAL/BODT_3/internal/Topology/Multi_face_removal.h>
#include <CGAL/BODT_3/Smoothing_options.h>
#include <CGAL/BODT_3/Smoothing_result.h>

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

/// What earlier passes learnt: the cells (by sorted vertex ids) tried in vain,
/// when and how many times in a row, and per vertex when it or a vertex sharing an
/// edge with it last changed (moved, or got a new star), and when its connectivity
/// last changed (a new star by a flip or an insertion), on a clock that the caller
/// advances at each sweep and the pass at each flip. A cell tried in vain is tried
/// again only once its neighbourhood changed (its flips depend on nothing else,
/// except for multi-face removals reaching further), and, after k failures in a
/// row, only every 2^(k-1) passes (at most 8): smoothing keeps moving the vertices
/// of a bad region a little, and such cells would otherwise be retried every pass.
/// After `retries_after_moves` failures, moves alone no longer make it worth
/// trying: only a new connectivity around it does (doc/stages.md measures both).
struct Attempt_history
{
  struct Failure
  {
    std::size_t clock;
    std::size_t pass;
    std::size_t count;
  };
  std::size_t clock = 0;
  std::size_t pass = 0;   // set by the caller
  std::size_t retries_after_moves = std::numeric_limits<std::size_t>::max();
  std::vector<std::size_t> region_stamp;     // last change within one edge
  std::vector<std::size_t> topology_stamp;   // last connectivity change within one edge
  Id_tuple_map<4, Failure> failed;

  static std::size_t stamp(const std::vector<std::size_t>& stamps, int v)
  {
    return v >= 0 && v < static_cast<int>(stamps.size()) ? stamps[v] : 0;
  }

  /// Marks vertex `v`'s star changed now (a flip or an insertion).
  void star_changed(int v)
  {
    for(std::vector<std::size_t>* stamps : {&region_stamp, &topology_stamp})
    {
      if(v >= static_cast<int>(stamps->size())) stamps->resize(v + 1, 0);
      (*stamps)[v] = clock;
    }
  }

  bool worth_trying(const std::array<int, 4>& ids) const
  {
    const Failure* found = failed.find(ids);
    if(!found) return true;
    const Failure& f = *found;
    const std::size_t wait = std::size_t(1) << std::min<std::size_t>(f.count - 1, 3);
    if(pass < f.pass + wait) return false;
    const std::vector<std::size_t>& changes = f.count > retries_after_moves ? topology_stamp : region_stamp;
    for(int v : ids)
      if(stamp(changes, v) > f.clock) return true;
    return false;
  }

  void record_failure(const std::array<int, 4>& ids)
  {
    bool inserted;
    Failure& f = failed.find_or_insert(ids, Failure{clock, pass, 1}, inserted);
    if(!inserted) f = Failure{clock, pass, f.count + 1};
  }
};

/// A cell the caller measured already (from the same points, in the cell's vertex
/// order, so that its quality is the one the pass would compute): a flip pass can
/// start from such cells without reading the triangulation's cells and vertices.
template <class Cell_handle, class Vertex_handle>
struct Measured_cell
{
  Cell_handle cell;
  std::array<Vertex_handle, 4> vertices;   // the cell's, in its order
  std::array<int, 4> ids;                  // their `vertex_id`s
  double quality;                          // by the pass's measure
};

/// One topology pass: the cells whose minimum dihedral sine is below the quality
/// threshold, worst first by `measure`, each get the best of the edge removals of
/// their six edges and the multi-face removals rooted at their four faces, if it
/// raises the worst quality (by `measure`) of the cells it replaces; new cells
/// below the threshold are tried again. Every
/// accepted flip strictly raises the worst cell of its region, so the pass ends.
/// The order depends only on the mesh (ties are broken by `vertex_id`, stable ids
/// of the vertices), so the same input gives the same output.
///
/// `touched` receives the vertices of every cell created (with repetitions).
/// `history` (optional) lets the pass skip cells tried in vain before whose
/// neighbourhood has not changed since. `candidates` (optional, with the minimum
/// dihedral sine as measure) are the cells to start from, flippable and measured,
/// a superset of the flippable cells below the threshold
/// (the caller may know them without measuring every cell); by default every finite
/// cell is measured. The result does not depend on which superset is given.
template <class Labels, class Vertex_id>
Topology_stats flip_pass(Labels& labels, const Flip_options& opt, const Dihedral_bounds& bounds,
                         const Vertex_id& vertex_id, std::vector<typename Labels::Vertex_handle>& touched,
                         Attempt_history* history = nullptr,
                         Quality_measure measure = Quality_measure::min_dihedral_sine,
                         const std::vector<Measured_cell<typename Labels::Cell_handle,
                                                         typename Labels::Vertex_handle>>* candidates = nullptr)
{
  using Vertex_handle = typename Labels::Vertex_handle;
  using Cell_handle = typename Labels::Cell_handle;
  CGAL::Real_timer timer;
  timer.start();

  const Flip_context<Labels> ctx(labels, bounds, opt.flip_outside, measure);
  Edge_removal<Labels> edge_removal;
  edge_removal.max_ring = opt.max_ring;
  Multi_face_removal<Labels> face_removal;
  face_removal.max_faces = opt.max_faces;

  struct Entry
  {
    double quality;
    std::array<int, 4> ids;   // sorted
    Cell_handle cell;
    std::array<Vertex_handle, 4> vertices;
    bool operator<(const Entry& o) const   // for a max-heap that pops the worst first
    {
      if(quality != o.quality) return quality > o.quality;
      return ids > o.ids;
    }
  };
  // The entry of cell c, if it is flippable and below the threshold.
  auto make_entry = [&](Cell_handle c, Entry& e) {
    if(!ctx.flippable(labels.region(c))) return false;
    const double q = ctx.quality(c);
    const double sine = measure == Quality_measure::min_dihedral_sine
                            ? q
                            : min_dihedral_sine(ctx.point(c->vertex(0)), ctx.point(c->vertex(1)),
                                                ctx.point(c->vertex(2)), ctx.point(c->vertex(3)));
    if(!(sine < opt.quality_threshold)) return false;
    e = Entry{q, {}, c, {c->vertex(0), c->vertex(1), c->vertex(2), c->vertex(3)}};
    for(int k = 0; k < 4; ++k) e.ids[k] = vertex_id(e.vertices[k]);
    std::sort(e.ids.begin(), e.ids.end());
    return true;
  };
  auto& tr = labels.triangulation();
  const std::size_t cells = labels.tds().number_of_cells();   // O(1), unlike counting the finite ones
  CGAL_precondition(!candidates || measure == Quality_measure::min_dihedral_sine);
  std::vector<Entry> start;
  Entry entry;
  if(candidates)
    for(const auto& m : *candidates)
    {
      CGAL_assertion(ctx.flippable(labels.region(m.cell)));
      if(!(m.quality < opt.quality_threshold)) continue;
      start.push_back(Entry{m.quality, m.ids, m.cell, m.vertices});
      std::sort(start.back().ids.begin(), start.back().ids.end());
    }
  else
    for(auto c = tr.finite_cells_begin(); c != tr.finite_cells_end(); ++c)
      if(make_entry(c, entry)) start.push_back(entry);
  std::priority_queue<Entry> queue(std::less<Entry>(), std::move(start));   // a heap in linear time

  // Within the pass, geometry is fixed: an edge removal or a face removal found
  // useless stays so until a flip touches its vertices.
  Id_tuple_map<2, std::size_t> useless_edges;
  Id_tuple_map<4, std::size_t> useless_faces;   // face ids and apex
  std::vector<std::size_t> touched_at;
  std::size_t flips_done = 0;
  auto last_touch = [&](int id) { return id < static_cast<int>(touched_at.size()) ? touched_at[id] : 0; };
  // Whether no flip touched the (finite) vertices with these ids since `when`.
  auto still_useless = [&](std::size_t when, std::initializer_list<int> ids) {
    for(int id : ids)
      if(last_touch(id) > when) return false;
    return true;
  };

  Topology_stats stats;
  Flip<Labels> candidate, best;
  std::vector<Cell_handle> created;
  const std::size_t max_flips = 4 * cells + 16;
  while(!queue.empty() && stats.total() < max_flips)
  {
    const Entry e = queue.top();
    queue.pop();
    // The history first: it does not read the cell, which is anywhere in memory.
    if(history && !history->worth_trying(e.ids)) continue;
    if(!labels.tds().cells().is_used(e.cell) ||
       !(e.cell->has_vertex(e.vertices[0]) && e.cell->has_vertex(e.vertices[1]) && e.cell->has_vertex(e.vertices[2]) &&
         e.cell->has_vertex(e.vertices[3])))
      continue;   // replaced since it was queued
    const Cell_handle c = e.cell;
    // The ids of c's vertices in c's order (e.ids is sorted): looked up once.
    std::array<int, 4> id;
    for(int k = 0; k < 4; ++k) id[k] = vertex_id(c->vertex(k));

    best.clear();
    auto consider = [&]() {
      if(candidate.improves() && candidate.new_worst > best.new_worst) std::swap(best, candidate);
    };
    for(int i = 0; i < 4; ++i)
      for(int j = i + 1; j < 4; ++j)
      {
        const std::array<int, 2> key{std::min(id[i], id[j]), std::max(id[i], id[j])};
        const std::size_t* known = useless_edges.find(key);
        if(known && still_useless(*known, {id[i], id[j]})) continue;
        // Only the best proposal for this cell counts: what cannot beat the best so
        // far is cut short, and then says nothing about the edge's own worth.
        const double at_least = best.improves() ? best.new_worst : -std::numeric_limits<double>::infinity();
        if(edge_removal(ctx, c, i, j, candidate, at_least) && candidate.improves())
          consider();
        else if(!best.improves() || candidate.old_worst >= at_least)
          useless_edges.assign(key, flips_done);
      }
    for(int i = 0; i < 4; ++i)
    {
      const Cell_handle n = c->neighbor(i);
      const Vertex_handle apex = n->vertex(n->index(c));
      if(tr.is_infinite(apex)) continue;
      std::array<int, 4> key;
      for(int k = 0, m = 0; k < 4; ++k)
        if(k != i) key[m++] = id[k];
      std::sort(key.begin(), key.begin() + 3);
      const int apex_id = vertex_id(apex);
      key[3] = std::min(apex_id, id[i]);
      const std::size_t* known = useless_faces.find(key);
      if(known && still_useless(*known, {id[0], id[1], id[2], id[3], apex_id}))
        continue;
      if(face_removal(ctx, c, i, candidate) && candidate.improves())
        consider();
      else
        useless_faces.assign(key, flips_done);
    }
    created.clear();
    if(!best.improves() || !replace_cells(labels, best.old_cells, best.new_cells, best.new_facets, &created))
    {
      if(history) history->record_failure(e.ids);
      continue;
    }
    switch(best.kind)
    {
    case Flip_kind::flip_2_3: ++stats.flips_2_3; break;
    case Flip_kind::flip_3_2: ++stats.flips_3_2; break;
    case Flip_kind::edge_removal: ++stats.edge_removals; break;
    case Flip_kind::multi_face_removal: ++stats.multi_face_removals; break;
    }
    if(best.boundary) ++stats.boundary_flips;
    if(history) ++history->clock;
    ++flips_done;
    for(Cell_handle n : created)
      for(int k = 0; k < 4; ++k)
      {
        touched.push_back(n->vertex(k));
        if(!tr.is_infinite(n->vertex(k)))
        {
          const int id = vertex_id(n->vertex(k));
          if(id >= static_cast<int>(touched_at.size())) touched_at.resize(id + 1, 0);
          touched_at[id] = flips_done;
          if(history) history->star_changed(id);
        }
      }
    for(Cell_handle n : created)
      if(!tr.is_infinite(n) && make_entry(n, entry)) queue.push(entry);
  }
  stats.seconds = timer.time();
  return stats;
}

} // namespace BODT_3
} // namespace CGAL

#endif // CGAL_BODT_3_INTERNAL_TOPOLOGY_FLIP_PASS_H
