// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_BODT_3_TET_MESH_CELL_BASE_3_H
#define CGAL_BODT_3_TET_MESH_CELL_BASE_3_H

#include <CGAL/Triangulation_cell_base_3.h>
#include <CGAL/tags.h>

#include <cstddef>

namespace CGAL {
namespace BODT_3 {

/// The cell of the complex a mesh file becomes (`Tet_mesh_c3t3`): what
/// `Mesh_complex_3_in_triangulation_3` and this package read and write (the
/// subdomain, the surface patch of each facet, a time stamp so that handles
/// compare the same in every run), without the caches Mesh_3's refinement keeps
/// in its cells (a surface point per facet, the circumcenter, the sliver value),
/// which nothing here uses: 96 bytes a cell instead of 248, the largest share of a
/// run's memory.
template <class GT, class Cb = CGAL::Triangulation_cell_base_3<GT>>
class Tet_mesh_cell_base_3 : public Cb
{
public:
  using Subdomain_index = int;
  using Surface_patch_index = int;
  using Index = int;
  using Vertex_handle = typename Cb::Vertex_handle;
  using Cell_handle = typename Cb::Cell_handle;
  using Point = typename GT::Point_3;

  template <class TDS2>
  struct Rebind_TDS
  {
    using Other = Tet_mesh_cell_base_3<GT, typename Cb::template Rebind_TDS<TDS2>::Other>;
  };

  // User-provided, so that placement new leaves `time_stamp_` as the container
  // set it (-1: "give me a stamp") instead of zeroing it.
  Tet_mesh_cell_base_3() {}
  Tet_mesh_cell_base_3(Vertex_handle v0, Vertex_handle v1, Vertex_handle v2, Vertex_handle v3)
    : Cb(v0, v1, v2, v3)
  {}
  Tet_mesh_cell_base_3(Vertex_handle v0, Vertex_handle v1, Vertex_handle v2, Vertex_handle v3, Cell_handle n0,
                       Cell_handle n1, Cell_handle n2, Cell_handle n3)
    : Cb(v0, v1, v2, v3, n0, n1, n2, n3)
  {}

  Subdomain_index subdomain_index() const { return subdomain_; }
  void set_subdomain_index(const Subdomain_index& index) { subdomain_ = index; }

  Surface_patch_index surface_patch_index(int facet) const { return patch_[facet]; }
  void set_surface_patch_index(int facet, const Surface_patch_index& index) { patch_[facet] = index; }
  bool is_facet_on_surface(int facet) const { return patch_[facet] != Surface_patch_index(); }

  // Mesh_3 keeps a point of the input surface per facet for its refinement; the
  // complex copies it between mirror facets. Nothing here refines: none is kept.
  void set_facet_surface_center(int, const Point&) {}
  Point get_facet_surface_center(int) const { return Point(); }

  using Has_timestamp = CGAL::Tag_true;
  std::size_t time_stamp() const { return time_stamp_; }
  void set_time_stamp(const std::size_t& ts) { time_stamp_ = ts; }

private:
  Subdomain_index subdomain_ = Subdomain_index();
  Surface_patch_index patch_[4] = {Surface_patch_index(), Surface_patch_index(), Surface_patch_index(),
                                   Surface_patch_index()};
  std::size_t time_stamp_;   // set by the Compact_container, not here
};

} // namespace BODT_3
} // namespace CGAL

#endif // CGAL_BODT_3_TET_MESH_CELL_BASE_3_H
