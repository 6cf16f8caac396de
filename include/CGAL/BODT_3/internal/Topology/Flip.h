// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_BODT_3_INTERNAL_TOPOLOGY_FLIP_H
#define CGAL_BODT_3_INTERNAL_TOPOLOGY_FLIP_H

#include <CGAL/BODT_3/internal/Mesh/Triangulation_adapter.h>
#include <CGAL/BODT_3/internal/Topology/replace_cells.h>
#include <CGAL/BODT_3/internal/Quality/tet_quality.h>

#include <CGAL/Kernel/global_functions.h>

#include <array>
#include <limits>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace BODT_3 {
namespace internal {

enum class Flip_kind : unsigned char
{
  flip_2_3,             // one face removed, an edge created
  flip_3_2,             // an edge of three cells removed
  edge_removal,         // an edge of four or more cells removed
  multi_face_removal,   // two or more faces removed, an edge created
  edge_contraction      // a vertex removed by moving it onto a neighbour (Edge_contraction.h)
};

/// A proposed connectivity change, ready for `replace_cells`: the cells it
/// removes, those it creates, the facets it adds to the complex, and the quality
/// of the worst measured cell before and after.
template <class Adapter>
struct Flip
{
  using Vertex_handle = typename Adapter::Vertex_handle;
  using Cell_handle = typename Adapter::Cell_handle;

  Flip_kind kind = Flip_kind::flip_2_3;
  bool boundary = false;   // flips exactly coplanar boundary or interface facets
  std::vector<Cell_handle> old_cells;
  std::vector<New_cell<Vertex_handle>> new_cells;
  std::vector<New_facet<Vertex_handle, typename Adapter::Patch>> new_facets;
  double old_worst = 0;
  double new_worst = -1;
  Vertex_handle removed = Vertex_handle();   // the vertex an edge contraction removes

  void clear()
  {
    removed = Vertex_handle();
    old_cells.clear();
    new_cells.clear();
    new_facets.clear();
    boundary = false;
    old_worst = 0;
    new_worst = -1;
  }
  bool improves() const { return new_worst > old_worst && new_worst > 0; }
};

/// What flips see of the mesh: points, regions, and how a cell is measured.
/// A flip is measured on the cells of the user's mesh it touches; a flip made
/// only of cells outside the complex (allowed when `flip_outside` is on) is
/// measured on those. Cells of the mesh must also stay within `bounds` (the
/// input's extreme dihedral angles), so neither extreme angle ever gets worse.
template <class Adapter>
class Flip_context
{
public:
  using Triangulation = typename Adapter::Triangulation;
  using Vertex_handle = typename Adapter::Vertex_handle;
  using Cell_handle = typename Adapter::Cell_handle;
  using Region = typename Adapter::Region;
  using Bare_point = std::decay_t<decltype(std::declval<typename Triangulation::Geom_traits>().construct_point_3_object()(
      std::declval<typename Triangulation::Point>()))>;

  static constexpr double invalid = -1;
  static constexpr double unmeasured = std::numeric_limits<double>::infinity();

  Flip_context(Adapter& adapter, const Dihedral_bounds& bounds, bool flip_outside,
               Quality_measure measure = Quality_measure::min_dihedral_sine)
    : adapter(adapter), bounds(bounds), flip_outside(flip_outside), measure(measure)
  {}

  Adapter& adapter;
  Dihedral_bounds bounds;
  bool flip_outside;
  Quality_measure measure;

  const Triangulation& triangulation() const { return adapter.triangulation(); }
  bool is_infinite(Vertex_handle v) const { return adapter.triangulation().is_infinite(v); }
  Bare_point point(Vertex_handle v) const
  {
    return adapter.triangulation().geom_traits().construct_point_3_object()(v->point());
  }

  /// Whether cells of region `r` may be replaced by a flip of that region alone.
  bool flippable(const Region& r) const
  {
    return r.kind == Region_kind::mesh || (flip_outside && r.kind == Region_kind::outside);
  }

  /// The measure of a cell with vertices `v` (in positive order) in a flip whose
  /// measured region kind is `measured`: `invalid` if it is finite and not
  /// positively oriented (exact predicate) or a mesh cell outside the bounds,
  /// `unmeasured` if valid but not measured, else its minimum dihedral sine. A
  /// measured cell no better than `floor` cannot make its flip improve anything and
  /// is reported `invalid` without the exact tests.
  double value(const std::array<Vertex_handle, 4>& v, Region_kind kind, Region_kind measured,
               double floor = -std::numeric_limits<double>::infinity()) const
  {
    for(const auto& x : v)
      if(is_infinite(x)) return unmeasured;
    const Bare_point p0 = point(v[0]), p1 = point(v[1]), p2 = point(v[2]), p3 = point(v[3]);
    if(kind != measured && kind != Region_kind::mesh)
      return CGAL::orientation(p0, p1, p2, p3) == CGAL::POSITIVE ? unmeasured : invalid;
    const Measured_tet<Bare_point> tet(measure, p0, p1, p2, p3);
    const double q = tet.quality();
    if(!(q > 0) || (kind == measured && q <= floor)) return invalid;
    if(CGAL::orientation(p0, p1, p2, p3) != CGAL::POSITIVE) return invalid;
    if(kind == Region_kind::mesh && !tet.within(bounds)) return invalid;
    return kind == measured ? q : unmeasured;
  }

  /// The quality of an existing finite cell.
  double quality(Cell_handle c) const
  {
    return tet_quality(measure, point(c->vertex(0)), point(c->vertex(1)), point(c->vertex(2)), point(c->vertex(3)));
  }

  /// Whether (a, b, c, d), a permutation of the vertices of `cell`, has the
  /// cell's own (positive) orientation: the triangulation data structure stores
  /// every cell, finite or not, with the same combinatorial orientation.
  static bool same_orientation(Cell_handle cell, Vertex_handle a, Vertex_handle b, Vertex_handle c, Vertex_handle d)
  {
    const int idx[4] = {cell->index(a), cell->index(b), cell->index(c), cell->index(d)};
    int inversions = 0;
    for(int i = 0; i < 4; ++i)
      for(int j = i + 1; j < 4; ++j) inversions += idx[i] > idx[j] ? 1 : 0;
    return inversions % 2 == 0;
  }
};

} // namespace internal
} // namespace BODT_3
} // namespace CGAL

#endif // CGAL_BODT_3_INTERNAL_TOPOLOGY_FLIP_H
