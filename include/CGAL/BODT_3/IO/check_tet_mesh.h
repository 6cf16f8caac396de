// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_BODT_3_IO_CHECK_TET_MESH_H
#define CGAL_BODT_3_IO_CHECK_TET_MESH_H

#include <CGAL/BODT_3/Tet_mesh.h>
#include <CGAL/BODT_3/IO/Mesh_io_error.h>

#include <algorithm>
#include <cmath>
#include <ostream>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace CGAL {
namespace BODT_3 {

/// Where each entity of a `Tet_mesh` came from, so that checks can name the line.
struct Tet_mesh_source
{
  std::string file;
  std::vector<long> vertex_lines;
  std::vector<long> tet_lines;
  std::vector<long> triangle_lines;

  long tet_line(std::size_t t) const { return t < tet_lines.size() ? tet_lines[t] : 0; }
};

namespace internal {

struct Sorted_triple_hash
{
  std::size_t operator()(const std::array<int, 3>& a) const
  {
    std::size_t h = std::hash<int>()(a[0]);
    h = h * 1000003u ^ std::hash<int>()(a[1]);
    return h * 1000003u ^ std::hash<int>()(a[2]);
  }
};

struct Sorted_quad_hash
{
  std::size_t operator()(const std::array<int, 4>& a) const
  {
    std::size_t h = 0;
    for(int i : a) h = h * 1000003u ^ std::hash<int>()(i);
    return h;
  }
};

inline std::string tet_to_string(const std::array<int, 4>& t)
{
  return std::to_string(t[0] + 1) + " " + std::to_string(t[1] + 1) + " " +
         std::to_string(t[2] + 1) + " " + std::to_string(t[3] + 1);
}

} // namespace internal

/// Checks that a mesh just read is a valid tetrahedral mesh, and makes its
/// orientation positive. Throws `Mesh_io_error` naming the file and line of the
/// first offending entity. Checked: finite coordinates, indices in range, no
/// tetrahedron using a vertex twice, no repeated tetrahedron, no face shared by
/// three or more tetrahedra, one orientation for all non-flat tetrahedra. When every
/// non-flat tetrahedron is negatively oriented (some meshers write them so), all are
/// reoriented and a warning goes to `warnings`. Flat tetrahedra are kept: quality
/// reports count them.
inline void check_and_orient(Tet_mesh& mesh, const Tet_mesh_source& src, std::ostream& warnings)
{
  const std::string& file = src.file;
  auto vline = [&](std::size_t i) { return i < src.vertex_lines.size() ? src.vertex_lines[i] : 0L; };

  for(std::size_t i = 0; i < mesh.points.size(); ++i)
  {
    const auto& p = mesh.points[i];
    if(!std::isfinite(p.x()) || !std::isfinite(p.y()) || !std::isfinite(p.z()))
      throw Mesh_io_error(file, vline(i), "vertex " + std::to_string(i + 1) +
                                              " has a coordinate that is not a finite number");
  }

  const int n = static_cast<int>(mesh.points.size());
  if(mesh.tets.empty())
    throw Mesh_io_error(file, 0, "the file contains no tetrahedra");

  for(std::size_t t = 0; t < mesh.tets.size(); ++t)
  {
    const auto& c = mesh.tets[t];
    for(int k = 0; k < 4; ++k)
      if(c[k] < 0 || c[k] >= n)
        throw Mesh_io_error(file, src.tet_line(t),
                            "tetrahedron " + std::to_string(t + 1) + " refers to vertex " +
                                std::to_string(c[k] + 1) + ", but there are only " +
                                std::to_string(n) + " vertices");
    for(int a = 0; a < 4; ++a)
      for(int b = a + 1; b < 4; ++b)
        if(c[a] == c[b])
          throw Mesh_io_error(file, src.tet_line(t),
                              "tetrahedron " + std::to_string(t + 1) + " uses vertex " +
                                  std::to_string(c[a] + 1) + " twice");
  }
  for(std::size_t f = 0; f < mesh.triangles.size(); ++f)
    for(int k = 0; k < 3; ++k)
    {
      const int v = mesh.triangles[f][k];
      if(v < 0 || v >= n)
        throw Mesh_io_error(file, f < src.triangle_lines.size() ? src.triangle_lines[f] : 0,
                            "triangle " + std::to_string(f + 1) + " refers to vertex " +
                                std::to_string(v + 1) + ", but there are only " +
                                std::to_string(n) + " vertices");
    }

  // Repeated tetrahedra.
  {
    std::unordered_map<std::array<int, 4>, std::size_t, internal::Sorted_quad_hash> seen;
    seen.reserve(mesh.tets.size());
    for(std::size_t t = 0; t < mesh.tets.size(); ++t)
    {
      auto key = mesh.tets[t];
      std::sort(key.begin(), key.end());
      auto ins = seen.emplace(key, t);
      if(!ins.second)
        throw Mesh_io_error(file, src.tet_line(t),
                            "tetrahedron " + std::to_string(t + 1) + " (" +
                                internal::tet_to_string(mesh.tets[t]) + ") repeats tetrahedron " +
                                std::to_string(ins.first->second + 1) +
                                (src.tet_line(ins.first->second) > 0
                                     ? " of line " + std::to_string(src.tet_line(ins.first->second))
                                     : std::string()));
    }
  }

  // Faces shared by more than two tetrahedra.
  {
    std::unordered_map<std::array<int, 3>, std::pair<std::size_t, int>, internal::Sorted_triple_hash> faces;
    faces.reserve(mesh.tets.size() * 3);
    for(std::size_t t = 0; t < mesh.tets.size(); ++t)
      for(int k = 0; k < 4; ++k)
      {
        std::array<int, 3> f;
        for(int j = 0, m = 0; j < 4; ++j)
          if(j != k) f[m++] = mesh.tets[t][j];
        std::sort(f.begin(), f.end());
        auto& entry = faces.emplace(f, std::make_pair(t, 0)).first->second;
        if(++entry.second == 3)
          throw Mesh_io_error(file, src.tet_line(t),
                              "tetrahedron " + std::to_string(t + 1) + " is the third to share face (" +
                                  std::to_string(f[0] + 1) + " " + std::to_string(f[1] + 1) + " " +
                                  std::to_string(f[2] + 1) + "), already shared by tetrahedron " +
                                  std::to_string(entry.first + 1) + " and another; a face "
                                  "belongs to at most two tetrahedra");
      }
  }

  // Orientation, decided by exact predicates.
  std::size_t positive = 0, negative = 0;
  std::size_t first_positive = 0, first_negative = 0;
  for(std::size_t t = 0; t < mesh.tets.size(); ++t)
  {
    const auto& c = mesh.tets[t];
    const CGAL::Orientation o = CGAL::orientation(mesh.points[c[0]], mesh.points[c[1]],
                                                  mesh.points[c[2]], mesh.points[c[3]]);
    if(o == CGAL::POSITIVE) { if(positive++ == 0) first_positive = t; }
    else if(o == CGAL::NEGATIVE) { if(negative++ == 0) first_negative = t; }
  }
  if(positive > 0 && negative > 0)
  {
    const bool neg_minority = negative <= positive;
    const std::size_t t = neg_minority ? first_negative : first_positive;
    throw Mesh_io_error(file, src.tet_line(t),
                        "tetrahedra have mixed orientation: tetrahedron " + std::to_string(t + 1) +
                            " is " + (neg_minority ? "negatively" : "positively") + " oriented, while " +
                            std::to_string(neg_minority ? positive : negative) + " others are " +
                            (neg_minority ? "positively" : "negatively") + " oriented");
  }
  if(negative > 0 && positive == 0)
  {
    warnings << "warning: " << file << ": all " << negative
             << " tetrahedra are negatively oriented; reoriented them\n";
    for(auto& c : mesh.tets) std::swap(c[2], c[3]);
  }
}

} // namespace BODT_3
} // namespace CGAL

#endif // CGAL_BODT_3_IO_CHECK_TET_MESH_H
