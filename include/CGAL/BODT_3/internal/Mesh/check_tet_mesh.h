// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_BODT_3_INTERNAL_MESH_CHECK_TET_MESH_H
#define CGAL_BODT_3_INTERNAL_MESH_CHECK_TET_MESH_H

#include <CGAL/BODT_3/Tet_mesh.h>
#include <CGAL/BODT_3/internal/Utilities/Thread_workers.h>
#include <CGAL/BODT_3/internal/Utilities/group_by_key.h>
#include <CGAL/BODT_3/internal/Utilities/id_keys.h>
#include <CGAL/BODT_3/Mesh_io_error.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <tuple>
#include <cmath>
#include <limits>
#include <ostream>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace CGAL {
namespace BODT_3 {
namespace internal {

/// Where each entity of a `Tet_mesh` came from, so that checks can name the line.
struct Tet_mesh_source
{
  std::string file;
  std::vector<long> vertex_lines;
  std::vector<long> tet_lines;
  std::vector<long> triangle_lines;

  long tet_line(std::size_t t) const { return t < tet_lines.size() ? tet_lines[t] : 0; }
};


inline std::string tet_to_string(const std::array<int, 4>& t)
{
  return std::to_string(t[0] + 1) + " " + std::to_string(t[1] + 1) + " " +
         std::to_string(t[2] + 1) + " " + std::to_string(t[3] + 1);
}


/// Checks that a mesh just read is a valid tetrahedral mesh, makes its orientation
/// positive, and records `src.file` as `mesh.source`. Throws `Mesh_io_error` naming
/// the file and line of the first offending entity. Checked: finite coordinates, indices in range, no
/// tetrahedron using a vertex twice, no repeated tetrahedron, no face shared by
/// three or more tetrahedra, no flat tetrahedron (whatever its label: label 0 cells
/// close a mesh and must stay valid too), one orientation for all tetrahedra. When
/// every tetrahedron is negatively oriented (some meshers write them so), all are
/// reoriented and a warning goes to `warnings`. `threads` (0: all cores) changes
/// nothing in the outcome.
inline void check_and_orient(Tet_mesh& mesh, const Tet_mesh_source& src, std::ostream& warnings, int threads = 1)
{
  const std::string& file = src.file;
  mesh.source = file;
  auto vline = [&](std::size_t i) { return i < src.vertex_lines.size() ? src.vertex_lines[i] : 0L; };

  // The quality measures and the moves multiply up to six coordinate differences
  // (volumes times lengths over areas squared): beyond these bounds they overflow
  // or underflow in double precision, and the angles come out as nonsense.
  const double largest = 1e30, smallest_extent = 1e-30;
  double lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
  for(std::size_t i = 0; i < mesh.points.size(); ++i)
  {
    const auto& p = mesh.points[i];
    if(!std::isfinite(p.x()) || !std::isfinite(p.y()) || !std::isfinite(p.z()))
      throw Mesh_io_error(file, vline(i), "vertex " + std::to_string(i + 1) +
                                              " has a coordinate that is not a finite number");
    for(int k = 0; k < 3; ++k)
    {
      if(std::abs(p[k]) > largest)
        throw Mesh_io_error(file, vline(i), "vertex " + std::to_string(i + 1) + " has a coordinate of magnitude " +
                                                "above 1e30, which double-precision geometry cannot handle; "
                                                "scale the mesh");
      lo[k] = i == 0 ? p[k] : std::min(lo[k], p[k]);
      hi[k] = i == 0 ? p[k] : std::max(hi[k], p[k]);
    }
  }
  if(!mesh.points.empty() && std::max({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]}) < smallest_extent)
    throw Mesh_io_error(file, 0, "the mesh's bounding box is smaller than 1e-30 on every side, which "
                                 "double-precision geometry cannot handle; scale the mesh");

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

  // Repeated tetrahedra, then faces shared by more than two tetrahedra: the faces
  // are bucketed by their smallest vertex (a counting sort), and each small bucket is
  // sorted, which is many times faster than hashing every face.
  {
    const std::size_t nt = mesh.tets.size();
    struct Face { int b, c, opposite; std::uint32_t tet; };
    std::vector<int> start;
    std::vector<Face> faces;
    group_by_key<Face>(nt, static_cast<std::size_t>(n), threads, [&mesh](std::size_t t, const auto& emit) {
      const auto& c = mesh.tets[t];
      for(int k = 0; k < 4; ++k)
      {
        int f[3] = {c[(k + 1) % 4], c[(k + 2) % 4], c[(k + 3) % 4]};
        std::sort(f, f + 3);
        emit(static_cast<std::size_t>(f[0]), Face{f[1], f[2], c[k], static_cast<std::uint32_t>(t)});
      }
    }, start, faces);
    // Per face group (sorted by tet), the first repeat and the first third tet, in
    // file order; buckets in parallel, each worker keeping the first it found
    // (ties between buckets go to the smaller vertex, as a sequential scan would).
    struct Found
    {
      std::size_t repeat = std::numeric_limits<std::size_t>::max(), repeated = 0;
      std::size_t third = std::numeric_limits<std::size_t>::max(), first_of_third = 0;
      std::size_t repeat_bucket = 0, third_bucket = 0;
      std::array<int, 3> third_face{};
    };
    auto keep_repeat = [](Found& f, std::size_t t, std::size_t other, std::size_t a) {
      if(std::make_pair(t, a) < std::make_pair(f.repeat, f.repeat_bucket))
      {
        f.repeat = t;
        f.repeated = other;
        f.repeat_bucket = a;
      }
    };
    Thread_workers<Found> workers(threads);
    workers.for_each(0, n, [&](Found& found, int va) {
      const auto a = static_cast<std::size_t>(va);
      auto begin = faces.begin() + static_cast<std::ptrdiff_t>(start[a]);
      auto end = faces.begin() + static_cast<std::ptrdiff_t>(start[a + 1]);
      std::sort(begin, end, [](const Face& x, const Face& y) {
        return std::tie(x.b, x.c, x.tet) < std::tie(y.b, y.c, y.tet);
      });
      for(auto g = begin; g != end;)
      {
        auto h = g + 1;
        while(h != end && h->b == g->b && h->c == g->c) ++h;
        if(h - g == 2)
        {
          if(g->opposite == (g + 1)->opposite) keep_repeat(found, (g + 1)->tet, g->tet, a);
        }
        else if(h - g > 2)
        {
          // Many tetrahedra on one face (a damaged file): find repeats by sorting, not pairwise.
          std::vector<Face> group(g, h);
          std::sort(group.begin(), group.end(), [](const Face& x, const Face& y) {
            return std::tie(x.opposite, x.tet) < std::tie(y.opposite, y.tet);
          });
          for(std::size_t i = 1; i < group.size(); ++i)
            if(group[i].opposite == group[i - 1].opposite)
            {
              std::size_t first = i - 1;
              while(first > 0 && group[first - 1].opposite == group[i].opposite) --first;
              keep_repeat(found, group[i].tet, group[first].tet, a);
            }
        }
        if(h - g >= 3 && std::make_pair(std::size_t((g + 2)->tet), a) < std::make_pair(found.third, found.third_bucket))
        {
          found.third = (g + 2)->tet;
          found.first_of_third = g->tet;
          found.third_bucket = a;
          found.third_face = {static_cast<int>(a), g->b, g->c};
        }
        g = h;
      }
    }, 1024);
    Found first;
    workers.each_worker([&](const Found& f) {
      keep_repeat(first, f.repeat, f.repeated, f.repeat_bucket);
      if(std::make_pair(f.third, f.third_bucket) < std::make_pair(first.third, first.third_bucket))
      {
        first.third = f.third;
        first.first_of_third = f.first_of_third;
        first.third_bucket = f.third_bucket;
        first.third_face = f.third_face;
      }
    });
    const std::size_t repeat = first.repeat, repeated = first.repeated, third = first.third;
    const std::size_t first_of_third = first.first_of_third;
    const std::array<int, 3> third_face = first.third_face;
    if(repeat < nt)
      throw Mesh_io_error(file, src.tet_line(repeat),
                          "tetrahedron " + std::to_string(repeat + 1) + " (" +
                              internal::tet_to_string(mesh.tets[repeat]) + ") repeats tetrahedron " +
                              std::to_string(repeated + 1) +
                              (src.tet_line(repeated) > 0 ? " of line " + std::to_string(src.tet_line(repeated))
                                                          : std::string()));
    if(third < nt)
      throw Mesh_io_error(file, src.tet_line(third),
                          "tetrahedron " + std::to_string(third + 1) + " is the third to share face (" +
                              std::to_string(third_face[0] + 1) + " " + std::to_string(third_face[1] + 1) + " " +
                              std::to_string(third_face[2] + 1) + "), already shared by tetrahedron " +
                              std::to_string(first_of_third + 1) + " and another; a face "
                              "belongs to at most two tetrahedra");
  }

  // Orientation, decided by exact predicates, in blocks merged in order.
  struct Orientations
  {
    std::size_t positive = 0, negative = 0;
    std::size_t first_positive, first_negative, first_flat;
  };
  const std::size_t nt = mesh.tets.size();
  std::vector<Orientations> blocks(static_cast<std::size_t>(block_count(nt)), Orientations{0, 0, nt, nt, nt});
  Thread_workers<char>(threads).for_blocks(nt, [&](char&, int b, std::size_t begin, std::size_t end) {
    Orientations& o = blocks[static_cast<std::size_t>(b)];
    for(std::size_t t = begin; t < end; ++t)
    {
      const auto& c = mesh.tets[t];
      const CGAL::Orientation sign = CGAL::orientation(mesh.points[c[0]], mesh.points[c[1]],
                                                       mesh.points[c[2]], mesh.points[c[3]]);
      if(sign == CGAL::POSITIVE) { if(o.positive++ == 0) o.first_positive = t; }
      else if(sign == CGAL::NEGATIVE) { if(o.negative++ == 0) o.first_negative = t; }
      else { o.first_flat = t; return; }
    }
  });
  std::size_t positive = 0, negative = 0, first_positive = nt, first_negative = nt;
  for(const Orientations& o : blocks)
  {
    if(o.first_flat < nt)
    {
      const auto& c = mesh.tets[o.first_flat];
      throw Mesh_io_error(file, src.tet_line(o.first_flat),
                          "tetrahedron " + std::to_string(o.first_flat + 1) + " (" + internal::tet_to_string(c) +
                              ") is flat: its four vertices are coplanar (exact predicate), so it has no "
                              "volume; every tetrahedron, labelled 0 or not, must have one");
    }
    positive += o.positive;
    negative += o.negative;
    first_positive = std::min(first_positive, o.first_positive);
    first_negative = std::min(first_negative, o.first_negative);
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

} // namespace internal
} // namespace BODT_3
} // namespace CGAL

#endif // CGAL_BODT_3_INTERNAL_MESH_CHECK_TET_MESH_H
