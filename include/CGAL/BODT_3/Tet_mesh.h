// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_BODT_3_TET_MESH_H
#define CGAL_BODT_3_TET_MESH_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <array>
#include <string>
#include <vector>

namespace CGAL {
namespace BODT_3 {

/// A tetrahedral mesh as files store it: indexed vertices and cells with labels,
/// plus the boundary and feature entities a mesher wrote alongside.
/// Indices are 0-based. A tetrahedron's label is its subdomain; label 0 marks a
/// tetrahedron outside the mesh unless every label is 0 (see `in_mesh()`).
struct Tet_mesh
{
  using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
  using Point = Kernel::Point_3;

  std::vector<Point> points;
  std::vector<int> vertex_refs;                 // one per point (Medit reference)
  std::vector<std::array<int, 4>> tets;
  std::vector<int> tet_labels;                  // one per tet
  std::vector<std::array<int, 3>> triangles;    // boundary and interface triangles
  std::vector<int> triangle_labels;             // surface patch per triangle
  std::vector<std::array<int, 2>> edges;        // feature edges as written by the mesher
  std::vector<int> edge_labels;
  std::vector<int> corners;                     // vertex indices
  std::vector<int> required_vertices;           // vertex indices
  std::vector<int> ridges;                      // indices into `edges`
  /// The file the mesh was read from (the readers set it; empty for a mesh made in
  /// code): the refusals of later steps, such as the conversion into a
  /// triangulation in `smooth`, name it as the readers' own refusals do.
  std::string source;

  std::size_t number_of_vertices() const { return points.size(); }
  std::size_t number_of_tets() const { return tets.size(); }

  /// True when every tetrahedron is labelled 0, so that all of them form the mesh.
  bool all_labels_zero() const
  {
    for(int l : tet_labels)
      if(l != 0) return false;
    return true;
  }

  /// Whether tetrahedron `t` belongs to the mesh (as opposed to the outside of a
  /// whole triangulation written with label 0).
  bool in_mesh(std::size_t t, bool all_zero) const { return all_zero || tet_labels[t] != 0; }
};

} // namespace BODT_3
} // namespace CGAL

#endif // CGAL_BODT_3_TET_MESH_H
