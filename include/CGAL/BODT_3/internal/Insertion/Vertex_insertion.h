// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_BODT_3_INTERNAL_INSERTION_VERTEX_INSERTION_H
#define CGAL_BODT_3_INTERNAL_INSERTION_VERTEX_INSERTION_H

#include <CGAL/BODT_3/internal/Mesh/Triangulation_adapter.h>
#include <CGAL/BODT_3/internal/Utilities/bare_point.h>
#include <CGAL/BODT_3/internal/Topology/replace_cells.h>

#include <CGAL/Kernel/global_functions.h>

#include <algorithm>
#include <array>
#include <iterator>
#include <stdexcept>
#include <vector>

namespace CGAL {
namespace BODT_3 {
namespace internal {

/// What a split did, so that `undo_split` can take it back: the cells it
/// created (by their vertices, since a later split may replace their handles), the
/// cells it replaced (vertices in positive order, regions), the facets of the
/// complex inside them, and the new vertex (with the edge it split).
template <class Adapter>
struct Split_record
{
  using Vertex_handle = typename Adapter::Vertex_handle;
  using Cell_handle = typename Adapter::Cell_handle;

  std::vector<std::array<Vertex_handle, 4>> created;
  std::vector<New_cell<Vertex_handle>> old_cells;
  std::vector<typename Adapter::Region> old_regions;
  std::vector<New_facet<Vertex_handle, typename Adapter::Patch>> old_facets;
  Vertex_handle vertex;
  Vertex_handle a, b;   // the split edge's ends; default for a split facet
  /// The boundary or interface facets split (in the complex, or between cells of
  /// different regions: the convex hull of a Triangulation_3), with their patches.
  std::vector<typename Adapter::Patch> boundary;
};


template <class Adapter>
bool finite_cells_positive(const Adapter& adapter, const std::vector<New_cell<typename Adapter::Vertex_handle>>& cells)
{
  const auto& tr = adapter.triangulation();
  for(const auto& c : cells)
  {
    bool finite = true;
    for(const auto& v : c.vertices) finite = finite && !tr.is_infinite(v);
    if(finite && CGAL::orientation(bare_point(tr, c.vertices[0]), bare_point(tr, c.vertices[1]),
                                   bare_point(tr, c.vertices[2]), bare_point(tr, c.vertices[3])) != CGAL::POSITIVE)
      return false;
  }
  return true;
}

// Records the replaced cells and the facets of the complex among them.
template <class Adapter>
void record_old(Adapter& adapter, const std::vector<typename Adapter::Cell_handle>& old, Split_record<Adapter>& r)
{
  for(std::size_t k = 0; k < old.size(); ++k)
  {
    const auto& c = old[k];
    r.old_cells.push_back({{c->vertex(0), c->vertex(1), c->vertex(2), c->vertex(3)}, static_cast<int>(k)});
    r.old_regions.push_back(adapter.region(c));
    for(int i = 0; i < 4; ++i)
    {
      const auto n = c->neighbor(i);
      if(std::find(old.begin(), old.end(), n) == old.end() || n < c) continue;   // each inner facet once
      const auto p = adapter.patch(c, i);
      if(!p.in_complex) continue;
      const auto& f = internal::kFacet[i];
      r.old_facets.push_back({{c->vertex(f[0]), c->vertex(f[1]), c->vertex(f[2])}, p});
    }
  }
}

// Whether the hull around new vertex `e` is locally convex, where the hull must
// stay convex: a split point off its edge or facet by round-off can dent it.
template <class Adapter>
bool hull_stays_convex(const Adapter& adapter, typename Adapter::Vertex_handle e)
{
  if(!adapter.convex_hull()) return true;
  const auto& tr = adapter.triangulation();
  std::vector<typename Adapter::Cell_handle> cells;
  tr.tds().incident_cells(e, std::back_inserter(cells));
  for(const auto& c : cells)
  {
    if(!tr.is_infinite(c)) continue;
    const int i = c->index(tr.infinite_vertex());
    const auto fc = c->neighbor(i);
    const auto& o = kFacet[fc->index(c)];
    // Oriented with the inside on the positive side.
    const auto a = bare_point(tr, fc->vertex(o[0])), b = bare_point(tr, fc->vertex(o[2])),
               d = bare_point(tr, fc->vertex(o[1]));
    for(int k = 0; k < 4; ++k)
    {
      if(k == i) continue;
      const auto nc = c->neighbor(k);
      const auto w = nc->vertex(nc->index(c));
      if(!tr.is_infinite(w) && CGAL::orientation(a, b, d, bare_point(tr, w)) == CGAL::NEGATIVE) return false;
    }
  }
  return true;
}


template <class Adapter>
void undo_split(Adapter& adapter, const Split_record<Adapter>& r);

// The cells around new vertex `e`: each old cell once per end of the split
// simplex, with that end replaced by e; they keep the old cell's region.
template <class Vertex_handle, class Cell_handle, class Ends>
std::vector<New_cell<Vertex_handle>> cells_around_new_vertex(const std::vector<Cell_handle>& old, Vertex_handle e,
                                                             const Ends& ends)
{
  std::vector<New_cell<Vertex_handle>> cells;
  for(std::size_t k = 0; k < old.size(); ++k)
    for(const Vertex_handle replaced : ends)
    {
      std::array<Vertex_handle, 4> q = {old[k]->vertex(0), old[k]->vertex(1), old[k]->vertex(2), old[k]->vertex(3)};
      *std::find(q.begin(), q.end(), replaced) = e;
      cells.push_back({q, static_cast<int>(k)});
    }
  return cells;
}

// Replaces `old` by the cells around new vertex `e`, recording it in `r`; if a new
// finite cell would not be positively oriented, nothing changes, `e` goes, and false.
template <class Adapter>
bool replace_by_split(Adapter& adapter, const std::vector<typename Adapter::Cell_handle>& old,
                      const std::vector<New_cell<typename Adapter::Vertex_handle>>& cells,
                      const std::vector<New_facet<typename Adapter::Vertex_handle, typename Adapter::Patch>>& facets,
                      typename Adapter::Vertex_handle e, Split_record<Adapter>& r)
{
  record_old(adapter, old, r);
  if(!finite_cells_positive(adapter, cells) || !replace_cells(adapter, old, cells, facets))
  {
    adapter.tds().delete_vertex(e);
    return false;
  }
  for(const auto& nc : cells) r.created.push_back(nc.vertices);
  r.vertex = e;
  return true;
}

// The last check of a split: the convex hull, where it must stay convex.
template <class Adapter>
bool keep_split(Adapter& adapter, Split_record<Adapter>& r, Split_record<Adapter>& record)
{
  if(!hull_stays_convex(adapter, r.vertex))
  {
    undo_split(adapter, r);
    return false;
  }
  record = std::move(r);
  return true;
}

/// Splits edge (c, i, j) at `p` (a point of the edge, up to rounding): every cell
/// around the edge, in the mesh or not, becomes two that keep its region; the
/// facets of the complex around the edge become two with the same patch; a curve
/// edge becomes two on the same curve. The new vertex's dimension and index follow
/// (curve, patch, or subdomain). Refused (nothing changes, false) when a new finite
/// cell would not be positively oriented, or a convex hull that must stay convex
/// would not.
template <class Adapter>
bool split_edge(Adapter& adapter, typename Adapter::Cell_handle c, int i, int j,
                const Bare_point_t<typename Adapter::Triangulation>& p, Split_record<Adapter>& record)
{
  using Vertex_handle = typename Adapter::Vertex_handle;
  using Cell_handle = typename Adapter::Cell_handle;
  const auto& tr = adapter.triangulation();
  const Vertex_handle u = c->vertex(i), v = c->vertex(j);
  if(tr.is_infinite(u) || tr.is_infinite(v)) return false;

  std::vector<Cell_handle> old;
  auto circ = tr.incident_cells(c, i, j), done = circ;
  do old.push_back(circ);
  while(++circ != done);

  // The facets of the complex around the edge, and where the new vertex lies.
  typename Adapter::Patch patch;
  std::vector<std::pair<Vertex_handle, typename Adapter::Patch>> around;   // (far vertex of (u, v, x), patch)
  typename Adapter::Region region = adapter.region(c);
  for(const Cell_handle& x : old)
  {
    if(adapter.region(x).kind == Region_kind::mesh) region = adapter.region(x);
    for(int k = 0; k < 4; ++k)
    {
      const Vertex_handle w = x->vertex(k);
      if(w == u || w == v) continue;
      // The facet (u, v, other) of x, opposite w, if it is a boundary or interface.
      const auto fp = adapter.patch(x, k);
      if(!fp.in_complex && adapter.region(x) == adapter.region(x->neighbor(k))) continue;
      Vertex_handle other;
      for(int l = 0; l < 4; ++l)
        if(l != k && x->vertex(l) != u && x->vertex(l) != v) other = x->vertex(l);
      bool seen = false;
      for(const auto& a : around) seen = seen || a.first == other;
      if(!seen) around.emplace_back(other, fp);
      if(fp.in_complex) patch = fp;
    }
  }

  const Vertex_handle e = adapter.create_vertex(p, u, v, patch, region);
  const std::array<Vertex_handle, 2> ends = {u, v};
  std::vector<New_facet<Vertex_handle, typename Adapter::Patch>> facets;
  for(const auto& a : around)
    if(a.second.in_complex)
    {
      facets.push_back({{u, e, a.first}, a.second});
      facets.push_back({{e, v, a.first}, a.second});
    }
  Split_record<Adapter> r;
  if(!replace_by_split(adapter, old, cells_around_new_vertex(old, e, ends), facets, e, r)) return false;
  adapter.split_curve(u, v, e);
  r.a = u;
  r.b = v;
  for(const auto& a : around) r.boundary.push_back(a.second);
  return keep_split(adapter, r, record);
}

/// Splits facet (c, i) at `p` (a point inside it, up to rounding): each of its two
/// cells becomes three that keep its region, and a facet of the complex becomes
/// three with its patch. Refused (false) when a new finite cell would not be
/// positively oriented, or a convex hull that must stay convex would not.
template <class Adapter>
bool split_facet(Adapter& adapter, typename Adapter::Cell_handle c, int i,
                 const Bare_point_t<typename Adapter::Triangulation>& p, Split_record<Adapter>& record)
{
  using Vertex_handle = typename Adapter::Vertex_handle;
  using Cell_handle = typename Adapter::Cell_handle;
  const Cell_handle n = c->neighbor(i);
  const std::vector<Cell_handle> old = {c, n};
  const auto patch = adapter.patch(c, i);
  const auto region = adapter.region(c).kind == Region_kind::mesh ? adapter.region(c) : adapter.region(n);
  std::array<Vertex_handle, 3> f;
  for(int k = 0, m = 0; k < 4; ++k)
    if(k != i) f[m++] = c->vertex(k);

  const Vertex_handle e = adapter.create_vertex(p, Vertex_handle(), Vertex_handle(), patch, region);
  std::vector<New_facet<Vertex_handle, typename Adapter::Patch>> facets;
  if(patch.in_complex)
    for(int k = 0; k < 3; ++k) facets.push_back({{f[k], f[(k + 1) % 3], e}, patch});
  Split_record<Adapter> r;
  if(!replace_by_split(adapter, old, cells_around_new_vertex(old, e, f), facets, e, r)) return false;
  if(patch.in_complex || adapter.region(c) != adapter.region(n)) r.boundary.push_back(patch);
  return keep_split(adapter, r, record);
}

/// Takes a split back: the cells it created (which must all still be there; the
/// caller first puts back the positions it changed since) become the cells it
/// replaced, with their regions and facets, a split curve edge is whole again, and
/// the new vertex goes.
template <class Adapter>
void undo_split(Adapter& adapter, const Split_record<Adapter>& r)
{
  std::vector<typename Adapter::Cell_handle> created;
  for(const auto& q : r.created)
  {
    typename Adapter::Cell_handle c;
    int i0, i1, i2, i3;
    if(!adapter.tds().is_cell(q[0], q[1], q[2], q[3], c, i0, i1, i2, i3))
      throw std::logic_error("undo_split: a cell of the split is gone");
    created.push_back(c);
  }
  if(r.a != typename Adapter::Vertex_handle()) adapter.join_curve(r.a, r.vertex, r.b);
  if(!replace_cells(adapter, created, r.old_cells, r.old_facets, nullptr, &r.old_regions, {r.vertex}))
    throw std::logic_error("undo_split: the split cannot be taken back");
}

} // namespace internal
} // namespace BODT_3
} // namespace CGAL

#endif // CGAL_BODT_3_INTERNAL_INSERTION_VERTEX_INSERTION_H
