// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_BODT_3_INTERNAL_SMOOTHING_SWEEP_ORDER_H
#define CGAL_BODT_3_INTERNAL_SMOOTHING_SWEEP_ORDER_H

#include <CGAL/BODT_3/internal/Mesh/Flat_mesh.h>

#include <algorithm>
#include <vector>

namespace CGAL {
namespace BODT_3 {
namespace internal {

/// The order in which a sweep visits the movable vertices: by colour, then by
/// index, for a greedy colouring (in index order) in which no two vertices of a
/// cell share a colour, nor a vertex and the far vertex of one of its hull checks
/// (`Flat_mesh::Hull_check`). Vertices of one colour then have disjoint
/// stars and read nothing the others move, so a parallel sweep may move them
/// concurrently and still reproduce this sequential order exactly; the order
/// depends on nothing but the mesh.
struct Sweep_order
{
  std::vector<int> vertices;        // movable vertices in visiting order
  std::vector<int> colour_begin;    // colour k is vertices[colour_begin[k] .. colour_begin[k+1])
};

template <class K>
Sweep_order sweep_order(const Flat_mesh<K>& mesh, const std::vector<char>& movable)
{
  const int nv = static_cast<int>(mesh.number_of_vertices());
  std::vector<int> colour(nv, -1);
  std::vector<int> stamp;   // stamp[c] == v: colour c is taken by a neighbour of v
  int colours = 0;
  for(int v = 0; v < nv; ++v)
  {
    if(!movable[v]) continue;
    auto take = [&](int u) {
      if(u != v && colour[u] >= 0) stamp[colour[u]] = v;
    };
    // A cell's vertices other than v are the incidence's face: read in place, not through the cells.
    for(int k = mesh.incidence_begin[v]; k < mesh.incidence_begin[v + 1]; ++k)
      for(int u : mesh.incidences[k].face) take(u);
    for(int k = mesh.hull_begin[v]; k < mesh.hull_begin[v + 1]; ++k) take(mesh.vertex_hull_checks[k][3]);
    for(int k = mesh.checked_begin[v]; k < mesh.checked_begin[v + 1]; ++k) take(mesh.checked_by[k]);
    int c = 0;
    while(c < colours && stamp[c] == v) ++c;
    if(c == colours)
    {
      ++colours;
      stamp.push_back(-1);
    }
    colour[v] = c;
  }
  Sweep_order order;
  order.colour_begin.assign(colours + 1, 0);
  for(int v = 0; v < nv; ++v)
    if(colour[v] >= 0) ++order.colour_begin[colour[v] + 1];
  for(int c = 0; c < colours; ++c) order.colour_begin[c + 1] += order.colour_begin[c];
  order.vertices.resize(order.colour_begin[colours]);
  std::vector<int> fill(order.colour_begin.begin(), order.colour_begin.end() - 1);
  for(int v = 0; v < nv; ++v)
    if(colour[v] >= 0) order.vertices[fill[colour[v]]++] = v;
  return order;
}

} // namespace internal
} // namespace BODT_3
} // namespace CGAL

#endif // CGAL_BODT_3_INTERNAL_SMOOTHING_SWEEP_ORDER_H
