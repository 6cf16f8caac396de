// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_BODT_3_MESH_QUALITY_H
#define CGAL_BODT_3_MESH_QUALITY_H

#include <CGAL/BODT_3/Tet_mesh.h>
#include <CGAL/BODT_3/internal/Utilities/Thread_workers.h>
#include <CGAL/BODT_3/internal/Quality/dihedral_angles.h>
#include <CGAL/BODT_3/internal/Utilities/tet_face_matching.h>
#include <CGAL/BODT_3/internal/Quality/tet_quality.h>

#include <CGAL/Kernel/global_functions.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <iterator>
#include <limits>
#include <map>
#include <ostream>
#include <sstream>
#include <string>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace BODT_3 {

struct Quality_options
{
  int histogram_bins = 36;          // bins of equal width over [0, 180] degrees
  double small_angle = 10.0;        // a tetrahedron with a dihedral angle below this is counted
  double large_angle = 170.0;       // ... and one with an angle above this
  int threads = 0;                  // threads measuring a Tet_mesh (0: every core); the report does not depend on it
};

/// Dihedral-angle quality of a tetrahedral mesh, the same measures for every
/// input type. Angles are in degrees. A tetrahedron is counted as inverted when
/// CGAL's exact orientation predicate says it is not positively oriented (this
/// includes flat tetrahedra).
struct Quality_report
{
  std::size_t num_vertices = 0;
  std::size_t num_tets = 0;
  double min_dihedral_deg = 0;
  double max_dihedral_deg = 0;
  std::size_t tets_below_small = 0;
  std::size_t tets_above_large = 0;
  /// The bad tetrahedra (below `small_angle` or above `large_angle`) by where they
  /// are: no vertex on the boundary or an interface; some but not all of their
  /// vertices there; all four there ("flat boundary" tets, which moving points
  /// cannot open and flips or insertion must).
  std::size_t bad_tets_interior = 0;
  std::size_t bad_tets_touching_boundary = 0;
  std::size_t bad_tets_all_vertices_on_boundary = 0;
  double min_radius_ratio = 0;
  double mean_radius_ratio = 0;
  double volume = 0;
  std::map<int, double> volume_per_subdomain;
  std::size_t inverted_tets = 0;
  /// The smallest angle of the triangles on the boundary and the interfaces
  /// (what a surface mesher's facet angle bounds); -1 when there are none.
  double min_boundary_triangle_angle_deg = -1;
  std::vector<std::size_t> histogram;   // counts of all six angles of each tetrahedron
  Quality_options options;
};

namespace internal {

/// The smallest angle of triangle (a, b, c) in degrees: the angle opposite its
/// shortest side, from atan2 of the cross and dot products (accurate when small;
/// 0 for a flat triangle).
template <class Point>
double smallest_triangle_angle(const Point& a, const Point& b, const Point& c)
{
  const Point* p[3] = {&a, &b, &c};
  // Side k is opposite corner k.
  const double side[3] = {CGAL::to_double(CGAL::squared_distance(b, c)), CGAL::to_double(CGAL::squared_distance(c, a)),
                          CGAL::to_double(CGAL::squared_distance(a, b))};
  const int k = static_cast<int>(std::min_element(side, side + 3) - side);
  const auto u = *p[(k + 1) % 3] - *p[k], v = *p[(k + 2) % 3] - *p[k];
  const auto n = CGAL::cross_product(u, v);
  const double cross = std::sqrt(CGAL::to_double(n * n)), dot = CGAL::to_double(u * v);
  return std::atan2(cross, dot) * 180 / pi;
}

// Above any angle: no boundary triangle seen yet; reported as -1.
constexpr double no_triangle = 181;
inline double triangle_angle_or_none(double smallest) { return smallest < no_triangle ? smallest : -1; }

} // namespace internal

/// Accumulates a `Quality_report` one tetrahedron at a time.
class Quality_accumulator
{
public:
  explicit Quality_accumulator(const Quality_options& opt = Quality_options())
  {
    r_.options = opt;
    r_.histogram.assign(std::max(1, opt.histogram_bins), 0);
    r_.min_dihedral_deg = std::numeric_limits<double>::infinity();
    r_.max_dihedral_deg = -std::numeric_limits<double>::infinity();
    r_.min_radius_ratio = std::numeric_limits<double>::infinity();
  }

  /// Adds a tetrahedron; `boundary_vertices` is how many of its vertices lie on the
  /// boundary or an interface.
  template <class Point>
  void add(const Point& p0, const Point& p1, const Point& p2, const Point& p3, int subdomain, int boundary_vertices)
  {
    const auto angles = internal::dihedral_angles(p0, p1, p2, p3);
    double lo = angles[0], hi = angles[0];
    const int bins = static_cast<int>(r_.histogram.size());
    for(double a : angles)
    {
      lo = std::min(lo, a);
      hi = std::max(hi, a);
      const int b = std::min(bins - 1, std::max(0, static_cast<int>(a / 180.0 * bins)));
      ++r_.histogram[b];
    }
    r_.min_dihedral_deg = std::min(r_.min_dihedral_deg, lo);
    r_.max_dihedral_deg = std::max(r_.max_dihedral_deg, hi);
    if(lo < r_.options.small_angle) ++r_.tets_below_small;
    if(hi > r_.options.large_angle) ++r_.tets_above_large;
    if(lo < r_.options.small_angle || hi > r_.options.large_angle)
    {
      if(boundary_vertices == 0) ++r_.bad_tets_interior;
      else if(boundary_vertices < 4) ++r_.bad_tets_touching_boundary;
      else ++r_.bad_tets_all_vertices_on_boundary;
    }
    const double rr = internal::radius_ratio(p0, p1, p2, p3);
    r_.min_radius_ratio = std::min(r_.min_radius_ratio, rr);
    rr_sum_ += rr;
    const double v = internal::tet_volume(p0, p1, p2, p3);
    r_.volume += v;
    r_.volume_per_subdomain[subdomain] += v;
    if(CGAL::orientation(p0, p1, p2, p3) != CGAL::POSITIVE) ++r_.inverted_tets;
    ++r_.num_tets;
  }

  /// Adds what `o` accumulated, as if its tetrahedra came after this one's.
  void merge(const Quality_accumulator& o)
  {
    for(std::size_t b = 0; b < r_.histogram.size(); ++b) r_.histogram[b] += o.r_.histogram[b];
    r_.min_dihedral_deg = std::min(r_.min_dihedral_deg, o.r_.min_dihedral_deg);
    r_.max_dihedral_deg = std::max(r_.max_dihedral_deg, o.r_.max_dihedral_deg);
    r_.tets_below_small += o.r_.tets_below_small;
    r_.tets_above_large += o.r_.tets_above_large;
    r_.bad_tets_interior += o.r_.bad_tets_interior;
    r_.bad_tets_touching_boundary += o.r_.bad_tets_touching_boundary;
    r_.bad_tets_all_vertices_on_boundary += o.r_.bad_tets_all_vertices_on_boundary;
    r_.min_radius_ratio = std::min(r_.min_radius_ratio, o.r_.min_radius_ratio);
    rr_sum_ += o.rr_sum_;
    r_.volume += o.r_.volume;
    for(const auto& kv : o.r_.volume_per_subdomain) r_.volume_per_subdomain[kv.first] += kv.second;
    r_.inverted_tets += o.r_.inverted_tets;
    r_.num_tets += o.r_.num_tets;
  }

  Quality_report result(std::size_t num_vertices) const
  {
    Quality_report r = r_;
    r.num_vertices = num_vertices;
    if(r.num_tets == 0)
    {
      r.min_dihedral_deg = r.max_dihedral_deg = r.min_radius_ratio = 0;
    }
    else
      r.mean_radius_ratio = rr_sum_ / static_cast<double>(r.num_tets);
    return r;
  }

private:
  Quality_report r_;
  double rr_sum_ = 0;
};

/// Quality of a `Tet_mesh`: tetrahedra labelled 0 are outside the mesh unless every
/// label is 0. Vertices are counted when a measured tetrahedron uses them.
inline Quality_report mesh_quality(const Tet_mesh& mesh, const Quality_options& opt = Quality_options())
{
  const bool all_zero = mesh.all_labels_zero();
  std::vector<std::size_t> measured;   // the tetrahedra in the mesh
  for(std::size_t t = 0; t < mesh.tets.size(); ++t)
    if(mesh.in_mesh(t, all_zero)) measured.push_back(t);
  std::vector<char> used(mesh.points.size(), 0);
  // A face is on the boundary or an interface unless two mesh tets of one label
  // share it; each vertex looks at the faces around it (in parallel).
  std::vector<char> on_boundary(mesh.points.size(), 0);
  internal::Thread_workers<char> workers(opt.threads);
  double smallest_triangle = internal::no_triangle;
  {
    std::vector<std::array<int, 4>> some;   // a copy only when some tetrahedra are not measured
    if(measured.size() < mesh.tets.size())
      for(std::size_t t : measured) some.push_back(mesh.tets[t]);
    const auto& cells = measured.size() < mesh.tets.size() ? some : mesh.tets;
    const internal::Tet_face_matching faces(cells, mesh.points.size(), opt.threads);
    // Whether face i of cell c is shared by a mesh tetrahedron of the same label.
    auto inner = [&](std::size_t c, int i) {
      const int m = faces.match[4 * c + static_cast<std::size_t>(i)];
      return m >= 0 && mesh.tet_labels[measured[static_cast<std::size_t>(m / 4)]] == mesh.tet_labels[measured[c]];
    };
    workers.for_each(0, static_cast<int>(mesh.points.size()), [&](char&, int v) {
      const int first = faces.vertex_cells_begin[v], last = faces.vertex_cells_begin[v + 1];
      used[static_cast<std::size_t>(v)] = first < last ? 1 : 0;
      for(int k = first; k < last && !on_boundary[static_cast<std::size_t>(v)]; ++k)
      {
        const auto c = static_cast<std::size_t>(faces.vertex_cells[k]);
        for(int i = 0; i < 4; ++i)
        {
          if(cells[c][i] == v || inner(c, i)) continue;
          on_boundary[static_cast<std::size_t>(v)] = 1;
          break;
        }
      }
    }, 1024);
    // The faces no mesh tetrahedron of the same label shares; the smallest of
    // each block's angles, then of the blocks (a minimum: no order to keep).
    std::vector<double> block_smallest(static_cast<std::size_t>(internal::block_count(cells.size())), internal::no_triangle);
    workers.for_blocks(cells.size(), [&](char&, int b, std::size_t begin, std::size_t end) {
      double& least = block_smallest[static_cast<std::size_t>(b)];
      for(std::size_t c = begin; c < end; ++c)
        for(int i = 0; i < 4; ++i)
        {
          if(inner(c, i)) continue;
          std::array<std::size_t, 3> f;
          for(int k = 0, l = 0; k < 4; ++k)
            if(k != i) f[static_cast<std::size_t>(l++)] = static_cast<std::size_t>(cells[c][k]);
          least = std::min(least, internal::smallest_triangle_angle(mesh.points[f[0]], mesh.points[f[1]],
                                                                    mesh.points[f[2]]));
        }
    });
    for(double least : block_smallest) smallest_triangle = std::min(smallest_triangle, least);
  }
  // Blocks of a fixed size, merged in order: the sums do not depend on the threads.
  std::vector<Quality_accumulator> parts(static_cast<std::size_t>(internal::block_count(measured.size())),
                                         Quality_accumulator(opt));
  workers.for_blocks(measured.size(), [&](char&, int b, std::size_t begin, std::size_t end) {
    Quality_accumulator& acc = parts[static_cast<std::size_t>(b)];
    for(std::size_t k = begin; k < end; ++k)
    {
      const std::size_t t = measured[k];
      const auto& c = mesh.tets[t];
      acc.add(mesh.points[c[0]], mesh.points[c[1]], mesh.points[c[2]], mesh.points[c[3]], mesh.tet_labels[t],
              on_boundary[c[0]] + on_boundary[c[1]] + on_boundary[c[2]] + on_boundary[c[3]]);
    }
  });
  Quality_accumulator acc(opt);
  for(const Quality_accumulator& part : parts) acc.merge(part);
  Quality_report r = acc.result(static_cast<std::size_t>(std::count(used.begin(), used.end(), 1)));
  r.min_boundary_triangle_angle_deg = internal::triangle_angle_or_none(smallest_triangle);
  return r;
}

namespace internal {
template <class T, class = void> struct Is_c3t3 : std::false_type {};
template <class T>
struct Is_c3t3<T, std::void_t<typename T::Triangulation, typename T::Subdomain_index>> : std::true_type {};
} // namespace internal

/// Quality of a `Mesh_complex_3_in_triangulation_3`: the cells in the complex.
template <class C3T3>
std::enable_if_t<internal::Is_c3t3<C3T3>::value, Quality_report>
mesh_quality(const C3T3& c3t3, const Quality_options& opt = Quality_options())
{
  const auto& tr = c3t3.triangulation();
  auto cp = tr.geom_traits().construct_point_3_object();
  Quality_accumulator acc(opt);
  std::vector<typename C3T3::Vertex_handle> used, on_boundary;
  double smallest_triangle = internal::no_triangle;
  for(auto f = c3t3.facets_in_complex_begin(); f != c3t3.facets_in_complex_end(); ++f)
  {
    for(int i = 0; i < 4; ++i)
      if(i != f->second) on_boundary.push_back(f->first->vertex(i));
    const int i = f->second;
    smallest_triangle = std::min(smallest_triangle,
                                 internal::smallest_triangle_angle(cp(f->first->vertex((i + 1) % 4)->point()),
                                                                   cp(f->first->vertex((i + 2) % 4)->point()),
                                                                   cp(f->first->vertex((i + 3) % 4)->point())));
  }
  std::sort(on_boundary.begin(), on_boundary.end());
  for(auto c = c3t3.cells_in_complex_begin(); c != c3t3.cells_in_complex_end(); ++c)
  {
    int nb = 0;
    for(int i = 0; i < 4; ++i) nb += std::binary_search(on_boundary.begin(), on_boundary.end(), c->vertex(i)) ? 1 : 0;
    acc.add(cp(c->vertex(0)->point()), cp(c->vertex(1)->point()), cp(c->vertex(2)->point()),
            cp(c->vertex(3)->point()), static_cast<int>(c3t3.subdomain_index(c)), nb);
    for(int i = 0; i < 4; ++i) used.push_back(c->vertex(i));
  }
  std::sort(used.begin(), used.end());
  Quality_report r = acc.result(static_cast<std::size_t>(std::unique(used.begin(), used.end()) - used.begin()));
  r.min_boundary_triangle_angle_deg = internal::triangle_angle_or_none(smallest_triangle);
  return r;
}

/// Quality of a `Triangulation_3`: its finite cells, all in subdomain 1.
template <class Tr>
std::enable_if_t<!internal::Is_c3t3<Tr>::value && !std::is_same<Tr, Tet_mesh>::value, Quality_report>
mesh_quality(const Tr& tr, const Quality_options& opt = Quality_options())
{
  auto cp = tr.geom_traits().construct_point_3_object();
  Quality_accumulator acc(opt);
  std::vector<typename Tr::Vertex_handle> hull;   // the boundary is the convex hull
  tr.adjacent_vertices(tr.infinite_vertex(), std::back_inserter(hull));
  std::sort(hull.begin(), hull.end());
  for(auto c = tr.finite_cells_begin(); c != tr.finite_cells_end(); ++c)
  {
    int nb = 0;
    for(int i = 0; i < 4; ++i) nb += std::binary_search(hull.begin(), hull.end(), c->vertex(i)) ? 1 : 0;
    acc.add(cp(c->vertex(0)->point()), cp(c->vertex(1)->point()), cp(c->vertex(2)->point()),
            cp(c->vertex(3)->point()), 1, nb);
  }
  Quality_report r = acc.result(tr.number_of_vertices());
  // The boundary is the convex hull: the finite faces of the infinite cells.
  double smallest_triangle = internal::no_triangle;
  for(auto c = tr.all_cells_begin(); c != tr.all_cells_end(); ++c)
  {
    if(!tr.is_infinite(c)) continue;
    const int i = c->index(tr.infinite_vertex());
    smallest_triangle = std::min(smallest_triangle,
                                 internal::smallest_triangle_angle(cp(c->vertex((i + 1) % 4)->point()),
                                                                   cp(c->vertex((i + 2) % 4)->point()),
                                                                   cp(c->vertex((i + 3) % 4)->point())));
  }
  r.min_boundary_triangle_angle_deg = internal::triangle_angle_or_none(smallest_triangle);
  return r;
}

// The report as JSON: src/report/json_report.h (the tools', not the package's).

/// The report as a few lines of text for people.
inline void print_report(std::ostream& out, const Quality_report& r)
{
  char buf[256];
  std::snprintf(buf, sizeof buf,
                "vertices %zu, tetrahedra %zu\n"
                "dihedral angles: min %.2f deg, max %.2f deg; %zu tets below %g deg, %zu above %g deg\n"
                "radius ratio: min %.4f, mean %.4f\n"
                "volume %.10g; inverted or flat tetrahedra: %zu\n",
                r.num_vertices, r.num_tets, r.min_dihedral_deg, r.max_dihedral_deg, r.tets_below_small,
                r.options.small_angle, r.tets_above_large, r.options.large_angle, r.min_radius_ratio,
                r.mean_radius_ratio, r.volume, r.inverted_tets);
  out << buf;
  if(r.min_boundary_triangle_angle_deg >= 0)
  {
    std::snprintf(buf, sizeof buf, "boundary and interface triangles: smallest angle %.2f deg\n",
                  r.min_boundary_triangle_angle_deg);
    out << buf;
  }
  if(r.volume_per_subdomain.size() > 1)
  {
    out << "volume per subdomain:";
    for(const auto& kv : r.volume_per_subdomain)
    {
      std::snprintf(buf, sizeof buf, " [%d] %.10g", kv.first, kv.second);
      out << buf;
    }
    out << "\n";
  }
}

} // namespace BODT_3
} // namespace CGAL

#endif // CGAL_BODT_3_MESH_QUALITY_H
