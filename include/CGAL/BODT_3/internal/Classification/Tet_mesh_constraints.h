// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_BODT_3_INTERNAL_CLASSIFICATION_TET_MESH_CONSTRAINTS_H
#define CGAL_BODT_3_INTERNAL_CLASSIFICATION_TET_MESH_CONSTRAINTS_H

#include <CGAL/BODT_3/internal/Mesh/Flat_mesh.h>
#include <CGAL/BODT_3/Tet_mesh.h>

#include <algorithm>
#include <array>
#include <map>
#include <numeric>
#include <set>
#include <tuple>
#include <vector>

namespace CGAL {
namespace BODT_3 {
namespace internal {

/// What a mesh file constrains beyond its labels, which the smoothing must keep:
///  - embedded surfaces: triangles listed with a label other than 0 between two
///    tetrahedra of the same label (libigl's and TetGen's internal facets; label 0
///    is left out because TetGen's `-f`/`-g` list every face with marker 0). Where
///    they cut a subdomain into parts, each part gets a working label of its own,
///    so that the surface is an interface like any other: its vertices slide in
///    its tangent plane, the volume on each side is kept, and no flip removes it.
///    Where they cut nothing (a sheet whose rim lies inside the subdomain), their
///    vertices are pinned and the triangles enter the complex, so flips keep them;
///  - cracks: vertices with a coincident twin (same coordinates, another index),
///    and the vertices of boundary faces that coincide with another boundary face
///    (the two sides of a crack, its front included), are pinned, so the crack
///    neither opens nor closes; the edges of those faces become curves of the
///    complex, so no flip changes either side.
struct Tet_mesh_constraints
{
  std::vector<int> subdomain;                   // per tetrahedron: its working label
  std::map<int, int> file_label;                // working label -> the file's label
  bool relabelled = false;                      // whether some working label differs from the file's
  std::vector<std::size_t> sheets;              // indices into `triangles` of embedded triangles that cut nothing
  std::vector<std::array<int, 2>> crack_edges;  // edges of coincident boundary faces
  std::vector<char> pinned;                     // per vertex
  std::size_t embedded_triangles = 0;
  std::size_t crack_vertices = 0;               // pinned because of a twin or a crack face
};

/// Finds the constraints of `tm`; `flat` is `tm` as the smoother sees it, with the
/// file's labels and its incidences built.
template <class K>
Tet_mesh_constraints find_constraints(const Tet_mesh& tm, const Flat_mesh<K>& flat)
{
  Tet_mesh_constraints out;
  const int nc = static_cast<int>(flat.cells.size());
  const int nv = static_cast<int>(flat.points.size());
  out.pinned.assign(nv, 0);
  out.subdomain = flat.subdomain;
  const bool all_zero = tm.all_labels_zero();
  auto facet = [&](int c, int i) {
    const auto& o = internal::facet_opposite[i];
    return internal::sorted({flat.cells[c][o[0]], flat.cells[c][o[1]], flat.cells[c][o[2]]});
  };

  // Embedded triangles, then the parts of each subdomain they separate. A listed
  // triangle's cells are found around its smallest vertex; the first listing wins.
  // Per facet, and only for a file with a labelled triangle.
  std::vector<char> barrier;
  if(std::any_of(tm.triangle_labels.begin(), tm.triangle_labels.end(), [](int l) { return l != 0; }))
    barrier.assign(4 * flat.cells.size(), 0);
  std::vector<std::pair<int, std::size_t>> embedded;   // (4 c + i, triangle), once per facet
  for(std::size_t f = 0; f < tm.triangles.size(); ++f)
  {
    if(tm.triangle_labels[f] == 0) continue;
    const auto t = internal::sorted(tm.triangles[f]);
    int sides[2], found = 0;
    for(int k = flat.incidence_begin[t[0]]; k < flat.incidence_begin[t[0] + 1]; ++k)
    {
      const int c = flat.incidences[k].cell;
      for(int i = 0; i < 4; ++i)
        if(facet(c, i) == t && found < 2) sides[found++] = 4 * c + i;
    }
    if(found != 2) continue;
    const int c = sides[0] / 4, n = sides[1] / 4;
    if(!flat.in_mesh[c] || !flat.in_mesh[n] || flat.subdomain[n] != flat.subdomain[c] || barrier[sides[0]]) continue;
    barrier[sides[0]] = barrier[sides[1]] = 1;
    embedded.push_back({std::min(sides[0], sides[1]), f});
  }
  std::sort(embedded.begin(), embedded.end());
  out.embedded_triangles = embedded.size();
  std::vector<int> part(embedded.empty() ? 0 : nc, -1);
  std::vector<int> label_of_part;
  int fresh = 1;
  for(int l : flat.subdomain) fresh = std::max(fresh, l + 1);
  std::set<int> seen;
  std::vector<int> stack;
  for(int s = 0; s < nc && !embedded.empty(); ++s)
  {
    if(!flat.in_mesh[s] || part[s] >= 0) continue;
    const int id = static_cast<int>(label_of_part.size());
    // An all-zero mesh is one subdomain, which the complex numbers 1.
    const int file = flat.subdomain[s], base = all_zero ? 1 : file;
    const bool first = seen.insert(file).second;
    const int working = first ? base : fresh++;
    label_of_part.push_back(working);
    out.file_label[working] = file;
    out.relabelled = out.relabelled || working != file;
    part[s] = id;
    stack.assign(1, s);
    while(!stack.empty())
    {
      const int c = stack.back();
      stack.pop_back();
      out.subdomain[c] = working;
      for(int i = 0; i < 4; ++i)
      {
        const int n = flat.neighbor[4 * c + i];
        if(n < 0 || !flat.in_mesh[n] || part[n] >= 0 || barrier[4 * c + i] || flat.subdomain[n] != file) continue;
        part[n] = id;
        stack.push_back(n);
      }
    }
  }
  for(const auto& e : embedded)
  {
    const int c = e.first / 4, n = flat.neighbor[e.first];
    if(part[c] != part[n]) continue;
    out.sheets.push_back(e.second);
    for(int v : tm.triangles[e.second]) out.pinned[v] = 1;
  }

  // Coincident vertices: each used vertex's twin class, by its coordinates.
  std::vector<int> used;
  for(int v = 0; v < nv; ++v)
    if(flat.incidence_begin[v + 1] > flat.incidence_begin[v]) used.push_back(v);
  auto coords = [&](int v) { return std::make_tuple(flat.points[v].x(), flat.points[v].y(), flat.points[v].z()); };
  std::sort(used.begin(), used.end(), [&](int a, int b) { return coords(a) < coords(b) || (coords(a) == coords(b) && a < b); });
  std::vector<int> twin_class(nv);
  std::iota(twin_class.begin(), twin_class.end(), 0);
  std::vector<char> crack(nv, 0);
  for(std::size_t k = 1; k < used.size(); ++k)
    if(coords(used[k]) == coords(used[k - 1]))
    {
      twin_class[used[k]] = twin_class[used[k - 1]];
      crack[used[k]] = crack[used[k - 1]] = 1;
    }
  // Boundary faces that coincide, through their vertices' classes, with another.
  std::map<std::array<int, 3>, std::vector<std::array<int, 3>>> faces_by_class;
  if(std::find(crack.begin(), crack.end(), 1) != crack.end())
    for(int c = 0; c < nc; ++c)
      for(int i = 0; i < 4; ++i)
      {
        if(!flat.is_mesh_boundary(c, i)) continue;
        const std::array<int, 3> f = facet(c, i);
        if(!crack[f[0]] && !crack[f[1]] && !crack[f[2]]) continue;
        faces_by_class[internal::sorted({twin_class[f[0]], twin_class[f[1]], twin_class[f[2]]})].push_back(f);
      }
  for(const auto& fc : faces_by_class)
  {
    if(fc.second.size() < 2) continue;
    for(const auto& f : fc.second)
      for(int k = 0; k < 3; ++k)
      {
        crack[f[k]] = 1;
        out.crack_edges.push_back({f[k], f[(k + 1) % 3]});
      }
  }
  for(int v = 0; v < nv; ++v)
    if(crack[v])
    {
      out.pinned[v] = 1;
      ++out.crack_vertices;
    }
  return out;
}

} // namespace internal
} // namespace BODT_3
} // namespace CGAL

#endif // CGAL_BODT_3_INTERNAL_CLASSIFICATION_TET_MESH_CONSTRAINTS_H
