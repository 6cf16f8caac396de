// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_BODT_3_INTERNAL_SMOOTHING_BOUNDARY_DISTANCE_GUARD_H
#define CGAL_BODT_3_INTERNAL_SMOOTHING_BOUNDARY_DISTANCE_GUARD_H

#include <CGAL/BODT_3/internal/Mesh/Flat_mesh.h>
#include <CGAL/BODT_3/internal/Utilities/group_by_key.h>

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Bbox_3.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>
#include <memory>
#include <vector>

namespace CGAL {
namespace BODT_3 {
namespace internal {

/// Whether the facet of mesh cell `c` opposite its local vertex `i` is a facet
/// of the surface the bound keeps near the input: the mesh's boundary, or an
/// interface between two subdomains. An interface facet is counted from the
/// side with the smaller label only, so that each surface facet is seen once.
template <class K>
bool is_surface_facet(const Flat_mesh<K>& mesh, int c, int i)
{
  if(!mesh.in_mesh[c]) return false;
  const int n = mesh.neighbor[4 * static_cast<std::size_t>(c) + i];
  return n < 0 || !mesh.in_mesh[n] || mesh.subdomain[n] > mesh.subdomain[c];
}

/// The surface facets of a flat mesh (`is_surface_facet`, both sides of an
/// interface): per vertex x0, the pairs (a, b) such that (x0, a, b) is one of
/// them, in CSR form (`begin` has one entry per vertex and one more).
template <class K>
void surface_facets_by_vertex(const Flat_mesh<K>& mesh, std::vector<int>& begin,
                              std::vector<std::array<int, 2>>& facets)
{
  group_by_key<std::array<int, 2>>(mesh.cells.size(), mesh.number_of_vertices(), mesh.threads,
                                   [&mesh](std::size_t c, const auto& emit) {
    if(!mesh.in_mesh[c]) return;
    for(int i = 0; i < 4; ++i)
    {
      const int n = mesh.neighbor[4 * c + i];
      if(!(n < 0 || !mesh.in_mesh[n] || mesh.subdomain[n] != mesh.subdomain[c])) continue;
      const auto& o = facet_opposite[i];
      const int t[3] = {mesh.cells[c][o[0]], mesh.cells[c][o[1]], mesh.cells[c][o[2]]};
      for(int k = 0; k < 3; ++k)
        emit(static_cast<std::size_t>(t[k]), std::array<int, 2>{t[(k + 1) % 3], t[(k + 2) % 3]});
    }
  }, begin, facets);
}

/// The bound on how far the mesh's surface (boundary and interfaces) may go from
/// the input's: an AABB tree of the input's surface triangles, built once per
/// run, and the distance `relative_bound` times the largest side of their
/// bounding box (as MMG's `-hausd`, relative).
///
/// A step that moves or creates a surface vertex is judged on the surface
/// triangles around the vertex after the step (`triangle_within`). The other
/// surface triangles did not change, and were judged when they last did.
///
/// The tree is built by the constructor and shared by copies; queries only read
/// it, so threads may judge concurrently, each with its own `Scratch`.
template <class K>
class Boundary_distance_guard
{
public:
  using Point = typename K::Point_3;
  using Triangle = typename K::Triangle_3;

private:
  using Primitive = CGAL::AABB_triangle_primitive<K, typename std::vector<Triangle>::const_iterator>;
  using Tree = CGAL::AABB_tree<CGAL::AABB_traits<K, Primitive>>;

public:
  /// What one thread's calls reuse: the input triangles near a vertex's fan, and
  /// those near one triangle of it.
  struct Scratch
  {
    std::vector<typename Tree::Primitive_id> fan, near;
  };

  /// No bound: every position is accepted.
  Boundary_distance_guard() = default;

  /// The bound `relative_bound` (relative to the largest side of the bounding box
  /// of `input_surface`) from the triangles of the input's surface; no bound when
  /// `relative_bound` is not positive or there is no surface.
  Boundary_distance_guard(std::vector<Triangle> input_surface, double relative_bound, std::vector<Point> origin = {})
  {
    if(!(relative_bound > 0) || input_surface.empty()) return;
    CGAL::Bbox_3 box;
    for(const Triangle& t : input_surface) box += t.bbox();
    bound_ = relative_bound * (std::max)({box.xmax() - box.xmin(), box.ymax() - box.ymin(), box.zmax() - box.zmin()});
    data_ = std::make_shared<Data>(std::move(input_surface), std::move(origin));
  }

  /// From the surface facets of a flat mesh, as the input of a run; its points
  /// are the vertices' input positions (`origin`).
  static Boundary_distance_guard of(const Flat_mesh<K>& mesh, double relative_bound)
  {
    if(!(relative_bound > 0)) return Boundary_distance_guard();
    std::vector<Triangle> triangles;
    for(int c = 0; c < static_cast<int>(mesh.cells.size()); ++c)
      for(int i = 0; i < 4; ++i)
        if(is_surface_facet(mesh, c, i))
        {
          const auto& o = facet_opposite[i];
          const auto& q = mesh.cells[c];
          triangles.emplace_back(mesh.points[q[o[0]]], mesh.points[q[o[1]]], mesh.points[q[o[2]]]);
        }
    return Boundary_distance_guard(std::move(triangles), relative_bound, mesh.points);
  }

  /// Whether there is a bound.
  bool active() const { return data_ != nullptr; }
  /// The bound, absolute (0 without one).
  double bound() const { return bound_; }

  /// The distance from `q` to the input's surface.
  double distance(const Point& q) const
  {
    return active() ? std::sqrt(CGAL::to_double(data_->tree.squared_distance(q))) : 0.0;
  }

  /// Whether `q` is within the bound of the input's surface. (Not a ball query:
  /// CGAL's Sphere_3 meets a triangle only through the sphere, not its inside.)
  bool within(const Point& q) const
  {
    return !active() || CGAL::to_double(data_->tree.squared_distance(q)) <= bound_ * bound_;
  }

  /// Whether the input position of vertex `v` (of the mesh the guard was made
  /// of; later vertices have none) is within the bound of the triangles of the
  /// surface around `v` with `v` at `p`, each given by its two other corners: the
  /// other direction of the distance, from the input's surface to the mesh's, at
  /// the point a move of `v` takes the surface from. (Only from those triangles,
  /// so the test may refuse a move that another part of the surface covers.)
  template <class Corners>
  bool covers_origin(std::size_t v, const Point& p, const Corners& corners) const
  {
    if(!active() || v >= data_->origin.size()) return true;
    const Point& x = data_->origin[v];
    const double b2 = bound_ * bound_;
    if(CGAL::to_double(CGAL::squared_distance(x, p)) <= b2) return true;
    for(const auto& ab : corners)
      if(CGAL::to_double(CGAL::squared_distance(x, Triangle(p, ab[0], ab[1]))) <= b2) return true;
    return false;
  }

  /// Whether vertex `v` may move to `p`: `p` within the bound, each surface
  /// triangle around it (given by its two other corners) within the bound
  /// (`triangle_within`), and its input position near them (`covers_origin`).
  /// One query of the tree for the whole fan; each triangle then looks only at
  /// the input triangles that meet its box grown by the bound (as a query of its
  /// own would find them: the samples depend on them).
  template <class Corners>
  bool keeps_near(std::size_t v, const Point& p, const Corners& corners, Scratch& s) const
  {
    if(!active() || corners.empty()) return true;
    if(!within(p)) return false;
    CGAL::Bbox_3 fan = p.bbox();
    for(const auto& ab : corners) fan += ab[0].bbox() + ab[1].bbox();
    s.fan.clear();
    data_->tree.all_intersected_primitives(grown(fan), std::back_inserter(s.fan));
    for(const auto& ab : corners)
    {
      const CGAL::Bbox_3 box = grown(p.bbox() + ab[0].bbox() + ab[1].bbox());
      s.near.clear();
      for(const auto& id : s.fan)
        if(CGAL::do_overlap(id->bbox(), box) && CGAL::do_intersect(*id, box)) s.near.push_back(id);
      if(!triangle_within(p, ab[0], ab[1], s.near)) return false;
    }
    return covers_origin(v, p, corners);
  }

  /// Whether the surface triangle (p, a, b), whose corner p is new or moved, is
  /// within the bound, given in `near_` every input triangle within the bound of
  /// some point of it (p itself is tested by `within`, once per vertex). The
  /// distance from a point of the triangle to the input's surface is the least
  /// of its distances to the input triangles near it; where the input is convex
  /// or concave there, it is the least of distances to their planes (affine in
  /// the point) on one side and the largest of convex functions on the other,
  /// so its maximum over the triangle is at a corner, below a vertex of the
  /// input, or where a side of the triangle passes an edge of the input. Those
  /// are the samples: p, the points of (p, a, b) nearest to the input's
  /// vertices, the points of the sides p a and p b nearest to the input's
  /// edges, and the midpoints of those sides and the centroid; the side a b
  /// did not change. Where the input is neither convex nor concave (a saddle)
  /// the maximum may fall between samples: doc/manual.md compares the bound with
  /// the measured Hausdorff distance.
  bool triangle_within(const Point& p, const Point& a, const Point& b,
                       const std::vector<typename Tree::Primitive_id>& near_) const
  {
    if(!active()) return true;
    const Point c = CGAL::centroid(p, a, b);
    if(near_.empty()) return false;
    // The distance to one input triangle is convex: if the three corners are within
    // the bound of the same one, so is the whole triangle (exact, and the usual case).
    const double b2 = bound_ * bound_;
    for(const auto& id : near_)
      if(CGAL::to_double(CGAL::squared_distance(p, *id)) <= b2 && CGAL::to_double(CGAL::squared_distance(a, *id)) <= b2 &&
         CGAL::to_double(CGAL::squared_distance(b, *id)) <= b2)
        return true;
    std::size_t hint = 0;   // the input triangle that covered the last sample: often the next one's
    auto covered = [&](const Point& q) {
      if(CGAL::to_double(CGAL::squared_distance(q, *near_[hint])) <= b2) return true;
      for(std::size_t i = 0; i < near_.size(); ++i)
        if(i != hint && CGAL::to_double(CGAL::squared_distance(q, *near_[i])) <= b2)
        {
          hint = i;
          return true;
        }
      return false;
    };
    if(!covered(CGAL::midpoint(p, a)) || !covered(CGAL::midpoint(p, b)) || !covered(c)) return false;

    const typename K::Vector_3 u = a - p, v = b - p, n = CGAL::cross_product(u, v);
    const double nn = CGAL::to_double(n * n);
    if(!(nn > 0)) return true;   // a flat triangle: its sides were sampled
    for(const auto& id : near_)
      for(int k = 0; k < 3; ++k)
      {
        // Below the input's vertex x: its projection on the plane, if inside the triangle.
        const Point& x = (*id)[k];
        const typename K::Vector_3 w = x - p;
        const double s = CGAL::to_double(CGAL::cross_product(w, v) * n) / nn;
        const double t = CGAL::to_double(CGAL::cross_product(u, w) * n) / nn;
        if(s > 0 && t > 0 && s + t < 1 && !covered(p + s * u + t * v)) return false;
        // Where the sides through p pass the input's edge x y.
        const Point& y = (*id)[(k + 1) % 3];
        for(const Point* q : {&a, &b})
        {
          double along;
          if(nearest_on_segment(p, *q, x, y, along) && !covered(p + along * (*q - p))) return false;
        }
      }
    return true;
  }

private:
  // A box grown by the bound on every side (a box query of the tree is solid).
  CGAL::Bbox_3 grown(const CGAL::Bbox_3& b) const
  {
    return CGAL::Bbox_3(b.xmin() - bound_, b.ymin() - bound_, b.zmin() - bound_, b.xmax() + bound_,
                        b.ymax() + bound_, b.zmax() + bound_);
  }

  struct Data
  {
    std::vector<Triangle> triangles;
    Tree tree;
    std::vector<Point> origin;   // per vertex of the input

    Data(std::vector<Triangle> t, std::vector<Point> o)
      : triangles(std::move(t)), tree(triangles.begin(), triangles.end()), origin(std::move(o))
    {
      // Built now, not at the first query: queries then only read, from any thread.
      tree.build();
      tree.accelerate_distance_queries();
      tree.squared_distance(triangles.front()[0]);
    }
  };

  // The point of segment (p, q) nearest to the line through x y, as the fraction
  // `along` of p q; false if it is an end, or the two are parallel.
  static bool nearest_on_segment(const Point& p, const Point& q, const Point& x, const Point& y, double& along)
  {
    const typename K::Vector_3 d1 = q - p, d2 = y - x, w = p - x;
    const double a = CGAL::to_double(d1 * d1), b = CGAL::to_double(d1 * d2), c = CGAL::to_double(d2 * d2);
    const double d = CGAL::to_double(d1 * w), e = CGAL::to_double(d2 * w);
    const double den = a * c - b * b;
    if(!(den > 1e-12 * a * c)) return false;
    along = (b * e - c * d) / den;
    return along > 0 && along < 1;
  }

  std::shared_ptr<const Data> data_;   // shared by copies: the tree is built once per run

  double bound_ = 0;
};

} // namespace internal
} // namespace BODT_3
} // namespace CGAL

#endif // CGAL_BODT_3_INTERNAL_SMOOTHING_BOUNDARY_DISTANCE_GUARD_H
