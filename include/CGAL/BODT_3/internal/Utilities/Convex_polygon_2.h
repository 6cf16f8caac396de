// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_BODT_3_INTERNAL_UTILITIES_CONVEX_POLYGON_2_H
#define CGAL_BODT_3_INTERNAL_UTILITIES_CONVEX_POLYGON_2_H

#include <algorithm>
#include <array>
#include <cmath>

namespace CGAL {
namespace BODT_3 {
namespace internal {

/// A point of the plane, in doubles.
using Point_2d = std::array<double, 2>;

/// An affine function of the plane, a x + b y + c.
struct Affine_2d
{
  double a = 0, b = 0, c = 0;
  double operator()(const Point_2d& p) const { return a * p[0] + b * p[1] + c; }
};

/// Twice the signed area of (p, q, r): positive when counterclockwise.
inline double orient_2d(const Point_2d& p, const Point_2d& q, const Point_2d& r)
{
  return (q[0] - p[0]) * (r[1] - p[1]) - (q[1] - p[1]) * (r[0] - p[0]);
}

/// The affine function that takes the values h[k] at the corners s[k] of a
/// triangle (not flat); the height over the plane of a triangle given by its
/// projection and its heights.
inline Affine_2d interpolating(const std::array<Point_2d, 3>& s, const std::array<double, 3>& h)
{
  const double det = orient_2d(s[0], s[1], s[2]);
  const double d1 = h[1] - h[0], d2 = h[2] - h[0];
  // lambda1 = cross(x - s0, s2 - s0) / det, lambda2 = cross(s1 - s0, x - s0) / det.
  const double ux = s[1][0] - s[0][0], uy = s[1][1] - s[0][1];
  const double vx = s[2][0] - s[0][0], vy = s[2][1] - s[0][1];
  Affine_2d f;
  f.a = (d1 * vy - d2 * uy) / det;
  f.b = (d2 * ux - d1 * vx) / det;
  f.c = h[0] - f.a * s[0][0] - f.b * s[0][1];
  return f;
}

/// A box of the plane, to skip clipping what cannot meet.
struct Box_2
{
  double xmin, ymin, xmax, ymax;

  static Box_2 of(const Point_2d& p, const Point_2d& q, const Point_2d& r)
  {
    return {(std::min)({p[0], q[0], r[0]}), (std::min)({p[1], q[1], r[1]}), (std::max)({p[0], q[0], r[0]}),
            (std::max)({p[1], q[1], r[1]})};
  }

  template <class Polygon>
  static Box_2 of(const Polygon& polygon)
  {
    Box_2 b{polygon[0][0], polygon[0][1], polygon[0][0], polygon[0][1]};
    for(int i = 1; i < polygon.size(); ++i)
    {
      b.xmin = (std::min)(b.xmin, polygon[i][0]);
      b.ymin = (std::min)(b.ymin, polygon[i][1]);
      b.xmax = (std::max)(b.xmax, polygon[i][0]);
      b.ymax = (std::max)(b.ymax, polygon[i][1]);
    }
    return b;
  }

  /// Whether the two boxes share a point (closed boxes).
  bool meets(const Box_2& o) const { return xmin <= o.xmax && o.xmin <= xmax && ymin <= o.ymax && o.ymin <= ymax; }
};

/// A convex polygon of the plane, clipped by half-planes (Sutherland and
/// Hodgman). A triangle clipped by n half-planes has at most 3 + n corners: the
/// capacity is a triangle's clipped thirteen times.
class Convex_polygon_2
{
public:
  static constexpr int capacity = 16;

  Convex_polygon_2() = default;
  /// A counterclockwise triangle.
  Convex_polygon_2(const Point_2d& p, const Point_2d& q, const Point_2d& r) : size_(3) { corners_ = {p, q, r}; }

  int size() const { return size_; }
  bool empty() const { return size_ == 0; }
  const Point_2d& operator[](int i) const { return corners_[i]; }

  /// Keeps the part where f >= 0. A polygon already at capacity becomes empty:
  /// the callers clip a triangle fewer times than that allows.
  void clip(const Affine_2d& f)
  {
    if(size_ == 0) return;
    std::array<double, capacity> value;
    bool in = false, out = false;
    for(int i = 0; i < size_; ++i)
    {
      value[i] = f(corners_[i]);
      (value[i] >= 0 ? in : out) = true;
    }
    if(!out) return;   // the usual case, with nothing to copy
    if(!in) return clear();
    std::array<Point_2d, capacity> kept;
    int n = 0;
    for(int i = 0; i < size_; ++i)
    {
      const int j = i + 1 == size_ ? 0 : i + 1;
      const Point_2d& p = corners_[i];
      const Point_2d& q = corners_[j];
      const double fp = value[i], fq = value[j];
      if(fp >= 0)
      {
        if(n == capacity) return clear();
        kept[n++] = p;
      }
      if((fp >= 0) != (fq >= 0))
      {
        if(n == capacity) return clear();
        const double t = fp / (fp - fq);
        kept[n++] = {p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1])};
      }
    }
    corners_ = kept;
    size_ = n;
  }

  /// Keeps the part inside the triangle (p, q, r), counterclockwise.
  void clip(const Point_2d& p, const Point_2d& q, const Point_2d& r)
  {
    clip(left_of(p, q));
    clip(left_of(q, r));
    clip(left_of(r, p));
  }

  /// The area (0 for fewer than three corners).
  double area() const
  {
    double twice = 0;
    for(int i = 1; i + 1 < size_; ++i) twice += orient_2d(corners_[0], corners_[i], corners_[i + 1]);
    return 0.5 * twice;
  }

private:
  // The affine function, positive on the left of the line from p to q.
  static Affine_2d left_of(const Point_2d& p, const Point_2d& q)
  {
    Affine_2d f;
    f.a = -(q[1] - p[1]);
    f.b = q[0] - p[0];
    f.c = -(f.a * p[0] + f.b * p[1]);
    return f;
  }

  void clear() { size_ = 0; }

  std::array<Point_2d, capacity> corners_{};
  int size_ = 0;
};

} // namespace internal
} // namespace BODT_3
} // namespace CGAL

#endif // CGAL_BODT_3_INTERNAL_UTILITIES_CONVEX_POLYGON_2_H
