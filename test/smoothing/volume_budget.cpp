// The volume promise whatever the coordinates: Volume_change encloses the exact
// change of a step, the budget never runs out, and a mesh far from the origin,
// where rounding a new position changes volumes by far more than the promise,
// keeps every subdomain's volume to 1e-10 in exact arithmetic.
#include "test_support.h"

#include <CGAL/BODT_3/internal/Smoothing/Volume_budget.h>
#include <CGAL/BODT_3/smooth.h>
#include <CGAL/Exact_rational.h>
#include <CGAL/FPU.h>
#include <CGAL/Random.h>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <map>

namespace BODT = CGAL::BODT_3;
using K = BODT::Tet_mesh::Kernel;
using Point = K::Point_3;
using Exact = CGAL::Exact_rational;

namespace {

Exact exact_det(const Point& o, const Point& a, const Point& b, const Point& c)
{
  const Exact ax = Exact(a.x()) - o.x(), ay = Exact(a.y()) - o.y(), az = Exact(a.z()) - o.z();
  const Exact bx = Exact(b.x()) - o.x(), by = Exact(b.y()) - o.y(), bz = Exact(b.z()) - o.z();
  const Exact cx = Exact(c.x()) - o.x(), cy = Exact(c.y()) - o.y(), cz = Exact(c.z()) - o.z();
  return ax * (by * cz - bz * cy) - ay * (bx * cz - bz * cx) + az * (bx * cy - by * cx);
}

bool encloses(const BODT::internal::Volume_change::Interval& i, const Exact& x)
{
  return Exact(i.inf()) <= x && x <= Exact(i.sup());
}

// Every subdomain's volume, exactly.
std::map<int, Exact> exact_volumes(const BODT::Tet_mesh& m)
{
  std::map<int, Exact> v;
  for(std::size_t t = 0; t < m.tets.size(); ++t)
  {
    const auto& q = m.tets[t];
    v[m.tet_labels[t]] += exact_det(m.points[q[0]], m.points[q[1]], m.points[q[2]], m.points[q[3]]) / 6;
  }
  return v;
}

} // namespace

TEST(VolumeChange, EnclosesTheExactChangeTightlyAtAnyScaleAndOffset)
{
  CGAL::Random rng(11);
  for(int trial = 0; trial < 2000; ++trial)
  {
    const double scale = std::pow(10.0, rng.get_int(-15, 16));
    const double offset = scale * std::pow(10.0, rng.get_int(0, 13));
    auto random_point = [&] {
      return Point(offset + scale * rng.get_double(-1, 1), offset + scale * rng.get_double(-1, 1),
                   scale * rng.get_double(-1, 1));
    };
    const Point x0 = random_point(), a = random_point(), b = random_point(), c = random_point();
    const Point p = x0 + scale * 1e-3 * K::Vector_3(rng.get_double(-1, 1), rng.get_double(-1, 1), rng.get_double(-1, 1));
    BODT::internal::Volume_change change;
    {
      CGAL::Protect_FPU_rounding<true> upward;
      change.add_move(3, x0, p, a, b, c);
      change.add_cell(5, 1, p, a, b, c);
      change.add_cell(5, -1, x0, a, b, c);
    }
    const Exact exact = (exact_det(p, a, b, c) - exact_det(x0, a, b, c)) / 6;
    ASSERT_EQ(change.parts().size(), 2u);
    EXPECT_TRUE(encloses(change.parts()[0].second, exact)) << "move, trial " << trial;
    EXPECT_TRUE(encloses(change.parts()[1].second, exact)) << "cells, trial " << trial;
    // No digit lost to the offset: the move's bound is as tight as the move is small.
    const double move = std::sqrt((p - x0).squared_length());
    const auto& i = change.parts()[0].second;
    EXPECT_LE(i.sup() - i.inf(), 1e-14 * move * scale * scale) << "trial " << trial;
  }
}

TEST(VolumeBudget, CostIsTheWorstSubdomainsShareAndTheBudgetNeverRunsOut)
{
  BODT::internal::Volume_budget budget({{1, 6.0}, {2, 600.0}});
  BODT::internal::Volume_change change;
  {
    CGAL::Protect_FPU_rounding<true> upward;
    // Subdomain 1 gains 3e-11 (half its allowed 6e-11), subdomain 2 loses 6e-11 (a hundredth).
    change.add_cell(1, 1, Point(0, 0, 0), Point(3e-11, 0, 0), Point(0, 6, 0), Point(0, 0, 1));
    change.add_cell(2, -1, Point(0, 0, 0), Point(6e-11, 0, 0), Point(0, 6, 0), Point(0, 0, 1));
  }
  EXPECT_NEAR(budget.cost(change), 0.5, 1e-12);
  BODT::internal::Volume_change unknown;
  {
    CGAL::Protect_FPU_rounding<true> upward;
    unknown.add_cell(7, 1, Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0), Point(0, 0, 1));
  }
  EXPECT_EQ(budget.cost(unknown), std::numeric_limits<double>::infinity());
  // Steps that each take all they may, one at a time or a colour at a time.
  for(int step = 0; step < 200; ++step)
  {
    const std::size_t together = step % 3 == 0 ? 1000 : 1;
    const double allowance = budget.allowance(together);
    for(std::size_t k = 0; k < together; ++k) budget.spend(allowance);
    ASSERT_LE(budget.spent(), 1) << "step " << step;
  }
}

// A two-subdomain box with curved boundary and interface, 1e8 away from the
// origin: rounding a boundary vertex's new position to a double there changes its
// star's volume by about 1e-8 of a cell, a thousand times the promise for the
// subdomain. Such moves are refused; interior vertices, which keep their volume
// exactly, still move.
TEST(Volume, KeptInExactArithmeticFarFromTheOrigin)
{
  BODT::Tet_mesh m = bodt_test::cube_grid(4, [](int i, int, int) { return i < 2 ? 1 : 2; });
  CGAL::Random rng(7);
  for(auto& p : m.points)
    p = Point(1e8 + p.x() + rng.get_double(-0.15, 0.15), p.y() + rng.get_double(-0.15, 0.15),
              p.z() + rng.get_double(-0.15, 0.15));
  for(const auto& t : m.tets)
    ASSERT_EQ(CGAL::orientation(m.points[t[0]], m.points[t[1]], m.points[t[2]], m.points[t[3]]), CGAL::POSITIVE);
  const BODT::Tet_mesh input = m;
  const auto before = exact_volumes(m);
  BODT::Smoothing_options opt;
  opt.max_iteration_number = 5;
  BODT::smooth(m, opt);
  const auto after = exact_volumes(m);
  ASSERT_EQ(after.size(), before.size());
  for(const auto& [label, volume] : before)
  {
    const Exact change = (after.at(label) - volume) / volume;
    EXPECT_LE(std::abs(CGAL::to_double(change)), 1e-10) << "subdomain " << label;
  }
  std::size_t moved = 0;
  for(std::size_t i = 0; i < input.points.size(); ++i) moved += m.points[i] != input.points[i];
  EXPECT_GT(moved, 0u);
}
