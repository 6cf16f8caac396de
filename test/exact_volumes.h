// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Volumes in exact arithmetic, for the tests of the steps that must keep them
// (flips, moves): no rounding of the test's own can hide or fake a change.
#ifndef BODT_TEST_EXACT_VOLUMES_H
#define BODT_TEST_EXACT_VOLUMES_H

#include <CGAL/Exact_rational.h>

#include <array>
#include <map>
#include <vector>

namespace bodt_test {

using Exact = CGAL::Exact_rational;

/// Six times the signed volume of (o, a, b, c), exactly.
template <class Point>
Exact exact_det(const Point& o, const Point& a, const Point& b, const Point& c)
{
  const Exact ax = Exact(a.x()) - o.x(), ay = Exact(a.y()) - o.y(), az = Exact(a.z()) - o.z();
  const Exact bx = Exact(b.x()) - o.x(), by = Exact(b.y()) - o.y(), bz = Exact(b.z()) - o.z();
  const Exact cx = Exact(c.x()) - o.x(), cy = Exact(c.y()) - o.y(), cz = Exact(c.z()) - o.z();
  return ax * (by * cz - bz * cy) - ay * (bx * cz - bz * cx) + az * (bx * cy - by * cx);
}

/// The volume of each label's cells, exactly; cells with `in_mesh` 0 (when given) are left out.
template <class Point>
std::map<int, Exact> exact_volumes(const std::vector<Point>& points, const std::vector<std::array<int, 4>>& cells,
                                   const std::vector<int>& labels, const std::vector<char>& in_mesh = {})
{
  std::map<int, Exact> v;
  for(std::size_t t = 0; t < cells.size(); ++t)
  {
    if(!in_mesh.empty() && !in_mesh[t]) continue;
    const auto& q = cells[t];
    v[labels[t]] += exact_det(points[q[0]], points[q[1]], points[q[2]], points[q[3]]) / 6;
  }
  return v;
}

/// Whether every volume of `after` is within `relative` of the same label's in `before`, exactly.
inline bool volumes_within(const std::map<int, Exact>& before, const std::map<int, Exact>& after, double relative)
{
  if(before.size() != after.size()) return false;
  for(const auto& kv : before)
  {
    const auto it = after.find(kv.first);
    if(it == after.end()) return false;
    const Exact diff = it->second - kv.second;
    const Exact bound = Exact(relative) * (kv.second < 0 ? -kv.second : kv.second);
    if(diff > bound || -diff > bound) return false;
  }
  return true;
}

} // namespace bodt_test

#endif // BODT_TEST_EXACT_VOLUMES_H
