// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_BODT_3_INTERNAL_UTILITIES_CANDIDATE_CELL_H
#define CGAL_BODT_3_INTERNAL_UTILITIES_CANDIDATE_CELL_H

#include <algorithm>
#include <array>

namespace CGAL {
namespace BODT_3 {
namespace internal {

/// A cell the insertion pass will try, as it was when it was queued: its
/// quality by the pass's measure, its vertex ids sorted (the key of the attempt
/// history, and what breaks ties, so that the order depends on the mesh alone),
/// its handle and its vertices (a later change may have replaced it).
template <class Cell_handle, class Vertex_handle>
struct Candidate_cell
{
  double quality;
  std::array<int, 4> ids;   // sorted
  Cell_handle cell;
  std::array<Vertex_handle, 4> vertices;

  /// The candidate of cell `c`, of quality `quality`; `vertex_id(v)` gives the ids.
  template <class Vertex_id>
  static Candidate_cell of(Cell_handle c, double quality, const Vertex_id& vertex_id)
  {
    Candidate_cell e{quality, {}, c, {c->vertex(0), c->vertex(1), c->vertex(2), c->vertex(3)}};
    for(int k = 0; k < 4; ++k) e.ids[k] = vertex_id(e.vertices[k]);
    std::sort(e.ids.begin(), e.ids.end());
    return e;
  }

  /// "Tried after": the worse cell goes first, ties by ids, so that a max-heap
  /// pops the worst first and sorting by `b < a` puts it first.
  bool operator<(const Candidate_cell& o) const
  {
    if(quality != o.quality) return quality > o.quality;
    return ids > o.ids;
  }

  /// Whether the cell is still in the triangulation data structure `tds` with its vertices.
  template <class Tds>
  bool still_there(const Tds& tds) const
  {
    return tds.cells().is_used(cell) && cell->has_vertex(vertices[0]) && cell->has_vertex(vertices[1]) &&
           cell->has_vertex(vertices[2]) && cell->has_vertex(vertices[3]);
  }
};

} // namespace internal
} // namespace BODT_3
} // namespace CGAL

#endif // CGAL_BODT_3_INTERNAL_UTILITIES_CANDIDATE_CELL_H
