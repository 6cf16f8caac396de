// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_BODT_3_IO_INTERNAL_VTK_CELLS_H
#define CGAL_BODT_3_IO_INTERNAL_VTK_CELLS_H

#include <CGAL/BODT_3/Tet_mesh.h>
#include <CGAL/BODT_3/internal/Quality/dihedral_angles.h>

#include <cstdint>
#include <limits>
#include <map>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

namespace CGAL {
namespace BODT_3 {
namespace IO {
namespace internal {

// VTK cell types we keep: corners, edges, boundary triangles, tetrahedra.
enum Cell_type : int { vertex_cell = 1, line_cell = 3, triangle_cell = 5, tetra_cell = 10 };

/// Cell data arrays that may hold the labels, in order of preference: ours, then
/// those meshio, Gmsh, DOLFIN and older versions of this package write.
inline int label_array_rank(std::string_view name)
{
  static const char* const names[] = {"label", "medit:ref", "gmsh:physical", "subdomain", "CellEntityIds",
                                      "tetgen:ref"};
  for(int i = 0; i < 6; ++i)
    if(name == names[i]) return i;
  return -1;
}

/// Point data arrays that may hold vertex references.
inline bool is_vertex_ref_array(std::string_view name) { return name == "ref" || name == "medit:ref"; }

/// The cells of `mesh` in the order VTK files get them: tetrahedra, triangles,
/// edges, then corners as vertex cells.
struct Cells
{
  const Tet_mesh& mesh;

  std::size_t size() const
  {
    return mesh.tets.size() + mesh.triangles.size() + mesh.edges.size() + mesh.corners.size();
  }

  std::size_t connectivity_size() const
  {
    return 4 * mesh.tets.size() + 3 * mesh.triangles.size() + 2 * mesh.edges.size() + mesh.corners.size();
  }

  /// Calls `f(type, nodes, count, label, tet)` for each cell (`tet` is its index or -1).
  template <class F>
  void for_each(F&& f) const
  {
    for(std::size_t i = 0; i < mesh.tets.size(); ++i)
      f(tetra_cell, mesh.tets[i].data(), 4, mesh.tet_labels[i], static_cast<long long>(i));
    for(std::size_t i = 0; i < mesh.triangles.size(); ++i)
      f(triangle_cell, mesh.triangles[i].data(), 3, mesh.triangle_labels[i], -1LL);
    for(std::size_t i = 0; i < mesh.edges.size(); ++i)
      f(line_cell, mesh.edges[i].data(), 2, mesh.edge_labels[i], -1LL);
    for(std::size_t i = 0; i < mesh.corners.size(); ++i)
      f(vertex_cell, &mesh.corners[i], 1, 0, -1LL);
  }

  /// The smallest dihedral angle of tetrahedron `t` in degrees; -1 for other cells,
  /// so that thresholding [0, 10] in ParaView picks the bad tetrahedra only.
  double min_angle(long long t) const
  {
    if(t < 0) return -1;
    const auto& c = mesh.tets[static_cast<std::size_t>(t)];
    return BODT_3::internal::min_max_dihedral_angle(mesh.points[c[0]], mesh.points[c[1]], mesh.points[c[2]], mesh.points[c[3]]).first;
  }
};

/// Adds the cells given as VTK arrays to `mesh`, skipping the types it does not
/// keep (counted in `skipped`). `error(message)` must throw. Every index is checked
/// in its full width before it is narrowed.
template <class Error>
void add_cells(Tet_mesh& mesh, const std::vector<long long>& connectivity, const std::vector<long long>& offsets,
               const std::vector<long long>& types, const std::vector<long long>* labels,
               std::map<long long, std::size_t>& skipped, Error&& error)
{
  const std::size_t n = types.size();
  if(offsets.size() != n + 1)
    error("the cells have " + std::to_string(offsets.size()) + " offsets for " + std::to_string(n) + " types");
  if(labels && labels->size() != n)
    error("the label array has " + std::to_string(labels->size()) + " values for " + std::to_string(n) + " cells");
  const long long np = static_cast<long long>(mesh.points.size());
  for(std::size_t c = 0; c < n; ++c)
  {
    const long long b = offsets[c], e = offsets[c + 1];
    if(b < 0 || e < b || static_cast<unsigned long long>(e) > connectivity.size())
      error("cell " + std::to_string(c) + " runs from " + std::to_string(b) + " to " + std::to_string(e) +
            " in a connectivity array of " + std::to_string(connectivity.size()));
    const long long type = types[c];
    const long long need = type == tetra_cell ? 4 : type == triangle_cell ? 3 : type == line_cell ? 2
                           : type == vertex_cell ? 1 : 0;
    if(need == 0)
    {
      ++skipped[type];
      continue;
    }
    if(e - b != need)
      error("cell " + std::to_string(c) + " of type " + std::to_string(type) + " has " + std::to_string(e - b) +
            " points instead of " + std::to_string(need));
    int v[4];
    for(long long k = 0; k < need; ++k)
    {
      const long long id = connectivity[static_cast<std::size_t>(b + k)];
      if(id < 0 || id >= np)
        error("cell " + std::to_string(c) + " refers to point " + std::to_string(id) + ", but point indices run from 0 to " +
              std::to_string(np - 1));
      v[k] = static_cast<int>(id);
    }
    long long label = labels ? (*labels)[c] : 0;
    if(label < std::numeric_limits<int>::min() || label > std::numeric_limits<int>::max())
      error("cell " + std::to_string(c) + " has label " + std::to_string(label) + ", out of range");
    const int l = static_cast<int>(label);
    switch(type)
    {
    case tetra_cell: mesh.tets.push_back({v[0], v[1], v[2], v[3]}); mesh.tet_labels.push_back(l); break;
    case triangle_cell: mesh.triangles.push_back({v[0], v[1], v[2]}); mesh.triangle_labels.push_back(l); break;
    case line_cell: mesh.edges.push_back({v[0], v[1]}); mesh.edge_labels.push_back(l); break;
    default: mesh.corners.push_back(v[0]);
    }
  }
}

inline void warn_skipped(std::ostream& warnings, const std::string& file, const std::map<long long, std::size_t>& skipped)
{
  for(const auto& s : skipped)
    warnings << "warning: " << file << ": skipped " << s.second << " cell(s) of VTK type " << s.first
             << "; only vertices, lines, triangles and tetrahedra are read\n";
}

} // namespace internal
} // namespace IO
} // namespace BODT_3
} // namespace CGAL

#endif // CGAL_BODT_3_IO_INTERNAL_VTK_CELLS_H
