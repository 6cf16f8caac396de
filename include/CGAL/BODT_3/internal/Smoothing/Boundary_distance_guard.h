// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_BODT_3_INTERNAL_SMOOTHING_BOUNDARY_DISTANCE_GUARD_H
#define CGAL_BODT_3_INTERNAL_SMOOTHING_BOUNDARY_DISTANCE_GUARD_H

#include <CGAL/BODT_3/internal/Mesh/Flat_mesh.h>
#include <CGAL/BODT_3/internal/Utilities/Convex_polygon_2.h>
#include <CGAL/BODT_3/internal/Utilities/group_by_key.h>

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Bbox_3.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>
#include <limits>
#include <memory>
#include <utility>
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
/// A step that moves a surface vertex is judged on the surface triangles around
/// the vertex, before and after: those after must be within the bound of the
/// input's surface (`triangle_within`), and the input's surface must stay within
/// the bound of the mesh's (`keeps_input_covered`). The other surface triangles
/// did not change, and were judged when they last did; a split or a flip of
/// coplanar facets does not change the surface.
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
  /// A point in the plane of an input triangle, and its height over it.
  struct Corner_2
  {
    Point_2d at;
    double height;
  };

  /// What one thread's calls reuse: the input triangles near a vertex's fan and
  /// those near one triangle of it; the fan's other corners in an input
  /// triangle's plane, and twice its triangles' areas before and after a move.
  struct Scratch
  {
    std::vector<typename Tree::Primitive_id> fan, near;
    std::vector<std::array<Corner_2, 2>> link;
    std::vector<double> size_before, size_after;
  };

  /// No bound: every position is accepted.
  Boundary_distance_guard() = default;

  /// The bound `relative_bound` (relative to the largest side of the bounding box
  /// of `input_surface`) from the triangles of the input's surface; no bound when
  /// `relative_bound` is not positive or there is no surface.
  Boundary_distance_guard(std::vector<Triangle> input_surface, double relative_bound)
  {
    if(!(relative_bound > 0) || input_surface.empty()) return;
    CGAL::Bbox_3 box;
    for(const Triangle& t : input_surface) box += t.bbox();
    bound_ = relative_bound * (std::max)({box.xmax() - box.xmin(), box.ymax() - box.ymin(), box.zmax() - box.zmin()});
    data_ = std::make_shared<Data>(std::move(input_surface));
  }

  /// From the surface facets of a flat mesh, as the input of a run.
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
    return Boundary_distance_guard(std::move(triangles), relative_bound);
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

  /// Whether a surface vertex may move from `from` to `p` (or, from where a
  /// split put it on the surface, to `p`): `p` within the bound, each surface
  /// triangle around it (given by its two other corners) within the bound
  /// (`triangle_within`), and the input's surface as near the mesh's as before
  /// (`keeps_input_covered`). One query of the tree for the whole fan, before and
  /// after; each triangle then looks only at the input triangles that meet its
  /// box grown by the bound (as a query of its own would find them: the
  /// distances `triangle_within` takes from them are the surface's only with all
  /// of them).
  template <class Corners>
  bool keeps_near(const Point& from, const Point& p, const Corners& corners, Scratch& s) const
  {
    if(!active() || corners.empty()) return true;
    if(!within(p)) return false;
    CGAL::Bbox_3 fan = p.bbox() + from.bbox();
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
    return keeps_input_covered(from, p, corners, s.fan, s);
  }

  /// The other direction, from the input's surface to the mesh's: whether moving
  /// a vertex from q to p, with the surface triangles around it given by their
  /// two other corners, leaves every point of the input's surface within the
  /// bound of the mesh's surface, given in `inputs` every input triangle that
  /// meets the box of both fans grown by the bound. The guard keeps a stronger
  /// promise, true at the start (the surfaces are the same) and after every step
  /// it accepts: the line through each input point along its triangle's normal
  /// meets, within the bound, a triangle of the mesh's surface that faces the
  /// input triangle's way within 60 degrees. A split or a flip of coplanar facets
  /// leaves the surface where it is, and so the promise; a move changes the
  /// surface only in the vertex's fan. So for each input triangle t and each
  /// facing triangle of the fan before the move, the points of t it kept (a
  /// convex polygon in t's plane: the part of t under it where its height over t
  /// is within the bound) must be kept by the facing triangles after the move:
  /// the parts of that polygon under them where their heights are within the
  /// bound must cover it (their areas add up to its own, to 1e-9 of t's). Exact
  /// up to rounding, where the new fan does not fold over t (its facing
  /// triangles' projections do not overlap); conservative, since a point may be
  /// kept near by a triangle the fan does not have. (Steeper triangles are left
  /// out of the promise: seen from t they fold over each other where the
  /// surface turns, and the fold moves with the vertex.)
  template <class Corners>
  bool keeps_input_covered(const Point& q, const Point& p, const Corners& corners,
                           const std::vector<typename Tree::Primitive_id>& inputs, Scratch& s) const
  {
    using Vector = typename K::Vector_3;
    if(q == p) return true;
    // Twice the fan triangles' areas, before and after: how much of them a plane sees.
    s.size_before.clear();
    s.size_after.clear();
    for(const auto& ab : corners)
    {
      const Vector before = CGAL::cross_product(ab[0] - q, ab[1] - q), after = CGAL::cross_product(ab[0] - p, ab[1] - p);
      s.size_before.push_back(std::sqrt(CGAL::to_double(before * before)));
      s.size_after.push_back(std::sqrt(CGAL::to_double(after * after)));
    }
    for(const auto& id : inputs)
    {
      const Triangle& t = *id;
      const Plane_frame frame(t[0], t[1], t[2]);
      if(!frame.valid) continue;   // a flat input triangle has no area to cover
      const Point_2d s0{0, 0}, s1 = frame(t[1]).at, s2 = frame(t[2]).at;
      const double tolerance = 1e-9 * 0.5 * orient_2d(s0, s1, s2);
      const Corner_2 before = frame(q), after = frame(p);
      s.link.clear();
      for(const auto& ab : corners) s.link.push_back({frame(ab[0]), frame(ab[1])});
      const Box_2 input = Box_2::of(s0, s1, s2);
      for(std::size_t i = 0; i < s.link.size(); ++i)
      {
        const auto& ab = s.link[i];
        if(!facing(before, ab[0], ab[1], s.size_before[i]) || !input.meets(Box_2::of(before.at, ab[0].at, ab[1].at)))
          continue;
        Convex_polygon_2 kept(s0, s1, s2);
        clip_under(kept, before, ab[0], ab[1]);
        const double area = kept.area();
        if(area <= tolerance) continue;
        const Box_2 box = Box_2::of(kept);
        double covered = 0;
        for(std::size_t j = 0; j < s.link.size(); ++j)
        {
          const auto& cd = s.link[j];
          if(!facing(after, cd[0], cd[1], s.size_after[j]) || !box.meets(Box_2::of(after.at, cd[0].at, cd[1].at)))
            continue;
          Convex_polygon_2 part = kept;
          clip_under(part, after, cd[0], cd[1]);
          covered += part.area();
        }
        if(covered < area - tolerance) return false;
      }
    }
    return true;
  }

  /// Whether the surface triangle (p, a, b), whose corner p is new or moved, is
  /// within the bound of the input's surface, given in `near_` every input
  /// triangle that meets the triangle's box grown by the bound (so the least
  /// distance to them is the distance to the surface wherever that is within
  /// the bound). Exact up to rounding, by three sufficient tests and, when none
  /// decides, the same on the four halves of the triangle, to `subdivision_depth`
  /// levels, after which the triangle is refused:
  /// - the input's surface seen along the triangle's normal (`projection_covers`);
  /// - the three corners within the bound of one input triangle: the distance to
  ///   a triangle is convex, so every point of the triangle is;
  /// - the centroid nearer than the bound by more than its distance to the
  ///   corners: the distance to the surface changes no faster than the point.
  /// A corner farther than the bound refuses it.
  bool triangle_within(const Point& p, const Point& a, const Point& b,
                       const std::vector<typename Tree::Primitive_id>& near_) const
  {
    if(!active()) return true;
    if(near_.empty()) return false;
    return part_within(p, a, b, near_, subdivision_depth);
  }

  /// Whether every point of the triangle (p, a, b) lies within the bound of the
  /// input triangles in `near_`, judged along the triangle's normal: the part of
  /// the triangle over an input triangle t (in projection on the triangle's
  /// plane) is at most the height of t above or below it from t, an affine
  /// function; so the part where that height is within the bound is a convex
  /// polygon, and the test is that those polygons cover the triangle (their areas
  /// add up to its own, to 1e-9 of it). The input triangles whose normal is
  /// within 60 degrees of the triangle's count, or else those within 60 degrees
  /// of its opposite (an interface triangle is listed from both sides): either
  /// kind makes one sheet over its plane (their projections do not overlap), as
  /// the input's surface within the bound of a triangle does unless it folds
  /// there or two of its sheets facing the same way are within the bound of each
  /// other.
  bool projection_covers(const Point& p, const Point& a, const Point& b,
                         const std::vector<typename Tree::Primitive_id>& near_) const
  {
    const Plane_frame frame(p, a, b);
    if(!frame.valid) return false;
    const Point_2d s0{0, 0}, s1 = frame(a).at, s2 = frame(b).at;
    const double whole = 0.5 * orient_2d(s0, s1, s2);
    const Box_2 box = Box_2::of(s0, s1, s2);
    double covered[2] = {0, 0};   // by the input triangles facing the same way, the other way
    for(const auto& id : near_)
    {
      const Triangle& t = *id;
      std::array<Corner_2, 3> c = {frame(t[0]), frame(t[1]), frame(t[2])};
      if(!box.meets(Box_2::of(c[0].at, c[1].at, c[2].at))) continue;
      // Its projection's area over its own is the cosine of the angle of the normals.
      const double projected = 0.5 * orient_2d(c[0].at, c[1].at, c[2].at);
      if(!within_60_degrees(projected * projected, CGAL::to_double(t.squared_area()))) continue;
      const int side = projected > 0 ? 0 : 1;
      if(side == 1) std::swap(c[1], c[2]);
      Convex_polygon_2 part(s0, s1, s2);
      clip_under(part, c[0], c[1], c[2]);
      covered[side] += part.area();
    }
    return (std::max)(covered[0], covered[1]) >= whole * (1 - 1e-9);
  }

private:
  // A box grown by the bound on every side (a box query of the tree is solid).
  CGAL::Bbox_3 grown(const CGAL::Bbox_3& b) const
  {
    return CGAL::Bbox_3(b.xmin() - bound_, b.ymin() - bound_, b.zmin() - bound_, b.xmax() + bound_,
                        b.ymax() + bound_, b.zmax() + bound_);
  }

  // An orthonormal frame of the plane of the triangle (o, a, b), from o, its
  // normal that of the triangle: a point's coordinates in the plane and its
  // height over it. Not valid for a flat triangle.
  struct Plane_frame
  {
    Point o;
    typename K::Vector_3 e1, e2, n;
    bool valid = false;

    Plane_frame(const Point& origin, const Point& a, const Point& b) : o(origin)
    {
      const typename K::Vector_3 u = a - o, normal = CGAL::cross_product(u, b - o);
      const double nn = CGAL::to_double(normal * normal), uu = CGAL::to_double(u * u);
      if(!(nn > 0)) return;
      n = normal / std::sqrt(nn);
      e1 = u / std::sqrt(uu);
      e2 = CGAL::cross_product(n, e1);
      valid = true;
    }

    Corner_2 operator()(const Point& x) const
    {
      const typename K::Vector_3 d = x - o;
      return {{CGAL::to_double(d * e1), CGAL::to_double(d * e2)}, CGAL::to_double(d * n)};
    }
  };

  // Whether two planes are within 60 degrees of each other, by the squared area
  // of a triangle of one projected on the other and its own: the ratio of the
  // areas is the cosine of the angle, at least a half.
  static bool within_60_degrees(double squared_projected, double squared_area)
  {
    return squared_projected >= 0.25 * squared_area;
  }

  // Whether the triangle (x, a, b), of twice the area `size`, faces the way of
  // the input triangle in whose plane its corners are given, within 60 degrees.
  static bool facing(const Corner_2& x, const Corner_2& a, const Corner_2& b, double size)
  {
    const double projected = orient_2d(x.at, a.at, b.at);
    return projected > 0 && within_60_degrees(projected * projected, size * size);
  }

  // Clips `part` (in an input triangle's plane) to the projection of the
  // triangle (x, a, b), counterclockwise there, and to where the triangle's
  // height over the plane is within the bound.
  void clip_under(Convex_polygon_2& part, const Corner_2& x, const Corner_2& a, const Corner_2& b) const
  {
    part.clip(x.at, a.at, b.at);
    if(part.empty()) return;
    const Affine_2d f = interpolating({x.at, a.at, b.at}, {x.height, a.height, b.height});
    part.clip(Affine_2d{-f.a, -f.b, bound_ - f.c});   // height <= bound
    part.clip(Affine_2d{f.a, f.b, bound_ + f.c});     // height >= -bound
  }

  // Levels of halving before `triangle_within` refuses a triangle no test decided.
  static constexpr int subdivision_depth = 3;

  // The least squared distance from q to the triangles of `near_`.
  static double squared_distance_to(const Point& q, const std::vector<typename Tree::Primitive_id>& near_)
  {
    double least = std::numeric_limits<double>::infinity();
    for(const auto& id : near_) least = (std::min)(least, CGAL::to_double(CGAL::squared_distance(q, *id)));
    return least;
  }

  // `triangle_within` for the part (p, a, b) of a triangle, with `depth` levels
  // of halving left.
  bool part_within(const Point& p, const Point& a, const Point& b,
                   const std::vector<typename Tree::Primitive_id>& near_, int depth) const
  {
    if(projection_covers(p, a, b, near_)) return true;
    const double b2 = bound_ * bound_;
    // The corners within the bound of one input triangle; else each corner's nearest.
    double least[3] = {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
                       std::numeric_limits<double>::infinity()};
    for(const auto& id : near_)
    {
      const double d[3] = {CGAL::to_double(CGAL::squared_distance(p, *id)),
                           CGAL::to_double(CGAL::squared_distance(a, *id)),
                           CGAL::to_double(CGAL::squared_distance(b, *id))};
      if(d[0] <= b2 && d[1] <= b2 && d[2] <= b2) return true;
      for(int k = 0; k < 3; ++k) least[k] = (std::min)(least[k], d[k]);
    }
    if(least[0] > b2 || least[1] > b2 || least[2] > b2) return false;
    const Point g = CGAL::centroid(p, a, b);
    const double reach = std::sqrt((std::max)({CGAL::to_double(CGAL::squared_distance(g, p)),
                                               CGAL::to_double(CGAL::squared_distance(g, a)),
                                               CGAL::to_double(CGAL::squared_distance(g, b))}));
    if(std::sqrt(squared_distance_to(g, near_)) + reach <= bound_) return true;
    if(depth == 0) return false;
    const Point ab = CGAL::midpoint(a, b), bp = CGAL::midpoint(b, p), pa = CGAL::midpoint(p, a);
    return part_within(p, pa, bp, near_, depth - 1) && part_within(pa, a, ab, near_, depth - 1) &&
           part_within(bp, ab, b, near_, depth - 1) && part_within(ab, bp, pa, near_, depth - 1);
  }

  struct Data
  {
    std::vector<Triangle> triangles;
    Tree tree;

    explicit Data(std::vector<Triangle> t) : triangles(std::move(t)), tree(triangles.begin(), triangles.end())
    {
      // Built now, not at the first query: queries then only read, from any thread.
      tree.build();
      tree.accelerate_distance_queries();
      tree.squared_distance(triangles.front()[0]);
    }
  };

  std::shared_ptr<const Data> data_;   // shared by copies: the tree is built once per run

  double bound_ = 0;
};

} // namespace internal
} // namespace BODT_3
} // namespace CGAL

#endif // CGAL_BODT_3_INTERNAL_SMOOTHING_BOUNDARY_DISTANCE_GUARD_H
