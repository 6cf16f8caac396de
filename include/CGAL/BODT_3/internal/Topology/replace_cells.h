// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_BODT_3_INTERNAL_TOPOLOGY_REPLACE_CELLS_H
#define CGAL_BODT_3_INTERNAL_TOPOLOGY_REPLACE_CELLS_H

#include <CGAL/BODT_3/internal/Mesh/Triangulation_adapter.h>

#include <algorithm>
#include <array>
#include <vector>

namespace CGAL {
namespace BODT_3 {
namespace internal {

/// A cell to create: its vertices, in positive order, and which of the replaced
/// cells gives it its region (subdomain).
template <class Vertex_handle>
struct New_cell
{
  std::array<Vertex_handle, 4> vertices;
  int region_of;
};

/// A facet between two new cells that enters the complex, with its patch.
template <class Vertex_handle, class Patch>
struct New_facet
{
  std::array<Vertex_handle, 3> vertices;
  Patch patch;
};


// For a cell (v0, v1, v2, v3), the facet opposite vertex i with the orientation the
// cell induces on it (every such triple is an even permutation away from the others).
constexpr int kFacet[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};

// An oriented triangle as a key: rotated so that its smallest handle comes first,
// so that two cells on the same side of a facet give the same key, and two cells on
// opposite sides give keys that differ by a swap of the last two entries.
template <class Vertex_handle>
std::array<Vertex_handle, 3> oriented_key(Vertex_handle a, Vertex_handle b, Vertex_handle c)
{
  if(b < a && b < c) return {b, c, a};
  if(c < a && c < b) return {c, a, b};
  return {a, b, c};
}

template <class Vertex_handle>
std::array<Vertex_handle, 3> sorted_key(std::array<Vertex_handle, 3> f)
{
  std::sort(f.begin(), f.end());
  return f;
}


/// Replaces `old_cells` of the triangulation behind `adapter` by `new_cells`: the
/// n-to-m step shared by every flip and split. The new cells must fill exactly the
/// region of the old ones: every facet on the boundary of the old group must be a
/// facet of exactly one new cell, with the same orientation, and every other facet
/// of a new cell must be shared by two new cells with opposite orientations; every
/// vertex of the old cells must remain. These conditions are checked before anything
/// changes, and the function returns false (the triangulation untouched) when one
/// fails. Geometry is the caller's business: it must have checked that the new
/// finite cells are positively oriented.
///
/// Labels travel: each new cell gets the region (subdomain) of the old cell named by
/// its `region_of`; boundary facets of the group keep their patch; `new_facets`
/// (facets between new cells) enter the complex. Old facets of the complex inside
/// the group leave it. Vertices keep pointing to live cells. The new cells are
/// appended to `created` when it is given, in the order of `new_cells`.
///
/// For undoing a split, `regions` (when given) replaces the old cells' regions as
/// what `region_of` indexes, and the vertices in `removed` may (must) disappear:
/// they are deleted from the triangulation.
template <class Adapter>
bool replace_cells(Adapter& adapter, const std::vector<typename Adapter::Cell_handle>& old_cells,
                   const std::vector<New_cell<typename Adapter::Vertex_handle>>& new_cells,
                   const std::vector<New_facet<typename Adapter::Vertex_handle, typename Adapter::Patch>>& new_facets,
                   std::vector<typename Adapter::Cell_handle>* created = nullptr,
                   const std::vector<typename Adapter::Region>* regions = nullptr,
                   const std::vector<typename Adapter::Vertex_handle>& removed = {})
{
  using Vertex_handle = typename Adapter::Vertex_handle;
  using Cell_handle = typename Adapter::Cell_handle;
  using Key = std::array<Vertex_handle, 3>;
  auto& tds = adapter.tds();

  auto is_old = [&](Cell_handle c) { return std::find(old_cells.begin(), old_cells.end(), c) != old_cells.end(); };

  // The boundary of the old group: outer neighbour, and the facet's patch.
  struct Boundary
  {
    Key key;
    Cell_handle old_cell;
    int old_index;
    Cell_handle outer;
    int outer_index;
    int matched;
  };
  std::vector<Boundary> boundary;
  std::vector<Vertex_handle> old_vertices;
  for(Cell_handle c : old_cells)
    for(int i = 0; i < 4; ++i)
    {
      old_vertices.push_back(c->vertex(i));
      const Cell_handle n = c->neighbor(i);
      if(is_old(n)) continue;
      const auto& f = internal::kFacet[i];
      boundary.push_back({internal::oriented_key(c->vertex(f[0]), c->vertex(f[1]), c->vertex(f[2])), c, i, n,
                          n->index(c), 0});
    }

  // Match the facets of the new cells.
  const std::size_t nn = new_cells.size();
  std::vector<std::array<int, 4>> partner(nn, std::array<int, 4>{-1, -1, -1, -1});   // 4 * cell + facet
  std::vector<std::array<int, 4>> outer(nn, std::array<int, 4>{-1, -1, -1, -1});     // into `boundary`
  std::vector<Key> keys(4 * nn);
  for(std::size_t k = 0; k < nn; ++k)
    for(int i = 0; i < 4; ++i)
    {
      const auto& v = new_cells[k].vertices;
      const auto& f = internal::kFacet[i];
      keys[4 * k + i] = internal::oriented_key(v[f[0]], v[f[1]], v[f[2]]);
    }
  for(std::size_t k = 0; k < nn; ++k)
    for(int i = 0; i < 4; ++i)
    {
      const Key& key = keys[4 * k + i];
      bool found = false;
      for(std::size_t b = 0; b < boundary.size() && !found; ++b)
        if(boundary[b].key == key)
        {
          if(boundary[b].matched++) return false;
          outer[k][i] = static_cast<int>(b);
          found = true;
        }
      if(found) continue;
      const Key opposite = {key[0], key[2], key[1]};
      for(std::size_t l = 0; l < nn && !found; ++l)
        for(int j = 0; j < 4 && !found; ++j)
          if(l != k && keys[4 * l + j] == opposite)
          {
            if(partner[k][i] >= 0) return false;
            partner[k][i] = static_cast<int>(4 * l + j);
            found = true;
          }
      if(!found) return false;
    }
  for(const Boundary& b : boundary)
    if(b.matched != 1) return false;
  for(Vertex_handle v : old_vertices)
  {
    bool kept = false;
    for(std::size_t k = 0; k < nn && !kept; ++k)
      kept = std::find(new_cells[k].vertices.begin(), new_cells[k].vertices.end(), v) != new_cells[k].vertices.end();
    const bool goes = std::find(removed.begin(), removed.end(), v) != removed.end();
    if(kept == goes) return false;
  }
  std::vector<int> facet_of_new_facet(new_facets.size(), -1);
  for(std::size_t f = 0; f < new_facets.size(); ++f)
  {
    const Key want = internal::sorted_key(new_facets[f].vertices);
    for(std::size_t k = 0; k < nn && facet_of_new_facet[f] < 0; ++k)
      for(int i = 0; i < 4; ++i)
        if(partner[k][i] >= 0 && internal::sorted_key(keys[4 * k + i]) == want)
        {
          facet_of_new_facet[f] = static_cast<int>(4 * k + i);
          break;
        }
    if(facet_of_new_facet[f] < 0) return false;
  }

  // Checked: now change the triangulation. Facets of the complex on the group's
  // boundary and inside it leave the complex while both sides still exist.
  std::vector<typename Adapter::Patch> boundary_patch(boundary.size());
  for(std::size_t b = 0; b < boundary.size(); ++b)
  {
    boundary_patch[b] = adapter.patch(boundary[b].old_cell, boundary[b].old_index);
    adapter.remove_facet(boundary[b].old_cell, boundary[b].old_index);
  }
  std::vector<typename Adapter::Region> old_regions;
  for(Cell_handle c : old_cells)
  {
    old_regions.push_back(adapter.region(c));
    for(int i = 0; i < 4; ++i)
      if(is_old(c->neighbor(i))) adapter.remove_facet(c, i);
  }
  for(Cell_handle c : old_cells) adapter.remove_cell(c);

  std::vector<Cell_handle> cells(nn);
  for(std::size_t k = 0; k < nn; ++k)
  {
    const auto& v = new_cells[k].vertices;
    cells[k] = tds.create_cell(v[0], v[1], v[2], v[3]);
  }
  for(std::size_t k = 0; k < nn; ++k)
    for(int i = 0; i < 4; ++i)
    {
      if(outer[k][i] >= 0)
      {
        const Boundary& b = boundary[outer[k][i]];
        tds.set_adjacency(cells[k], i, b.outer, b.outer_index);
      }
      else
      {
        const int p = partner[k][i];
        tds.set_adjacency(cells[k], i, cells[p / 4], p % 4);
      }
    }
  for(std::size_t k = 0; k < nn; ++k)
    for(int i = 0; i < 4; ++i) cells[k]->vertex(i)->set_cell(cells[k]);
  for(Cell_handle c : old_cells)
  {
    adapter.changed(c);
    tds.delete_cell(c);
  }
  for(Vertex_handle v : removed) tds.delete_vertex(v);

  const auto& region = regions ? *regions : old_regions;
  for(std::size_t k = 0; k < nn; ++k) adapter.add_cell(cells[k], region[new_cells[k].region_of]);
  for(std::size_t k = 0; k < nn; ++k)
    for(int i = 0; i < 4; ++i)
      if(outer[k][i] >= 0) adapter.add_facet(cells[k], i, boundary_patch[outer[k][i]]);
  for(std::size_t f = 0; f < new_facets.size(); ++f)
    adapter.add_facet(cells[facet_of_new_facet[f] / 4], facet_of_new_facet[f] % 4, new_facets[f].patch);
  for(Cell_handle c : cells) adapter.changed(c);
  if(created) created->insert(created->end(), cells.begin(), cells.end());
  return true;
}

} // namespace internal
} // namespace BODT_3
} // namespace CGAL

#endif // CGAL_BODT_3_INTERNAL_TOPOLOGY_REPLACE_CELLS_H
