// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_BODT_3_INTERNAL_QUALITY_TET_QUALITY_H
#define CGAL_BODT_3_INTERNAL_QUALITY_TET_QUALITY_H

#include <CGAL/BODT_3/Smoothing_options.h>
#include <CGAL/BODT_3/internal/Quality/dihedral_angles.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

namespace CGAL {
namespace BODT_3 {
namespace internal {


// The even permutations of a tetrahedron's vertices, one per first vertex.
constexpr int even_orders[4][4] = {{0, 1, 2, 3}, {1, 0, 3, 2}, {2, 3, 0, 1}, {3, 2, 1, 0}};

// The even permutation whose first vertex has the three edges with the smallest
// product of lengths. Determinants and cross products computed from that vertex
// have the smallest rounding error (about 1e-16 times that product): a tetrahedron
// with one vertex 1e10 away from the three others loses every digit when the far
// vertex is the base.
template <class Point>
int best_base(const Point* const p[4])
{
  auto d2 = [&](int i, int j) {
    const double x = p[i]->x() - p[j]->x(), y = p[i]->y() - p[j]->y(), z = p[i]->z() - p[j]->z();
    return x * x + y * y + z * z;
  };
  int best = 0;
  double best_product = std::numeric_limits<double>::infinity();
  for(int k = 0; k < 4; ++k)
  {
    const int* o = even_orders[k];
    const double product = d2(o[0], o[1]) * d2(o[0], o[2]) * d2(o[0], o[3]);
    if(product < best_product)
    {
      best_product = product;
      best = k;
    }
  }
  return best;
}


/// The signed volume of the tetrahedron, computed from its best-conditioned vertex
/// (`internal::best_base`), so that a tetrahedron with a far vertex keeps its
/// volume to round-off. The sign is the orientation's.
template <class Point>
double tet_volume(const Point& p0, const Point& p1, const Point& p2, const Point& p3)
{
  const Point* p[4] = {&p0, &p1, &p2, &p3};
  const int* o = internal::even_orders[internal::best_base(p)];
  const Point &a = *p[o[0]], &b = *p[o[1]], &c = *p[o[2]], &d = *p[o[3]];
  const double ax = b.x() - a.x(), ay = b.y() - a.y(), az = b.z() - a.z();
  const double bx = c.x() - a.x(), by = c.y() - a.y(), bz = c.z() - a.z();
  const double cx = d.x() - a.x(), cy = d.y() - a.y(), cz = d.z() - a.z();
  return (ax * (by * cz - bz * cy) - ay * (bx * cz - bz * cx) + az * (bx * cy - by * cx)) / 6;
}

/// The quality measure that decides everything that changes the mesh (the
/// smoothing guard, flips, insertion and its undo): the minimum sine of the six
/// dihedral angles of a tetrahedron. It is 0 for a flat tetrahedron, sqrt(8)/3
/// (0.9428) for the regular one, and since sin(t) = sin(180 - t), a tetrahedron of
/// quality q has every dihedral angle in [asin q, 180 - asin q]: the measure
/// punishes small and large angles alike, as the two figures users read (minimum
/// and maximum dihedral angle) do. doc/manual.md compares it with the alternatives.
///
/// With N_k the area vector (cross product) of the face opposite vertex k and
/// D = 6 |tau|, the dihedral angle at the edge shared by faces k and l has
/// sin = D |e| / (|N_k| |N_l|), |e| the edge's length (from |tau| = 2 A_k A_l sin / (3 |e|)),
/// so the measure needs one square root. Returns -1 when the tetrahedron is not
/// positively oriented in floating point (callers decide orientation exactly).
template <class Point>
double min_dihedral_sine(const Point& q0, const Point& q1, const Point& q2, const Point& q3)
{
  // The measure is invariant under even permutations: compute it from the
  // best-conditioned vertex.
  const Point* q[4] = {&q0, &q1, &q2, &q3};
  const int* o = internal::even_orders[internal::best_base(q)];
  const Point &p0 = *q[o[0]], &p1 = *q[o[1]], &p2 = *q[o[2]], &p3 = *q[o[3]];
  const double ax = p1.x() - p0.x(), ay = p1.y() - p0.y(), az = p1.z() - p0.z();
  const double bx = p2.x() - p0.x(), by = p2.y() - p0.y(), bz = p2.z() - p0.z();
  const double cx = p3.x() - p0.x(), cy = p3.y() - p0.y(), cz = p3.z() - p0.z();
  const double D = ax * (by * cz - bz * cy) - ay * (bx * cz - bz * cx) + az * (bx * cy - by * cx);
  if(!(D > 0)) return -1;
  // Squared norms of the face area vectors (opposite vertex 0..3) and of the edges.
  auto cross2 = [](double ux, double uy, double uz, double vx, double vy, double vz) {
    const double x = uy * vz - uz * vy, y = uz * vx - ux * vz, z = ux * vy - uy * vx;
    return x * x + y * y + z * z;
  };
  const double dx = p2.x() - p1.x(), dy = p2.y() - p1.y(), dz = p2.z() - p1.z();   // p2 - p1
  const double ex = p3.x() - p1.x(), ey = p3.y() - p1.y(), ez = p3.z() - p1.z();   // p3 - p1
  const double fx = p3.x() - p2.x(), fy = p3.y() - p2.y(), fz = p3.z() - p2.z();   // p3 - p2
  const double N0 = cross2(dx, dy, dz, ex, ey, ez);
  const double N1 = cross2(bx, by, bz, cx, cy, cz);
  const double N2 = cross2(ax, ay, az, cx, cy, cz);
  const double N3 = cross2(ax, ay, az, bx, by, bz);
  const double l01 = ax * ax + ay * ay + az * az, l02 = bx * bx + by * by + bz * bz, l03 = cx * cx + cy * cy + cz * cz;
  const double l12 = dx * dx + dy * dy + dz * dz, l13 = ex * ex + ey * ey + ez * ez, l23 = fx * fx + fy * fy + fz * fz;
  // Edge (i, j) lies on the faces opposite the two other vertices.
  const double s = std::min({l01 / (N2 * N3), l02 / (N1 * N3), l03 / (N1 * N2), l12 / (N0 * N3),
                             l13 / (N0 * N2), l23 / (N0 * N1)});
  return std::min(1.0, D * std::sqrt(s));
}

/// The cosines of the six dihedral angles of a tetrahedron, -(n_k . n_l) for the
/// outward unit normals of the two faces at each edge.
template <class Point>
std::array<double, 6> dihedral_cosines(const Point& p0, const Point& p1, const Point& p2, const Point& p3)
{
  const Point* p[4] = {&p0, &p1, &p2, &p3};
  // Outward for a positively oriented tetrahedron: (a, b, c) has p_k on its negative side.
  static const int face[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};
  double n[4][3];
  for(int k = 0; k < 4; ++k)
  {
    const Point& a = *p[face[k][0]];
    const Point& b = *p[face[k][1]];
    const Point& c = *p[face[k][2]];
    const double ux = b.x() - a.x(), uy = b.y() - a.y(), uz = b.z() - a.z();
    const double vx = c.x() - a.x(), vy = c.y() - a.y(), vz = c.z() - a.z();
    double x = uy * vz - uz * vy, y = uz * vx - ux * vz, z = ux * vy - uy * vx;
    const double len = std::sqrt(x * x + y * y + z * z);
    if(len > 0) { x /= len; y /= len; z /= len; }
    n[k][0] = x; n[k][1] = y; n[k][2] = z;
  }
  static const int faces_at_edge[6][2] = {{2, 3}, {1, 3}, {1, 2}, {0, 3}, {0, 2}, {0, 1}};
  std::array<double, 6> out;
  for(int e = 0; e < 6; ++e)
  {
    const double* a = n[faces_at_edge[e][0]];
    const double* b = n[faces_at_edge[e][1]];
    out[e] = -(a[0] * b[0] + a[1] * b[1] + a[2] * b[2]);
  }
  return out;
}

/// The largest-angle measure of a tetrahedron, 1 + its smallest dihedral cosine,
/// with its cosines in `cosines` for a caller that checks them too; -1 (and no
/// cosines) for a tetrahedron that is not positively oriented in floating point.
template <class Point>
double largest_angle_measure(const Point& p0, const Point& p1, const Point& p2, const Point& p3,
                             std::array<double, 6>& cosines)
{
  // The orientation test of `min_dihedral_sine` (the same determinant), without its sines.
  if(!(tet_volume(p0, p1, p2, p3) > 0)) return -1;
  cosines = dihedral_cosines(p0, p1, p2, p3);
  return 1 + *std::min_element(cosines.begin(), cosines.end());
}

/// The quality of a tetrahedron by `measure`: larger is better, -1 for a
/// tetrahedron that is not positively oriented in floating point.
template <class Point>
double tet_quality(Quality_measure measure, const Point& p0, const Point& p1, const Point& p2, const Point& p3)
{
  if(measure == Quality_measure::largest_dihedral_angle)
  {
    std::array<double, 6> cosines;
    return largest_angle_measure(p0, p1, p2, p3, cosines);
  }
  const double q = min_dihedral_sine(p0, p1, p2, p3);
  if(measure == Quality_measure::min_dihedral_sine || q < 0) return q;
  if(measure == Quality_measure::radius_ratio) return radius_ratio(p0, p1, p2, p3);
  const auto a = dihedral_angles(p0, p1, p2, p3);
  return *std::min_element(a.begin(), a.end());
}

/// The largest-angle measure of a tetrahedron whose largest dihedral angle is
/// `degrees`, and the minimum sine of one with an angle of `degrees`: thresholds
/// given as angles, in each measure's units.
inline double largest_angle_quality(double degrees) { return 1 + std::cos(degrees * pi / 180); }
inline double dihedral_sine(double degrees) { return std::sin(degrees * pi / 180); }

/// The extreme dihedral angles a mesh may reach, as cosines: every angle t must
/// have cos t in [cos_largest, cos_smallest]. Set to a mesh's own extremes, they
/// guarantee that its smallest angle never decreases and its largest never
/// increases while the measure above decides (a tetrahedron with a better sine
/// can still have a smaller angle than the mesh's smallest, when the mesh's worst
/// sine comes from its largest angle). Default-constructed, they accept every angle.
class Dihedral_bounds
{
public:

  /// Bounds that nothing satisfies yet, to be widened by `include`.
  static Dihedral_bounds empty()
  {
    Dihedral_bounds b;
    b.cos_smallest_ = -2;
    b.cos_largest_ = 2;
    b.safe_ = 2;
    return b;
  }

  /// Widens the bounds to include the angles of a tetrahedron.
  template <class Point>
  void include(const Point& p0, const Point& p1, const Point& p2, const Point& p3)
  {
    for(double c : dihedral_cosines(p0, p1, p2, p3))
    {
      cos_smallest_ = std::max(cos_smallest_, c);
      cos_largest_ = std::min(cos_largest_, c);
    }
    safe_ = safe_sine();
  }

  /// Widens the bounds to include other bounds (those of other tetrahedra): the
  /// result does not depend on how the tetrahedra were grouped.
  void include(const Dihedral_bounds& other)
  {
    cos_smallest_ = std::max(cos_smallest_, other.cos_smallest_);
    cos_largest_ = std::min(cos_largest_, other.cos_largest_);
    safe_ = safe_sine();
  }

  /// A tetrahedron whose minimum dihedral sine is at least this has every angle
  /// within the bounds, so `contains` needs no cosines for it.
  double safe_sine() const
  {
    auto sine = [](double c) { return c >= 1 || c <= -1 ? 0.0 : std::sqrt((1 - c) * (1 + c)); };
    if(cos_smallest_ < cos_largest_) return 2;   // empty
    return std::max(sine(cos_smallest_), sine(cos_largest_));
  }

  /// Whether every dihedral angle of a tetrahedron of minimum sine `q` is within
  /// the bounds.
  template <class Point>
  bool contains(const Point& p0, const Point& p1, const Point& p2, const Point& p3, double q) const
  {
    return q >= safe_ || within(dihedral_cosines(p0, p1, p2, p3));
  }

  /// The same for a tetrahedron whose dihedral cosines are known.
  bool contains(const std::array<double, 6>& cosines, double q) const { return q >= safe_ || within(cosines); }

  /// Whether a tetrahedron of minimum sine `q` is within the bounds whatever its
  /// cosines (`contains` then needs none).
  bool safe(double q) const { return q >= safe_; }

  double cos_smallest() const { return cos_smallest_; }   // the cosine of the smallest angle allowed
  double cos_largest() const { return cos_largest_; }     // the cosine of the largest angle allowed

private:
  bool within(const std::array<double, 6>& cosines) const
  {
    for(double c : cosines)
      if(c > cos_smallest_ || c < cos_largest_) return false;
    return true;
  }

  double cos_smallest_ = 1;
  double cos_largest_ = -1;
  double safe_ = 0;
};

/// A tetrahedron measured by `measure`, with what checking it against bounds
/// needs: by the largest angle, the measure is made of the cosines the bounds
/// check, so they are computed once (the moves' guard and the flips measure
/// every candidate tetrahedron so). The points must outlive it.
template <class Point>
class Measured_tet
{
public:
  Measured_tet(Quality_measure measure, const Point& p0, const Point& p1, const Point& p2, const Point& p3)
    : measure_(measure), p_{&p0, &p1, &p2, &p3}
  {
    quality_ = measure == Quality_measure::largest_dihedral_angle ? largest_angle_measure(p0, p1, p2, p3, cosines_)
                                                                  : tet_quality(measure, p0, p1, p2, p3);
  }

  double quality() const { return quality_; }

  /// Whether every dihedral angle is within `bounds` (`Dihedral_bounds::contains`).
  bool within(const Dihedral_bounds& bounds) const
  {
    if(measure_ == Quality_measure::largest_dihedral_angle && quality_ >= 0) return bounds.contains(cosines_, 0.0);
    return bounds.contains(*p_[0], *p_[1], *p_[2], *p_[3],
                           measure_ == Quality_measure::min_dihedral_sine ? quality_ : 0.0);
  }

private:
  Quality_measure measure_;
  std::array<const Point*, 4> p_;
  double quality_;
  std::array<double, 6> cosines_;   // set when the measure is the largest angle and the tetrahedron is positive
};

/// Compares two groups of tetrahedra by their qualities, worst first: sorted in
/// increasing order, the first value that differs decides. Returns 1 when `after`
/// is better, -1 when it is worse, 0 when they tie over the shorter group. Both
/// vectors are sorted in place.
inline int compare_worst_first(std::vector<double>& after, std::vector<double>& before)
{
  std::sort(after.begin(), after.end());
  std::sort(before.begin(), before.end());
  const std::size_t n = std::min(after.size(), before.size());
  for(std::size_t i = 0; i < n; ++i)
  {
    if(after[i] > before[i]) return 1;
    if(after[i] < before[i]) return -1;
  }
  return 0;
}

} // namespace internal
} // namespace BODT_3
} // namespace CGAL

#endif // CGAL_BODT_3_INTERNAL_QUALITY_TET_QUALITY_H
