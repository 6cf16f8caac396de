// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_BODT_3_INTERNAL_INSERTION_INSERTION_PASS_H
#define CGAL_BODT_3_INTERNAL_INSERTION_INSERTION_PASS_H

#include <CGAL/BODT_3/Smoothing_options.h>
#include <CGAL/BODT_3/Smoothing_result.h>
#include <CGAL/BODT_3/internal/Classification/Vertex_classification.h>
#include <CGAL/BODT_3/internal/Insertion/Bad_tet_shape.h>
#include <CGAL/BODT_3/internal/Insertion/Cavity_insertion.h>
#include <CGAL/BODT_3/internal/Insertion/Vertex_insertion.h>
#include <CGAL/BODT_3/internal/Mesh/Triangulation_adapter.h>
#include <CGAL/BODT_3/internal/Quality/dihedral_angles.h>
#include <CGAL/BODT_3/internal/Quality/tet_quality.h>
#include <CGAL/BODT_3/internal/Smoothing/Local_smoothing.h>
#include <CGAL/BODT_3/internal/Smoothing/Volume_budget.h>
#include <CGAL/BODT_3/internal/Utilities/Attempt_history.h>
#include <CGAL/BODT_3/internal/Utilities/Candidate_cell.h>
#include <CGAL/BODT_3/internal/Utilities/Thread_workers.h>
#include <CGAL/BODT_3/internal/Utilities/bare_point.h>

#include <CGAL/FPU.h>
#include <CGAL/Real_timer.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <initializer_list>
#include <iterator>
#include <map>
#include <optional>
#include <vector>

namespace CGAL {
namespace BODT_3 {
namespace internal {

/// A vertex an insertion pass added, with how it moves.
template <class Vertex_handle>
struct Added_vertex
{
  Vertex_handle vertex;
  Vertex_kind kind;
  Vertex_handle a, b;   // its neighbours on its curve, for a feature vertex
};

/// How a vertex moves: its kind and, for a feature vertex, its neighbours on its curve.
template <class Vertex_handle>
struct Vertex_motion
{
  Vertex_kind kind = Vertex_kind::fixed;
  Vertex_handle a, b;
};

/// One insertion pass (paper, Sec. 2.3): the mesh cells whose minimum dihedral
/// sine is below `opt.quality_threshold`, worst first (by `measure`), that are
/// spades, caps, slivers or wedges (Bad_tet_shape.h, with the angle bounds of the
/// threshold) are split: a spade's edge at the projection of its vertex, a
/// wedge's long edge at the projection of its short edge's middle, a cap's face at
/// the projection of its vertex, a sliver's two crossing edges at their closest
/// points. The new vertices and the tetrahedron's own are then smoothed
/// (`Local_smoothing`, `opt.smoothing_rounds` times), and the insertion is kept
/// only if the cells around those vertices compare better than before, worst
/// first (`compare_worst_first`), and stay within `bounds`; otherwise it is undone.
///
/// `motion(v)` tells how an existing vertex moves; `boundary_moves` says whether
/// boundary vertices may move at all (not for the interior-only ODT baseline).
/// With a `volume_budget`, a split whose rounded point, off its boundary edge or
/// facet, changes a subdomain's volume and the moves of the smoothing that follows
/// are paid from it, as in the sweeps (Volume_budget.h); a split it cannot pay is undone.
/// With a `distance` guard, the smoothing keeps surface vertices near the input's surface.
///
/// With `opt.cavity` (the worst-cell phase's `cavity_insertion`), the pass instead tries
/// its `opt.max_cavity_attempts` worst cells by an interior vertex in an optimized
/// cavity (Cavity_insertion.h), kept as found: no smoothing after it, nothing to undo;
/// the searches run on `threads` threads, with the same result on any number.
template <class Adapter, class Motion, class Vertex_id>
class Insertion_pass
{
public:
  using Vertex_handle = typename Adapter::Vertex_handle;
  using Cell_handle = typename Adapter::Cell_handle;
  using Point = Bare_point_t<typename Adapter::Triangulation>;
  using Candidate = Candidate_cell<Cell_handle, Vertex_handle>;

  using Distance_guard = Boundary_distance_guard<typename Local_smoothing<Adapter>::K>;

  Insertion_pass(Adapter& adapter, const Insertion_options& opt, const Dihedral_bounds& bounds,
                 Quality_measure measure, const Tensor_voting_options& voting, bool boundary_moves,
                 const Motion& motion, const Vertex_id& vertex_id, Volume_budget* volume_budget,
                 const Distance_guard* distance = nullptr, int threads = 1)
    : adapter_(adapter), tr_(adapter.triangulation()), opt_(opt), bounds_(bounds), measure_(measure),
      boundary_moves_(boundary_moves), motion_(motion), vertex_id_(vertex_id), volume_budget_(volume_budget),
      smoother_(adapter, bounds, measure, voting, volume_budget, distance), searchers_(threads)
  {
    shapes_ = opt.shapes;
    shapes_.small_angle = std::asin(std::min(1.0, opt.quality_threshold)) * 180 / pi;
    shapes_.large_angle = 180 - shapes_.small_angle;
  }

  /// Runs the pass with at most `budget` new vertices. `seeds`, when given, holds
  /// every mesh cell below the threshold (the quality guard knows them), so that
  /// the pass does not measure every cell again. `added` receives the new
  /// vertices, `touched` the vertices whose star changed; `history` (optional)
  /// skips cells tried in vain whose neighbourhood has not changed since.
  Insertion_stats operator()(std::size_t budget, std::vector<Added_vertex<Vertex_handle>>& added,
                             std::vector<Vertex_handle>& touched, Attempt_history* history,
                             const std::vector<Cell_handle>* seeds)
  {
    CGAL::Real_timer timer;
    timer.start();
    Insertion_stats stats;
    if(opt_.cavity)
    {
      cavities(candidates(seeds), budget, added, touched, history, stats);
      stats.seconds = timer.time();
      return stats;
    }
    for(const Candidate& e : candidates(seeds))
    {
      if(budget < 1) break;
      if(!e.still_there(adapter_.tds())) continue;
      if(history && !history->worth_trying(e.ids)) continue;
      if(const std::optional<std::array<int, 2>> inner = ear_inner_edge(e.cell))
      {
        keep_sine_ = true;
        const bool kept = try_split(e.cell, [&] { return split_ear(e.cell, *inner); });
        keep_sine_ = false;
        if(kept)
        {
          keep(added, touched, stats);
          ++stats.ear_splits;
          budget -= records_.size();
          if(history) ++history->clock;
          continue;
        }
        ++stats.undone;
        if(history) history->record_failure(e.ids);
        continue;
      }
      const Bad_tet shape = classify_bad_tet(point(e.cell->vertex(0)), point(e.cell->vertex(1)),
                                             point(e.cell->vertex(2)), point(e.cell->vertex(3)), shapes_);
      const std::size_t needed = shape.shape == Bad_tet_shape::sliver ? 2 : 1;
      if(!splits(shape.shape) || needed > budget)
      {
        if(history) history->record_failure(e.ids);
        continue;
      }
      if(try_split(e.cell, [&] { return split_shape(e.cell, shape); }))
      {
        keep(added, touched, stats);
        count(shape.shape, stats);
        budget -= records_.size();
        if(history) ++history->clock;
        continue;
      }
      ++stats.undone;
      if(history) history->record_failure(e.ids);
    }
    stats.seconds = timer.time();
    return stats;
  }

private:
  static bool splits(Bad_tet_shape s)
  {
    return s == Bad_tet_shape::spade || s == Bad_tet_shape::cap || s == Bad_tet_shape::sliver ||
           s == Bad_tet_shape::wedge;
  }

  Point point(Vertex_handle v) const { return bare_point(tr_, v); }

  double quality(Cell_handle c) const
  {
    return tet_quality(measure_, point(c->vertex(0)), point(c->vertex(1)), point(c->vertex(2)), point(c->vertex(3)));
  }

  // A boundary ear: a mesh cell two of whose facets lie on the boundary of its
  // subdomain (outside or another subdomain across), meeting at an edge where its
  // dihedral angle is above `ear_angle`. No other cell of the subdomain shares that
  // edge there, so the angle is the surface's, whatever the cell's vertices do
  // within it; only a vertex on the opposite (inner) edge, moved inside, splits it.
  // Returns the slots of the inner edge's vertices.
  std::optional<std::array<int, 2>> ear_inner_edge(Cell_handle c) const
  {
    if(!(opt_.ear_angle > 0)) return std::nullopt;
    const auto region = adapter_.region(c);
    std::array<int, 4> off{};
    int n = 0;
    for(int i = 0; i < 4; ++i)
      if(!(adapter_.region(c->neighbor(i)) == region))
      {
        if(n == 2) return std::nullopt;
        off[n++] = i;
      }
    if(n != 2) return std::nullopt;
    // The ear edge joins the other two slots; dihedral_angles lists the edges 01, 02, 03, 12, 13, 23.
    int e[2], m = 0;
    for(int k = 0; k < 4; ++k)
      if(k != off[0] && k != off[1]) e[m++] = k;
    static const int edge_index[4][4] = {{-1, 0, 1, 2}, {0, -1, 3, 4}, {1, 3, -1, 5}, {2, 4, 5, -1}};
    const auto angles = dihedral_angles(point(c->vertex(0)), point(c->vertex(1)), point(c->vertex(2)),
                                        point(c->vertex(3)));
    if(!(angles[static_cast<std::size_t>(edge_index[e[0]][e[1]])] > opt_.ear_angle)) return std::nullopt;
    return std::array<int, 2>{off[0], off[1]};
  }

  // The mesh cells below the threshold (by their sine), or the ears, worst first by the measure.
  std::vector<Candidate> candidates(const std::vector<Cell_handle>* seeds) const
  {
    std::vector<Candidate> found;
    auto consider = [&](Cell_handle c) {
      if(adapter_.region(c).kind != Region_kind::mesh) return;
      if(ear_inner_edge(c))
      {
        found.push_back(Candidate::of(c, quality(c), vertex_id_));
        return;
      }
      const double sine = min_dihedral_sine(point(c->vertex(0)), point(c->vertex(1)), point(c->vertex(2)),
                                            point(c->vertex(3)));
      if(sine < opt_.quality_threshold) found.push_back(Candidate::of(c, quality(c), vertex_id_));
    };
    if(seeds)
      for(Cell_handle c : *seeds) consider(c);
    else
      for(auto c = tr_.finite_cells_begin(); c != tr_.finite_cells_end(); ++c) consider(c);
    std::sort(found.begin(), found.end(), [](const Candidate& a, const Candidate& b) { return b < a; });
    return found;
  }

  // Splits cell c (`split()`), smooths, and keeps the result if it is better;
  // otherwise undoes everything and says so.
  template <class Split>
  bool try_split(Cell_handle c, const Split& split)
  {
    records_.clear();
    const std::vector<Vertex_handle> own = {c->vertex(0), c->vertex(1), c->vertex(2), c->vertex(3)};
    std::vector<double> before = cells_around(own);
    sine_before_ = worst_sine();
    const bool done = split();
    moved_.clear();
    was_.clear();
    if(done && smooth_and_judge(own, before)) return true;
    undo();
    return false;
  }

  // The cavity mode: the worst cells, at most `opt_.max_cavity_attempts` tried,
  // in order, each by the best cavity found from it (Cavity_insertion). The
  // searches only read the mesh: they run ahead, concurrently, on the next cells
  // worth trying as a round starts (one per thread); then, in order, a cell's
  // search is used if none of the cells it read was replaced since, else made
  // again on the mesh as it is. Either way each cell gets the search the
  // one-by-one order gives it: the same result on any number of threads.
  void cavities(const std::vector<Candidate>& candidates, std::size_t budget,
                std::vector<Added_vertex<Vertex_handle>>& added, std::vector<Vertex_handle>& touched,
                Attempt_history* history, Insertion_stats& stats)
  {
    using Search = Cavity_insertion<Adapter>;
    auto worth_trying = [&](const Candidate& e) {
      return e.still_there(adapter_.tds()) && (!history || history->worth_trying(e.ids));
    };
    int attempts = 0;
    std::vector<std::size_t> ahead;
    std::vector<typename Search::Proposal> proposals;
    std::vector<char> found;
    std::vector<Cell_handle> replaced;   // since the round's searches, by address
    for(std::size_t next = 0; next < candidates.size();)
    {
      ahead.clear();
      std::size_t end = next;
      // The worst cells only: in a good mesh most cells are near the worst.
      if(attempts >= opt_.max_cavity_attempts) return;
      const std::size_t room = static_cast<std::size_t>(opt_.max_cavity_attempts - attempts);
      const std::size_t round = std::min(room, static_cast<std::size_t>(searchers_.threads()));
      for(; end < candidates.size() && ahead.size() < round; ++end)
        if(worth_trying(candidates[end])) ahead.push_back(end);
      proposals.resize(ahead.size());
      found.assign(ahead.size(), 0);
      searchers_.for_each(0, static_cast<int>(ahead.size()), [&](char&, int k) {
        const std::size_t j = static_cast<std::size_t>(k);
        found[j] = Search(adapter_, bounds_, measure_)(candidates[ahead[j]].cell, proposals[j]);
      }, 1);
      replaced.clear();
      for(std::size_t a = 0; next < end; ++next)
      {
        const Candidate& e = candidates[next];
        if(budget < 1) return;
        if(!worth_trying(e)) continue;
        if(++attempts > opt_.max_cavity_attempts) return;
        while(a < ahead.size() && ahead[a] < next) ++a;
        typename Search::Proposal own;
        const bool ran_ahead = a < ahead.size() && ahead[a] == next && !Search::reads_any(proposals[a].read, replaced);
        typename Search::Proposal& proposal = ran_ahead ? proposals[a] : own;
        const bool has = ran_ahead ? found[a] != 0 : Search(adapter_, bounds_, measure_)(e.cell, proposal);
        if(has && insert_in_cavity(e.cell, proposal))
        {
          replaced.insert(replaced.end(), proposal.cavity.begin(), proposal.cavity.end());
          std::sort(replaced.begin(), replaced.end(), Search::by_address);
          keep(added, touched, stats);
          ++stats.cavity_insertions;
          budget -= 1;
          if(history) ++history->clock;
        }
        else if(history)
          history->record_failure(e.ids);
      }
    }
  }

  // An interior vertex at the proposal's point, joined to its cavity's boundary.
  bool insert_in_cavity(Cell_handle c, const typename Cavity_insertion<Adapter>::Proposal& proposal)
  {
    records_.clear();
    const auto region = adapter_.region(c);
    const Vertex_handle e =
        adapter_.create_vertex(proposal.point, Vertex_handle(), Vertex_handle(), typename Adapter::Patch(), region);
    std::vector<New_cell<Vertex_handle>> cells;
    const auto& cavity = proposal.cavity;
    for(const auto& [k, i] : proposal.facets)
    {
      const Cell_handle x = cavity[static_cast<std::size_t>(k)];
      std::array<Vertex_handle, 4> q = {x->vertex(0), x->vertex(1), x->vertex(2), x->vertex(3)};
      q[static_cast<std::size_t>(i)] = e;
      cells.push_back({q, k});
    }
    Split_record<Adapter> r;
    if(!replace_by_split(adapter_, cavity, cells, {}, e, r)) return false;
    fresh_[r.vertex] = Vertex_motion<Vertex_handle>{Vertex_kind::interior, {}, {}};
    records_.push_back(std::move(r));
    cells_around({e});
    return true;
  }

  bool split_shape(Cell_handle c, const Bad_tet& shape)
  {
    switch(shape.shape)
    {
    case Bad_tet_shape::wedge: return split_wedge(c, shape);
    case Bad_tet_shape::spade: return split_spade(c, shape);
    case Bad_tet_shape::sliver: return split_sliver(c, shape);
    default: return split_cap(c, shape);
    }
  }

  // An ear: its inner edge at the middle; the smoothing then moves the new vertex inside.
  bool split_ear(Cell_handle c, const std::array<int, 2>& inner)
  {
    return split_at_edge(c->vertex(inner[0]), c->vertex(inner[1]), on_edge(c, inner[0], inner[1], 0.5));
  }

  // A wedge: the edge opposite the short one, at the projection of the short edge's middle.
  bool split_wedge(Cell_handle c, const Bad_tet& shape)
  {
    int cd[2], m = 0;
    for(int k = 0; k < 4; ++k)
      if(k != shape.edge[0] && k != shape.edge[1]) cd[m++] = k;
    const Point pc = point(c->vertex(cd[0])), pd = point(c->vertex(cd[1]));
    const Point mid = CGAL::midpoint(point(c->vertex(shape.edge[0])), point(c->vertex(shape.edge[1])));
    const double t = ((mid - pc) * (pd - pc)) / (pd - pc).squared_length();
    if(!(t > shapes_.margin && t < 1 - shapes_.margin)) return false;
    return split_at_edge(c->vertex(cd[0]), c->vertex(cd[1]), on_edge(c, cd[0], cd[1], t));
  }

  // A spade: its edge at the projection of the opposite vertex.
  bool split_spade(Cell_handle c, const Bad_tet& shape)
  {
    return split_at_edge(c->vertex(shape.edge[0]), c->vertex(shape.edge[1]),
                         on_edge(c, shape.edge[0], shape.edge[1], shape.t[0]));
  }

  // A sliver: both crossing edges at their closest points (both found before c goes).
  bool split_sliver(Cell_handle c, const Bad_tet& shape)
  {
    const Vertex_handle a = c->vertex(shape.edge[0]), b = c->vertex(shape.edge[1]);
    const Vertex_handle d = c->vertex(shape.edge[2]), f = c->vertex(shape.edge[3]);
    const Point p = on_edge(c, shape.edge[0], shape.edge[1], shape.t[0]);
    const Point q = on_edge(c, shape.edge[2], shape.edge[3], shape.t[1]);
    return split_at_edge(a, b, p) && split_at_edge(d, f, q);
  }

  // A cap: the face opposite its vertex, at the vertex's projection.
  bool split_cap(Cell_handle c, const Bad_tet& shape)
  {
    int f[3], m = 0;
    for(int k = 0; k < 4; ++k)
      if(k != shape.vertex) f[m++] = k;
    const Vertex_handle fv[3] = {c->vertex(f[0]), c->vertex(f[1]), c->vertex(f[2])};
    const Point pf[3] = {point(fv[0]), point(fv[1]), point(fv[2])};
    const double s = shape.bary[0] + shape.bary[1] + shape.bary[2];
    const Point p((shape.bary[0] * pf[0].x() + shape.bary[1] * pf[1].x() + shape.bary[2] * pf[2].x()) / s,
                  (shape.bary[0] * pf[0].y() + shape.bary[1] * pf[1].y() + shape.bary[2] * pf[2].y()) / s,
                  (shape.bary[0] * pf[0].z() + shape.bary[1] * pf[1].z() + shape.bary[2] * pf[2].z()) / s);
    Split_record<Adapter> r;
    if(!split_facet(adapter_, c, shape.vertex, p, r)) return false;
    if(!split_within_budget(r, {fv[0], fv[1], fv[2]}))
    {
      undo_split(adapter_, r);
      return false;
    }
    Vertex_motion<Vertex_handle> m_new{r.boundary.empty() ? Vertex_kind::interior : Vertex_kind::surface, {}, {}};
    // A facet whose three vertices are fixed lies where nothing may move (a crack
    // face, a surface embedded in one subdomain): its new vertex stays where it is.
    bool pinned = !r.boundary.empty();
    for(Vertex_handle x : fv) pinned = pinned && motion_of(x).kind == Vertex_kind::fixed;
    if(pinned || (m_new.kind != Vertex_kind::interior && !boundary_moves_)) m_new.kind = Vertex_kind::fixed;
    fresh_[r.vertex] = m_new;
    records_.push_back(std::move(r));
    return true;
  }

  Point on_edge(Cell_handle c, int a, int b, double t) const
  {
    const Point pa = point(c->vertex(a)), pb = point(c->vertex(b));
    return pa + t * (pb - pa);
  }

  // Splits edge (u, v) at p; the new vertex moves on the curve, the boundary, or freely.
  bool split_at_edge(Vertex_handle u, Vertex_handle v, const Point& p)
  {
    Cell_handle cell;
    int i, j;
    Split_record<Adapter> r;
    if(!adapter_.tds().is_edge(u, v, cell, i, j) || !split_edge(adapter_, cell, i, j, p, r)) return false;
    if(!split_within_budget(r, {u, v}))
    {
      undo_split(adapter_, r);
      return false;
    }
    fresh_[r.vertex] = motion_of_split_edge(r, u, v);
    records_.push_back(std::move(r));
    return true;
  }

  Vertex_motion<Vertex_handle> motion_of_split_edge(const Split_record<Adapter>& r, Vertex_handle u,
                                                    Vertex_handle v) const
  {
    Vertex_motion<Vertex_handle> m{Vertex_kind::interior, u, v};
    const Vertex_motion<Vertex_handle> mu = motion_of(u), mv = motion_of(v);
    const bool boundary_ends = mu.kind != Vertex_kind::interior && mv.kind != Vertex_kind::interior;
    if(adapter_.is_curve_edge(r.vertex, u) || r.boundary.size() > 2 ||
       (r.boundary.size() == 2 && (r.boundary[0] != r.boundary[1] ||
                                   (mu.kind != Vertex_kind::surface && mv.kind != Vertex_kind::surface))))
      m.kind = Vertex_kind::feature;   // on a curve, a junction of patches, or a sharp edge between such vertices
    else if(!r.boundary.empty())
      m.kind = Vertex_kind::surface;
    if(m.kind == Vertex_kind::feature && !boundary_ends) m.kind = Vertex_kind::fixed;
    if(m.kind != Vertex_kind::interior && !boundary_moves_) m.kind = Vertex_kind::fixed;
    return m;
  }

  // Whether a split's point, on its edge or facet `ends` up to rounding, changes
  // the subdomains around it within the budget (then paid). A split with no
  // boundary or interface facet keeps its region's union exactly.
  bool split_within_budget(const Split_record<Adapter>& r, std::initializer_list<Vertex_handle> ends)
  {
    if(!volume_budget_ || !volume_budget_->limited() || r.boundary.empty()) return true;
    const Point p = point(r.vertex);
    change_.clear();
    {
      CGAL::Protect_FPU_rounding<true> upward;
      for(const auto& old : r.old_cells)
      {
        const auto& region = r.old_regions[old.region_of];
        if(region.kind != Region_kind::mesh) continue;
        const int s = static_cast<int>(region.subdomain);
        Point q[4];
        for(int k = 0; k < 4; ++k) q[k] = point(old.vertices[k]);
        change_.add_cell(s, -1, q[0], q[1], q[2], q[3]);
        // Each end of the split simplex, replaced by p, gives one of the new cells.
        for(int k = 0; k < 4; ++k)
          if(std::find(ends.begin(), ends.end(), old.vertices[k]) != ends.end())
          {
            Point n[4] = {q[0], q[1], q[2], q[3]};
            n[k] = p;
            change_.add_cell(s, 1, n[0], n[1], n[2], n[3]);
          }
      }
    }
    const double cost = volume_budget_->cost(change_);
    if(!(cost <= volume_budget_->allowance())) return false;
    volume_budget_->spend(cost);
    return true;
  }

  // Smooths the new vertices and the tetrahedron's own, then judges the cells
  // around them against `before`, worst first, within the bounds.
  bool smooth_and_judge(const std::vector<Vertex_handle>& own, std::vector<double>& before)
  {
    std::vector<Vertex_handle> order;
    for(const auto& r : records_) order.push_back(r.vertex);
    order.insert(order.end(), own.begin(), own.end());
    for(int round = 0; round < opt_.smoothing_rounds; ++round)
      for(std::size_t i = 0; i < order.size(); ++i)
      {
        const Vertex_handle v = order[i];
        const Point p = point(v);
        const auto m = motion_of(v);
        if(smoother_.move(v, m.kind, m.a, m.b) && std::find(moved_.begin(), moved_.end(), v) == moved_.end())
        {
          moved_.push_back(v);
          was_.push_back(p);
        }
      }
    std::vector<Vertex_handle> region = own;
    for(const auto& r : records_) region.push_back(r.vertex);
    std::vector<double> after = cells_around(region);
    for(Cell_handle x : around_)
      if(!bounds_.contains(point(x->vertex(0)), point(x->vertex(1)), point(x->vertex(2)), point(x->vertex(3)), 0.0))
        return false;
    if(keep_sine_ && worst_sine() < sine_before_) return false;
    return compare_worst_first(after, before) > 0;
  }

  double worst_sine() const
  {
    double w = 2;
    for(Cell_handle x : around_)
      w = std::min(w, min_dihedral_sine(point(x->vertex(0)), point(x->vertex(1)), point(x->vertex(2)), point(x->vertex(3))));
    return w;
  }

  void keep(std::vector<Added_vertex<Vertex_handle>>& added, std::vector<Vertex_handle>& touched,
            Insertion_stats& stats)
  {
    for(const auto& r : records_)
    {
      const Vertex_motion<Vertex_handle>& m = fresh_[r.vertex];
      added.push_back({r.vertex, m.kind, m.a, m.b});
      ++stats.vertices_added;
    }
    for(Cell_handle x : around_)
      for(int k = 0; k < 4; ++k) touched.push_back(x->vertex(k));
  }

  static void count(Bad_tet_shape shape, Insertion_stats& stats)
  {
    if(shape == Bad_tet_shape::spade) ++stats.spade_splits;
    if(shape == Bad_tet_shape::wedge) ++stats.wedge_splits;
    if(shape == Bad_tet_shape::cap) ++stats.cap_splits;
    if(shape == Bad_tet_shape::sliver) ++stats.sliver_splits;
  }

  // Positions first, then the splits in reverse order.
  void undo()
  {
    for(std::size_t k = moved_.size(); k-- > 0;) set_bare_point(tr_, moved_[k], was_[k]);
    for(std::size_t k = records_.size(); k-- > 0;)
    {
      fresh_.erase(records_[k].vertex);
      undo_split(adapter_, records_[k]);
    }
  }

  Vertex_motion<Vertex_handle> motion_of(Vertex_handle v) const
  {
    const auto it = fresh_.find(v);
    return it != fresh_.end() ? it->second : motion_(v);
  }

  // The mesh cells around some vertices (in `around_`), and their qualities.
  std::vector<double> cells_around(const std::vector<Vertex_handle>& vs)
  {
    around_.clear();
    for(Vertex_handle v : vs)
    {
      scratch_.clear();
      tr_.tds().incident_cells(v, std::back_inserter(scratch_));
      for(Cell_handle c : scratch_)
        if(adapter_.region(c).kind == Region_kind::mesh && std::find(around_.begin(), around_.end(), c) == around_.end())
          around_.push_back(c);
    }
    std::vector<double> q;
    for(Cell_handle c : around_) q.push_back(quality(c));
    return q;
  }

  Adapter& adapter_;
  typename Adapter::Triangulation& tr_;
  const Insertion_options& opt_;
  const Dihedral_bounds& bounds_;
  Quality_measure measure_;
  Bad_tet_options shapes_;
  bool boundary_moves_;
  const Motion& motion_;
  const Vertex_id& vertex_id_;
  Volume_budget* volume_budget_;
  Local_smoothing<Adapter> smoother_;
  Thread_workers<char> searchers_;   // the cavity searches run ahead
  Volume_change change_;
  std::map<Vertex_handle, Vertex_motion<Vertex_handle>> fresh_;   // vertices added in this pass
  // The attempt under way: its splits, and the vertices its smoothing moved.
  std::vector<Split_record<Adapter>> records_;
  std::vector<Vertex_handle> moved_;
  std::vector<Point> was_;
  std::vector<Cell_handle> around_, scratch_;
  bool keep_sine_ = false;
  double sine_before_ = 0;
};

/// One insertion pass (`Insertion_pass`) on the triangulation behind `adapter`,
/// with at most `budget` new vertices.
template <class Adapter, class Motion, class Vertex_id>
Insertion_stats insertion_pass(Adapter& adapter, const Insertion_options& opt, const Dihedral_bounds& bounds,
                               Quality_measure measure, const Tensor_voting_options& voting, std::size_t budget,
                               bool boundary_moves, const Motion& motion, const Vertex_id& vertex_id,
                               std::vector<Added_vertex<typename Adapter::Vertex_handle>>& added,
                               std::vector<typename Adapter::Vertex_handle>& touched,
                               Attempt_history* history = nullptr,
                               const std::vector<typename Adapter::Cell_handle>* seeds = nullptr,
                               Volume_budget* volume_budget = nullptr,
                               const typename Insertion_pass<Adapter, Motion, Vertex_id>::Distance_guard* distance =
                                   nullptr,
                               int threads = 1)
{
  Insertion_pass<Adapter, Motion, Vertex_id> pass(adapter, opt, bounds, measure, voting, boundary_moves, motion,
                                                  vertex_id, volume_budget, distance, threads);
  return pass(budget, added, touched, history, seeds);
}

} // namespace internal
} // namespace BODT_3
} // namespace CGAL

#endif // CGAL_BODT_3_INTERNAL_INSERTION_INSERTION_PASS_H
