// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A Delaunay triangulation's finite cells as index arrays, with its adjacency:
// an input for the tests of face matching (utilities/) and of the quality report
// on many threads (quality/).
#ifndef BODT_TEST_DELAUNAY_CELLS_H
#define BODT_TEST_DELAUNAY_CELLS_H

#include <CGAL/BODT_3/Tet_mesh.h>
#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Random.h>

#include <array>
#include <map>
#include <vector>

namespace bodt_test {

// The finite cells of a Delaunay triangulation of `n` random points in the unit
// cube, as index arrays, with the TDS's own adjacency to compare against.
struct Delaunay_cells
{
  std::vector<CGAL::BODT_3::Tet_mesh::Point> points;
  std::vector<std::array<int, 4>> cells;
  std::vector<int> neighbor;   // 4 c + i: the finite cell across, or -1

  explicit Delaunay_cells(int n)
  {
    using Dt = CGAL::Delaunay_triangulation_3<CGAL::Epick>;
    CGAL::Random random(7);
    std::vector<CGAL::BODT_3::Tet_mesh::Point> in;
    for(int i = 0; i < n; ++i) in.emplace_back(random.get_double(), random.get_double(), random.get_double());
    Dt dt(in.begin(), in.end());
    std::map<Dt::Vertex_handle, int> vid;
    for(auto v = dt.finite_vertices_begin(); v != dt.finite_vertices_end(); ++v)
    {
      vid[v] = static_cast<int>(points.size());
      points.push_back(v->point());
    }
    std::map<Dt::Cell_handle, int> cid;
    for(auto c = dt.finite_cells_begin(); c != dt.finite_cells_end(); ++c)
    {
      cid[c] = static_cast<int>(cells.size());
      cells.push_back({vid[c->vertex(0)], vid[c->vertex(1)], vid[c->vertex(2)], vid[c->vertex(3)]});
    }
    for(auto c = dt.finite_cells_begin(); c != dt.finite_cells_end(); ++c)
      for(int i = 0; i < 4; ++i)
        neighbor.push_back(dt.is_infinite(c->neighbor(i)) ? -1 : cid[c->neighbor(i)]);
  }
};

} // namespace bodt_test

#endif // BODT_TEST_DELAUNAY_CELLS_H
