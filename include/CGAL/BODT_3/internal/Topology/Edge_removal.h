// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_BODT_3_INTERNAL_TOPOLOGY_EDGE_REMOVAL_H
#define CGAL_BODT_3_INTERNAL_TOPOLOGY_EDGE_REMOVAL_H

#include <CGAL/BODT_3/internal/Topology/Flip.h>
#include <CGAL/BODT_3/internal/Utilities/prefetch.h>

#include <CGAL/Triangulation_utils_3.h>

#include <algorithm>
#include <array>
#include <limits>
#include <vector>

namespace CGAL {
namespace BODT_3 {
namespace internal {


// The best triangulation of a polygon w_0 .. w_{n-1} (ring order around an edge
// u v) for edge removal, by dynamic programming (Klincsek; Shewchuk, "Two discrete
// optimization algorithms for the topological improvement of tetrahedral meshes"):
// each triangle (w_a, w_b, w_c), a < b < c, gives the cells (w_a, w_b, w_c, v) and
// (w_c, w_b, w_a, u), and the triangulation maximizing the worst of its cells wins.
class Polygon_triangulation
{
public:
  // `value(a, b, c)` is the worse of the two cells of triangle (a, b, c). The
  // tables are kept from one call to the next (edge removal is tried often).
  template <class Value>
  void solve(int n, const Value& value)
  {
    n_ = n;
    best_.assign(n * n, 0);
    split_.assign(n * n, -1);
    for(int a = 0; a + 1 < n; ++a) best_[a * n + a + 1] = std::numeric_limits<double>::infinity();
    for(int len = 2; len < n; ++len)
      for(int a = 0; a + len < n; ++a)
      {
        const int c = a + len;
        double best = -2;
        int arg = -1;
        for(int b = a + 1; b < c; ++b)
        {
          // The triangle cannot raise the result above its two sub-polygons':
          // skip its (costly) cells when they already lose.
          const double sub = std::min(best_[a * n + b], best_[b * n + c]);
          if(sub <= best) continue;
          const double q = std::min(sub, value(a, b, c));
          if(q > best)
          {
            best = q;
            arg = b;
          }
        }
        best_[a * n + c] = best;
        split_[a * n + c] = arg;
      }
  }

  double worst() const { return best_[n_ - 1]; }

  // The triangles (a, b, c) of the best triangulation.
  void triangles(std::vector<std::array<int, 3>>& out) const { collect(0, n_ - 1, out); }

private:
  void collect(int a, int c, std::vector<std::array<int, 3>>& out) const
  {
    if(c - a < 2) return;
    const int b = split_[a * n_ + c];
    out.push_back({a, b, c});
    collect(a, b, out);
    collect(b, c, out);
  }

  int n_ = 0;
  std::vector<double> best_;
  std::vector<int> split_;
};


/// Edge removal: the m cells around an edge u v are replaced by the 2 (m - 2)
/// cells of the best triangulation of the ring of its m neighbours (m = 3 is the
/// 3-2 flip, m = 4 the 4-4 flip). The outer facets of the ring keep their place,
/// so boundary facets on the ring are kept.
///
/// Allowed where the edge is not a curve edge, and either
///  - all cells around it are of one flippable region (inside one subdomain, or
///    outside the complex when flips there are on), or
///  - exactly two facets around it are constrained (in the complex, or between
///    different regions), of the same patch, and the edge's endpoints and the two
///    far vertices r_p, r_q of those facets are exactly coplanar: then both sides are
///    triangulated separately with the chord r_p r_q, the facets (u, r_p, r_q) and
///    (v, r_p, r_q) replace (u, v, r_p) and (u, v, r_q) in the complex (a 2-2 flip
///    on the surface, or 4-4 with the cells beyond), and the surface does not move.
///    A side made of infinite cells (the edge on the convex hull) must be two cells.
template <class Adapter>
struct Edge_removal
{
  using Vertex_handle = typename Adapter::Vertex_handle;
  using Cell_handle = typename Adapter::Cell_handle;

  int max_ring = 10;   // larger rings are left alone: they rarely help and cost O(m^3)

private:
  // Scratch space kept between calls.
  mutable std::vector<Vertex_handle> ring_;
  mutable std::vector<int> constrained_;
  mutable std::vector<std::array<int, 3>> triangles_;
  mutable internal::Polygon_triangulation polygon_;

public:

  /// Proposes the removal of edge (c, i, j) in `out`; returns false if it is not
  /// allowed or no triangulation is valid. `out.improves()` tells whether to apply it.
  /// With `at_least`, only a proposal whose worst cell is better than that counts
  /// (a caller comparing alternatives passes its best so far): the search skips
  /// what cannot beat it, and returns false when nothing does.
  bool operator()(const Flip_context<Adapter>& ctx, Cell_handle c, int i, int j, Flip<Adapter>& out,
                  double at_least = -std::numeric_limits<double>::infinity()) const
  {
    out.clear();
    Vertex_handle u = c->vertex(i), v = c->vertex(j);
    if(ctx.is_infinite(u) || ctx.is_infinite(v) || ctx.adapter.is_curve_edge(u, v)) return false;

    // Around the edge as the TDS's circulator turns: cell k's neighbour across the
    // facet opposite its vertex next_around_edge(u, v) is cell k + 1, so that
    // vertex, ring[k], is shared by cells k - 1 and k, and cell k is
    // {u, v, ring[k], ring[k+1]}.
    std::vector<Cell_handle>& cells = out.old_cells;
    std::vector<Vertex_handle>& ring = ring_;
    ring.clear();
    Cell_handle x = c;
    do
    {
      const int next = Triangulation_utils_3::next_around_edge(x->index(u), x->index(v));
      cells.push_back(x);
      ring.push_back(x->vertex(next));
      if(static_cast<int>(cells.size()) > max_ring) return false;
      x = x->neighbor(next);
      prefetch(x);
      prefetch(ring.back());
    } while(x != c);
    const int m = static_cast<int>(cells.size());
    if(m < 3) return false;

    if(!Flip_context<Adapter>::same_orientation(cells[0], u, v, ring[0], ring[1])) std::swap(u, v);

    // Constrained facets (u, v, ring[k]) between cells k-1 and k.
    std::vector<int>& constrained = constrained_;
    constrained.clear();
    for(int k = 0; k < m; ++k)
    {
      const Cell_handle prev = cells[(k + m - 1) % m];
      const int f = cells[k]->index(ring[(k + 1) % m]);
      if(ctx.adapter.patch(cells[k], f).in_complex || ctx.adapter.region(prev) != ctx.adapter.region(cells[k]))
        constrained.push_back(k);
    }

    // Sides: runs of ring positions first .. last (last may pass m), triangulated apart.
    struct Side
    {
      int first, last;
    };
    Side sides[2];
    int num_sides = 0;
    Region_kind measured = Region_kind::mesh;
    if(constrained.empty())
    {
      const auto r = ctx.adapter.region(cells[0]);
      if(!ctx.flippable(r)) return false;
      measured = r.kind;
      sides[num_sides++] = {0, m - 1};
    }
    else if(constrained.size() == 2)
    {
      const int p = constrained[0], q = constrained[1];
      const int fp = cells[p]->index(ring[(p + 1) % m]), fq = cells[q]->index(ring[(q + 1) % m]);
      if(ctx.adapter.patch(cells[p], fp) != ctx.adapter.patch(cells[q], fq)) return false;
      if(ctx.is_infinite(ring[p]) || ctx.is_infinite(ring[q])) return false;
      if(CGAL::orientation(ctx.point(u), ctx.point(v), ctx.point(ring[p]), ctx.point(ring[q])) != CGAL::COPLANAR)
        return false;
      bool any_mesh = false;
      for(const Side s : {Side{p, q}, Side{q, p + m}})
      {
        const auto r = ctx.adapter.region(cells[s.first % m]);
        if(s.last - s.first < 2 || (r.kind == Region_kind::infinite && s.last - s.first != 2)) return false;
        any_mesh = any_mesh || r.kind == Region_kind::mesh;
        sides[num_sides++] = s;
      }
      if(!any_mesh) return false;
      out.boundary = true;
      out.new_facets.push_back({{u, ring[p], ring[q]}, ctx.adapter.patch(cells[p], fp)});
      out.new_facets.push_back({{v, ring[p], ring[q]}, ctx.adapter.patch(cells[p], fp)});
    }
    else
      return false;

    out.old_worst = Flip_context<Adapter>::unmeasured;
    for(const Cell_handle& x : cells)
      if(ctx.adapter.region(x).kind == measured) out.old_worst = std::min(out.old_worst, ctx.quality(x));

    const double floor = std::max(out.old_worst, at_least);
    out.new_worst = Flip_context<Adapter>::unmeasured;
    std::vector<std::array<int, 3>>& triangles = triangles_;
    for(int k = 0; k < num_sides; ++k)
    {
      const Side& s = sides[k];
      const int n = s.last - s.first + 1;
      const int region_of = s.first % m;
      const Region_kind kind = ctx.adapter.region(cells[region_of]).kind;
      auto w = [&](int a) { return ring[(s.first + a) % m]; };
      // A triangle no better than the cells removed (or than `at_least`) cannot be
      // part of a proposal that counts.
      auto value = [&](int a, int b, int c) {
        const double top = ctx.value({w(a), w(b), w(c), v}, kind, measured, floor);
        if(top == Flip_context<Adapter>::invalid) return top;
        return std::min(top, ctx.value({w(c), w(b), w(a), u}, kind, measured, floor));
      };
      internal::Polygon_triangulation& best = polygon_;
      best.solve(n, value);
      out.new_worst = std::min(out.new_worst, best.worst());
      if(out.new_worst <= 0) return false;
      triangles.clear();
      best.triangles(triangles);
      for(const auto& t : triangles)
      {
        out.new_cells.push_back({{w(t[0]), w(t[1]), w(t[2]), v}, region_of});
        out.new_cells.push_back({{w(t[2]), w(t[1]), w(t[0]), u}, region_of});
      }
    }
    out.kind = m == 3 ? Flip_kind::flip_3_2 : Flip_kind::edge_removal;
    return true;
  }
};

} // namespace internal
} // namespace BODT_3
} // namespace CGAL

#endif // CGAL_BODT_3_INTERNAL_TOPOLOGY_EDGE_REMOVAL_H
