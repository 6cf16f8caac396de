// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The smoothing steps called directly, on constructed grids: the move guard
// (validity by CGAL's exact orientation against an exact oracle, shorter steps,
// the quality guard, the volume budget), the smoothing sweep (validity, volume to
// 1e-12, labels and fixed vertices kept, the worst cell never worse, quality raised,
// the same bits on any number of threads), and local smoothing on a triangulation
// (validity, exact volume, the star's worst cell raised, fixed vertices stay).
#include "c3t3_checks.h"
#include "exact_volumes.h"
#include "test_support.h"

#include <CGAL/BODT_3/Tet_mesh_conversion.h>
#include <CGAL/BODT_3/internal/Classification/Tensor_voting.h>
#include <CGAL/BODT_3/internal/Classification/Vertex_classification.h>
#include <CGAL/BODT_3/internal/Mesh/Triangulation_adapter.h>
#include <CGAL/BODT_3/internal/Quality/tet_quality.h>
#include <CGAL/BODT_3/internal/Smoothing/Boundary_distance_guard.h>
#include <CGAL/BODT_3/internal/Smoothing/Local_smoothing.h>
#include <CGAL/BODT_3/internal/Smoothing/Move_guard.h>
#include <CGAL/BODT_3/internal/Moves/Volume_preserving_move.h>
#include <CGAL/BODT_3/internal/Smoothing/Smoothing_sweep.h>
#include <CGAL/BODT_3/internal/Smoothing/Volume_budget.h>
#include <CGAL/Random.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iostream>
#include <limits>
#include <map>
#include <vector>

namespace BODT = CGAL::BODT_3;
namespace BI = CGAL::BODT_3::internal;
using K = BODT::Tet_mesh::Kernel;
using Point = K::Point_3;
using Vector = K::Vector_3;
using Flat_mesh = BI::Flat_mesh<K>;
using Guard = BI::Move_guard<K>;
using bodt_test::Exact;

namespace {

Flat_mesh flat_mesh_of(const BODT::Tet_mesh& m)
{
  Flat_mesh s;
  s.points = m.points;
  s.cells = m.tets;
  s.in_mesh.assign(m.tets.size(), 1);
  s.subdomain = m.tet_labels;
  s.build_incidences();
  return s;
}

int one_label(int, int, int) { return 1; }
int two_labels(int i, int, int) { return i == 0 ? 1 : 2; }   // an interface at x = 1

// cube_grid(n) with its interior points moved by up to `jitter` (seeded); points of
// the interface x = 1 (when `keep_interface`) stay on it.
BODT::Tet_mesh jittered(int n, int (*label)(int, int, int), double jitter, bool keep_interface = true)
{
  BODT::Tet_mesh m = bodt_test::cube_grid(n, label);
  CGAL::Random rng(17);
  for(auto& p : m.points)
  {
    if(p.x() == 0 || p.y() == 0 || p.z() == 0 || p.x() == n || p.y() == n || p.z() == n) continue;
    const double dx = (keep_interface && p.x() == 1) ? 0 : rng.get_double(-jitter, jitter);
    p = Point(p.x() + dx, p.y() + rng.get_double(-jitter, jitter), p.z() + rng.get_double(-jitter, jitter));
  }
  return m;
}

// Whether v may go to p, decided independently of the guard: every cell of v, with
// v at p, has a positive determinant in exact arithmetic.
bool valid_position(const Flat_mesh& s, int v, const Point& p)
{
  for(const auto& c : s.cells)
  {
    if(std::find(c.begin(), c.end(), v) == c.end()) continue;
    Point q[4];
    for(int k = 0; k < 4; ++k) q[k] = c[k] == v ? p : s.points[c[k]];
    if(!(bodt_test::exact_det(q[0], q[1], q[2], q[3]) > 0)) return false;
  }
  return true;
}

double worst_of(const Flat_mesh& s, int v = -1)
{
  double worst = 2;
  for(const auto& c : s.cells)
    if(v < 0 || std::find(c.begin(), c.end(), v) != c.end())
      worst = std::min(worst, BI::min_dihedral_sine(s.points[c[0]], s.points[c[1]], s.points[c[2]], s.points[c[3]]));
  return worst;
}

double mean_of(const Flat_mesh& s)
{
  double sum = 0;
  for(const auto& c : s.cells)
    sum += BI::min_dihedral_sine(s.points[c[0]], s.points[c[1]], s.points[c[2]], s.points[c[3]]);
  return sum / s.cells.size();
}

std::size_t not_positive(const Flat_mesh& s)
{
  std::size_t bad = 0;
  for(const auto& c : s.cells)
    if(CGAL::orientation(s.points[c[0]], s.points[c[1]], s.points[c[2]], s.points[c[3]]) != CGAL::POSITIVE) ++bad;
  return bad;
}

std::map<int, Exact> volumes(const Flat_mesh& s) { return bodt_test::exact_volumes(s.points, s.cells, s.subdomain); }

BI::Dihedral_bounds extreme_angles(const Flat_mesh& s)
{
  BI::Dihedral_bounds b = BI::Dihedral_bounds::empty();
  for(const auto& c : s.cells) b.include(s.points[c[0]], s.points[c[1]], s.points[c[2]], s.points[c[3]]);
  return b;
}

} // namespace

// The guard accepts a position exactly when every cell of the vertex stays
// positively oriented in exact arithmetic: random positions, and positions on a
// half-integer lattice, many of them exactly on the plane of a face of the star.
TEST(MoveGuard, DecidesValidityByExactOrientation)
{
  Flat_mesh s = flat_mesh_of(bodt_test::cube_grid(2, one_label));
  const int v = bodt_test::grid_index(2, 1, 1, 1);
  Guard guard(s, false, BI::Dihedral_bounds());
  Guard::Trial trial;
  CGAL::Random rng(3);
  int accepted = 0, refused = 0, degenerate = 0;
  for(int t = 0; t < 3000; ++t)
  {
    Point p;
    if(t % 2)
      p = Point(rng.get_double(0, 2), rng.get_double(0, 2), rng.get_double(0, 2));
    else
      p = Point(0.5 * rng.get_int(0, 5), 0.5 * rng.get_int(0, 5), 0.5 * rng.get_int(0, 5));
    const bool expected = valid_position(s, v, p);
    ASSERT_EQ(guard.accepts(v, p, trial), expected) << "position " << p;
    if(!expected)
    {
      EXPECT_EQ(trial.last_refusal, Guard::Refusal::inverts_mesh_cell);
      ++refused;
    }
    else
      ++accepted;
    for(const auto& c : s.cells)
      if(std::find(c.begin(), c.end(), v) != c.end())
      {
        Point q[4];
        for(int k = 0; k < 4; ++k) q[k] = c[k] == v ? p : s.points[c[k]];
        if(CGAL::orientation(q[0], q[1], q[2], q[3]) == CGAL::COPLANAR)
        {
          ++degenerate;
          break;
        }
      }
  }
  EXPECT_GT(accepted, 100);
  EXPECT_GT(refused, 100);
  EXPECT_GT(degenerate, 50);
  EXPECT_EQ(s.points[v], Point(1, 1, 1));   // accepts() alone moves nothing
}

// A refused move is tried at 1/2, 1/4, 1/8 of its length: the guard applies the
// longest valid one (the exact oracle's), to the bit, or none.
TEST(MoveGuard, ShortensARefusedMoveByHalves)
{
  const int v = bodt_test::grid_index(2, 1, 1, 1);
  int shortened = 0, none = 0;
  CGAL::Random rng(5);
  for(int t = 0; t < 200; ++t)
  {
    Flat_mesh s = flat_mesh_of(bodt_test::cube_grid(2, one_label));
    Guard guard(s, false, BI::Dihedral_bounds());
    Guard::Trial trial;
    const double length = rng.get_double(0.2, 12.0);
    Vector X(rng.get_double(-1, 1), rng.get_double(-1, 1), rng.get_double(-1, 1));
    X = X * (length / std::sqrt(X.squared_length()));
    const Point x0 = s.points[v];
    double expected = 0;
    for(double f = 1; f >= 0.125; f *= 0.5)
      if(valid_position(s, v, x0 + f * X))
      {
        expected = f;
        break;
      }
    const double got = guard.move(v, X, trial);
    ASSERT_EQ(got, expected) << "move " << X;
    EXPECT_EQ(s.points[v], expected > 0 ? x0 + expected * X : x0);
    if(expected < 1) { EXPECT_EQ(trial.first_refusal, Guard::Refusal::inverts_mesh_cell); }
    shortened += expected > 0 && expected < 1;
    none += expected == 0;
    EXPECT_EQ(not_positive(s), 0u);
  }
  EXPECT_GT(shortened, 10);
  EXPECT_GT(none, 10);
}

// With the quality guard, no accepted move makes the star's worst cell worse or
// leaves the extreme angles of the input; the cell qualities the guard keeps are
// those of the cells now; moves that would worsen the star are refused as such.
TEST(MoveGuard, QualityGuardNeverWorsensTheStar)
{
  Flat_mesh s = flat_mesh_of(jittered(3, one_label, 0.2));
  ASSERT_EQ(not_positive(s), 0u);
  const BI::Dihedral_bounds bounds = extreme_angles(s);
  Guard guard(s, true, bounds);
  Guard::Trial trial;
  CGAL::Random rng(9);
  int moved = 0, worsening = 0;
  const double mesh_worst = worst_of(s);
  for(int t = 0; t < 400; ++t)
  {
    const int v = bodt_test::grid_index(3, 1 + rng.get_int(0, 2), 1 + rng.get_int(0, 2), 1 + rng.get_int(0, 2));
    const Vector X(rng.get_double(-0.3, 0.3), rng.get_double(-0.3, 0.3), rng.get_double(-0.3, 0.3));
    const double before = worst_of(s, v);
    EXPECT_NEAR(guard.worst_around(v), before, 1e-12);
    const Point x0 = s.points[v];
    const double f = guard.move(v, X, trial);
    if(f > 0)
    {
      ++moved;
      EXPECT_GE(worst_of(s, v), before - 1e-12);
      EXPECT_TRUE(valid_position(s, v, s.points[v]));
      for(std::size_t c = 0; c < s.cells.size(); ++c)
      {
        const auto& q = s.cells[c];
        if(std::find(q.begin(), q.end(), v) == q.end()) continue;
        EXPECT_NEAR(guard.cell_quality(static_cast<int>(c)),
                  BI::min_dihedral_sine(s.points[q[0]], s.points[q[1]], s.points[q[2]], s.points[q[3]]), 1e-12);
        EXPECT_TRUE(bounds.contains(s.points[q[0]], s.points[q[1]], s.points[q[2]], s.points[q[3]],
                                    guard.cell_quality(static_cast<int>(c))));
      }
    }
    else
      EXPECT_EQ(s.points[v], x0);
    if(f < 1 && trial.first_refusal == Guard::Refusal::worsens_quality) ++worsening;
  }
  EXPECT_GT(moved, 20);
  EXPECT_GT(worsening, 20);
  EXPECT_GE(worst_of(s), mesh_worst);
  EXPECT_EQ(not_positive(s), 0u);
}

// With a budget: a vertex inside one subdomain keeps the volumes exactly and is
// not priced; a vertex of the interface x = 1 may slide in it (the volumes stay
// within 1e-12, exactly) but not leave it (refused as a volume change).
TEST(MoveGuard, VolumeBudgetPricesOnlyMovesThatMayChangeAVolume)
{
  Flat_mesh s = flat_mesh_of(bodt_test::cube_grid(3, two_labels));
  const BI::Volume_budget budget = BI::Volume_budget::of(s);
  ASSERT_TRUE(budget.limited());
  Guard guard(s, false, BI::Dihedral_bounds(), BODT::Quality_measure::min_dihedral_sine, 1, &budget);
  Guard::Trial trial;
  const int inner = bodt_test::grid_index(3, 2, 1, 2), on_interface = bodt_test::grid_index(3, 1, 2, 1);
  EXPECT_TRUE(guard.keeps_volume(inner));
  EXPECT_FALSE(guard.keeps_volume(on_interface));
  const auto before = volumes(s);

  EXPECT_EQ(guard.move(inner, Vector(0.13, -0.21, 0.17), trial), 1.0);
  EXPECT_EQ(trial.cost, 0);
  EXPECT_TRUE(volumes(s) == before) << "an interior vertex changed a volume";

  const Point x0 = s.points[on_interface];
  EXPECT_EQ(guard.move(on_interface, Vector(0.2, 0.05, -0.1), trial), 0.0);
  EXPECT_EQ(trial.first_refusal, Guard::Refusal::changes_volume);
  EXPECT_EQ(s.points[on_interface], x0);

  EXPECT_EQ(guard.move(on_interface, Vector(0, 0.15, -0.1), trial), 1.0);
  EXPECT_LE(trial.cost, budget.allowance());
  EXPECT_EQ(s.points[on_interface].x(), 1.0);
  EXPECT_TRUE(bodt_test::volumes_within(before, volumes(s), 1e-12));
  EXPECT_TRUE(volumes(s) == before) << "a slide within a planar interface is exact";
  EXPECT_EQ(not_positive(s), 0u);
}

namespace {

struct Sweep_run
{
  Flat_mesh mesh;
  BI::Vertex_classification classification;
  std::size_t moved = 0;
  double spent = 0;   // of the volume budget
};

// `sweeps` sweeps over the jittered two-subdomain grid, its interface jittered too
// (moved by `offset`), on `threads` threads.
Flat_mesh sweep_input(double offset)
{
  BODT::Tet_mesh m = jittered(4, two_labels, 0.2, false);   // a curved interface
  for(auto& p : m.points) p = Point(p.x() + offset, p.y() + offset, p.z() + offset);
  return flat_mesh_of(m);
}

Sweep_run run_sweeps(int sweeps, int threads, double offset = 0)
{
  Sweep_run r{sweep_input(offset), {}, 0, 0};
  r.classification = BI::classify_vertices(r.mesh, BI::Feature_hints(), BI::Classification_options());
  BODT::Smoothing_options opt;
  opt.threads = threads;
  BI::Volume_budget budget = BI::Volume_budget::of(r.mesh, threads);
  BI::Smoothing_sweep<K> sweep(r.mesh, r.classification, opt, extreme_angles(r.mesh), &budget);
  for(int k = 0; k < sweeps; ++k)
  {
    BODT::Iteration_stats stats;
    sweep.run(stats);
    r.moved += stats.moved;
  }
  r.spent = budget.spent();
  return r;
}

} // namespace

// Sweeps over a jittered grid of two subdomains (a curved interface): every cell
// stays positively oriented (exact), every subdomain keeps its volume to 1e-12
// (exact arithmetic), the budget is charged for the moves that may change it,
// labels and fixed vertices stay, the worst cell is never worse and the mean
// quality rises.
TEST(SmoothingSweep, KeepsValidityVolumeAndLabelsAndRaisesQuality)
{
  const Flat_mesh input = sweep_input(0);
  ASSERT_EQ(not_positive(input), 0u);
  const Sweep_run r = run_sweeps(5, 1);
  EXPECT_GT(r.moved, 20u);
  // The interface's and the boundary's vertices moved, and paid for it, within the budget.
  EXPECT_GT(r.spent, 0.0);
  EXPECT_LT(r.spent, 1.0);
  EXPECT_EQ(not_positive(r.mesh), 0u);
  EXPECT_TRUE(bodt_test::volumes_within(volumes(input), volumes(r.mesh), 1e-12));
  EXPECT_EQ(r.mesh.subdomain, input.subdomain);
  EXPECT_EQ(r.mesh.cells, input.cells);
  std::size_t fixed = 0;
  for(std::size_t v = 0; v < input.points.size(); ++v)
    if(r.classification.kind[v] == BI::Vertex_kind::fixed)
    {
      ++fixed;
      EXPECT_EQ(r.mesh.points[v], input.points[v]) << "fixed vertex " << v;
    }
  EXPECT_GE(fixed, 8u);   // the box's corners at least
  EXPECT_GE(worst_of(r.mesh), worst_of(input));
  EXPECT_GT(mean_of(r.mesh), mean_of(input) + 0.01);
  // Every mesh cell within the input's extreme angles.
  const BI::Dihedral_bounds bounds = extreme_angles(input);
  for(const auto& c : r.mesh.cells)
  {
    const auto& p = r.mesh.points;
    const double q = BI::min_dihedral_sine(p[c[0]], p[c[1]], p[c[2]], p[c[3]]);
    EXPECT_TRUE(bounds.contains(p[c[0]], p[c[1]], p[c[2]], p[c[3]], q));
  }
}

// Far from the origin (1e7), rounding a new position on the curved interface
// changes volumes by far more than the promise: the sweep's moves are priced and
// refused when the budget cannot pay, so every subdomain keeps its volume within
// the budget's 1e-11 (exact arithmetic; without the budget's allowance, 1e-9).
TEST(SmoothingSweep, FarFromTheOriginTheBudgetKeepsTheVolume)
{
  const double offset = 1e7;
  const Flat_mesh input = sweep_input(offset);
  ASSERT_EQ(not_positive(input), 0u);
  const Sweep_run r = run_sweeps(5, 1, offset);
  EXPECT_GT(r.moved, 10u);
  EXPECT_EQ(not_positive(r.mesh), 0u);
  EXPECT_LT(r.spent, 1.0);
  EXPECT_TRUE(bodt_test::volumes_within(volumes(input), volumes(r.mesh), 1e-11));
}

// Vertices of one colour move concurrently: the same bits on one and two threads.
TEST(SmoothingSweep, SameBitsOnAnyNumberOfThreads)
{
  const Sweep_run one = run_sweeps(3, 1), two = run_sweeps(3, 2);
  EXPECT_EQ(one.moved, two.moved);
  EXPECT_EQ(one.mesh.points, two.mesh.points);
}

namespace {

struct Max_min_run
{
  Flat_mesh mesh;
  std::size_t moves = 0;
  double spent = 0;
  std::size_t searches = 0;   // vertices searched, over all passes
};

// The volume budget of `mesh`, as if each subdomain's volume were `scale` times
// what it is: below 1, each step takes a larger share of it.
BI::Volume_budget scaled_budget(const Flat_mesh& mesh, double scale)
{
  std::map<int, double> volume;
  for(std::size_t c = 0; c < mesh.cells.size(); ++c)
  {
    const auto& q = mesh.cells[c];
    volume[mesh.subdomain[c]] += scale * CGAL::volume(mesh.points[q[0]], mesh.points[q[1]], mesh.points[q[2]], mesh.points[q[3]]);
  }
  return BI::Volume_budget(std::vector<std::pair<int, double>>(volume.begin(), volume.end()));
}

// The max-min steps of every vertex of the input of `run_sweeps`, through
// `Smoothing_sweep::raise_worst` (searches judged ahead in blocks, on `threads`
// threads), `passes` times.
Max_min_run max_min_by_sweep(double offset, double scale, int threads, int passes = 1)
{
  Max_min_run r{sweep_input(offset)};
  const BI::Vertex_classification classification =
      BI::classify_vertices(r.mesh, BI::Feature_hints(), BI::Classification_options());
  BODT::Smoothing_options opt;
  opt.threads = threads;
  BI::Volume_budget budget = scaled_budget(r.mesh, scale);
  BI::Smoothing_sweep<K> sweep(r.mesh, classification, opt, extreme_angles(r.mesh), &budget);
  for(int pass = 0; pass < passes; ++pass)
  {
    BODT::Iteration_stats stats;
    sweep.raise_worst(1.0, stats);
    r.moves += stats.max_min_moves;
    r.searches += stats.max_min_searches;
  }
  r.spent = budget.spent();
  return r;
}

void max_min_pass(Flat_mesh& mesh, const BI::Vertex_classification& classification, Guard& guard,
                  BI::Volume_budget& budget, Max_min_run& r);

// The same steps one vertex after another, each on the mesh as the ones before
// left it, through the guard's own `accepts` and `apply`: the compass search as it
// was first written, before its searches were judged ahead, every vertex
// searched in every pass.
Max_min_run max_min_one_by_one(double offset, double scale, int passes = 1)
{
  Max_min_run r{sweep_input(offset)};
  Flat_mesh& mesh = r.mesh;
  const BI::Vertex_classification classification =
      BI::classify_vertices(mesh, BI::Feature_hints(), BI::Classification_options());
  const BODT::Smoothing_options opt;
  BI::Volume_budget budget = scaled_budget(mesh, scale);
  Guard guard(mesh, true, extreme_angles(mesh), opt.quality_measure, 1, &budget);
  for(int pass = 0; pass < passes; ++pass)
    max_min_pass(mesh, classification, guard, budget, r);
  r.spent = budget.spent();
  return r;
}

void max_min_pass(Flat_mesh& mesh, const BI::Vertex_classification& classification, Guard& guard,
                  BI::Volume_budget& budget, Max_min_run& r)
{
  const BODT::Smoothing_options opt;
  std::vector<int> vertices;
  for(std::size_t c = 0; c < mesh.cells.size(); ++c)
    if(mesh.in_mesh[c] && guard.cell_quality(static_cast<int>(c)) < 1.0)
      vertices.insert(vertices.end(), mesh.cells[c].begin(), mesh.cells[c].end());
  std::sort(vertices.begin(), vertices.end());
  vertices.erase(std::unique(vertices.begin(), vertices.end()), vertices.end());
  const BI::Volume_preserving_move mover;
  BI::Vertex_star<K> star;
  Guard::Trial trial, best_trial;
  for(int v : vertices)
  {
    const BI::Vertex_kind kind = classification.kind[v];
    if(kind == BI::Vertex_kind::fixed) continue;
    ++r.searches;
    mesh.gather_star(v, star);
    Vector feature(0, 0, 0);
    if(kind == BI::Vertex_kind::feature)
    {
      const auto& nb = classification.curve_neighbors[v];
      feature = nb[0] >= 0 ? mesh.points[nb[1]] - mesh.points[nb[0]] : BI::tensor_vote(star, opt.tensor_voting).direction;
    }
    Vector dirs[3];
    const int n = mover.free_directions(star, kind, feature, dirs);
    if(n == 0) continue;
    double shortest = std::numeric_limits<double>::infinity();
    for(const auto& c : star.cells)
      for(const Point* p : {&c.a, &c.b, &c.c}) shortest = std::min(shortest, CGAL::squared_distance(star.x0, *p));
    shortest = std::sqrt(shortest);
    double worst = guard.worst_around(v);
    bool moved = false;
    int steps = 0;
    for(double h = 0.2 * shortest; h > 1e-3 * shortest && steps < 200; ++steps)
    {
      Point best;
      double best_worst = worst;
      for(int d = 0; d < n; ++d)
        for(double sign : {1.0, -1.0})
        {
          const Point p = mesh.points[v] + (sign * h) * dirs[d];
          guard.allow(budget.allowance());
          if(guard.accepts(v, p, trial) && Guard::accepted_worst(trial) > best_worst)
          {
            best_worst = Guard::accepted_worst(trial);
            best = p;
            std::swap(best_trial, trial);
          }
        }
      if(best_worst > worst)
      {
        guard.apply(v, best, best_trial);
        budget.spend(best_trial.cost);
        worst = best_worst;
        moved = true;
      }
      else
        h *= 0.5;
    }
    r.moves += moved;
  }
}

} // namespace

// The max-min steps judge blocks of vertices ahead, concurrently, and apply each
// search in order only if nothing it read changed since (a vertex it depends on
// moved, or the budget shrank below a step it took), else make it again: the same
// bits as one vertex after another, on 1, 2 and 4 threads. On a curved interface
// whose moves the budget pays; 1e7 from the origin; and with budgets 1e5 and 1e7
// times smaller, nearly spent by the steps, where the budget's check decides
// (without it the one-by-one results differ there).
TEST(SmoothingSweep, MaxMinStepsAreTheOneByOneStepsOnAnyNumberOfThreads)
{
  for(double offset : {0.0, 1e7})
    for(double scale : {1.0, 1e-5, 1e-7})
    {
      const Max_min_run reference = max_min_one_by_one(offset, scale);
      EXPECT_GT(reference.moves, 20u) << offset << " " << scale;
      EXPECT_GT(reference.spent, 0.0) << offset << " " << scale;
      EXPECT_LT(reference.spent, 1.0) << offset << " " << scale;
      EXPECT_EQ(not_positive(reference.mesh), 0u);
      for(int threads : {1, 2, 4})
      {
        const Max_min_run r = max_min_by_sweep(offset, scale, threads);
        EXPECT_EQ(r.moves, reference.moves) << offset << " " << scale << ", " << threads << " threads";
        EXPECT_EQ(r.spent, reference.spent) << offset << " " << scale << ", " << threads << " threads";
        EXPECT_EQ(r.mesh.points, reference.mesh.points) << offset << " " << scale << ", " << threads << " threads";
      }
    }
}

// Passes of max-min steps one after the other, as the worst-cell phase makes
// them: a vertex whose search found no step is not searched again until a vertex
// its search depends on moves, and that changes no bit: the same positions,
// steps and budget as every vertex searched in every pass, on 1 and 2 threads.
// With an ample budget every pass still moves most vertices of this small grid,
// which wakes the others; with a budget nearly spent, most searches are skipped.
TEST(SmoothingSweep, RepeatedMaxMinPassesSearchOnlyWhereSomethingChanged)
{
  constexpr int passes = 12;
  for(double scale : {1.0, 1e-5})
  {
    const Max_min_run reference = max_min_one_by_one(0, scale, passes);
    const Max_min_run first = max_min_one_by_one(0, scale, 1);
    EXPECT_GT(reference.moves, first.moves + 20) << scale;   // the later passes move vertices too
    for(int threads : {1, 2})
    {
      const Max_min_run r = max_min_by_sweep(0, scale, threads, passes);
      EXPECT_EQ(r.moves, reference.moves) << scale << ", " << threads << " threads";
      EXPECT_EQ(r.spent, reference.spent) << scale << ", " << threads << " threads";
      EXPECT_EQ(r.mesh.points, reference.mesh.points) << scale << ", " << threads << " threads";
      if(scale < 1) EXPECT_LT(r.searches, reference.searches * 3 / 4) << scale << ", " << threads << " threads";
    }
  }
}

namespace {

using File_c3t3 = bodt_test::File_c3t3;
using Adapter = BI::C3t3_adapter<File_c3t3>;
using Vertex_handle = File_c3t3::Vertex_handle;
using bodt_test::bare;
using bodt_test::exact_subdomain_volumes;

double star_worst(const File_c3t3& c3t3, Vertex_handle v)
{
  std::vector<File_c3t3::Cell_handle> cells;
  c3t3.triangulation().finite_incident_cells(v, std::back_inserter(cells));
  double worst = 2;
  for(const auto& c : cells)
    if(c3t3.is_in_complex(c))
      worst = std::min(worst, BI::min_dihedral_sine(bare(c3t3, c->vertex(0)), bare(c3t3, c->vertex(1)),
                                                    bare(c3t3, c->vertex(2)), bare(c3t3, c->vertex(3))));
  return worst;
}

} // namespace

// The interior vertex of a 2 x 2 x 2 grid, pushed off its place: its local move on
// the triangulation brings it back towards it, raising its star's worst cell,
// keeping the volume exactly and every cell positively oriented; a fixed vertex stays.
TEST(LocalSmoothing, InteriorMoveRaisesTheStarAndKeepsTheVolumeExactly)
{
  BODT::Tet_mesh m = bodt_test::cube_grid(2, one_label);
  const int centre = bodt_test::grid_index(2, 1, 1, 1);
  m.points[centre] = Point(0.82, 0.9, 1.14);
  File_c3t3 c3t3;
  std::vector<Vertex_handle> handles;
  BODT::tet_mesh_to_c3t3(m, c3t3, "test", &handles);
  bodt_test::expect_valid(c3t3);
  Adapter adapter(c3t3, false);
  BI::Local_smoothing<Adapter> smoothing(adapter, BI::Dihedral_bounds(), BODT::Quality_measure::min_dihedral_sine,
                                         BODT::Tensor_voting_options());
  const auto before = exact_subdomain_volumes(c3t3);
  const double worst = star_worst(c3t3, handles[centre]);
  const Point corner = bare(c3t3, handles[0]);
  EXPECT_FALSE(smoothing.move(handles[0], BI::Vertex_kind::fixed));
  EXPECT_EQ(bare(c3t3, handles[0]), corner);

  ASSERT_TRUE(smoothing.move(handles[centre], BI::Vertex_kind::interior));
  bodt_test::expect_valid(c3t3);
  EXPECT_TRUE(exact_subdomain_volumes(c3t3) == before);
  EXPECT_GT(star_worst(c3t3, handles[centre]), worst + 0.01);
  const Point now = bare(c3t3, handles[centre]);
  EXPECT_LT(CGAL::squared_distance(now, Point(1, 1, 1)),
            CGAL::squared_distance(Point(0.82, 0.9, 1.14), Point(1, 1, 1)));
}

// A vertex of the planar interface x = 1, moved as a surface vertex with a volume
// budget: it stays on the interface, and both subdomains keep their volume to
// 1e-12 (exact arithmetic); the budget is charged no more than it holds.
TEST(LocalSmoothing, InterfaceMoveKeepsBothVolumesWithinTheBudget)
{
  BODT::Tet_mesh m = bodt_test::cube_grid(2, two_labels);
  const int centre = bodt_test::grid_index(2, 1, 1, 1);
  m.points[centre] = Point(1, 0.8, 1.15);
  File_c3t3 c3t3;
  std::vector<Vertex_handle> handles;
  BODT::tet_mesh_to_c3t3(m, c3t3, "test", &handles);
  Adapter adapter(c3t3, false);
  BI::Volume_budget budget(std::vector<std::pair<int, double>>{{1, 4.0}, {2, 4.0}});
  BI::Local_smoothing<Adapter> smoothing(adapter, BI::Dihedral_bounds(), BODT::Quality_measure::min_dihedral_sine,
                                         BODT::Tensor_voting_options(), &budget);
  const auto before = exact_subdomain_volumes(c3t3);
  const double worst = star_worst(c3t3, handles[centre]);
  ASSERT_TRUE(smoothing.move(handles[centre], BI::Vertex_kind::surface));
  bodt_test::expect_valid(c3t3);
  EXPECT_TRUE(bodt_test::volumes_within(before, exact_subdomain_volumes(c3t3), 1e-12));
  EXPECT_LT(budget.spent(), 1.0);
  EXPECT_GE(star_worst(c3t3, handles[centre]), worst);
  EXPECT_NE(bare(c3t3, handles[centre]), Point(1, 0.8, 1.15));
}

// Every interior vertex of a jittered grid, moved five times over: no move makes
// its star's worst cell worse (the guard), none inverts a cell, and the volume stays
// exactly the same (each link stays).
TEST(LocalSmoothing, MovesNeverWorsenTheStarAndKeepTheVolumeExactly)
{
  const BODT::Tet_mesh m = jittered(3, one_label, 0.25);
  File_c3t3 c3t3;
  std::vector<Vertex_handle> handles;
  BODT::tet_mesh_to_c3t3(m, c3t3, "test", &handles);
  bodt_test::expect_valid(c3t3);
  Adapter adapter(c3t3, false);
  BI::Local_smoothing<Adapter> smoothing(adapter, BI::Dihedral_bounds(), BODT::Quality_measure::min_dihedral_sine,
                                         BODT::Tensor_voting_options());
  const auto before = exact_subdomain_volumes(c3t3);
  int moved = 0;
  for(int round = 0; round < 5; ++round)
    for(int k = 1; k <= 2; ++k)
      for(int j = 1; j <= 2; ++j)
        for(int i = 1; i <= 2; ++i)
        {
          const Vertex_handle v = handles[bodt_test::grid_index(3, i, j, k)];
          const double worst = star_worst(c3t3, v);
          const Point x0 = bare(c3t3, v);
          if(smoothing.move(v, BI::Vertex_kind::interior))
          {
            ++moved;
            EXPECT_GE(star_worst(c3t3, v), worst - 1e-12) << "round " << round << ", vertex " << i << j << k;
          }
          else
            EXPECT_EQ(bare(c3t3, v), x0);
        }
  EXPECT_GT(moved, 10);
  bodt_test::expect_valid(c3t3);
  EXPECT_TRUE(exact_subdomain_volumes(c3t3) == before);
}

// A budget that allows no measurable change: the interface vertex, off the plane
// of its neighbours, is not moved, and nothing is charged.
TEST(LocalSmoothing, RefusesAMoveTheBudgetCannotPay)
{
  BODT::Tet_mesh m = bodt_test::cube_grid(2, two_labels);
  const int centre = bodt_test::grid_index(2, 1, 1, 1);
  m.points[centre] = Point(1.1, 0.8, 1.15);
  File_c3t3 c3t3;
  std::vector<Vertex_handle> handles;
  BODT::tet_mesh_to_c3t3(m, c3t3, "test", &handles);
  Adapter adapter(c3t3, false);
  BI::Volume_budget budget(std::vector<std::pair<int, double>>{{1, 1e-30}, {2, 1e-30}});
  BI::Local_smoothing<Adapter> smoothing(adapter, BI::Dihedral_bounds(), BODT::Quality_measure::min_dihedral_sine,
                                         BODT::Tensor_voting_options(), &budget);
  const auto before = exact_subdomain_volumes(c3t3);
  EXPECT_FALSE(smoothing.move(handles[centre], BI::Vertex_kind::surface));
  EXPECT_EQ(bare(c3t3, handles[centre]), Point(1.1, 0.8, 1.15));
  EXPECT_TRUE(exact_subdomain_volumes(c3t3) == before);
  EXPECT_EQ(budget.spent(), 0.0);
  // Without a budget, the same vertex moves.
  BI::Local_smoothing<Adapter> free(adapter, BI::Dihedral_bounds(), BODT::Quality_measure::min_dihedral_sine,
                                    BODT::Tensor_voting_options());
  EXPECT_TRUE(free.move(handles[centre], BI::Vertex_kind::surface));
}

// The distance guard on a tent (two slopes meeting at a ridge of height 0.2, 2
// wide): a point is judged by its exact distance, a triangle everywhere, so a
// chord under the ridge whose corners lie on the input is refused; without a
// bound everything passes.
TEST(BoundaryDistanceGuard, JudgesPointsByDistanceAndTrianglesBetweenTheirCorners)
{
  const double h = 0.2;
  const Point l0(-1, 0, 0), l1(-1, 1, 0), r0(0, 0, h), r1(0, 1, h), s0(1, 0, 0), s1(1, 1, 0);
  std::vector<K::Triangle_3> tent = {{l0, r0, r1}, {l0, r1, l1}, {r0, s0, s1}, {r0, s1, r1}};
  const BI::Boundary_distance_guard<K> guard(tent, 0.01);   // 0.02: the box's largest side is 2
  ASSERT_TRUE(guard.active());
  EXPECT_DOUBLE_EQ(guard.bound(), 0.02);
  EXPECT_TRUE(guard.within(Point(0, 0.5, h + 0.019)));
  EXPECT_FALSE(guard.within(Point(0, 0.5, h + 0.021)));
  EXPECT_NEAR(guard.distance(Point(0, 0.5, h + 0.05)), 0.05, 1e-12);

  BI::Boundary_distance_guard<K>::Scratch scratch;
  // Corners on the input, the middle 0.2 below the ridge.
  EXPECT_TRUE(guard.within(Point(-1, 0.5, 0)));
  using Fan = std::vector<std::array<Point, 2>>;
  EXPECT_FALSE(guard.keeps_near(Point(-1, 0.5, 0), Point(-1, 0.5, 0), Fan{{Point(1, 0.4, 0), Point(1, 0.6, 0)}}, scratch));
  // A corner lifted 0.01 above the ridge, the others on a slope: within.
  EXPECT_TRUE(guard.keeps_near(Point(0, 0.5, h + 0.01), Point(0, 0.5, h + 0.01), Fan{{Point(0.5, 0.5, h / 2), Point(0.5, 0.7, h / 2)}},
                               scratch));
  // The same lifted by 0.03: the corner itself is out.
  EXPECT_FALSE(guard.within(Point(0, 0.5, h + 0.03)));

  const BI::Boundary_distance_guard<K> none(tent, 0);
  EXPECT_FALSE(none.active());
  EXPECT_TRUE(none.within(Point(5, 5, 5)));
  EXPECT_TRUE(none.keeps_near(Point(-1, 0.5, 0), Point(-1, 0.5, 0), Fan{{Point(1, 0.4, 0), Point(1, 0.6, 0)}}, scratch));
}

// A surface triangle the guard accepts is within the bound at every point, on a
// bumpy surface with ridges, valleys and saddles between its vertices (a height
// field on a grid of 12 by 12 squares, their diagonals alternating), for random
// triangles near it: the largest distance over 1,891 points of the triangle,
// each measured exactly, is within the bound. (The sampled test this replaced
// accepted triangles up to 1.5 times the bound on third-party meshes.) And the
// guard is no blanket refusal: it accepts most triangles that stay within half
// the bound.
TEST(BoundaryDistanceGuard, AcceptedTrianglesAreWithinTheBoundEverywhere)
{
  const int n = 12;
  auto z = [](double x, double y) { return 0.06 * std::sin(7 * x) * std::cos(5 * y) + 0.04 * x * y; };
  auto grid = [&](int i, int j) { return Point(double(i) / n, double(j) / n, z(double(i) / n, double(j) / n)); };
  std::vector<K::Triangle_3> surface;
  for(int i = 0; i < n; ++i)
    for(int j = 0; j < n; ++j)
      if((i + j) % 2 == 0)
      {
        surface.emplace_back(grid(i, j), grid(i + 1, j), grid(i + 1, j + 1));
        surface.emplace_back(grid(i, j), grid(i + 1, j + 1), grid(i, j + 1));
      }
      else
      {
        surface.emplace_back(grid(i, j), grid(i + 1, j), grid(i, j + 1));
        surface.emplace_back(grid(i + 1, j), grid(i + 1, j + 1), grid(i, j + 1));
      }
  const BI::Boundary_distance_guard<K> guard(surface, 0.01);
  const double bound = guard.bound();
  ASSERT_NEAR(bound, 0.01, 1e-12);

  CGAL::Random random(29);
  // A point over (x, y) on the surface's triangles (not the smooth function),
  // lifted by up to `lift` times the bound.
  auto near_surface = [&](double x, double y, double lift) {
    for(const auto& t : surface)
    {
      const Point &a = t[0], &b = t[1], &c = t[2];
      const double det = (b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x());
      const double l1 = ((x - a.x()) * (c.y() - a.y()) - (y - a.y()) * (c.x() - a.x())) / det;
      const double l2 = ((b.x() - a.x()) * (y - a.y()) - (b.y() - a.y()) * (x - a.x())) / det;
      if(l1 >= 0 && l2 >= 0 && l1 + l2 <= 1)
        return Point(x, y, a.z() + l1 * (b.z() - a.z()) + l2 * (c.z() - a.z()) + random.get_double(-lift, lift) * bound);
    }
    ADD_FAILURE() << "no triangle over " << x << " " << y;
    return Point(x, y, 0);
  };
  BI::Boundary_distance_guard<K>::Scratch scratch;
  using Fan = std::vector<std::array<Point, 2>>;
  int accepted = 0, within_half = 0, within_half_accepted = 0;
  for(int trial = 0; trial < 400; ++trial)
  {
    const double x = random.get_double(0.2, 0.8), y = random.get_double(0.2, 0.8), r = random.get_double(0.03, 0.15);
    const double angle = random.get_double(0, 6.283185307179586);
    const double lift = trial % 2 == 0 ? 1.2 : 0.3;
    const Point p = near_surface(x, y, lift);
    const Point a = near_surface(x + r * std::cos(angle), y + r * std::sin(angle), lift);
    const Point b = near_surface(x + r * std::cos(angle + 2), y + r * std::sin(angle + 2), lift);
    double farthest = 0;
    const int m = 60;
    for(int i = 0; i <= m; ++i)
      for(int j = 0; i + j <= m; ++j)
        farthest = (std::max)(farthest, guard.distance(CGAL::barycenter(p, double(i) / m, a, double(j) / m, b,
                                                                          1 - double(i) / m - double(j) / m)));
    const bool accepts = guard.keeps_near(p, p, Fan{{a, b}}, scratch);   // the triangle alone
    if(accepts)
    {
      ++accepted;
      EXPECT_LE(farthest, bound * (1 + 1e-9)) << "trial " << trial;
    }
    if(farthest <= 0.5 * bound)
    {
      ++within_half;
      within_half_accepted += accepts;
    }
  }
  EXPECT_GT(accepted, 40);
  ASSERT_GT(within_half, 40);
  EXPECT_GE(within_half_accepted, 0.9 * within_half);
  std::cout << "accepted " << accepted << " of 400; within half the bound " << within_half << ", of them accepted "
            << within_half_accepted << "\n";
}

// The other direction: the input's surface must stay within the bound of the
// mesh's. A fan of four triangles around an apex `h` above a square base of
// radius `r`, the bound 0.01. A narrow spike (r = 0.005, h = 0.05) flattened:
// every point of the flat fan is within 0.005 of the spike's sides, so the fan is
// within the bound of the input, but the spike's tip is 0.05 from it: refused. A
// low bump (r = 0.1, h = 0.02): lowered by half the bound, accepted; by twice
// the bound, refused; its apex moved a little way along one of its sides (the
// other sides now pass about 0.002 under the top), accepted; and across the base once
// flattened (the surface unchanged), accepted.
TEST(BoundaryDistanceGuard, InputSurfaceStaysWithinTheBoundOfTheMovedFan)
{
  BI::Boundary_distance_guard<K>::Scratch scratch;
  auto link_of = [](double r) {
    return std::vector<std::array<Point, 2>>{{Point(r, 0, 0), Point(0, r, 0)},
                                             {Point(0, r, 0), Point(-r, 0, 0)},
                                             {Point(-r, 0, 0), Point(0, -r, 0)},
                                             {Point(0, -r, 0), Point(r, 0, 0)}};
  };
  auto fan = [](const Point& apex, const std::vector<std::array<Point, 2>>& link) {
    std::vector<K::Triangle_3> triangles;
    for(const auto& ab : link) triangles.emplace_back(apex, ab[0], ab[1]);
    return triangles;
  };
  const double bound = 0.01;

  const auto spike_link = link_of(0.005);
  const Point spike_tip(0, 0, 0.05);
  const BI::Boundary_distance_guard<K> spike(fan(spike_tip, spike_link), bound / 0.05);
  ASSERT_NEAR(spike.bound(), bound, 1e-15);
  EXPECT_LT(spike.distance(Point(0, 0, 0)), 0.005);
  EXPECT_FALSE(spike.keeps_near(spike_tip, Point(0, 0, 0), spike_link, scratch));

  const auto bump_link = link_of(0.1);
  const Point top(0, 0, 0.02);
  const BI::Boundary_distance_guard<K> bump(fan(top, bump_link), bound / 0.2);
  ASSERT_NEAR(bump.bound(), bound, 1e-15);
  EXPECT_TRUE(bump.keeps_near(top, Point(0, 0, 0.02 - bound / 2), bump_link, scratch));
  EXPECT_FALSE(bump.keeps_near(top, Point(0, 0, 0.02 - 2 * bound), bump_link, scratch));
  EXPECT_TRUE(bump.keeps_near(top, CGAL::barycenter(top, 0.9, bump_link[0][0], 0.05, bump_link[0][1], 0.05),
                              bump_link, scratch));
  const BI::Boundary_distance_guard<K> plane(fan(Point(0, 0, 0), bump_link), bound / 0.2);
  EXPECT_TRUE(plane.keeps_near(Point(0, 0, 0), Point(0.03, -0.04, 0), bump_link, scratch));
}

// Both directions through many moves: random moves of the interior vertices of a
// bumpy surface (a height field on a grid of 10 by 10 squares, with narrow spikes
// four times the bound high at a quarter of its vertices), each kept only if the
// guard accepts it, judged with the vertex's fan as it is then. A lowered spike
// stays within the bound of its sides, so only the second test keeps the spikes'
// tips near the surface. After the moves the symmetric distance between the
// input's surface and the moved one, measured on 231 points per triangle of
// each, exactly to the other's triangles, is within the bound; and many moves
// were kept.
TEST(BoundaryDistanceGuard, RandomMovesKeepTheSymmetricDistanceWithinTheBound)
{
  const int n = 10;
  const double bound = 0.1;   // relative to the grid's side, 1
  auto z = [](double x, double y) { return 0.08 * std::sin(6 * x) * std::cos(4 * y) + 0.05 * x * y; };
  std::vector<Point> points;
  for(int i = 0; i <= n; ++i)
    for(int j = 0; j <= n; ++j)
    {
      const bool spike = i > 0 && i < n && j > 0 && j < n && (i + j) % 4 == 0 && i % 2 == 0;
      points.emplace_back(double(i) / n, double(j) / n, z(double(i) / n, double(j) / n) + (spike ? 4 * bound : 0));
    }
  auto id = [&](int i, int j) { return i * (n + 1) + j; };
  std::vector<std::array<int, 3>> triangles;   // counterclockwise seen from above
  for(int i = 0; i < n; ++i)
    for(int j = 0; j < n; ++j)
      if((i + j) % 2 == 0)
      {
        triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
        triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
      }
      else
      {
        triangles.push_back({id(i, j), id(i + 1, j), id(i, j + 1)});
        triangles.push_back({id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
      }
  auto surface_of = [&](const std::vector<Point>& at) {
    std::vector<K::Triangle_3> s;
    for(const auto& t : triangles) s.emplace_back(at[t[0]], at[t[1]], at[t[2]]);
    return s;
  };
  const std::vector<K::Triangle_3> input = surface_of(points);
  const BI::Boundary_distance_guard<K> guard(input, bound);
  ASSERT_NEAR(guard.bound(), bound, 1e-12);

  CGAL::Random random(7);
  BI::Boundary_distance_guard<K>::Scratch scratch;
  int kept = 0;
  for(int attempt = 0; attempt < 3000; ++attempt)
  {
    const int i = random.get_int(1, n), j = random.get_int(1, n), v = id(i, j);
    std::vector<std::array<Point, 2>> fan;
    for(const auto& t : triangles)
      for(int k = 0; k < 3; ++k)
        if(t[k] == v) fan.push_back({points[t[(k + 1) % 3]], points[t[(k + 2) % 3]]});
    const double step = 0.3 / n;
    const Point p = points[v] + Vector(random.get_double(-step, step), random.get_double(-step, step),
                                       random.get_double(-0.5, 0.5) * bound);
    // Keep the fan valid seen from above, as the mesh's orientation tests would.
    bool valid = true;
    for(const auto& ab : fan)
      valid = valid && CGAL::orientation(CGAL::Point_2<K>(p.x(), p.y()), CGAL::Point_2<K>(ab[0].x(), ab[0].y()),
                                         CGAL::Point_2<K>(ab[1].x(), ab[1].y())) == CGAL::LEFT_TURN;
    if(valid && guard.keeps_near(points[v], p, fan, scratch))
    {
      points[v] = p;
      ++kept;
    }
  }
  EXPECT_GT(kept, 200);

  const std::vector<K::Triangle_3> moved = surface_of(points);
  using Primitive = CGAL::AABB_triangle_primitive<K, std::vector<K::Triangle_3>::const_iterator>;
  using Tree = CGAL::AABB_tree<CGAL::AABB_traits<K, Primitive>>;
  auto farthest = [](const std::vector<K::Triangle_3>& from, const std::vector<K::Triangle_3>& to) {
    Tree tree(to.begin(), to.end());
    tree.accelerate_distance_queries();
    double worst = 0;
    const int m = 20;
    for(const auto& t : from)
      for(int a = 0; a <= m; ++a)
        for(int b = 0; a + b <= m; ++b)
          worst = (std::max)(worst, tree.squared_distance(CGAL::barycenter(t[0], double(a) / m, t[1], double(b) / m,
                                                                            t[2], 1 - double(a) / m - double(b) / m)));
    return std::sqrt(worst);
  };
  const double out = farthest(moved, input), in = farthest(input, moved);
  EXPECT_LE(out, bound * (1 + 1e-9));
  EXPECT_LE(in, bound * (1 + 1e-9));
  EXPECT_GT((std::max)(out, in), 0.5 * bound);   // the moves went near the bound
  std::cout << "kept " << kept << " moves; distances " << out / bound << " and " << in / bound << " of the bound\n";
}
