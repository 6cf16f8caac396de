// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_BODT_3_INTERNAL_QUALITY_DIHEDRAL_ANGLES_H
#define CGAL_BODT_3_INTERNAL_QUALITY_DIHEDRAL_ANGLES_H

#include <CGAL/Kernel/global_functions.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace CGAL {
namespace BODT_3 {
namespace internal {

constexpr double pi = 3.14159265358979323846;

/// The six dihedral angles of tetrahedron (p0, p1, p2, p3), in degrees, in the
/// edge order (01, 02, 03, 12, 13, 23). Each is measured with `atan2`, which stays
/// accurate near 0 and 180 degrees where `acos` loses digits. A flat tetrahedron
/// has angles of exactly 0 or 180.
template <class Point>
std::array<double, 6> dihedral_angles(const Point& p0, const Point& p1, const Point& p2, const Point& p3)
{
  const Point* p[4] = {&p0, &p1, &p2, &p3};
  // Area vector of the face opposite vertex k, oriented away from vertex k.
  std::array<std::array<double, 3>, 4> n;
  for(int k = 0; k < 4; ++k)
  {
    const Point& a = *p[(k + 1) % 4];
    const Point& b = *p[(k + 2) % 4];
    const Point& c = *p[(k + 3) % 4];
    const double ux = b.x() - a.x(), uy = b.y() - a.y(), uz = b.z() - a.z();
    const double vx = c.x() - a.x(), vy = c.y() - a.y(), vz = c.z() - a.z();
    std::array<double, 3> m = {uy * vz - uz * vy, uz * vx - ux * vz, ux * vy - uy * vx};
    const Point& o = *p[k];
    const double side = m[0] * (o.x() - a.x()) + m[1] * (o.y() - a.y()) + m[2] * (o.z() - a.z());
    if(side > 0) { m[0] = -m[0]; m[1] = -m[1]; m[2] = -m[2]; }
    n[k] = m;
  }
  // The dihedral angle at edge (i, j) is pi minus the angle between the outward
  // normals of the two faces that contain the edge, opposite k and l.
  static const int edges[6][4] = {{0, 1, 2, 3}, {0, 2, 1, 3}, {0, 3, 1, 2},
                                  {1, 2, 0, 3}, {1, 3, 0, 2}, {2, 3, 0, 1}};
  std::array<double, 6> angles;
  for(int e = 0; e < 6; ++e)
  {
    const auto& a = n[edges[e][2]];
    const auto& b = n[edges[e][3]];
    const double cx = a[1] * b[2] - a[2] * b[1];
    const double cy = a[2] * b[0] - a[0] * b[2];
    const double cz = a[0] * b[1] - a[1] * b[0];
    const double sin_part = std::sqrt(cx * cx + cy * cy + cz * cz);
    const double cos_part = -(a[0] * b[0] + a[1] * b[1] + a[2] * b[2]);
    angles[e] = std::atan2(sin_part, cos_part) * (180.0 / pi);
  }
  return angles;
}

/// Smallest and largest dihedral angle of a tetrahedron, in degrees.
template <class Point>
std::pair<double, double> min_max_dihedral_angle(const Point& p0, const Point& p1, const Point& p2,
                                                 const Point& p3)
{
  const auto a = dihedral_angles(p0, p1, p2, p3);
  const auto mm = std::minmax_element(a.begin(), a.end());
  return {*mm.first, *mm.second};
}

/// Radius ratio 3 r / R of a tetrahedron (1 for the regular tetrahedron, 0 for a
/// flat one), with r the inradius and R the circumradius.
template <class Point>
double radius_ratio(const Point& p0, const Point& p1, const Point& p2, const Point& p3)
{
  const double ax = p1.x() - p0.x(), ay = p1.y() - p0.y(), az = p1.z() - p0.z();
  const double bx = p2.x() - p0.x(), by = p2.y() - p0.y(), bz = p2.z() - p0.z();
  const double cx = p3.x() - p0.x(), cy = p3.y() - p0.y(), cz = p3.z() - p0.z();
  const double det = ax * (by * cz - bz * cy) - ay * (bx * cz - bz * cx) + az * (bx * cy - by * cx);
  const double volume = std::abs(det) / 6.0;
  if(volume == 0.0) return 0.0;
  auto tri_area = [](const Point& a, const Point& b, const Point& c) {
    const double ux = b.x() - a.x(), uy = b.y() - a.y(), uz = b.z() - a.z();
    const double vx = c.x() - a.x(), vy = c.y() - a.y(), vz = c.z() - a.z();
    const double x = uy * vz - uz * vy, y = uz * vx - ux * vz, z = ux * vy - uy * vx;
    return 0.5 * std::sqrt(x * x + y * y + z * z);
  };
  const double area = tri_area(p1, p2, p3) + tri_area(p0, p2, p3) + tri_area(p0, p1, p3) + tri_area(p0, p1, p2);
  const double inradius = 3.0 * volume / area;
  // Circumcenter offset from p0: (|a|^2 (b x c) + |b|^2 (c x a) + |c|^2 (a x b)) / (2 det).
  const double a2 = ax * ax + ay * ay + az * az, b2 = bx * bx + by * by + bz * bz, c2 = cx * cx + cy * cy + cz * cz;
  const double ox = a2 * (by * cz - bz * cy) + b2 * (cy * az - cz * ay) + c2 * (ay * bz - az * by);
  const double oy = a2 * (bz * cx - bx * cz) + b2 * (cz * ax - cx * az) + c2 * (az * bx - ax * bz);
  const double oz = a2 * (bx * cy - by * cx) + b2 * (cx * ay - cy * ax) + c2 * (ax * by - ay * bx);
  const double circumradius = std::sqrt(ox * ox + oy * oy + oz * oz) / (2.0 * std::abs(det));
  return 3.0 * inradius / circumradius;
}

} // namespace internal
} // namespace BODT_3
} // namespace CGAL

#endif // CGAL_BODT_3_INTERNAL_QUALITY_DIHEDRAL_ANGLES_H
