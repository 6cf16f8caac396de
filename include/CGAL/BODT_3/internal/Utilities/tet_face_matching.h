// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_BODT_3_INTERNAL_UTILITIES_TET_FACE_MATCHING_H
#define CGAL_BODT_3_INTERNAL_UTILITIES_TET_FACE_MATCHING_H

#include <CGAL/BODT_3/internal/Utilities/Thread_workers.h>
#include <CGAL/BODT_3/internal/Utilities/group_by_key.h>
#include <CGAL/BODT_3/internal/Utilities/first_touch.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace BODT_3 {
namespace internal {

/// Which faces of a tetrahedral mesh are glued (the face of cell `c` opposite its
/// vertex `i` has id `4 * c + i`), found without hashing: vertex by vertex, among
/// the faces of its cells. Memory: the vertex-to-cells lists (one int per face), the
/// result, and the faces around one vertex.
struct Tet_face_matching
{
  /// `match[4 * c + i]`: the face id of the other cell with the same three
  /// vertices, or -1 when there is none or when three or more cells share it.
  std::vector<int> match;
  /// The first face (in face id order) shared by three or more cells, or -1.
  long long crowded_face = -1;
  /// The cells around each vertex, in cell order: `vertex_cells[k]` for k in
  /// [`vertex_cells_begin[v]`, `vertex_cells_begin[v + 1]`).
  std::vector<int> vertex_cells_begin, vertex_cells;
  /// The threads it was built with, for the checks that use it.
  int threads = 1;

  /// `number_of_threads`: as `Smoothing_options::threads` (0: every core); the
  /// result does not depend on it.
  Tet_face_matching(const std::vector<std::array<int, 4>>& cells, std::size_t number_of_points,
                    int number_of_threads = 1)
    : threads(number_of_threads)
  {
    const std::size_t nc = cells.size();
    std::vector<int>& begin = vertex_cells_begin;
    std::vector<int>& around = vertex_cells;
    group_by_key<int>(nc, number_of_points, threads, [&cells](std::size_t c, const auto& emit) {
      for(int v : cells[c]) emit(static_cast<std::size_t>(v), static_cast<int>(c));
    }, begin, around);

    // Each face is matched at its smallest vertex: the faces of the cells around a
    // vertex that have it as smallest vertex, sorted by their two other vertices,
    // pair up with their equals. Vertices are independent: they run in parallel.
    assign_fresh(match, 4 * nc, -1, threads);
    Thread_workers<Worker> workers(threads);
    workers.for_each(0, static_cast<int>(number_of_points), [&](Worker& w, int v) {
      auto& faces = w.faces;
      faces.clear();
      for(int k = begin[v]; k < begin[v + 1]; ++k)
      {
        const int cell = around[k];
        const auto& q = cells[cell];
        for(int i = 0; i < 4; ++i)
        {
          const int x = q[(i + 1) & 3], y = q[(i + 2) & 3], z = q[(i + 3) & 3];
          if(std::min(x, std::min(y, z)) != v) continue;
          int o[2], m = 0;
          for(int a : {x, y, z})
            if(a != v && m < 2) o[m++] = a;
          if(m < 2) continue;   // a cell using a vertex twice has no face here
          faces.push_back({std::min(o[0], o[1]), std::max(o[0], o[1]), 4 * cell + i});
        }
      }
      std::sort(faces.begin(), faces.end());
      for(std::size_t a = 0; a < faces.size();)
      {
        std::size_t b = a + 1;
        while(b < faces.size() && faces[b].same(faces[a])) ++b;
        if(b - a == 2)
        {
          match[static_cast<std::size_t>(faces[a].id)] = faces[a + 1].id;
          match[static_cast<std::size_t>(faces[a + 1].id)] = faces[a].id;
        }
        else if(b - a > 2 && (w.crowded < 0 || faces[a].id < w.crowded))
          w.crowded = faces[a].id;
        a = b;
      }
    }, 256);
    workers.each_worker([this](const Worker& w) {
      if(w.crowded >= 0 && (crowded_face < 0 || w.crowded < crowded_face)) crowded_face = w.crowded;
    });
  }

private:
  struct Face
  {
    int b, c, id;
    bool operator<(const Face& o) const { return b != o.b ? b < o.b : c != o.c ? c < o.c : id < o.id; }
    bool same(const Face& o) const { return b == o.b && c == o.c; }
  };
  struct Worker
  {
    std::vector<Face> faces;   // around one vertex
    long long crowded = -1;
  };
};

} // namespace internal
} // namespace BODT_3
} // namespace CGAL

#endif // CGAL_BODT_3_INTERNAL_UTILITIES_TET_FACE_MATCHING_H
