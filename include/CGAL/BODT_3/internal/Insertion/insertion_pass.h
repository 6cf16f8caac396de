// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_BODT_3_INTERNAL_INSERTION_INSERTION_PASS_H
#define CGAL_BODT_3_INTERNAL_INSERTION_INSERTION_PASS_H

#include <CGAL/BODT_3/internal/Insertion/Bad_tet_shape.h>
#include <CGAL/BODT_3/internal/Smoothing/Local_smoothing.h>
#include <CGAL/BODT_3/internal/Mesh/Triangulation_adapter.h>
#include <CGAL/BODT_3/Smoothing_options.h>
#include <CGAL/BODT_3/Smoothing_result.h>
#include <CGAL/BODT_3/internal/Classification/Vertex_classification.h>
#include <CGAL/BODT_3/internal/Insertion/Vertex_insertion.h>
#include <CGAL/BODT_3/internal/Smoothing/Volume_budget.h>
#include <CGAL/BODT_3/internal/Utilities/bare_point.h>
#include <CGAL/BODT_3/internal/Topology/flip_pass.h>
#include <CGAL/BODT_3/internal/Quality/tet_quality.h>

#include <CGAL/FPU.h>
#include <CGAL/Real_timer.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>
#include <map>
#include <queue>
#include <vector>

namespace CGAL {
namespace BODT_3 {

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
/// spades, caps or slivers (Bad_tet_shape.h, with the angle bounds of the
/// threshold) are split: a spade's edge at the projection of its vertex, a cap's
/// face at the projection of its vertex, a sliver's two crossing edges at their
/// closest points. The new vertices and the tetrahedron's own are then smoothed
/// (`Local_smoothing`, `opt.smoothing_rounds` times), and the insertion is kept
/// only if the cells around those vertices compare better than before, worst first
/// (`compare_worst_first`), and stay within `bounds`; otherwise it is undone.
/// At most `budget` vertices are added.
///
/// `seeds`, when given, holds every mesh cell below the threshold (the quality
/// guard knows them), so that the pass does not measure every cell again.
///
/// `motion(v)` tells how an existing vertex moves; `boundary_moves` says whether
/// boundary vertices may move at all (not for the interior-only ODT baseline).
/// `added` receives the new vertices, `touched` the vertices whose star changed.
/// With a `volume_budget`, a split whose rounded point, off its boundary edge or
/// facet, changes a subdomain's volume and the moves of the smoothing that follows
/// are paid from it, as in the sweeps (Volume_budget.h); a split it cannot pay is undone.
template <class Labels, class Motion, class Vertex_id>
Insertion_stats insertion_pass(Labels& labels, const Insertion_options& opt, const Dihedral_bounds& bounds,
                               Quality_measure measure, const Tensor_voting_options& voting, std::size_t budget,
                               bool boundary_moves, const Motion& motion, const Vertex_id& vertex_id,
                               std::vector<Added_vertex<typename Labels::Vertex_handle>>& added,
                               std::vector<typename Labels::Vertex_handle>& touched, Attempt_history* history = nullptr,
                               const std::vector<typename Labels::Cell_handle>* seeds = nullptr,
                               Volume_budget* volume_budget = nullptr)
{
  using Vertex_handle = typename Labels::Vertex_handle;
  using Cell_handle = typename Labels::Cell_handle;
  using Tr = typename Labels::Triangulation;
  using Point = Bare_point_t<Tr>;
  CGAL::Real_timer timer;
  timer.start();
  Insertion_stats stats;
  Tr& tr = labels.triangulation();
  const auto point = [&](Vertex_handle v) { return bare_point(tr, v); };
  const auto quality = [&](Cell_handle c) {
    return tet_quality(measure, point(c->vertex(0)), point(c->vertex(1)), point(c->vertex(2)), point(c->vertex(3)));
  };

  Bad_tet_options shapes = opt.shapes;
  shapes.small_angle = std::asin(std::min(1.0, opt.quality_threshold)) * 180 / 3.14159265358979323846;
  shapes.large_angle = 180 - shapes.small_angle;

  struct Entry
  {
    double quality;
    std::array<int, 4> ids;
    Cell_handle cell;
    std::array<Vertex_handle, 4> vertices;
    bool operator<(const Entry& o) const
    {
      if(quality != o.quality) return quality > o.quality;
      return ids > o.ids;
    }
  };
  std::vector<Entry> candidates;
  auto consider = [&](Cell_handle c) {
    if(labels.region(c).kind != Region_kind::mesh) return;
    const double sine = min_dihedral_sine(point(c->vertex(0)), point(c->vertex(1)), point(c->vertex(2)),
                                          point(c->vertex(3)));
    if(!(sine < opt.quality_threshold)) return;
    Entry e{quality(c), {}, c, {c->vertex(0), c->vertex(1), c->vertex(2), c->vertex(3)}};
    for(int k = 0; k < 4; ++k) e.ids[k] = vertex_id(e.vertices[k]);
    std::sort(e.ids.begin(), e.ids.end());
    candidates.push_back(e);
  };
  if(seeds)
    for(Cell_handle c : *seeds) consider(c);
  else
    for(auto c = tr.finite_cells_begin(); c != tr.finite_cells_end(); ++c) consider(c);
  std::sort(candidates.begin(), candidates.end(), [](const Entry& a, const Entry& b) { return b < a; });

  Local_smoothing<Labels> smoother(labels, bounds, measure, voting, volume_budget);
  Volume_change change;
  // Whether a split's point, on its edge or facet `ends` up to rounding, changes
  // the subdomains around it within the budget (then paid). A split with no
  // boundary or interface facet keeps its region's union exactly.
  auto split_within_budget = [&](const Split_record<Labels>& r, std::initializer_list<Vertex_handle> ends) {
    if(!volume_budget || !volume_budget->limited() || r.boundary.empty()) return true;
    const Point p = point(r.vertex);
    change.clear();
    {
      CGAL::Protect_FPU_rounding<true> upward;
      for(const auto& old : r.old_cells)
      {
        const auto& region = r.old_regions[old.region_of];
        if(region.kind != Region_kind::mesh) continue;
        const int s = static_cast<int>(region.subdomain);
        Point q[4];
        for(int k = 0; k < 4; ++k) q[k] = point(old.vertices[k]);
        change.add_cell(s, -1, q[0], q[1], q[2], q[3]);
        // Each end of the split simplex, replaced by p, gives one of the new cells.
        for(int k = 0; k < 4; ++k)
          if(std::find(ends.begin(), ends.end(), old.vertices[k]) != ends.end())
          {
            Point n[4] = {q[0], q[1], q[2], q[3]};
            n[k] = p;
            change.add_cell(s, 1, n[0], n[1], n[2], n[3]);
          }
      }
    }
    const double cost = volume_budget->cost(change);
    if(!(cost <= volume_budget->allowance())) return false;
    volume_budget->spend(cost);
    return true;
  };
  std::map<Vertex_handle, Vertex_motion<Vertex_handle>> fresh;   // vertices added in this pass
  auto motion_of = [&](Vertex_handle v) {
    const auto it = fresh.find(v);
    return it != fresh.end() ? it->second : motion(v);
  };
  // The mesh cells around some vertices, and their qualities.
  std::vector<Cell_handle> around, scratch;
  auto cells_around = [&](const std::vector<Vertex_handle>& vs) {
    around.clear();
    for(Vertex_handle v : vs)
    {
      scratch.clear();
      tr.tds().incident_cells(v, std::back_inserter(scratch));
      for(Cell_handle c : scratch)
        if(labels.region(c).kind == Region_kind::mesh && std::find(around.begin(), around.end(), c) == around.end())
          around.push_back(c);
    }
    std::vector<double> q;
    for(Cell_handle c : around) q.push_back(quality(c));
    return q;
  };

  for(const Entry& e : candidates)
  {
    if(budget < 1) break;
    if(!tr.tds().cells().is_used(e.cell) ||
       !(e.cell->has_vertex(e.vertices[0]) && e.cell->has_vertex(e.vertices[1]) && e.cell->has_vertex(e.vertices[2]) &&
         e.cell->has_vertex(e.vertices[3])))
      continue;
    if(history && !history->worth_trying(e.ids)) continue;
    const Cell_handle c = e.cell;
    const Bad_tet shape = classify_bad_tet(point(c->vertex(0)), point(c->vertex(1)), point(c->vertex(2)),
                                           point(c->vertex(3)), shapes);
    const std::size_t needed = shape.shape == Bad_tet_shape::sliver ? 2 : 1;
    if((shape.shape != Bad_tet_shape::spade && shape.shape != Bad_tet_shape::cap &&
        shape.shape != Bad_tet_shape::sliver && shape.shape != Bad_tet_shape::wedge) ||
       needed > budget)
    {
      if(history) history->record_failure(e.ids);
      continue;
    }

    const std::vector<Vertex_handle> own = {c->vertex(0), c->vertex(1), c->vertex(2), c->vertex(3)};
    std::vector<double> before = cells_around(own);
    auto on_edge = [&](int a, int b, double t) {
      const Point pa = point(c->vertex(a)), pb = point(c->vertex(b));
      return pa + t * (pb - pa);
    };

    // The splits, each followed by the new vertex's motion.
    std::vector<Split_record<Labels>> records;
    auto split_at_edge = [&](Vertex_handle u, Vertex_handle v, const Point& p) {
      Cell_handle cell;
      int i, j;
      Split_record<Labels> r;
      if(!tr.tds().is_edge(u, v, cell, i, j) || !split_edge(labels, cell, i, j, p, r)) return false;
      if(!split_within_budget(r, {u, v}))
      {
        undo_split(labels, r);
        return false;
      }
      Vertex_motion<Vertex_handle> m{Vertex_kind::interior, u, v};
      const Vertex_motion<Vertex_handle> mu = motion_of(u), mv = motion_of(v);
      const bool boundary_ends = mu.kind != Vertex_kind::interior && mv.kind != Vertex_kind::interior;
      if(labels.is_curve_edge(r.vertex, u) || r.boundary.size() > 2 ||
         (r.boundary.size() == 2 && (r.boundary[0] != r.boundary[1] ||
                                     (mu.kind != Vertex_kind::surface && mv.kind != Vertex_kind::surface))))
        m.kind = Vertex_kind::feature;   // on a curve, a junction of patches, or a sharp edge between such vertices
      else if(!r.boundary.empty())
        m.kind = Vertex_kind::surface;
      if(m.kind == Vertex_kind::feature && !boundary_ends) m.kind = Vertex_kind::fixed;
      if(m.kind != Vertex_kind::interior && !boundary_moves) m.kind = Vertex_kind::fixed;
      fresh[r.vertex] = m;
      records.push_back(std::move(r));
      return true;
    };
    bool done = false;
    if(shape.shape == Bad_tet_shape::wedge)
    {
      // The edge opposite the short one, at the projection of the short edge's middle.
      int cd[2], m = 0;
      for(int k = 0; k < 4; ++k)
        if(k != shape.edge[0] && k != shape.edge[1]) cd[m++] = k;
      const Point pc = point(c->vertex(cd[0])), pd = point(c->vertex(cd[1]));
      const Point mid = CGAL::midpoint(point(c->vertex(shape.edge[0])), point(c->vertex(shape.edge[1])));
      const double t = ((mid - pc) * (pd - pc)) / (pd - pc).squared_length();
      if(t > shapes.margin && t < 1 - shapes.margin) done = split_at_edge(c->vertex(cd[0]), c->vertex(cd[1]), on_edge(cd[0], cd[1], t));
    }
    else if(shape.shape == Bad_tet_shape::spade)
      done = split_at_edge(c->vertex(shape.edge[0]), c->vertex(shape.edge[1]),
                           on_edge(shape.edge[0], shape.edge[1], shape.t[0]));
    else if(shape.shape == Bad_tet_shape::sliver)
    {
      const Vertex_handle a = c->vertex(shape.edge[0]), b = c->vertex(shape.edge[1]);
      const Vertex_handle d = c->vertex(shape.edge[2]), f = c->vertex(shape.edge[3]);
      const Point p = on_edge(shape.edge[0], shape.edge[1], shape.t[0]);
      const Point q = on_edge(shape.edge[2], shape.edge[3], shape.t[1]);
      done = split_at_edge(a, b, p) && split_at_edge(d, f, q);
    }
    else
    {
      int f[3], m = 0;
      for(int k = 0; k < 4; ++k)
        if(k != shape.vertex) f[m++] = k;
      const Vertex_handle fv[3] = {c->vertex(f[0]), c->vertex(f[1]), c->vertex(f[2])};
      const Point pf[3] = {point(fv[0]), point(fv[1]), point(fv[2])};
      const double s = shape.bary[0] + shape.bary[1] + shape.bary[2];
      const Point p(
          (shape.bary[0] * pf[0].x() + shape.bary[1] * pf[1].x() + shape.bary[2] * pf[2].x()) / s,
          (shape.bary[0] * pf[0].y() + shape.bary[1] * pf[1].y() + shape.bary[2] * pf[2].y()) / s,
          (shape.bary[0] * pf[0].z() + shape.bary[1] * pf[1].z() + shape.bary[2] * pf[2].z()) / s);
      Split_record<Labels> r;
      bool split = split_facet(labels, c, shape.vertex, p, r);
      if(split && !split_within_budget(r, {fv[0], fv[1], fv[2]}))
      {
        undo_split(labels, r);
        split = false;
      }
      if(split)
      {
        Vertex_motion<Vertex_handle> m{r.boundary.empty() ? Vertex_kind::interior : Vertex_kind::surface, {}, {}};
        // A facet whose three vertices are fixed lies where nothing may move (a crack
        // face, a surface embedded in one subdomain): its new vertex stays where it is.
        bool pinned = !r.boundary.empty();
        for(Vertex_handle x : fv) pinned = pinned && motion_of(x).kind == Vertex_kind::fixed;
        if(pinned || (m.kind != Vertex_kind::interior && !boundary_moves)) m.kind = Vertex_kind::fixed;
        fresh[r.vertex] = m;
        records.push_back(std::move(r));
        done = true;
      }
    }

    // Smooth the new vertices and the tetrahedron's own, then judge.
    std::vector<Vertex_handle> moved;
    std::vector<Point> was;
    if(done)
    {
      std::vector<Vertex_handle> order;
      for(const auto& r : records) order.push_back(r.vertex);
      order.insert(order.end(), own.begin(), own.end());
      for(int round = 0; round < opt.smoothing_rounds; ++round)
        for(Vertex_handle v : order)
        {
          const Point p = point(v);
          const auto m = motion_of(v);
          if(smoother.move(v, m.kind, m.a, m.b) && std::find(moved.begin(), moved.end(), v) == moved.end())
          {
            moved.push_back(v);
            was.push_back(p);
          }
        }
      std::vector<Vertex_handle> region = own;
      for(const auto& r : records) region.push_back(r.vertex);
      std::vector<double> after = cells_around(region);
      bool within = true;
      for(Cell_handle x : around)
        within = within && bounds.contains(point(x->vertex(0)), point(x->vertex(1)), point(x->vertex(2)),
                                           point(x->vertex(3)), 0.0);
      if(within && compare_worst_first(after, before) > 0)
      {
        for(const auto& r : records)
        {
          added.push_back({r.vertex, fresh[r.vertex].kind, fresh[r.vertex].a, fresh[r.vertex].b});
          ++stats.vertices_added;
          --budget;
        }
        for(Cell_handle x : around)
          for(int k = 0; k < 4; ++k) touched.push_back(x->vertex(k));
        if(shape.shape == Bad_tet_shape::spade || shape.shape == Bad_tet_shape::wedge) ++stats.spade_splits;
        if(shape.shape == Bad_tet_shape::cap) ++stats.cap_splits;
        if(shape.shape == Bad_tet_shape::sliver) ++stats.sliver_splits;
        if(history) ++history->clock;
        continue;
      }
    }
    // Undo: positions first, then the splits in reverse order.
    for(std::size_t k = moved.size(); k-- > 0;) set_bare_point(tr, moved[k], was[k]);
    for(std::size_t k = records.size(); k-- > 0;)
    {
      fresh.erase(records[k].vertex);
      undo_split(labels, records[k]);
    }
    ++stats.undone;
    if(history) history->record_failure(e.ids);
  }
  stats.seconds = timer.time();
  return stats;
}

} // namespace BODT_3
} // namespace CGAL

#endif // CGAL_BODT_3_INTERNAL_INSERTION_INSERTION_PASS_H
