// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_BODT_3_INTERNAL_TOPOLOGY_MULTI_FACE_REMOVAL_H
#define CGAL_BODT_3_INTERNAL_TOPOLOGY_MULTI_FACE_REMOVAL_H

#include <CGAL/BODT_3/internal/Topology/Flip.h>

#include <algorithm>
#include <array>
#include <limits>
#include <vector>

namespace CGAL {
namespace BODT_3 {
namespace internal {

/// Multi-face removal, the inverse of edge removal (Shewchuk, "Two discrete
/// optimization algorithms for the topological improvement of tetrahedral
/// meshes"): for a face with apexes u and w, the faces of its "sandwich" (faces
/// whose two cells have apexes u and w, reached across edges of exactly four cells)
/// are removed with their 2 k cells, and the edge u w is created with one cell
/// (u, w, p, q) per boundary edge p q of the removed faces: k + 2 cells. Which
/// faces to remove is chosen by dynamic programming over the tree of the sandwich,
/// to maximize the worst new cell. One face is the 2-3 flip.
///
/// Allowed inside one flippable region only: no face, edge or cell touched is in
/// the complex as a boundary, interface or curve, and u w is not already an edge.
template <class Adapter>
struct Multi_face_removal
{
  using Vertex_handle = typename Adapter::Vertex_handle;
  using Cell_handle = typename Adapter::Cell_handle;

  int max_faces = 10;   // the sandwich is explored up to this many faces

private:
  struct Face
  {
    std::array<Vertex_handle, 3> v;   // (v0, v1, v2, w) has the orientation of cell_w
    Cell_handle cell_w, cell_u;
    std::array<int, 3> child;          // across edge (v[k], v[k+1]): a face index, -1, or -2 (parent)
  };
  // Scratch space kept between calls (removals are tried often).
  mutable std::vector<Face> faces_;
  mutable std::vector<double> value_;
  mutable std::vector<std::array<char, 3>> extend_;
  mutable std::vector<int> stack_;

public:
  /// Proposes a multi-face removal rooted at facet (c, i) in `out`; returns false
  /// if none is allowed or valid. `out.improves()` tells whether to apply it. A
  /// proposal whose worst new cell is not above `at_least` (the best the caller
  /// has) is not checked for validity, as the caller will not take it.
  bool operator()(const Flip_context<Adapter>& ctx, Cell_handle c, int i, Flip<Adapter>& out,
                  double at_least = -std::numeric_limits<double>::infinity()) const
  {
    out.clear();
    const Cell_handle n = c->neighbor(i);
    const Vertex_handle w = c->vertex(i);
    const Vertex_handle u = n->vertex(n->index(c));
    if(ctx.is_infinite(u) || ctx.is_infinite(w)) return false;
    const auto region = ctx.adapter.region(c);
    if(!ctx.flippable(region) || ctx.adapter.region(n) != region || ctx.adapter.patch(c, i).in_complex) return false;

    // The sandwich, explored depth first from the root face.
    std::vector<Face>& faces = faces_;
    faces.clear();
    {
      std::array<Vertex_handle, 3> v;
      for(int k = 0, l = 0; k < 4; ++k)
        if(k != i) v[l++] = c->vertex(k);
      if(!Flip_context<Adapter>::same_orientation(c, v[0], v[1], v[2], w)) std::swap(v[1], v[2]);
      faces.push_back({v, c, n, {-1, -1, -1}});
    }
    auto known = [&](Vertex_handle a, Vertex_handle b, Vertex_handle x) {
      for(const Face& f : faces)
        if(std::count(f.v.begin(), f.v.end(), a) + std::count(f.v.begin(), f.v.end(), b) +
               std::count(f.v.begin(), f.v.end(), x) == 3)
          return true;
      return false;
    };
    for(std::size_t f = 0; f < faces.size(); ++f)
      for(int k = 0; k < 3; ++k)
      {
        if(faces[f].child[k] == -2 || static_cast<int>(faces.size()) >= max_faces) continue;
        const Vertex_handle p = faces[f].v[k], q = faces[f].v[(k + 1) % 3], y = faces[f].v[(k + 2) % 3];
        const Cell_handle cw = faces[f].cell_w, cu = faces[f].cell_u;
        const Cell_handle N = cw->neighbor(cw->index(y)), M = cu->neighbor(cu->index(y));
        Vertex_handle x;
        for(int l = 0; l < 4; ++l)
          if(N->vertex(l) != p && N->vertex(l) != q && N->vertex(l) != w) x = N->vertex(l);
        if(ctx.is_infinite(x) || !M->has_vertex(x) || N->neighbor(N->index(w)) != M) continue;
        if(ctx.adapter.region(N) != region || ctx.adapter.region(M) != region) continue;
        if(ctx.adapter.patch(cw, cw->index(y)).in_complex || ctx.adapter.patch(cu, cu->index(y)).in_complex ||
           ctx.adapter.patch(N, N->index(w)).in_complex || ctx.adapter.is_curve_edge(p, q))
          continue;
        if(known(p, q, x)) continue;
        faces[f].child[k] = static_cast<int>(faces.size());
        faces.push_back({{q, p, x}, N, M, {-2, -1, -1}});
      }

    // Values bottom-up: children come after their parents.
    const Region_kind measured = region.kind;
    auto new_cell = [&](const Face& f, int k) {
      return std::array<Vertex_handle, 4>{u, w, f.v[k], f.v[(k + 1) % 3]};
    };
    std::vector<double>& value = value_;
    value.assign(faces.size(), 0);
    std::vector<std::array<char, 3>>& extend = extend_;
    extend.assign(faces.size(), std::array<char, 3>{0, 0, 0});
    for(std::size_t f = faces.size(); f-- > 0;)
    {
      double worst = std::numeric_limits<double>::infinity();
      for(int k = 0; k < 3; ++k)
      {
        if(faces[f].child[k] == -2) continue;
        double best = ctx.value(new_cell(faces[f], k), region.kind, measured);
        if(faces[f].child[k] >= 0 && value[faces[f].child[k]] > best)
        {
          best = value[faces[f].child[k]];
          extend[f][k] = 1;
        }
        worst = std::min(worst, best);
      }
      value[f] = worst;
    }
    out.new_worst = value[0];
    if(out.new_worst <= 0) return false;

    // The chosen faces, and the new cells on their boundary edges.
    std::vector<int>& stack = stack_;
    stack.assign(1, 0);
    std::size_t chosen = 0;
    out.old_worst = std::numeric_limits<double>::infinity();
    while(!stack.empty())
    {
      const int f = stack.back();
      stack.pop_back();
      ++chosen;
      out.old_cells.push_back(faces[f].cell_w);
      out.old_cells.push_back(faces[f].cell_u);
      out.old_worst = std::min({out.old_worst, ctx.quality(faces[f].cell_w), ctx.quality(faces[f].cell_u)});
      for(int k = 0; k < 3; ++k)
      {
        if(faces[f].child[k] == -2) continue;
        if(extend[f][k])
          stack.push_back(faces[f].child[k]);
        else
          out.new_cells.push_back({new_cell(faces[f], k), 0});
      }
    }
    out.kind = chosen == 1 ? Flip_kind::flip_2_3 : Flip_kind::multi_face_removal;
    // An edge u w elsewhere would make the new cells overlap others: checked only
    // for a flip worth applying, since it costs most.
    return !(out.improves() && out.new_worst > at_least && ctx.adapter.tds().is_edge(u, w));
  }
};

} // namespace internal
} // namespace BODT_3
} // namespace CGAL

#endif // CGAL_BODT_3_INTERNAL_TOPOLOGY_MULTI_FACE_REMOVAL_H
