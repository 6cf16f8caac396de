// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Smoothing speed and quality on the ~40,000-tetrahedra generated inputs: B-ODT
// (bodt_optimize_mesh_3, 20 iterations) beside CGAL's odt_optimize_mesh_3 with
// 20 iterations, in the same run on the same input. Throughput is tetrahedra in
// the mesh times iterations per second, on one core.
#include "inputs/generated_inputs.h"

#include <CGAL/BODT_3/mesh_quality.h>
#include <CGAL/Real_timer.h>
#include <CGAL/bodt_optimize_mesh_3.h>
#include <CGAL/odt_optimize_mesh_3.h>

#include <cstdio>
#include <cstring>
#include <string>

using namespace bodt_inputs;
namespace BODT = CGAL::BODT_3;

namespace {

struct Iteration_counter
{
  std::size_t* iterations;
  void after_classification(const BODT::Smoothing_result&) const {}
  void after_iteration(const BODT::Iteration_stats& s) const { *iterations = s.iteration; }
};

void row(const char* input, const char* method, const BODT::Quality_report& q, std::size_t tets,
         std::size_t iterations, double seconds)
{
  const double throughput = seconds > 0 ? double(tets) * double(iterations) / seconds : 0;
  std::printf("| %-15s | %-22s | %7.2f | %7.2f | %6zu | %6zu | %4zu | %8.4f | %8.3f |\n", input, method,
              q.min_dihedral_deg, q.max_dihedral_deg, q.tets_below_small, q.tets_above_large, iterations,
              iterations ? seconds / double(iterations) : 0.0, throughput / 1e6);
}

} // namespace

int main(int argc, char** argv)
{
  const bool small = argc > 1 && !std::strcmp(argv[1], "--small");
  const Size size = small ? Size::small : Size::benchmark;
  std::printf("| input           | method                 | min deg | max deg |  <10deg | >170deg | its | s/iter   | M tets*it/s |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|\n");
  for(Shape shape : all_shapes())
  {
    const Generated_mesh input = make_input(shape, size);
    const std::size_t tets = input.c3t3.number_of_cells_in_complex();
    const std::string label = name(shape) + " " + std::to_string(tets / 1000) + "k";
    row(label.c_str(), "input", BODT::mesh_quality(input.c3t3), tets, 0, 0);

    C3t3 bodt = input.c3t3;
    std::size_t its = 0;
    CGAL::Real_timer t;
    t.start();
    CGAL::bodt_optimize_mesh_3(bodt, CGAL::parameters::max_iteration_number = 20,
                               CGAL::parameters::progress_visitor = Iteration_counter{&its});
    t.stop();
    row(label.c_str(), "bodt_optimize_mesh_3", BODT::mesh_quality(bodt), tets, its, t.time());

    C3t3 odt = input.c3t3;
    t.reset();
    t.start();
    CGAL::odt_optimize_mesh_3(odt, *input.domain, CGAL::parameters::max_iteration_number = 20,
                              CGAL::parameters::convergence = 0, CGAL::parameters::freeze_bound = 0);
    t.stop();
    row(label.c_str(), "CGAL odt_optimize_mesh_3", BODT::mesh_quality(odt), odt.number_of_cells_in_complex(), 20,
        t.time());
  }
  Delaunay sphere = make_random_sphere(size);
  const std::size_t tets = sphere.number_of_finite_cells();
  const std::string label = "random_sphere " + std::to_string(tets / 1000) + "k";
  row(label.c_str(), "input", BODT::mesh_quality(sphere), tets, 0, 0);
  std::size_t its = 0;
  CGAL::Real_timer t;
  t.start();
  CGAL::bodt_optimize_mesh_3(sphere, CGAL::parameters::max_iteration_number = 20,
                             CGAL::parameters::progress_visitor = Iteration_counter{&its});
  t.stop();
  row(label.c_str(), "bodt_optimize_mesh_3", BODT::mesh_quality(sphere), tets, its, t.time());
  return 0;
}
