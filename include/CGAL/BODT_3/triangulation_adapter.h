// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_BODT_3_TRIANGULATION_ADAPTER_H
#define CGAL_BODT_3_TRIANGULATION_ADAPTER_H

#include <CGAL/BODT_3/Smoothing_mesh.h>
#include <CGAL/BODT_3/Vertex_classification.h>

#include <CGAL/Kernel_traits.h>

#include <map>
#include <stdexcept>
#include <type_traits>
#include <unordered_map>
#include <vector>

namespace CGAL {
namespace BODT_3 {

/// Copies a 3D triangulation (a `Triangulation_3`, `Delaunay_triangulation_3`,
/// `Regular_triangulation_3`, or the triangulation of a C3T3) into a
/// `Smoothing_mesh` and writes the smoothed positions back. Connectivity is
/// never changed: only `Vertex::set_point` is called, with the vertex's weight
/// kept for weighted points.
template <class Tr>
class Triangulation_adapter
{
public:
  using Vertex_handle = typename Tr::Vertex_handle;
  using Cell_handle = typename Tr::Cell_handle;
  using Bare_point = std::decay_t<decltype(std::declval<typename Tr::Geom_traits>().construct_point_3_object()(
      std::declval<typename Tr::Point>()))>;
  using Kernel = typename CGAL::Kernel_traits<Bare_point>::Kernel;
  using Mesh = Smoothing_mesh<Kernel>;

  /// Fills `mesh` with the points, the finite cells (all in the mesh, subdomain 1,
  /// until `set_cell_labels` says otherwise) and the hull checks of `tr`.
  explicit Triangulation_adapter(Tr& tr) : tr_(tr)
  {
    if(tr.dimension() != 3)
      throw std::invalid_argument("B-ODT smoothing needs a triangulation of dimension 3");
    auto cp = tr.geom_traits().construct_point_3_object();
    for(auto v = tr.finite_vertices_begin(); v != tr.finite_vertices_end(); ++v)
    {
      index_.emplace(v, static_cast<int>(handles_.size()));
      handles_.push_back(v);
      mesh_.points.push_back(cp(v->point()));
    }
    for(auto c = tr.finite_cells_begin(); c != tr.finite_cells_end(); ++c)
    {
      cells_.push_back(c);
      mesh_.cells.push_back({index(c->vertex(0)), index(c->vertex(1)), index(c->vertex(2)), index(c->vertex(3))});
    }
    mesh_.in_mesh.assign(mesh_.cells.size(), 1);
    mesh_.subdomain.assign(mesh_.cells.size(), 1);
    add_hull_checks();
  }

  Mesh& mesh() { return mesh_; }
  const std::vector<Cell_handle>& cells() const { return cells_; }
  const std::vector<Vertex_handle>& vertices() const { return handles_; }
  int index(Vertex_handle v) const { return index_.at(v); }

  /// Writes the positions of `mesh()` back into the triangulation.
  void write_back()
  {
    for(std::size_t i = 0; i < handles_.size(); ++i) set_bare_point(handles_[i], mesh_.points[i]);
  }

private:
  template <class P = typename Tr::Point>
  static std::enable_if_t<std::is_same<P, Bare_point>::value> set_bare(Vertex_handle v, const Bare_point& p)
  {
    v->set_point(p);
  }
  template <class P = typename Tr::Point>
  static std::enable_if_t<!std::is_same<P, Bare_point>::value> set_bare(Vertex_handle v, const Bare_point& p)
  {
    v->set_point(P(p, v->point().weight()));
  }
  void set_bare_point(Vertex_handle v, const Bare_point& p)
  {
    auto cp = tr_.geom_traits().construct_point_3_object();
    if(cp(v->point()) != p) set_bare(v, p);
  }

  // For each hull facet and each of its three neighbours on the hull, the far
  // vertex of the neighbour must stay on the inner side of the facet's plane;
  // checks that do not hold now (a hull that is not convex there) are left out.
  void add_hull_checks()
  {
    const Vertex_handle inf = tr_.infinite_vertex();
    for(auto c = tr_.all_cells_begin(); c != tr_.all_cells_end(); ++c)
    {
      if(!c->has_vertex(inf)) continue;
      const int i = c->index(inf);
      const Cell_handle fc = c->neighbor(i);
      const int j = fc->index(c);
      const auto& o = internal::kOpposite[j];
      // Swap two vertices of kOpposite[j] so that the interior is on the positive side.
      const int a = index(fc->vertex(o[0])), b = index(fc->vertex(o[2])), d = index(fc->vertex(o[1]));
      for(int k = 0; k < 4; ++k)
      {
        if(k == i) continue;
        const Cell_handle nc = c->neighbor(k);
        const Vertex_handle w = nc->vertex(nc->index(c));
        if(w == inf) continue;
        const int wi = index(w);
        if(CGAL::orientation(mesh_.points[a], mesh_.points[b], mesh_.points[d], mesh_.points[wi]) !=
           CGAL::NEGATIVE)
          mesh_.hull_checks.push_back({a, b, d, wi});
      }
    }
  }

  Tr& tr_;
  Mesh mesh_;
  std::vector<Vertex_handle> handles_;
  std::vector<Cell_handle> cells_;
  std::unordered_map<Vertex_handle, int> index_;
};

/// For a `Mesh_complex_3_in_triangulation_3`: marks the cells in the complex with
/// their subdomain, and collects what the complex knows of its features (vertex
/// dimensions, curve edges, corners, surface patches).
template <class C3T3>
Feature_hints c3t3_feature_hints(const C3T3& c3t3, Triangulation_adapter<typename C3T3::Triangulation>& adapter)
{
  auto& mesh = adapter.mesh();
  const auto& cells = adapter.cells();
  for(std::size_t c = 0; c < cells.size(); ++c)
  {
    mesh.in_mesh[c] = c3t3.is_in_complex(cells[c]) ? 1 : 0;
    mesh.subdomain[c] = mesh.in_mesh[c] ? static_cast<int>(c3t3.subdomain_index(cells[c])) : 0;
  }
  Feature_hints hints;
  hints.dimension.resize(adapter.vertices().size());
  for(std::size_t v = 0; v < adapter.vertices().size(); ++v)
    hints.dimension[v] = static_cast<signed char>(c3t3.in_dimension(adapter.vertices()[v]));
  for(auto e = c3t3.edges_in_complex_begin(); e != c3t3.edges_in_complex_end(); ++e)
    hints.feature_edges.push_back(
        {adapter.index(e->first->vertex(e->second)), adapter.index(e->first->vertex(e->third))});
  for(auto v = c3t3.vertices_in_complex_begin(); v != c3t3.vertices_in_complex_end(); ++v)
    hints.corners.push_back(adapter.index(v));
  std::map<typename C3T3::Surface_patch_index, int> patch_ids;
  for(auto f = c3t3.facets_in_complex_begin(); f != c3t3.facets_in_complex_end(); ++f)
  {
    const auto id = patch_ids.emplace(c3t3.surface_patch_index(*f), static_cast<int>(patch_ids.size())).first->second;
    std::array<int, 3> t;
    for(int k = 0, m = 0; k < 4; ++k)
      if(k != f->second) t[m++] = adapter.index(f->first->vertex(k));
    hints.facet_patches.push_back({t, id});
  }
  return hints;
}

} // namespace BODT_3
} // namespace CGAL

#endif // CGAL_BODT_3_TRIANGULATION_ADAPTER_H
