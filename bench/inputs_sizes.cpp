// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Prints the size and generation time of every generated input, to check the
// sizes promised in generated_inputs.h (small: a few thousand cells, benchmark:
// about 40,000).
#include "inputs/generated_inputs.h"

#include <chrono>
#include <iomanip>
#include <iostream>
#include <utility>

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start)
{
  return std::chrono::duration<double>(Clock::now() - start).count();
}

const char* size_name(bodt_inputs::Size size)
{
  return size == bodt_inputs::Size::small ? "small" : "benchmark";
}

void print_row(const std::string& name, const char* size, std::size_t cells,
               std::size_t vertices, double seconds)
{
  std::cout << std::left << std::setw(16) << name << std::setw(11) << size << std::right
            << std::setw(8) << cells << std::setw(10) << vertices << std::setw(10)
            << std::fixed << std::setprecision(3) << seconds << '\n';
}

} // namespace

int main()
{
  using namespace bodt_inputs;

  std::cout << std::left << std::setw(16) << "input" << std::setw(11) << "size" << std::right
            << std::setw(8) << "cells" << std::setw(10) << "vertices" << std::setw(10)
            << "seconds" << '\n';
  for(Size size : {Size::small, Size::benchmark})
  {
    for(Shape shape : all_shapes())
    {
      const Clock::time_point start = Clock::now();
      const Generated_mesh mesh = make_input(shape, size);
      const double seconds = seconds_since(start);
      print_row(mesh.name, size_name(size), mesh.c3t3.number_of_cells_in_complex(),
                mesh.c3t3.triangulation().number_of_vertices(), seconds);
    }
    // For the random sphere, "cells" counts the finite cells of the triangulation.
    const Clock::time_point start = Clock::now();
    const Delaunay dt = make_random_sphere(size);
    const double seconds = seconds_since(start);
    print_row("random_sphere", size_name(size), dt.number_of_finite_cells(),
              dt.number_of_vertices(), seconds);
  }
  return 0;
}
