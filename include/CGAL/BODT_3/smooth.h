// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_BODT_3_SMOOTH_H
#define CGAL_BODT_3_SMOOTH_H

#include <CGAL/BODT_3/Smoothing_options.h>
#include <CGAL/BODT_3/Tet_mesh.h>
#include <CGAL/BODT_3/mesh_quality.h>
#include <CGAL/BODT_3/smooth_mesh.h>
#include <CGAL/BODT_3/triangulation_adapter.h>

#include <type_traits>

namespace CGAL {
namespace BODT_3 {

/// B-ODT smoothing of a `Mesh_complex_3_in_triangulation_3`: the cells in the
/// complex are the mesh, each subdomain keeps its volume, and the features the
/// complex knows (Mesh_3's protected curves and corners, surface patches) are kept.
template <class C3T3, class Visitor = Null_smoothing_visitor>
std::enable_if_t<internal::Is_c3t3<C3T3>::value, Smoothing_result>
smooth(C3T3& c3t3, const Smoothing_options& options, Visitor&& visitor = Visitor())
{
  Triangulation_adapter<typename C3T3::Triangulation> adapter(c3t3.triangulation());
  const Feature_hints hints = c3t3_feature_hints(c3t3, adapter);
  adapter.mesh().build_incidences();
  const Smoothing_result r = smooth_mesh(adapter.mesh(), hints, options, visitor);
  adapter.write_back();
  return r;
}

/// B-ODT smoothing of a `Triangulation_3`: its finite cells are the mesh, its
/// convex hull the boundary, and the hull stays convex. Features are found by
/// tensor voting. The connectivity is kept, so a Delaunay triangulation is in
/// general no longer Delaunay afterwards.
template <class Tr, class Visitor = Null_smoothing_visitor>
std::enable_if_t<!internal::Is_c3t3<Tr>::value && !std::is_same<Tr, Tet_mesh>::value, Smoothing_result>
smooth(Tr& tr, const Smoothing_options& options, Visitor&& visitor = Visitor())
{
  Triangulation_adapter<Tr> adapter(tr);
  adapter.mesh().build_incidences();
  const Smoothing_result r = smooth_mesh(adapter.mesh(), Feature_hints(), options, visitor);
  adapter.write_back();
  return r;
}

/// B-ODT smoothing of a mesh read from a file. Tetrahedra labelled 0 are outside
/// the mesh (unless all are), but stay valid; `Edges`, `Corners`, `RequiredVertices`
/// and triangle labels give the features, and tensor voting is used when none is given.
template <class Visitor = Null_smoothing_visitor>
Smoothing_result smooth(Tet_mesh& tm, const Smoothing_options& options, Visitor&& visitor = Visitor())
{
  using K = Tet_mesh::Kernel;
  Smoothing_mesh<K> mesh;
  mesh.points = tm.points;
  mesh.cells = tm.tets;
  const bool all_zero = tm.all_labels_zero();
  mesh.in_mesh.resize(tm.tets.size());
  for(std::size_t t = 0; t < tm.tets.size(); ++t) mesh.in_mesh[t] = tm.in_mesh(t, all_zero) ? 1 : 0;
  mesh.subdomain = tm.tet_labels;
  mesh.build_incidences();

  Feature_hints hints;
  hints.feature_edges = tm.edges;
  hints.corners = tm.corners;
  hints.corners.insert(hints.corners.end(), tm.required_vertices.begin(), tm.required_vertices.end());
  for(std::size_t f = 0; f < tm.triangles.size(); ++f) hints.facet_patches.push_back({tm.triangles[f], tm.triangle_labels[f]});

  const Smoothing_result r = smooth_mesh(mesh, hints, options, visitor);
  tm.points = mesh.points;
  return r;
}

} // namespace BODT_3
} // namespace CGAL

#endif // CGAL_BODT_3_SMOOTH_H
