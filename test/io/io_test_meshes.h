// Meshes for the I/O tests: small, with every entity a format may keep.
#ifndef BODT_IO_TEST_MESHES_H
#define BODT_IO_TEST_MESHES_H

#include "test_support.h"

#include <CGAL/BODT_3/Tet_mesh.h>

#include <cmath>

namespace bodt_test {

/// A 3x3x3 grid of perturbed cubes, six tetrahedra each, whose coordinates need all
/// 17 digits; labels 0, 1 and 2 in runs, boundary triangles and edges with labels
/// 0, 10 and -3, the eight corners, and ridges and required vertices for Medit.
inline CGAL::BODT_3::Tet_mesh grid_mesh()
{
  using Point = CGAL::BODT_3::Tet_mesh::Point;
  const int n = 3;
  CGAL::BODT_3::Tet_mesh m = cube_grid(n, [](int i, int j, int k) { return (i + j + k) % 3; });
  auto vid = [&](int i, int j, int k) { return grid_index(n, i, j, k); };
  // Move the points off the grid by less than keeps the tetrahedra positive.
  for(int i = 0; i <= n; ++i)
    for(int j = 0; j <= n; ++j)
      for(int k = 0; k <= n; ++k)
      {
        const double e = 1e-3 * std::sin(1.0 + i + 7 * j + 13 * k);
        m.points[vid(i, j, k)] = Point(i / 3.0 + e, j / 7.0 - e, k * 0.1 + e / 3.0);
        m.vertex_refs[vid(i, j, k)] = (i + j + k) % 4;
      }
  const int labels[3] = {0, 10, -3};
  for(int i = 0; i < n; ++i)
    for(int j = 0; j < n; ++j)
    {
      m.triangles.push_back({vid(i, j, 0), vid(i + 1, j, 0), vid(i + 1, j + 1, 0)});
      m.triangles.push_back({vid(i, j, 0), vid(i + 1, j + 1, 0), vid(i, j + 1, 0)});
      m.triangle_labels.push_back(labels[(i + j) % 3]);
      m.triangle_labels.push_back(labels[(i + j + 1) % 3]);
    }
  for(int i = 0; i < n; ++i)
  {
    m.edges.push_back({vid(i, 0, 0), vid(i + 1, 0, 0)});
    m.edge_labels.push_back(labels[i % 3]);
  }
  for(int c = 0; c < 8; ++c) m.corners.push_back(vid((c & 1) * n, (c >> 1 & 1) * n, (c >> 2 & 1) * n));
  m.required_vertices = {vid(1, 1, 1)};
  m.ridges = {0, 2};
  return m;
}

} // namespace bodt_test

#endif // BODT_IO_TEST_MESHES_H
