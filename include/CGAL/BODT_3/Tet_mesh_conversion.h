// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_BODT_3_TET_MESH_CONVERSION_H
#define CGAL_BODT_3_TET_MESH_CONVERSION_H

#include <CGAL/BODT_3/internal/Utilities/Handle_index_map.h>
#include <CGAL/BODT_3/Tet_mesh.h>
#include <CGAL/BODT_3/Tet_mesh_cell_base_3.h>
#include <CGAL/BODT_3/internal/Utilities/Thread_workers.h>
#include <CGAL/BODT_3/internal/Utilities/first_touch.h>
#include <CGAL/BODT_3/internal/Utilities/facet_surface_centers.h>
#include <CGAL/BODT_3/internal/Utilities/id_keys.h>
#include <CGAL/BODT_3/internal/Utilities/tet_face_matching.h>
#include <CGAL/BODT_3/Mesh_io_error.h>
#include <CGAL/BODT_3/internal/Mesh/check_tet_mesh.h>

#include <CGAL/Kernel/global_functions.h>
#include <CGAL/Mesh_complex_3_in_triangulation_3.h>
#include <CGAL/Mesh_triangulation_3.h>
#include <CGAL/Triangulation_utils_3.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cstdint>
#include <iostream>
#include <iterator>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <unordered_map>
#include <utility>
#include <vector>

namespace CGAL {
namespace BODT_3 {

namespace internal {

template <class T> struct Is_pair : std::false_type {};
template <class A, class B> struct Is_pair<std::pair<A, B>> : std::true_type {};

// The face of `t` opposite its vertex `i`, in the order CGAL gives it
// (counterclockwise seen from vertex `i`).
inline std::array<int, 3> oriented_face(const std::array<int, 4>& t, int i)
{
  using U = Triangulation_utils_3;
  return {t[U::vertex_triple_index(i, 0)], t[U::vertex_triple_index(i, 1)], t[U::vertex_triple_index(i, 2)]};
}

// Two oriented triangles on the same vertices have the same orientation iff
// their rotations starting at the smallest vertex are equal.
inline std::array<int, 3> smallest_first(std::array<int, 3> f)
{
  std::rotate(f.begin(), std::min_element(f.begin(), f.end()), f.end());
  return f;
}

inline std::string face_to_string(const std::array<int, 3>& f)
{
  return std::to_string(f[0] + 1) + " " + std::to_string(f[1] + 1) + " " + std::to_string(f[2] + 1);
}

// Mesh_3 vertices keep the index of the input face they lie on; other vertex
// types, or index types that cannot hold `x`, are left alone.
template <class Vertex_handle, class T>
void set_vertex_index(const Vertex_handle& v, const T& x)
{
  using Index = typename std::decay_t<decltype(*v)>::Index;
  if constexpr(std::is_constructible<Index, const T&>::value)
    v->set_index(Index(x));
}

// File labels for C3T3 indices: integral indices are written as they are; other
// types (Mesh_3's std::pair surface patch indices) are numbered 1, 2, ... in the
// order they are first met.
template <class T>
class Label_numbering
{
public:
  int operator()(const T& x)
  {
    if constexpr(std::is_integral<T>::value)
      return static_cast<int>(x);
    else
      return ids_.emplace(x, static_cast<int>(ids_.size()) + 1).first->second;
  }

private:
  std::map<T, int> ids_;
};


// What the steps of `tet_mesh_to_c3t3` share: the input, the complex being built
// (swapped into the caller's only at the end, so that a refusal leaves the caller's
// unchanged), and the handle of each point and each tetrahedron.
template <class C3T3>
struct Tet_mesh_to_c3t3_state
{
  using Tr = typename C3T3::Triangulation;
  using Vertex_handle = typename Tr::Vertex_handle;
  using Cell_handle = typename Tr::Cell_handle;

  Tet_mesh_to_c3t3_state(const Tet_mesh& m, const std::string& f, const Tet_face_matching* matched)
    : mesh(m), file(f), faces(matched), n(static_cast<int>(m.points.size())), nt(m.tets.size()),
      threads(matched ? matched->threads : 1), workers(threads)
  {}

  [[noreturn]] void fail(const std::string& message) const { throw Mesh_io_error(file, 0, message); }

  const Tet_mesh& mesh;
  const std::string& file;
  const Tet_face_matching* faces;          // the caller's matching, or `own`
  std::optional<Tet_face_matching> own;
  const int n;                             // points
  const std::size_t nt;                    // tetrahedra
  const int threads;
  Thread_workers<char> workers;
  C3T3 result;
  std::vector<char> used;                  // per point: whether a tetrahedron uses it
  std::vector<Vertex_handle> vh;           // per point; a default handle for unused points
  std::vector<Cell_handle> cells;          // per tetrahedron
  Vertex_handle infinite;
};

// Step 1: one label per entity, vertex indices in range and distinct within each
// tetrahedron, no negatively oriented tetrahedron. Checked in parallel blocks; the
// first tetrahedron that fails is reported.
template <class C3T3>
void check_tetrahedra(Tet_mesh_to_c3t3_state<C3T3>& s)
{
  const Tet_mesh& mesh = s.mesh;
  const std::size_t nt = s.nt;
  if(nt == 0) s.fail("the mesh has no tetrahedra");
  if(mesh.tet_labels.size() != nt || mesh.triangle_labels.size() != mesh.triangles.size() ||
     mesh.edge_labels.size() != mesh.edges.size())
    s.fail("tetrahedra, triangles and edges need one label each");
  auto problem = [&](std::size_t t) -> std::string {
    const auto& q = mesh.tets[t];
    for(int k = 0; k < 4; ++k)
    {
      if(q[k] < 0 || q[k] >= s.n)
        return "tetrahedron " + std::to_string(t + 1) + " refers to vertex " + std::to_string(q[k] + 1) +
               ", but there are " + std::to_string(s.n) + " vertices";
      for(int j = 0; j < k; ++j)
        if(q[j] == q[k]) return "tetrahedron " + std::to_string(t + 1) + " uses a vertex twice";
    }
    // Flat tetrahedra are kept, as the readers keep them; inverted ones would turn
    // the triangulation inside out.
    if(CGAL::orientation(mesh.points[q[0]], mesh.points[q[1]], mesh.points[q[2]], mesh.points[q[3]]) ==
       CGAL::NEGATIVE)
      return "tetrahedron " + std::to_string(t + 1) +
             " is negatively oriented; a triangulation needs positively oriented cells";
    return std::string();
  };
  std::vector<std::size_t> first_bad(static_cast<std::size_t>(block_count(nt)), nt);
  s.workers.for_blocks(nt, [&](char&, int b, std::size_t begin, std::size_t end) {
    for(std::size_t t = begin; t < end; ++t)
      if(!problem(t).empty()) { first_bad[static_cast<std::size_t>(b)] = t; return; }
  });
  for(std::size_t t : first_bad)
    if(t < nt) s.fail(problem(t));
}

// Step 2: an empty triangulation of dimension 3 with its infinite vertex, and a
// vertex per point some tetrahedron uses, in the points' order.
template <class C3T3>
void create_vertices(Tet_mesh_to_c3t3_state<C3T3>& s)
{
  using Tr = typename C3T3::Triangulation;
  using Bare_point = std::decay_t<decltype(std::declval<typename Tr::Geom_traits>().construct_point_3_object()(
      std::declval<typename Tr::Point>()))>;
  s.used.assign(static_cast<std::size_t>(s.n), 0);
  for(const auto& q : s.mesh.tets)
    for(int v : q) s.used[v] = 1;
  Tr& tr = s.result.triangulation();
  auto& tds = tr.tds();
  tds.clear();   // not tr.clear(), which would create a new infinite vertex
  tds.set_dimension(3);
  s.infinite = tds.create_vertex();
  tr.set_infinite_vertex(s.infinite);
  s.vh.assign(static_cast<std::size_t>(s.n), typename Tr::Vertex_handle());
  for(int i = 0; i < s.n; ++i)
  {
    if(!s.used[i]) continue;
    const auto& p = s.mesh.points[i];
    s.vh[i] = tds.create_vertex();
    s.vh[i]->set_point(typename Tr::Point(Bare_point(p.x(), p.y(), p.z())));
  }
}

// Step 3: the finite cells, glued along the faces they share, once no face has
// three tetrahedra and two tetrahedra on a face induce opposite orientations on it.
template <class C3T3>
void glue_finite_cells(Tet_mesh_to_c3t3_state<C3T3>& s)
{
  const Tet_mesh& mesh = s.mesh;
  const std::size_t nt = s.nt;
  auto& tds = s.result.triangulation().tds();
  if(!s.faces) s.faces = &s.own.emplace(mesh.tets, mesh.points.size());
  const Tet_face_matching& faces = *s.faces;
  if(faces.crowded_face >= 0)
  {
    const auto t = static_cast<std::size_t>(faces.crowded_face / 4);
    s.fail("face (" + face_to_string(oriented_face(mesh.tets[t], static_cast<int>(faces.crowded_face % 4))) +
           ") belongs to three or more tetrahedra");
  }
  std::vector<std::size_t> first_bad(static_cast<std::size_t>(block_count(nt)), nt);
  s.workers.for_blocks(nt, [&](char&, int b, std::size_t begin, std::size_t end) {
    for(std::size_t t = begin; t < end; ++t)
      for(int i = 0; i < 4; ++i)
      {
        const int m = faces.match[4 * t + static_cast<std::size_t>(i)];
        const auto other = static_cast<std::size_t>(m / 4);
        if(m < 0 || other > t) continue;
        if(smallest_first(oriented_face(mesh.tets[t], i)) == smallest_first(oriented_face(mesh.tets[other], m % 4)))
        {
          first_bad[static_cast<std::size_t>(b)] = t;
          return;
        }
      }
  });
  for(std::size_t t : first_bad)
    for(int i = 0; t < nt && i < 4; ++i)
    {
      const int m = faces.match[4 * t + static_cast<std::size_t>(i)];
      const auto other = static_cast<std::size_t>(m / 4);
      const std::array<int, 3> f = oriented_face(mesh.tets[t], i);
      if(m >= 0 && other < t && smallest_first(f) == smallest_first(oriented_face(mesh.tets[other], m % 4)))
        s.fail("tetrahedra " + std::to_string(other + 1) + " and " + std::to_string(t + 1) +
               " lie on the same side of their common face (" + face_to_string(f) + ")");
    }
  // The cells, one after the other (the container is not thread-safe); then each
  // cell's neighbours and each vertex's first cell, written by their owner in parallel.
  resize_for_overwrite(s.cells, nt, s.threads);
  for(std::size_t t = 0; t < nt; ++t)
  {
    const auto& q = mesh.tets[t];
    s.cells[t] = tds.create_cell(s.vh[q[0]], s.vh[q[1]], s.vh[q[2]], s.vh[q[3]]);
  }
  s.workers.for_blocks(nt, [&](char&, int, std::size_t begin, std::size_t end) {
    for(std::size_t t = begin; t < end; ++t)
      for(int i = 0; i < 4; ++i)
      {
        const int m = faces.match[4 * t + static_cast<std::size_t>(i)];
        if(m >= 0) s.cells[t]->set_neighbor(i, s.cells[static_cast<std::size_t>(m / 4)]);
      }
  });
  s.workers.for_each(0, s.n, [&](char&, int v) {
    const int k = faces.vertex_cells_begin[v];
    if(k < faces.vertex_cells_begin[v + 1]) s.vh[v]->set_cell(s.cells[static_cast<std::size_t>(faces.vertex_cells[k])]);
  }, 4096);
}

// Step 4: an infinite cell on each boundary face: the finite cell's vertices with
// the infinite vertex in place of the far one and two others swapped, so that both
// cells induce opposite orientations on the face. Infinite cells are then glued
// along boundary edges, which must have exactly two boundary faces. The boundary
// faces are found in parallel blocks, and the cells made in the tetrahedra's order.
template <class C3T3>
void close_with_infinite_cells(Tet_mesh_to_c3t3_state<C3T3>& s)
{
  using Vertex_handle = typename Tet_mesh_to_c3t3_state<C3T3>::Vertex_handle;
  using Cell_handle = typename Tet_mesh_to_c3t3_state<C3T3>::Cell_handle;
  auto& tds = s.result.triangulation().tds();
  const Vertex_handle inf = s.infinite;
  const Tet_face_matching& faces = *s.faces;
  const std::vector<std::size_t> boundary =
      s.workers.indices_where(4 * s.nt, [&](std::size_t f) { return faces.match[f] < 0; });
  struct Hull_edge
  {
    std::uint64_t key;
    Cell_handle cell;
    int index;
  };
  std::vector<Hull_edge> hull_edges;
  for(const std::size_t f : boundary)
  {
    const std::size_t t = f / 4;
    const int i = static_cast<int>(f % 4);
    const Cell_handle c = s.cells[t];
    std::array<Vertex_handle, 4> v = {c->vertex(0), c->vertex(1), c->vertex(2), c->vertex(3)};
    std::array<int, 4> id = s.mesh.tets[t];
    v[i] = inf;
    id[i] = -1;
    std::swap(v[(i + 1) & 3], v[(i + 2) & 3]);
    std::swap(id[(i + 1) & 3], id[(i + 2) & 3]);
    const Cell_handle h = tds.create_cell(v[0], v[1], v[2], v[3]);
    if(inf->cell() == Cell_handle()) inf->set_cell(h);
    tds.set_adjacency(h, i, c, i);
    for(int k = 0; k < 4; ++k)
    {
      if(k == i) continue;
      // The face opposite `k` holds the infinite vertex and the boundary edge `e`.
      int e[2], m = 0;
      for(int j = 0; j < 4; ++j)
        if(j != k && j != i) e[m++] = id[j];
      hull_edges.push_back({packed_edge_key(e[0], e[1]), h, k});
    }
  }
  std::sort(hull_edges.begin(), hull_edges.end(), [](const Hull_edge& x, const Hull_edge& y) { return x.key < y.key; });
  for(std::size_t first = 0, last = 0; first < hull_edges.size(); first = last)
  {
    while(last < hull_edges.size() && hull_edges[last].key == hull_edges[first].key) ++last;
    if(last - first == 2)
    {
      tds.set_adjacency(hull_edges[first].cell, hull_edges[first].index, hull_edges[first + 1].cell,
                        hull_edges[first + 1].index);
      continue;
    }
    const std::uint64_t key = hull_edges[first].key;
    const int a = static_cast<int>(key >> 32), b = static_cast<int>(key & 0xffffffffu);
    s.fail("the boundary is not manifold at edge (" + std::to_string(a + 1) + " " + std::to_string(b + 1) +
           "): " + std::to_string(last - first) +
           " boundary triangles meet there, and a triangulation needs two to close the outside");
  }
}

// Step 5: triangulations reach the cells around a vertex through the faces around
// it, so tetrahedra that only touch at a vertex would be lost. The tetrahedra around
// each vertex must be connected through faces holding it (the outside cells connect
// nothing more: every boundary edge has two boundary faces, checked in step 4);
// vertices are checked in parallel, and the first failing one reported.
template <class C3T3>
void check_vertex_stars(const Tet_mesh_to_c3t3_state<C3T3>& s)
{
  const Tet_face_matching& faces = *s.faces;
  struct Star_worker
  {
    std::vector<int> mark;    // per cell: the last vertex whose star reached it
    std::vector<int> stack;
    int first_bad = -1;
  };
  Thread_workers<Star_worker> star_workers(s.threads);
  star_workers.for_each(0, s.n, [&](Star_worker& w, int v) {
    const int b = faces.vertex_cells_begin[v], e = faces.vertex_cells_begin[v + 1];
    if(b == e) return;
    if(w.mark.empty()) w.mark.assign(s.nt, -1);
    w.mark[faces.vertex_cells[b]] = v;
    w.stack.assign(1, faces.vertex_cells[b]);
    int reached = 1;
    while(!w.stack.empty())
    {
      const int c = w.stack.back();
      w.stack.pop_back();
      for(int i = 0; i < 4; ++i)
      {
        const int m = faces.match[4 * static_cast<std::size_t>(c) + i];
        if(s.mesh.tets[c][i] == v || m < 0 || w.mark[m / 4] == v) continue;
        w.mark[m / 4] = v;
        w.stack.push_back(m / 4);
        ++reached;
      }
    }
    if(reached != e - b && (w.first_bad < 0 || v < w.first_bad)) w.first_bad = v;
  }, 256);
  int pinched = -1;
  star_workers.each_worker([&pinched](const Star_worker& w) {
    if(w.first_bad >= 0 && (pinched < 0 || w.first_bad < pinched)) pinched = w.first_bad;
  });
  if(pinched >= 0)
    s.fail("the mesh is not manifold at vertex " + std::to_string(pinched + 1) + ": its " +
           std::to_string(faces.vertex_cells_begin[pinched + 1] - faces.vertex_cells_begin[pinched]) +
           " tetrahedra form separate groups that only touch there, and a triangulation needs them "
           "connected through faces");
}

// The subdomain index of tetrahedron `t` in the complex (all in 1 when every label is 0).
template <class C3T3>
typename C3T3::Subdomain_index complex_subdomain(const Tet_mesh& mesh, std::size_t t, bool all_zero)
{
  return typename C3T3::Subdomain_index(all_zero ? 1 : mesh.tet_labels[t]);
}

// Step 6a: every vertex of dimension 3, the labelled cells in the complex, and each
// vertex's index the subdomain of its last cell in the complex.
template <class C3T3>
void add_complex_cells(Tet_mesh_to_c3t3_state<C3T3>& s)
{
  const Tet_mesh& mesh = s.mesh;
  const Tet_face_matching& faces = *s.faces;
  for(int i = 0; i < s.n; ++i)
    if(s.used[i]) s.result.set_dimension(s.vh[i], 3);
  const bool all_zero = mesh.all_labels_zero();
  for(std::size_t t = 0; t < s.nt; ++t)
    if(mesh.in_mesh(t, all_zero)) s.result.add_to_complex(s.cells[t], complex_subdomain<C3T3>(mesh, t, all_zero));
  s.workers.for_each(0, s.n, [&](char&, int v) {
    for(int k = faces.vertex_cells_begin[v + 1]; k-- > faces.vertex_cells_begin[v];)
    {
      const auto t = static_cast<std::size_t>(faces.vertex_cells[k]);
      if(!mesh.in_mesh(t, all_zero)) continue;
      set_vertex_index(s.vh[v], complex_subdomain<C3T3>(mesh, t, all_zero));
      break;
    }
  }, 4096);
}

// Step 6b: the faces between different subdomains (or a subdomain and the outside)
// as facets of the complex, each from the first cell that has it, found from the
// flat arrays in parallel blocks; their vertices get dimension 2 and the patch.
template <class C3T3>
void add_complex_facets(Tet_mesh_to_c3t3_state<C3T3>& s)
{
  using Subdomain_index = typename C3T3::Subdomain_index;
  using Surface_patch_index = typename C3T3::Surface_patch_index;
  const Tet_mesh& mesh = s.mesh;
  const Tet_face_matching& faces = *s.faces;
  const std::size_t nt = s.nt;
  const bool all_zero = mesh.all_labels_zero();
  std::unordered_map<std::array<int, 3>, int, internal::Id_hash> listed;
  int next_patch = 1;
  if constexpr(!Is_pair<Surface_patch_index>::value)
    for(std::size_t f = 0; f < mesh.triangles.size(); ++f)
    {
      listed.emplace(sorted(mesh.triangles[f]), mesh.triangle_labels[f]);
      next_patch = (std::max)(next_patch, mesh.triangle_labels[f] + 1);
    }
  std::vector<Subdomain_index> label(nt);
  for(std::size_t t = 0; t < nt; ++t)
    if(mesh.in_mesh(t, all_zero)) label[t] = complex_subdomain<C3T3>(mesh, t, all_zero);
  // The faces (4 t + i) between two labels, each once (from the tetrahedron with the smaller index).
  const std::vector<std::size_t> between = s.workers.indices_where(4 * nt, [&](std::size_t f) {
    const std::size_t t = f / 4;
    const int m = faces.match[f];
    const Subdomain_index other = m < 0 ? Subdomain_index() : label[static_cast<std::size_t>(m / 4)];
    return !(label[t] == other) && (m < 0 || static_cast<std::size_t>(m / 4) > t);
  });
  std::map<std::pair<Subdomain_index, Subdomain_index>, Surface_patch_index> derived;
  for(const std::size_t f : between)
  {
    const std::size_t t = f / 4;
    const int i = static_cast<int>(f % 4);
    const auto c = s.cells[t];
    const Subdomain_index s0 = label[t], s1 = s.result.subdomain_index(c->neighbor(i));
    const std::pair<Subdomain_index, Subdomain_index> sides = (std::minmax)(s0, s1);
    Surface_patch_index patch;
    if constexpr(Is_pair<Surface_patch_index>::value)
      patch = Surface_patch_index(sides.first, sides.second);
    else
    {
      const auto it = listed.find(sorted(oriented_face(mesh.tets[t], i)));
      if(it != listed.end() && !(Surface_patch_index(it->second) == Surface_patch_index()))
        patch = Surface_patch_index(it->second);
      else
      {
        auto d = derived.emplace(sides, Surface_patch_index(next_patch));
        if(d.second) ++next_patch;
        patch = d.first->second;
      }
    }
    s.result.add_to_complex(c, i, patch);
    for(int k = 0; k < 4; ++k)
      if(k != i)
      {
        s.result.set_dimension(c->vertex(k), 2);
        set_vertex_index(c->vertex(k), patch);
      }
  }
}

// Step 6c: `mesh.edges` as curve edges of the complex, their vertices of dimension 1.
template <class C3T3>
void add_curve_edges(Tet_mesh_to_c3t3_state<C3T3>& s)
{
  using Curve_index = typename C3T3::Curve_index;
  const Tet_mesh& mesh = s.mesh;
  auto& tds = s.result.triangulation().tds();
  int unlabelled_curve = 1;
  for(int l : mesh.edge_labels) unlabelled_curve = (std::max)(unlabelled_curve, l + 1);
  for(std::size_t e = 0; e < mesh.edges.size(); ++e)
  {
    const int a = mesh.edges[e][0], b = mesh.edges[e][1];
    typename Tet_mesh_to_c3t3_state<C3T3>::Cell_handle c;
    int i, j;
    if(a < 0 || b < 0 || a >= s.n || b >= s.n || a == b || !s.used[a] || !s.used[b] ||
       !tds.is_edge(s.vh[a], s.vh[b], c, i, j))
      s.fail("Edges entry " + std::to_string(e + 1) + " (" + std::to_string(a + 1) + " " + std::to_string(b + 1) +
             ") is not an edge of the tetrahedra");
    if(s.result.is_in_complex(s.vh[a], s.vh[b])) continue;
    Curve_index curve(mesh.edge_labels[e]);
    if(curve == Curve_index()) curve = Curve_index(unlabelled_curve);
    s.result.add_to_complex(s.vh[a], s.vh[b], curve);
    for(int v : {a, b})
    {
      s.result.set_dimension(s.vh[v], 1);
      set_vertex_index(s.vh[v], curve);
    }
  }
}

// Step 6d: `mesh.corners` then `mesh.required_vertices` as corners, numbered 1, 2, ...
template <class C3T3>
void add_corners(Tet_mesh_to_c3t3_state<C3T3>& s)
{
  using Corner_index = typename C3T3::Corner_index;
  int next_corner = 1;
  for(const std::vector<int>* list : {&s.mesh.corners, &s.mesh.required_vertices})
    for(int v : *list)
    {
      if(v < 0 || v >= s.n) s.fail("corner " + std::to_string(v + 1) + " is not a vertex");
      if(!s.used[v] || s.result.is_in_complex(s.vh[v])) continue;
      const Corner_index corner(next_corner++);
      s.result.add_to_complex(s.vh[v], corner);
      set_vertex_index(s.vh[v], corner);
    }
}

// Step 6: the complex: cells, facets, curves and corners, each vertex with the
// dimension and index of the lowest face it lies on; then the facets' surface centers.
template <class C3T3>
void add_labels(Tet_mesh_to_c3t3_state<C3T3>& s)
{
  add_complex_cells(s);
  add_complex_facets(s);
  add_curve_edges(s);
  add_corners(s);
  set_facet_surface_centers(s.result);
}

// What `c3t3_to_tet_mesh` and `update_tet_mesh` read from a complex: a vertex's
// position in doubles, and a facet of the complex as the triangle a file lists,
// its normal out of the complex cell on its side (out of the one with the
// smaller subdomain index between two subdomains).
template <class C3T3>
class Complex_reader
{
public:
  using Tr = typename C3T3::Triangulation;
  using Vertex_handle = typename Tr::Vertex_handle;

  explicit Complex_reader(const C3T3& c3t3) : c3t3_(c3t3), tr_(c3t3.triangulation()) {}

  Tet_mesh::Point point(Vertex_handle v) const
  {
    const auto& p = tr_.geom_traits().construct_point_3_object()(v->point());
    return Tet_mesh::Point(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
  }

  std::array<Vertex_handle, 3> triangle(const typename C3T3::Facet& f) const
  {
    using U = Triangulation_utils_3;
    const auto mirror = tr_.mirror_facet(f);
    const bool flip = !c3t3_.is_in_complex(f.first) ||
                      (c3t3_.is_in_complex(mirror.first) &&
                       c3t3_.subdomain_index(mirror.first) < c3t3_.subdomain_index(f.first));
    const auto& side = flip ? mirror : f;
    // Reversing CGAL's order (counterclockwise seen from inside) points the normal out.
    return {side.first->vertex(U::vertex_triple_index(side.second, 2)),
            side.first->vertex(U::vertex_triple_index(side.second, 1)),
            side.first->vertex(U::vertex_triple_index(side.second, 0))};
  }

private:
  const C3T3& c3t3_;
  const Tr& tr_;
};

} // namespace internal

/// Builds `c3t3` (a `Mesh_complex_3_in_triangulation_3`) from `mesh`, replacing its
/// content. The triangulation has the mesh's vertices, in the same order, and its
/// tetrahedra as finite cells (same vertex order); each boundary face of the
/// tetrahedra gets an infinite cell, as `CGAL::IO::read_MEDIT` does. Vertices that
/// no tetrahedron uses cannot be in a triangulation and are left out.
///
/// The complex:
///  - cells: the tetrahedra with a label other than 0, with their label as subdomain
///    index (all tetrahedra, in subdomain 1, when every label is 0);
///  - facets: the faces between a cell of the complex and one of another subdomain
///    or outside the complex. Their surface patch index is, when
///    `Surface_patch_index` is a `std::pair` (Mesh_3's labeled and implicit
///    domains), the ordered pair of subdomain indices (0 outside), as
///    `Labeled_mesh_domain_3` makes it, so file triangle labels are not kept; when it
///    is constructible from `int`, the label of the face in `mesh.triangles` if it is
///    listed with a label other than 0, else a new index per pair of subdomains,
///    above every triangle label. Triangles that are not such faces are ignored;
///  - curve edges: `mesh.edges`, with the edge label as `Curve_index` (labels 0,
///    which the complex reads as "not an edge", get one index above all labels);
///  - corners: `mesh.corners` then `mesh.required_vertices`, numbered 1, 2, ...
/// Each vertex gets the dimension of the lowest face it lies on (0 corner, 1 curve
/// edge, 2 complex facet, 3 otherwise) and, where the vertex `Index` type can hold
/// it, that face's index (for dimension 3, the subdomain of a complex cell around it).
///
/// When the boundary of the tetrahedra has several components or a handle, the
/// infinite vertex's star is not a ball: every adjacency is valid, but
/// `tds().is_valid()` reports the Euler relation unsatisfied, as for
/// `CGAL::IO::read_MEDIT`'s output.
///
/// Throws `Mesh_io_error` (naming `file`, line 0) when the tetrahedra cannot form a
/// CGAL triangulation: a boundary edge with more than two boundary faces, a vertex
/// whose tetrahedra only touch there, a face of three tetrahedra, tetrahedra of
/// inconsistent or negative orientation, bad indices, or an `Edges` entry that is
/// no edge of the tetrahedra. `c3t3` is unchanged then.
///
/// When `handles` is given, it receives the vertex of each point (a default handle
/// for points no tetrahedron uses), for `update_tet_mesh`. `faces`: the faces of
/// `mesh.tets` matched, if the caller has them already.
template <class C3T3>
void tet_mesh_to_c3t3(const Tet_mesh& mesh, C3T3& c3t3, const std::string& file = std::string(),
                      std::vector<typename C3T3::Vertex_handle>* handles = nullptr,
                      const internal::Tet_face_matching* faces = nullptr)
{
  using namespace internal;
  using Surface_patch_index = typename C3T3::Surface_patch_index;
  static_assert(std::is_constructible<typename C3T3::Subdomain_index, int>::value,
                "Subdomain_index must be constructible from int");
  static_assert(Is_pair<Surface_patch_index>::value || std::is_constructible<Surface_patch_index, int>::value,
                "Surface_patch_index must be a std::pair of subdomain indices or constructible from int");
  static_assert(std::is_constructible<typename C3T3::Curve_index, int>::value,
                "Curve_index must be constructible from int");
  static_assert(std::is_constructible<typename C3T3::Corner_index, int>::value,
                "Corner_index must be constructible from int");

  Tet_mesh_to_c3t3_state<C3T3> state(mesh, file, faces);
  check_tetrahedra(state);
  create_vertices(state);
  glue_finite_cells(state);
  close_with_infinite_cells(state);
  check_vertex_stars(state);
  add_labels(state);
  c3t3.swap(state.result);
  if(handles) handles->swap(state.vh);
}

/// The cells of `c3t3`'s complex as a `Tet_mesh`:
///  - points: the vertices of those cells, in the triangulation's vertex order
///    (vertices of no cell of the complex are left out, so that every written vertex
///    belongs to a tetrahedron), with reference 0;
///  - tets: the cells of the complex, with their subdomain index as label;
///  - triangles: the facets of the complex whose vertices are written, oriented
///    with their normal out of the complex cell on their side (out of the one with
///    the smaller subdomain index between two subdomains);
///  - edges: the curve edges, corners: the corners of the complex.
/// Integral subdomain, surface patch and curve indices are written as they are;
/// other types (Mesh_3's `std::pair` surface patch indices) are numbered 1, 2, ...
/// in the order the facets (edges, cells) are visited.
template <class C3T3>
Tet_mesh c3t3_to_tet_mesh(const C3T3& c3t3)
{
  using namespace internal;
  using Vertex_handle = typename C3T3::Vertex_handle;
  const auto& tr = c3t3.triangulation();
  const Complex_reader<C3T3> read(c3t3);

  std::unordered_map<Vertex_handle, int> index;
  for(auto c = c3t3.cells_in_complex_begin(); c != c3t3.cells_in_complex_end(); ++c)
    for(int k = 0; k < 4; ++k) index.emplace(c->vertex(k), -1);
  Tet_mesh mesh;
  for(auto v = tr.finite_vertices_begin(); v != tr.finite_vertices_end(); ++v)
  {
    const auto it = index.find(v);
    if(it == index.end()) continue;
    it->second = static_cast<int>(mesh.points.size());
    mesh.points.push_back(read.point(v));
  }
  mesh.vertex_refs.assign(mesh.points.size(), 0);

  Label_numbering<typename C3T3::Subdomain_index> subdomain_label;
  for(auto c = c3t3.cells_in_complex_begin(); c != c3t3.cells_in_complex_end(); ++c)
  {
    mesh.tets.push_back({index.at(c->vertex(0)), index.at(c->vertex(1)), index.at(c->vertex(2)),
                         index.at(c->vertex(3))});
    mesh.tet_labels.push_back(subdomain_label(c3t3.subdomain_index(c)));
  }

  Label_numbering<typename C3T3::Surface_patch_index> patch_label;
  for(auto f = c3t3.facets_in_complex_begin(); f != c3t3.facets_in_complex_end(); ++f)
  {
    const std::array<Vertex_handle, 3> triangle = read.triangle(*f);
    std::array<int, 3> t;
    bool written = true;
    for(int k = 0; k < 3; ++k)
    {
      const auto it = index.find(triangle[k]);
      written = written && it != index.end();
      if(written) t[k] = it->second;
    }
    if(!written) continue;
    mesh.triangles.push_back(t);
    mesh.triangle_labels.push_back(patch_label(c3t3.surface_patch_index(*f)));
  }

  Label_numbering<typename C3T3::Curve_index> curve_label;
  for(auto e = c3t3.edges_in_complex_begin(); e != c3t3.edges_in_complex_end(); ++e)
  {
    const auto a = index.find(e->first->vertex(e->second)), b = index.find(e->first->vertex(e->third));
    if(a == index.end() || b == index.end()) continue;
    mesh.edges.push_back({a->second, b->second});
    mesh.edge_labels.push_back(curve_label(c3t3.curve_index(*e)));
  }

  for(auto v = c3t3.vertices_in_complex_begin(); v != c3t3.vertices_in_complex_end(); ++v)
  {
    const auto it = index.find(v);
    if(it != index.end()) mesh.corners.push_back(it->second);
  }
  return mesh;
}

/// A C3T3 type that holds what a mesh file holds: integral subdomain, surface
/// patch (the file's triangle labels), curve and corner indices.
struct Tet_mesh_domain_indices
{
  using R = Tet_mesh::Kernel;
  using Point_3 = R::Point_3;
  using Subdomain_index = int;
  using Surface_patch_index = int;
  using Curve_index = int;
  using Corner_index = int;
  using Index = int;
  using Has_features = CGAL::Tag_true;
};
using Tet_mesh_triangulation = CGAL::Mesh_triangulation_3<
    Tet_mesh_domain_indices, CGAL::Default, CGAL::Sequential_tag, CGAL::Default,
    Tet_mesh_cell_base_3<CGAL::Robust_weighted_circumcenter_filtered_traits_3<Tet_mesh::Kernel>>>::type;
using Tet_mesh_c3t3 = CGAL::Mesh_complex_3_in_triangulation_3<Tet_mesh_triangulation, int, int>;

namespace internal {

// update_tet_mesh, told whether the file's tetrahedron labels were all 0: smooth()
// frees the labels during its run.
template <class C3T3>
void update_tet_mesh(Tet_mesh& mesh, const C3T3& c3t3, const std::vector<typename C3T3::Vertex_handle>& handles,
                     int threads, bool all_zero)
{
  using Tr = typename C3T3::Triangulation;
  using Vertex_handle = typename Tr::Vertex_handle;
  const Tr& tr = c3t3.triangulation();
  const Complex_reader<C3T3> read(c3t3);

  Handle_index_map<Vertex_handle> index_map;
  index_map.reset(tr.number_of_vertices());
  const char* const unindexed_vertex = "update_tet_mesh: a vertex of the triangulation is not indexed";
  auto index = [&](Vertex_handle v) {
    const int i = index_map.find(v);
    if(i < 0) throw std::out_of_range(unindexed_vertex);
    return i;
  };
  for(std::size_t i = 0; i < handles.size(); ++i)
    if(handles[i] != Vertex_handle())
    {
      index_map.insert(handles[i], static_cast<int>(i));
      mesh.points[i] = read.point(handles[i]);
    }
  for(auto v = tr.finite_vertices_begin(); v != tr.finite_vertices_end(); ++v)
    if(index_map.insert(v, static_cast<int>(mesh.points.size())))
    {
      mesh.points.push_back(read.point(v));
      mesh.vertex_refs.push_back(0);
    }

  // The cells in the triangulation's order, then their vertex indices (lookups
  // only) in parallel.
  std::vector<typename Tr::Cell_handle> finite;
  reserve_fresh(finite, tr.number_of_cells(), threads);   // not number_of_finite_cells(), which counts them one by one
  for(auto c = tr.finite_cells_begin(); c != tr.finite_cells_end(); ++c) finite.push_back(c);
  resize_for_overwrite(mesh.tets, finite.size(), threads);
  resize_for_overwrite(mesh.tet_labels, finite.size(), threads);
  std::atomic<bool> unindexed{false};
  Thread_workers<char>(threads).for_each(0, static_cast<int>(finite.size()), [&](char&, int t) {
    const auto c = finite[t];
    for(int k = 0; k < 4; ++k)
    {
      mesh.tets[t][k] = index_map.find(c->vertex(k));
      if(mesh.tets[t][k] < 0) unindexed.store(true, std::memory_order_relaxed);
    }
    mesh.tet_labels[t] = all_zero || !c3t3.is_in_complex(c) ? 0 : static_cast<int>(c3t3.subdomain_index(c));
  }, 4096);
  if(unindexed) throw std::out_of_range(unindexed_vertex);

  if(!mesh.triangles.empty())
  {
    std::map<int, bool> labels;
    for(int l : mesh.triangle_labels) labels[l] = true;
    std::unordered_map<std::array<int, 3>, int, internal::Id_hash> present;   // sorted -> patch
    std::vector<std::array<int, 3>> added;
    std::vector<int> added_labels;
    for(auto f = c3t3.facets_in_complex_begin(); f != c3t3.facets_in_complex_end(); ++f)
    {
      const int patch = static_cast<int>(c3t3.surface_patch_index(*f));
      if(!labels.count(patch)) continue;
      const std::array<Vertex_handle, 3> triangle = read.triangle(*f);
      std::array<int, 3> t;
      for(int k = 0; k < 3; ++k) t[k] = index(triangle[k]);
      present.emplace(sorted(t), patch);
      added.push_back(t);
      added_labels.push_back(patch);
    }
    std::vector<std::array<int, 3>> triangles;
    std::vector<int> triangle_labels;
    for(std::size_t f = 0; f < mesh.triangles.size(); ++f)
    {
      const auto it = present.find(sorted(mesh.triangles[f]));
      if(it == present.end()) continue;
      triangles.push_back(mesh.triangles[f]);
      triangle_labels.push_back(mesh.triangle_labels[f]);
      it->second = -1;   // written
    }
    for(std::size_t f = 0; f < added.size(); ++f)
    {
      auto& written = present.at(sorted(added[f]));
      if(written == -1) continue;
      written = -1;
      triangles.push_back(added[f]);
      triangle_labels.push_back(added_labels[f]);
    }
    mesh.triangles.swap(triangles);
    mesh.triangle_labels.swap(triangle_labels);
  }

  // Edges: an input edge no longer in the complex was split; its pieces run from
  // one end to the other through added curve vertices.
  std::vector<std::array<int, 2>> edges;
  std::vector<int> edge_labels;
  std::vector<int> first_piece(mesh.edges.size() + 1, 0);
  for(std::size_t e = 0; e < mesh.edges.size(); ++e)
  {
    const int a = mesh.edges[e][0], b = mesh.edges[e][1];
    const Vertex_handle va = handles[a], vb = handles[b];
    if(c3t3.is_in_complex(va, vb))
    {
      edges.push_back(mesh.edges[e]);
      edge_labels.push_back(mesh.edge_labels[e]);
    }
    else
    {
      // Walk from `a` through added vertices, trying each first step, until an
      // original vertex: the walk that ends at `b` is the split edge.
      const int original = static_cast<int>(handles.size());
      std::vector<std::pair<Vertex_handle, typename C3T3::Curve_index>> around;
      std::vector<int> chain;
      c3t3.adjacent_vertices_in_complex(va, std::back_inserter(around));
      const auto starts = around;
      for(const auto& start : starts)
      {
        chain.assign(1, a);
        Vertex_handle prev = va, cur = start.first;
        while(index(cur) >= original)
        {
          chain.push_back(index(cur));
          around.clear();
          c3t3.adjacent_vertices_in_complex(cur, std::back_inserter(around));
          Vertex_handle next;
          for(const auto& x : around)
            if(x.first != prev) next = x.first;
          if(next == Vertex_handle() || chain.size() > handles.size() + mesh.points.size()) break;
          prev = cur;
          cur = next;
        }
        if(cur != vb || chain.size() < 2) continue;
        chain.push_back(b);
        for(std::size_t k = 0; k + 1 < chain.size(); ++k)
        {
          edges.push_back({chain[k], chain[k + 1]});
          edge_labels.push_back(mesh.edge_labels[e]);
        }
        break;
      }
    }
    first_piece[e + 1] = static_cast<int>(edges.size());
  }
  std::vector<int> ridges;
  for(int r : mesh.ridges)
    for(int k = first_piece[r]; k < first_piece[r + 1]; ++k) ridges.push_back(k);
  mesh.edges.swap(edges);
  mesh.edge_labels.swap(edge_labels);
  mesh.ridges.swap(ridges);
}

} // namespace internal

/// Writes back into `mesh` what a pipeline did to `c3t3`, which
/// `tet_mesh_to_c3t3(mesh, c3t3, file, &handles)` built:
///  - points: every point keeps its index and gets its vertex's position; vertices
///    added to the triangulation are appended (reference 0);
///  - tets: the finite cells, labelled with their subdomain, or 0 outside the
///    complex (0 for all when every input label was 0);
///  - triangles (only if the input had some): the facets of the complex whose patch
///    is a label of the input's triangles; a facet the input listed keeps its place
///    and orientation, new ones (from flips and splits) follow, oriented as
///    `c3t3_to_tet_mesh` orients them;
///  - edges: the input's edges, each replaced in place by the curve edges it was
///    split into; ridges follow their edges; corners and required vertices stay.
/// `threads` (as `Smoothing_options::threads`) changes nothing in the result.
template <class C3T3>
void update_tet_mesh(Tet_mesh& mesh, const C3T3& c3t3, const std::vector<typename C3T3::Vertex_handle>& handles,
                     int threads = 1)
{
  internal::update_tet_mesh(mesh, c3t3, handles, threads, mesh.all_labels_zero());
}

} // namespace BODT_3
} // namespace CGAL

#endif // CGAL_BODT_3_TET_MESH_CONVERSION_H
