// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_BODT_3_INTERNAL_SMOOTHING_VOLUME_BUDGET_H
#define CGAL_BODT_3_INTERNAL_SMOOTHING_VOLUME_BUDGET_H

#include <CGAL/BODT_3/internal/Utilities/Thread_workers.h>
#include <CGAL/BODT_3/internal/Quality/tet_quality.h>

#include <CGAL/Interval_nt.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

namespace CGAL {
namespace BODT_3 {
namespace internal {

/// How much of its volume a subdomain may gain or lose over a whole run, relative.
/// Ten times below the promise of 1e-10, so that a volume measured in floating
/// point (the report's, a user's) still shows the promise kept.
constexpr double volume_tolerance = 1e-11;

/// The change of each subdomain's volume that one step makes (a vertex moved, a
/// point inserted), enclosed with interval arithmetic: a guaranteed bound for the
/// rounded double points the step really uses, whatever the mesh's scale.
/// Reused by one thread; `clear` before each step.
class Volume_change
{
public:
  using Interval = CGAL::Interval_nt_advanced;

  void clear() { parts_.clear(); }

  /// Moving x0 to p in the cell (x0, a, b, c) of `subdomain`, positively oriented:
  /// the volume is linear in x0, so the change is -(p - x0) . ((b - a) x (c - a)) / 6,
  /// computed from differences of nearby points (no digits lost to far coordinates).
  /// Call within a `CGAL::Protect_FPU_rounding<true>` scope.
  template <class Point>
  void add_move(int subdomain, const Point& x0, const Point& p, const Point& a, const Point& b, const Point& c)
  {
    const Interval d[3] = {diff(p, x0, 0), diff(p, x0, 1), diff(p, x0, 2)};
    const Interval u[3] = {diff(b, a, 0), diff(b, a, 1), diff(b, a, 2)};
    const Interval w[3] = {diff(c, a, 0), diff(c, a, 1), diff(c, a, 2)};
    const Interval n[3] = {u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]};
    part(subdomain) -= (d[0] * n[0] + d[1] * n[1] + d[2] * n[2]) / 6;
  }

  /// Adds `sign` times the volume of the cell (p0, p1, p2, p3) of `subdomain`.
  /// Call within a `CGAL::Protect_FPU_rounding<true>` scope.
  template <class Point>
  void add_cell(int subdomain, int sign, const Point& p0, const Point& p1, const Point& p2, const Point& p3)
  {
    const Interval a[3] = {diff(p1, p0, 0), diff(p1, p0, 1), diff(p1, p0, 2)};
    const Interval b[3] = {diff(p2, p0, 0), diff(p2, p0, 1), diff(p2, p0, 2)};
    const Interval c[3] = {diff(p3, p0, 0), diff(p3, p0, 1), diff(p3, p0, 2)};
    const Interval det = a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
                         a[2] * (b[0] * c[1] - b[1] * c[0]);
    part(subdomain) += (sign > 0 ? det : -det) / 6;
  }

  const std::vector<std::pair<int, Interval>>& parts() const { return parts_; }

private:
  template <class Point>
  static Interval diff(const Point& p, const Point& q, int i)
  {
    return Interval(p[i]) - Interval(q[i]);
  }

  Interval& part(int subdomain)
  {
    for(auto& [s, v] : parts_)
      if(s == subdomain) return v;
    parts_.emplace_back(subdomain, Interval(0));
    return parts_.back().second;
  }

  std::vector<std::pair<int, Interval>> parts_;
};

/// The volume promise as a budget: every subdomain may change by `volume_tolerance`
/// of its volume over the whole run. A step is charged its cost, the largest bound
/// of `Volume_change` over the subdomains it touches relative to their allowed
/// change; the costs spent so far add up to less than 1, so the promise holds
/// after any number of steps, with round-off counted at its worst (no cancellation
/// assumed). Each step may take half of what is left, shared between the steps
/// judged at once (a colour of a sweep): on ordinary meshes a step costs a
/// millionth or less and nothing is refused, while a step whose round-off is large
/// against its subdomain (a vertex 1e10 away from cells of size 1) is.
///
/// A default-constructed budget has no limit (NODT, which does not keep volume).
class Volume_budget
{
public:
  Volume_budget() = default;

  /// With the volume of every subdomain, by label.
  explicit Volume_budget(std::vector<std::pair<int, double>> volumes) : capacity_(std::move(volumes)), limited_(true)
  {
    std::sort(capacity_.begin(), capacity_.end());
    for(auto& [label, v] : capacity_) v = volume_tolerance * std::abs(v);
  }

  /// From the mesh cells of a `Flat_mesh`, summed on `threads` threads in
  /// blocks of cells added in block order (the same sums on any number of threads).
  template <class Mesh>
  static Volume_budget of(const Mesh& mesh, int threads = 1)
  {
    using Sums = std::vector<std::pair<int, double>>;
    auto add = [](Sums& sums, int label, double v) {
      auto it = std::find_if(sums.begin(), sums.end(), [&](const auto& x) { return x.first == label; });
      if(it == sums.end()) sums.emplace_back(label, v);
      else it->second += v;
    };
    std::vector<Sums> blocks(static_cast<std::size_t>(block_count(mesh.cells.size())));
    Thread_workers<char>(threads).for_blocks(mesh.cells.size(), [&](char&, int b, std::size_t begin, std::size_t end) {
      for(std::size_t c = begin; c < end; ++c)
      {
        if(!mesh.in_mesh[c]) continue;
        const auto& q = mesh.cells[c];
        add(blocks[static_cast<std::size_t>(b)], mesh.subdomain[c],
            tet_volume(mesh.points[q[0]], mesh.points[q[1]], mesh.points[q[2]], mesh.points[q[3]]));
      }
    });
    Sums volumes;
    for(const Sums& sums : blocks)
      for(const auto& [label, v] : sums) add(volumes, label, v);
    return Volume_budget(std::move(volumes));
  }

  bool limited() const { return limited_; }

  /// What one of `concurrent` steps judged together may cost.
  double allowance(std::size_t concurrent = 1) const { return allowance_at(spent_, concurrent); }

  /// What `allowance` would be with `spent` spent: for steps judged ahead and
  /// paid later (the max-min steps), checked against what was spent meanwhile.
  double allowance_at(double spent, std::size_t concurrent = 1) const
  {
    if(!limited_) return std::numeric_limits<double>::infinity();
    return 0.5 * (1 - spent) / static_cast<double>(std::max<std::size_t>(concurrent, 1));
  }

  /// The cost of a change: infinite for a subdomain the budget does not know.
  double cost(const Volume_change& change) const
  {
    double cost = 0;
    for(const auto& [label, dv] : change.parts())
    {
      const auto it = std::lower_bound(capacity_.begin(), capacity_.end(), std::pair<int, double>(label, -1.0));
      const double bound = std::max(std::abs(dv.inf()), std::abs(dv.sup()));
      if(bound == 0) continue;
      if(it == capacity_.end() || it->first != label || !(it->second > 0))
        return std::numeric_limits<double>::infinity();
      cost = std::max(cost, bound / it->second);
    }
    return cost;
  }

  void spend(double cost) { spent_ += cost; }

  /// The fraction of the budget spent so far.
  double spent() const { return spent_; }

private:
  std::vector<std::pair<int, double>> capacity_;   // label, allowed change; sorted by label
  double spent_ = 0;
  bool limited_ = false;
};

} // namespace internal
} // namespace BODT_3
} // namespace CGAL

#endif // CGAL_BODT_3_INTERNAL_SMOOTHING_VOLUME_BUDGET_H
