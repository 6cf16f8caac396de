// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_BODT_3_INTERNAL_UTILITIES_FACET_SURFACE_CENTERS_H
#define CGAL_BODT_3_INTERNAL_UTILITIES_FACET_SURFACE_CENTERS_H

#include <CGAL/Kernel/global_functions_3.h>

#include <type_traits>
#include <utility>

namespace CGAL {
namespace BODT_3 {
namespace internal {

template <class Cell, class = void>
struct Has_facet_surface_centers : std::false_type {};
template <class Cell>
struct Has_facet_surface_centers<
    Cell, std::void_t<decltype(std::declval<Cell&>().set_facet_surface_center_index(0, std::declval<typename Cell::Index>()))>>
    : std::true_type {};


/// Mesh_3's cells keep, for each facet of the complex, the point where the facet's
/// dual Voronoi edge meets the surface (its "surface center") and that point's
/// index; CGAL's `lloyd_optimize_mesh_3` and `odt_optimize_mesh_3` read them. A
/// complex built from a file, or changed by our moves, flips and insertions, has
/// none or stale ones (Lloyd crashed on such a complex: every center at the origin
/// made a degenerate polygon). Without the domain the best stand-in is the facet's
/// circumcenter, where the dual edge meets the facet's plane; it is set on both
/// sides of every facet of the complex, with the facet's surface patch as index.
/// A cell type without surface centers (`Tet_mesh_cell_base_3`) is left alone.
template <class C3T3>
void set_facet_surface_centers(C3T3& c3t3)
{
  using Tr = typename C3T3::Triangulation;
  using Cell = typename Tr::Cell;
  if constexpr(internal::Has_facet_surface_centers<Cell>::value)
  {
    using Index = typename Cell::Index;
    const Tr& tr = c3t3.triangulation();
    auto cp = tr.geom_traits().construct_point_3_object();
    for(auto f = c3t3.facets_in_complex_begin(); f != c3t3.facets_in_complex_end(); ++f)
    {
      const auto c = f->first;
      const int i = f->second;
      const auto center = CGAL::circumcenter(cp(c->vertex((i + 1) & 3)->point()), cp(c->vertex((i + 2) & 3)->point()),
                                             cp(c->vertex((i + 3) & 3)->point()));
      const auto patch = c3t3.surface_patch_index(c, i);
      const auto n = c->neighbor(i);
      const int j = n->index(c);
      for(const auto& side : {std::make_pair(c, i), std::make_pair(n, j)})
      {
        side.first->set_facet_surface_center(side.second, center);
        if constexpr(std::is_constructible<Index, decltype(patch)>::value)
          side.first->set_facet_surface_center_index(side.second, Index(patch));
      }
    }
  }
}

} // namespace internal
} // namespace BODT_3
} // namespace CGAL

#endif // CGAL_BODT_3_INTERNAL_UTILITIES_FACET_SURFACE_CENTERS_H
