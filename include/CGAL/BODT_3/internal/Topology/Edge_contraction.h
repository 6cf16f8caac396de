// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_BODT_3_INTERNAL_TOPOLOGY_EDGE_CONTRACTION_H
#define CGAL_BODT_3_INTERNAL_TOPOLOGY_EDGE_CONTRACTION_H

#include <CGAL/BODT_3/internal/Topology/Flip.h>

#include <algorithm>
#include <array>
#include <limits>
#include <vector>

namespace CGAL {
namespace BODT_3 {
namespace internal {

/// Edge contraction (Klingner and Shewchuk's Stellar, Sec. 3): vertex u is
/// removed by moving it onto its neighbour w, which stays where it is. The cells
/// around u that contain w vanish; every other cell around u becomes the same
/// cell with w for u. The proposal goes into a `Flip` (with `removed` set to u)
/// for `replace_cells`.
///
/// Allowed only where it changes no constraint, so that every region keeps its
/// exact volume and the surface keeps its exact shape:
///  - u is not on a curve edge, and the facets around u that are constrained (in
///    the complex, or between cells of different regions) are all of one patch
///    and exactly coplanar; when there are any, w is on that plane and u w is an
///    edge of one of them (a vertex of a flat part of the boundary or of an
///    interface slides along it; a vertex with none is inside one region). Then
///    every region's part of u's star is the union of the new cells of that region.
///  - The link condition holds (the contraction keeps the triangulation a
///    manifold): the links of u and w share no triangle, and the vertices and
///    edges they share are exactly those of the link of u w. The infinite vertex
///    counts as any other, so this holds for the triangulation as a sphere.
///  - Every new finite cell is positively oriented (exact predicate) and, in the
///    mesh, within the context's bounds.
/// The caller decides which vertices may go (their classification: corners and
/// feature vertices never do).
template <class Adapter>
struct Edge_contraction
{
  using Vertex_handle = typename Adapter::Vertex_handle;
  using Cell_handle = typename Adapter::Cell_handle;

private:
  using Triangle = std::array<Vertex_handle, 3>;
  using Edge = std::array<Vertex_handle, 2>;

  // Scratch space kept between calls.
  mutable std::vector<Cell_handle> star_w_;
  mutable std::vector<Triangle> link_u_, link_w_;
  mutable std::vector<Edge> edges_u_, edges_w_, ring_edges_;
  mutable std::vector<Vertex_handle> near_u_, near_w_, ring_;

  static Triangle sorted(Vertex_handle a, Vertex_handle b, Vertex_handle c)
  {
    Triangle t{a, b, c};
    std::sort(t.begin(), t.end());
    return t;
  }
  static Edge sorted(Vertex_handle a, Vertex_handle b) { return a < b ? Edge{a, b} : Edge{b, a}; }
  template <class T>
  static void unique(std::vector<T>& v)
  {
    std::sort(v.begin(), v.end());
    v.erase(std::unique(v.begin(), v.end()), v.end());
  }

  // The link of vertex x over its star: triangles, edges and vertices (sorted, unique).
  static void link(const std::vector<Cell_handle>& star, Vertex_handle x, std::vector<Triangle>& triangles,
                   std::vector<Edge>& edges, std::vector<Vertex_handle>& vertices)
  {
    triangles.clear();
    edges.clear();
    vertices.clear();
    for(const Cell_handle& c : star)
    {
      const int i = c->index(x);
      const Vertex_handle a = c->vertex((i + 1) % 4), b = c->vertex((i + 2) % 4), d = c->vertex((i + 3) % 4);
      triangles.push_back(sorted(a, b, d));
      edges.push_back(sorted(a, b));
      edges.push_back(sorted(b, d));
      edges.push_back(sorted(a, d));
      vertices.insert(vertices.end(), {a, b, d});
    }
    unique(triangles);
    unique(edges);
    unique(vertices);
  }

  // Whether contracting u w keeps the triangulation a manifold (see above).
  bool link_condition(Adapter& adapter, Vertex_handle u, Vertex_handle w,
                      const std::vector<Cell_handle>& star_u) const
  {
    star_w_.clear();
    adapter.tds().incident_cells(w, std::back_inserter(star_w_));
    link(star_u, u, link_u_, edges_u_, near_u_);
    link(star_w_, w, link_w_, edges_w_, near_w_);
    // The link of u w: the ring around the edge, and its edges.
    ring_.clear();
    ring_edges_.clear();
    for(const Cell_handle& c : star_u)
    {
      if(!c->has_vertex(w)) continue;
      Vertex_handle other[2];
      for(int k = 0, m = 0; k < 4; ++k)
        if(c->vertex(k) != u && c->vertex(k) != w) other[m++] = c->vertex(k);
      ring_.insert(ring_.end(), {other[0], other[1]});
      ring_edges_.push_back(sorted(other[0], other[1]));
    }
    unique(ring_);
    unique(ring_edges_);
    // Shared vertices other than u and w: exactly the ring.
    std::size_t shared = 0;
    for(Vertex_handle x : near_u_)
    {
      if(x == w || !std::binary_search(near_w_.begin(), near_w_.end(), x)) continue;
      if(!std::binary_search(ring_.begin(), ring_.end(), x)) return false;
      ++shared;
    }
    if(shared != ring_.size()) return false;
    // Shared edges: exactly the ring's (those of u's link through w are not w's).
    for(const Edge& e : edges_u_)
      if(std::binary_search(edges_w_.begin(), edges_w_.end(), e) &&
         !std::binary_search(ring_edges_.begin(), ring_edges_.end(), e))
        return false;
    for(const Triangle& t : link_u_)
      if(std::binary_search(link_w_.begin(), link_w_.end(), t)) return false;
    return true;
  }

public:
  /// Proposes the contraction of u onto w in `out` (its cells are those around u,
  /// `out.removed` gets u); returns false if it is not allowed or makes an invalid
  /// cell. `out.improves()` tells whether the worst mesh cell around u gets better.
  /// With `at_least`, a proposal whose worst cell is not better than that fails early.
  bool operator()(const Flip_context<Adapter>& ctx, Vertex_handle u, Vertex_handle w, Flip<Adapter>& out,
                  double at_least = -std::numeric_limits<double>::infinity()) const
  {
    out.clear();
    if(ctx.is_infinite(u) || ctx.is_infinite(w) || u == w) return false;
    Adapter& adapter = ctx.adapter;
    std::vector<Cell_handle>& star = out.old_cells;
    adapter.tds().incident_cells(u, std::back_inserter(star));

    // The constraints around u: no curve, one patch, one plane through w.
    bool joins = false;   // u w is a constrained facet's edge
    const Triangle* plane = nullptr;
    Triangle first{};
    typename Adapter::Patch patch;
    for(const Cell_handle& c : star)
    {
      const auto r = adapter.region(c);
      if(r.kind != Region_kind::infinite && r.kind != Region_kind::mesh && !ctx.flippable(r)) return false;
      const int i = c->index(u);
      for(int k = 0; k < 4; ++k)
      {
        if(k == i) continue;
        const Cell_handle n = c->neighbor(k);
        const auto p = adapter.patch(c, k);
        if(!p.in_complex && adapter.region(n) == r) continue;
        Triangle t;
        for(int j = 0, m = 0; j < 4; ++j)
          if(j != k) t[m++] = c->vertex(j);
        for(const Vertex_handle& x : t)
          if(ctx.is_infinite(x)) return false;   // through the infinite vertex: no plane to keep
        if(!plane)
        {
          first = t;
          plane = &first;
          patch = p;
        }
        else if(p != patch)
          return false;
        for(const Vertex_handle& x : t)
          if(CGAL::orientation(ctx.point(first[0]), ctx.point(first[1]), ctx.point(first[2]), ctx.point(x)) !=
             CGAL::COPLANAR)
            return false;
        joins = joins || std::find(t.begin(), t.end(), w) != t.end();
      }
      for(int k = 0; k < 4; ++k)
        if(k != i && !ctx.is_infinite(c->vertex(k)) && adapter.is_curve_edge(u, c->vertex(k))) return false;
    }
    if(plane && !joins) return false;   // w on the plane is implied: u w is an edge of a facet in it
    if(!link_condition(adapter, u, w, star)) return false;

    out.old_worst = Flip_context<Adapter>::unmeasured;
    for(const Cell_handle& c : star)
      if(adapter.region(c).kind == Region_kind::mesh) out.old_worst = std::min(out.old_worst, ctx.quality(c));
    if(out.old_worst == Flip_context<Adapter>::unmeasured) return false;   // no mesh cell: nothing to improve

    const double floor = std::max(out.old_worst, at_least);
    out.new_worst = Flip_context<Adapter>::unmeasured;
    for(std::size_t k = 0; k < star.size(); ++k)
    {
      const Cell_handle c = star[k];
      if(c->has_vertex(w)) continue;
      std::array<Vertex_handle, 4> v;
      for(int j = 0; j < 4; ++j) v[j] = c->vertex(j) == u ? w : c->vertex(j);
      const double q = ctx.value(v, adapter.region(c).kind, Region_kind::mesh, floor);
      if(q == Flip_context<Adapter>::invalid) return false;
      out.new_worst = std::min(out.new_worst, q);
      out.new_cells.push_back({v, static_cast<int>(k)});
      // Constrained facets through u move with it onto w, with their patch.
      const int i = c->index(u);
      for(int f = 0; f < 4; ++f)
      {
        if(f == i || !adapter.patch(c, f).in_complex) continue;
        Triangle t;
        for(int j = 0, m = 0; j < 4; ++j)
          if(j != f) t[m++] = v[j];
        if(c->neighbor(f)->has_vertex(w) || !(c->vertex(f) < c->neighbor(f)->vertex(c->neighbor(f)->index(c))))
          continue;   // each facet once (from the side with the smaller far vertex)
        out.new_facets.push_back({t, adapter.patch(c, f)});
      }
    }
    if(out.new_cells.empty()) return false;
    out.kind = Flip_kind::edge_contraction;
    out.boundary = plane != nullptr;
    out.removed = u;
    return true;
  }
};

} // namespace internal
} // namespace BODT_3
} // namespace CGAL

#endif // CGAL_BODT_3_INTERNAL_TOPOLOGY_EDGE_CONTRACTION_H
