// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_BODT_3_BOUNDARY_DISTANCE_H
#define CGAL_BODT_3_BOUNDARY_DISTANCE_H

#include <CGAL/BODT_3/Tet_mesh.h>
#include <CGAL/BODT_3/internal/Utilities/Thread_workers.h>
#include <CGAL/BODT_3/internal/Utilities/tet_face_matching.h>
#include <CGAL/BODT_3/mesh_quality.h>

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Bbox_3.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <vector>

namespace CGAL {
namespace BODT_3 {

using Boundary_triangles = std::vector<Tet_mesh::Kernel::Triangle_3>;

/// The boundary and interface triangles of a `Tet_mesh`: faces between a mesh
/// tetrahedron and a non-mesh one (or none), and faces between two subdomains,
/// each once, in the order of the tetrahedra.
inline Boundary_triangles boundary_triangles(const Tet_mesh& mesh, int threads = 1)
{
  const bool all_zero = mesh.all_labels_zero();
  const internal::Tet_face_matching faces(mesh.tets, mesh.points.size(), threads);
  auto label = [&](std::size_t t) { return mesh.in_mesh(t, all_zero) ? mesh.tet_labels[t] : -1; };
  Boundary_triangles out;
  for(std::size_t t = 0; t < mesh.tets.size(); ++t)
  {
    const int a = label(t);
    if(a < 0) continue;
    for(int k = 0; k < 4; ++k)
    {
      // A face between two labels is taken from the side of the smaller one.
      const int m = faces.match[4 * t + static_cast<std::size_t>(k)];
      const int b = m >= 0 ? label(static_cast<std::size_t>(m / 4)) : -1;
      if(a == b || (b >= 0 && b < a)) continue;
      std::array<Tet_mesh::Point, 3> p;
      for(int j = 0, n = 0; j < 4; ++j)
        if(j != k) p[n++] = mesh.points[mesh.tets[t][j]];
      out.emplace_back(p[0], p[1], p[2]);
    }
  }
  out.shrink_to_fit();   // kept through the run, for the distance after it
  return out;
}

/// The facets in a C3T3's complex: its boundary and interface triangles.
template <class C3T3>
std::enable_if_t<internal::Is_c3t3<C3T3>::value, Boundary_triangles> boundary_triangles(const C3T3& c3t3)
{
  auto cp = c3t3.triangulation().geom_traits().construct_point_3_object();
  Boundary_triangles out;
  for(auto f = c3t3.facets_in_complex_begin(); f != c3t3.facets_in_complex_end(); ++f)
  {
    std::array<Tet_mesh::Point, 3> p;
    for(int k = 0, m = 0; k < 4; ++k)
      if(k != f->second) p[m++] = cp(f->first->vertex(k)->point());
    out.emplace_back(p[0], p[1], p[2]);
  }
  return out;
}

/// The convex hull facets of a `Triangulation_3`.
template <class Tr>
std::enable_if_t<!internal::Is_c3t3<Tr>::value && !std::is_same<Tr, Tet_mesh>::value, Boundary_triangles>
boundary_triangles(const Tr& tr)
{
  auto cp = tr.geom_traits().construct_point_3_object();
  Boundary_triangles out;
  for(auto c = tr.all_cells_begin(); c != tr.all_cells_end(); ++c)
  {
    if(!c->has_vertex(tr.infinite_vertex())) continue;
    const int i = c->index(tr.infinite_vertex());
    std::array<Tet_mesh::Point, 3> p;
    for(int k = 0, m = 0; k < 4; ++k)
      if(k != i) p[m++] = cp(c->vertex(k)->point());
    out.emplace_back(p[0], p[1], p[2]);
  }
  return out;
}

/// Largest side of the bounding box of a set of triangles.
inline double largest_bbox_side(const Boundary_triangles& t)
{
  CGAL::Bbox_3 box;
  for(const auto& tri : t) box += tri.bbox();
  return std::max({box.xmax() - box.xmin(), box.ymax() - box.ymin(), box.zmax() - box.zmin()});
}

namespace internal {

/// The points of a barycentric grid on each triangle (`samples` subdivisions per
/// side, vertices included), each point once, in no particular order. Triangles
/// that share a vertex or an edge share grid points: at 2 subdivisions (corners
/// and side midpoints) every shared point is the same, bit for bit, from either
/// side (a corner is copied, a midpoint is (a + b) / 2 in either order), so a
/// closed surface has a third of the points its triangles list, and each one's
/// distance is measured once.
inline std::vector<Tet_mesh::Kernel::Point_3> grid_points(const Boundary_triangles& triangles, int samples)
{
  using Point = Tet_mesh::Kernel::Point_3;
  std::vector<Point> points;
  points.reserve(triangles.size() * static_cast<std::size_t>((samples + 1) * (samples + 2) / 2));
  for(const auto& t : triangles)
    for(int i = 0; i <= samples; ++i)
      for(int j = 0; i + j <= samples; ++j)
      {
        const double u = double(i) / samples, v = double(j) / samples, x = 1 - u - v;
        points.emplace_back(u * t[0].x() + v * t[1].x() + x * t[2].x(), u * t[0].y() + v * t[1].y() + x * t[2].y(),
                            u * t[0].z() + v * t[1].z() + x * t[2].z());
      }
  auto less = [](const Point& a, const Point& b) {
    return a.x() != b.x() ? a.x() < b.x() : a.y() != b.y() ? a.y() < b.y() : a.z() < b.z();
  };
  std::sort(points.begin(), points.end(), less);
  points.erase(std::unique(points.begin(), points.end()), points.end());
  return points;
}

} // namespace internal

/// Symmetric Hausdorff distance between two triangle sets, approximated by
/// sampling each triangle on a barycentric grid (`samples` subdivisions per side,
/// vertices included) and measuring exact point-to-surface distances with an
/// AABB tree. The sampling error is at most the grid spacing times the largest
/// change in the other surface's distance, which is far below what it measures
/// here (moves of a fraction of an edge). The result does not depend on `threads`.
inline double hausdorff_distance(const Boundary_triangles& a, const Boundary_triangles& b, int samples = 6,
                                 int threads = 1)
{
  using K = Tet_mesh::Kernel;
  using Primitive = CGAL::AABB_triangle_primitive<K, Boundary_triangles::const_iterator>;
  using Tree = CGAL::AABB_tree<CGAL::AABB_traits<K, Primitive>>;
  internal::Thread_workers<char> workers(threads);
  // The two directions' samples and trees are made side by side (each is one
  // thread's work), then each direction's queries are shared by all threads.
  const Boundary_triangles* from[2] = {&a, &b};
  const Boundary_triangles* to[2] = {&b, &a};
  std::vector<K::Point_3> points[2];
  std::optional<Tree> tree[2];
  workers.for_each(0, 2, [&](char&, int k) {
    if(from[k]->empty() || to[k]->empty()) return;
    points[k] = internal::grid_points(*from[k], samples);
    tree[k].emplace(to[k]->begin(), to[k]->end());
    tree[k]->accelerate_distance_queries();
    // Built before the threads query it: queries only read.
    tree[k]->squared_distance(points[k].front());
  }, 1);
  double worst = 0;
  for(int k = 0; k < 2; ++k)
  {
    if(!tree[k]) continue;
    std::vector<double> block_worst(static_cast<std::size_t>(internal::block_count(points[k].size(), 4096)), 0.0);
    workers.for_blocks(points[k].size(), [&](char&, int block, std::size_t begin, std::size_t end) {
      double w = 0;
      for(std::size_t i = begin; i < end; ++i) w = std::max(w, tree[k]->squared_distance(points[k][i]));
      block_worst[static_cast<std::size_t>(block)] = w;
    }, 4096);
    worst = std::max(worst, *std::max_element(block_worst.begin(), block_worst.end()));
  }
  return std::sqrt(worst);
}

/// The paper's relative Hausdorff distance (Table 2): the distance between the
/// boundary surfaces before and after, divided by the largest side of the
/// bounding box of the surface before; `samples` as for `hausdorff_distance`.
inline double relative_hausdorff_distance(const Boundary_triangles& before, const Boundary_triangles& after,
                                          int threads = 1, int samples = 6)
{
  const double L = largest_bbox_side(before);
  return L > 0 ? hausdorff_distance(before, after, samples, threads) / L : 0.0;
}

} // namespace BODT_3
} // namespace CGAL

#endif // CGAL_BODT_3_BOUNDARY_DISTANCE_H
