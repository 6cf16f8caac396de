// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_BODT_3_INTERNAL_MESH_FLAT_MESH_H
#define CGAL_BODT_3_INTERNAL_MESH_FLAT_MESH_H

#include <CGAL/BODT_3/internal/Moves/Vertex_star.h>
#include <CGAL/BODT_3/internal/Utilities/Thread_workers.h>
#include <CGAL/BODT_3/internal/Utilities/first_touch.h>
#include <CGAL/BODT_3/internal/Utilities/group_by_key.h>
#include <CGAL/BODT_3/internal/Utilities/id_keys.h>
#include <CGAL/BODT_3/internal/Utilities/tet_face_matching.h>

#include <algorithm>
#include <array>
#include <vector>

namespace CGAL {
namespace BODT_3 {
namespace internal {


// For a positively oriented cell (p0, p1, p2, p3), facet_opposite[j] lists the facet
// opposite p_j so that orientation(p_j, a, b, c) is positive.
constexpr int facet_opposite[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};


/// The mesh as the smoother works on it: points and finite cells in flat arrays,
/// with the incidences each vertex needs precomputed once, since smoothing moves
/// points and never changes the connectivity. Every finite cell is here, in the
/// mesh or not (`in_mesh`), because every one of them must stay positively
/// oriented. Built by the adapters for `Tet_mesh`, `Mesh_complex_3_in_triangulation_3`
/// and `Triangulation_3`; call `build_incidences()` after filling the first block.
template <class K>
struct Flat_mesh
{
  using Point = typename K::Point_3;

  /// A cell around a vertex, with the face opposite the vertex: the sweeps read
  /// the faces of a star in a row (reading them from the cells, in 4-byte
  /// incidences, made the one-thread runs of the Mesh_3 benches 5% to 30% slower).
  struct Incidence
  {
    int cell;
    std::array<int, 3> face;   // orientation(vertex, face) is positive
  };

  /// A hull facet (a, b, c) containing the vertex, with the interior on its
  /// positive side, and the far vertex w of a neighbouring hull facet: moving the
  /// vertex must keep orientation(a, b, c, w) non-negative (a convex hull stays one).
  using Hull_check = std::array<int, 4>;

  // Filled by the adapters.
  std::vector<Point> points;
  std::vector<std::array<int, 4>> cells;   // finite cells, positively oriented
  std::vector<char> in_mesh;               // per cell
  std::vector<int> subdomain;              // per cell, meaningful when in_mesh
  std::vector<Hull_check> hull_checks;     // empty unless the input is a triangulation

  // Derived by build_incidences().
  std::vector<int> incidence_begin;        // per vertex, into `incidences`
  std::vector<Incidence> incidences;
  std::vector<int> boundary_begin;         // per vertex, into `boundary_facets`
  std::vector<std::array<int, 2>> boundary_facets;   // (a, b): (x0, a, b) outward of the mesh
  std::vector<int> hull_begin;             // per vertex, into `vertex_hull_checks`
  std::vector<Hull_check> vertex_hull_checks;
  std::vector<int> checked_begin;          // per vertex, into `checked_by`
  std::vector<int> checked_by;             // vertices with a hull check whose far vertex it is
  std::vector<int> neighbor;               // per cell facet (4 c + i): cell across, or -1
  int threads = 1;                         // for build_incidences (0: every core); changes no result

  std::size_t number_of_vertices() const { return points.size(); }

  /// Whether the facet of `cell` opposite local vertex `i` separates the mesh from
  /// what is not the mesh (its outside, or nothing).
  bool is_mesh_boundary(int cell, int i) const
  {
    const int n = neighbor[4 * cell + i];
    return in_mesh[cell] && (n < 0 || !in_mesh[n]);
  }

  /// Derives the second block. `neighbor` may be given already (an adapter that
  /// knows the adjacency fills it); otherwise it is found by matching facets.
  void build_incidences()
  {
    const int nv = static_cast<int>(points.size());
    if(neighbor.size() != 4 * cells.size()) find_neighbors();

    // Vertex -> incident cells, with the face opposite the vertex.
    group_by_key<Incidence>(cells.size(), points.size(), threads, [this](std::size_t c, const auto& emit) {
      const auto& q = cells[c];
      for(int j = 0; j < 4; ++j)
      {
        const auto& o = internal::facet_opposite[j];
        emit(static_cast<std::size_t>(q[j]), Incidence{static_cast<int>(c), {q[o[0]], q[o[1]], q[o[2]]}});
      }
    }, incidence_begin, incidences);

    // Vertex -> boundary facets of the mesh around it, oriented outward (re-derived
    // after every flip pass).
    group_by_key<std::array<int, 2>>(cells.size(), points.size(), threads, [this](std::size_t c, const auto& emit) {
      for(int i = 0; i < 4; ++i)
      {
        if(!is_mesh_boundary(static_cast<int>(c), i)) continue;
        // facet_opposite[i] is oriented with p_i on its negative side: its normal points out.
        const auto& o = internal::facet_opposite[i];
        const int t[3] = {cells[c][o[0]], cells[c][o[1]], cells[c][o[2]]};
        for(int k = 0; k < 3; ++k)
          emit(static_cast<std::size_t>(t[k]), std::array<int, 2>{t[(k + 1) % 3], t[(k + 2) % 3]});
      }
    }, boundary_begin, boundary_facets);
    std::vector<int> fill;

    // Vertex -> hull checks involving it as a facet vertex, and the vertices whose
    // checks have it as far vertex.
    hull_begin.assign(nv + 1, 0);
    for(const Hull_check& h : hull_checks)
      for(int k = 0; k < 3; ++k) ++hull_begin[h[k] + 1];
    for(int v = 0; v < nv; ++v) hull_begin[v + 1] += hull_begin[v];
    vertex_hull_checks.resize(hull_begin[nv]);
    fill.assign(hull_begin.begin(), hull_begin.end() - 1);
    for(const Hull_check& h : hull_checks)
      for(int k = 0; k < 3; ++k) vertex_hull_checks[fill[h[k]]++] = h;
    checked_begin.assign(nv + 1, 0);
    for(int v = 0; v < nv; ++v)
      for(int k = hull_begin[v]; k < hull_begin[v + 1]; ++k) ++checked_begin[vertex_hull_checks[k][3] + 1];
    for(int v = 0; v < nv; ++v) checked_begin[v + 1] += checked_begin[v];
    checked_by.resize(checked_begin[nv]);
    fill.assign(checked_begin.begin(), checked_begin.end() - 1);
    for(int v = 0; v < nv; ++v)
      for(int k = hull_begin[v]; k < hull_begin[v + 1]; ++k) checked_by[fill[vertex_hull_checks[k][3]]++] = v;
  }

  /// Frees the incidences and boundary facets per vertex: a pass that changes
  /// the cells reads neither, and `build_incidences()` derives them again after it.
  void release_incidences()
  {
    std::vector<int>().swap(incidence_begin);
    std::vector<Incidence>().swap(incidences);
    std::vector<int>().swap(boundary_begin);
    std::vector<std::array<int, 2>>().swap(boundary_facets);
  }

  /// Fills `star` with the mesh cells around `v` and the boundary facets through it.
  void gather_star(int v, Vertex_star<K>& star) const
  {
    star.clear();
    star.x0 = points[v];
    for(int k = incidence_begin[v]; k < incidence_begin[v + 1]; ++k)
    {
      const Incidence& inc = incidences[k];
      if(!in_mesh[inc.cell]) continue;
      star.cells.push_back({points[inc.face[0]], points[inc.face[1]], points[inc.face[2]], subdomain[inc.cell]});
    }
    for(int k = boundary_begin[v]; k < boundary_begin[v + 1]; ++k)
      star.boundary.push_back({points[boundary_facets[k][0]], points[boundary_facets[k][1]]});
  }

  /// The cell across each face, from matched faces of `cells`.
  void set_neighbors(const Tet_face_matching& faces)
  {
    const std::size_t n = faces.match.size();
    resize_for_overwrite(neighbor, n, threads);
    Thread_workers<char>(threads).for_blocks(n, [&](char&, int, std::size_t begin, std::size_t end) {
      for(std::size_t f = begin; f < end; ++f) neighbor[f] = faces.match[f] < 0 ? -1 : faces.match[f] / 4;
    });
  }

private:
  // Cell adjacency through shared facets.
  void find_neighbors() { set_neighbors(Tet_face_matching(cells, points.size())); }
};

} // namespace internal
} // namespace BODT_3
} // namespace CGAL

#endif // CGAL_BODT_3_INTERNAL_MESH_FLAT_MESH_H
