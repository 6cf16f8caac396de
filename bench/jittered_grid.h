// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A generated mesh of any size for the benchmarks: the unit cube cut into N^3
// cubes, six tetrahedra each (N = 60: 1.3 M tetrahedra), inner vertices jittered
// by up to a fraction of a cube's side (seeded). The easy kind (2%, the I/O
// benchmark's) has two subdomains (x below and above 1/2) and the bottom and top
// faces as labelled triangles; the hard kind (15%), as users' files come, one
// subdomain and no boundary triangles, and cells bad enough that every phase of
// the pipeline has work.
#ifndef BODT_BENCH_JITTERED_GRID_H
#define BODT_BENCH_JITTERED_GRID_H

#include <CGAL/BODT_3/Tet_mesh.h>

#include <array>
#include <random>
#include <utility>

namespace bodt_bench {

using CGAL::BODT_3::Tet_mesh;

enum class Grid_kind
{
  easy,   // 2% jitter, two subdomains, labelled top and bottom faces
  hard    // 15% jitter, one subdomain, no triangles
};

inline Tet_mesh jittered_grid(int n, Grid_kind kind = Grid_kind::easy)
{
  const bool easy = kind == Grid_kind::easy;
  Tet_mesh m;
  auto id = [n](int i, int j, int k) { return (k * (n + 1) + j) * (n + 1) + i; };
  std::mt19937_64 random(42);
  std::uniform_real_distribution<double> jitter(easy ? -0.02 : -0.15, easy ? 0.02 : 0.15);
  const double h = 1.0 / n;
  for(int k = 0; k <= n; ++k)
    for(int j = 0; j <= n; ++j)
      for(int i = 0; i <= n; ++i)
      {
        auto coordinate = [&](int c) { return (c + ((c > 0 && c < n) ? jitter(random) : 0.0)) * h; };
        m.points.emplace_back(coordinate(i), coordinate(j), coordinate(k));
        m.vertex_refs.push_back(0);
      }
  // Six tetrahedra around each cube's main diagonal, one per path from corner 0 to 7.
  const int paths[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  for(int k = 0; k < n; ++k)
    for(int j = 0; j < n; ++j)
      for(int i = 0; i < n; ++i)
        for(const auto& path : paths)
        {
          int c[3] = {i, j, k};
          std::array<int, 4> t;
          t[0] = id(c[0], c[1], c[2]);
          for(int s = 0; s < 3; ++s)
          {
            ++c[path[s]];
            t[s + 1] = id(c[0], c[1], c[2]);
          }
          if(CGAL::orientation(m.points[t[0]], m.points[t[1]], m.points[t[2]], m.points[t[3]]) != CGAL::POSITIVE)
            std::swap(t[2], t[3]);
          m.tets.push_back(t);
          m.tet_labels.push_back(easy && 2 * i >= n ? 2 : 1);
        }
  // The bottom and top faces as labelled triangles.
  for(int j = 0; j < n && easy; ++j)
    for(int i = 0; i < n; ++i)
      for(int k : {0, n})
      {
        m.triangles.push_back({id(i, j, k), id(i + 1, j, k), id(i + 1, j + 1, k)});
        m.triangles.push_back({id(i, j, k), id(i + 1, j + 1, k), id(i, j + 1, k)});
        m.triangle_labels.insert(m.triangle_labels.end(), 2, k == 0 ? 10 : 11);
      }
  return m;
}

} // namespace bodt_bench

#endif // BODT_BENCH_JITTERED_GRID_H
