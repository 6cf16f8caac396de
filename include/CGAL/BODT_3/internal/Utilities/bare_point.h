// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_BODT_3_INTERNAL_UTILITIES_BARE_POINT_H
#define CGAL_BODT_3_INTERNAL_UTILITIES_BARE_POINT_H

#include <type_traits>
#include <utility>

namespace CGAL {
namespace BODT_3 {
namespace internal {

/// The unweighted point type of a triangulation (its `Point` for a Delaunay
/// triangulation, the point of its weighted points for a regular one).
template <class Tr>
using Bare_point_t = std::decay_t<decltype(std::declval<typename Tr::Geom_traits>().construct_point_3_object()(
    std::declval<typename Tr::Point>()))>;

/// Where vertex `v` is, without its weight.
template <class Tr>
Bare_point_t<Tr> bare_point(const Tr& tr, typename Tr::Vertex_handle v)
{
  return tr.geom_traits().construct_point_3_object()(v->point());
}

/// Moves vertex `v` to `p`, keeping its weight (smoothing moves points; weights
/// belong to Mesh_3's protecting balls).
template <class Tr>
void set_bare_point(const Tr& tr, typename Tr::Vertex_handle v, const Bare_point_t<Tr>& p)
{
  using Point = typename Tr::Point;
  if(bare_point(tr, v) == p) return;
  if constexpr(std::is_same<Point, Bare_point_t<Tr>>::value)
    v->set_point(p);
  else
    v->set_point(Point(p, v->point().weight()));
}

} // namespace internal
} // namespace BODT_3
} // namespace CGAL

#endif // CGAL_BODT_3_INTERNAL_UTILITIES_BARE_POINT_H
