// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What the largest-angle phases (Smoothing_options::largest_angle_phase) gain and
// cost: the default pipeline with and without them, one thread, on the generated
// inputs and on Mesh_3 meshes of the .off surfaces given; per phase, iterations
// and seconds in sweeps, flips and the rest (max-min steps, re-reads).
//
//   phase_costs [--only NAME]... [surface.off...]
#include "../src/compare/compare.h"

#include <CGAL/BODT_3/mesh_quality.h>
#include <CGAL/BODT_3/smooth.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

using namespace bodt_compare;

namespace {

struct Phase_times
{
  std::array<std::size_t, 3> iterations{};
  std::array<double, 3> sweeps{}, flips{}, total{};
};

struct Recorder
{
  Phase_times* t;
  double* last;
  void after_classification(const BODT::Smoothing_result&) const {}
  void after_iteration(const BODT::Iteration_stats& s) const
  {
    ++t->iterations[s.phase];
    t->sweeps[s.phase] += s.sweep_seconds;
    t->flips[s.phase] += s.topology.seconds;
    t->total[s.phase] += s.seconds - *last;
    *last = s.seconds;
  }
};

template <class C3T3>
void run(const std::string& name, const C3T3& input)
{
  for(bool phases : {false, true})
  {
    C3T3 c3t3 = input;
    BODT::Smoothing_options opt;
    opt.threads = 1;
    opt.largest_angle_phase = phases;
    Phase_times t;
    double last = 0;
    const auto r = BODT::smooth(c3t3, opt, Recorder{&t, &last});
    const auto q = BODT::mesh_quality(c3t3);
    std::printf("| %s | %s | %.2f / %.2f | %.2f |", name.c_str(), phases ? "yes" : "no", q.min_dihedral_deg,
                q.max_dihedral_deg, r.seconds);
    for(int p = 0; p < 3; ++p)
      std::printf(" %zu: %.2f (%.2f + %.2f) |", t.iterations[p], t.total[p], t.sweeps[p], t.flips[p]);
    std::printf("\n");
    std::fflush(stdout);
  }
}

} // namespace

int main(int argc, char** argv)
{
  std::vector<std::string> only, offs;
  for(int i = 1; i < argc; ++i)
  {
    if(!std::strcmp(argv[i], "--only") && i + 1 < argc) only.push_back(argv[++i]);
    else offs.push_back(argv[i]);
  }
  std::printf("| input | largest-angle phases | min / max | s | per phase (main, largest angle, last): "
              "iterations: s (sweeps + flips) |\n|---|---|---|---|---|---|---|\n");
  if(offs.empty() || !only.empty())
    for(auto& in : generated_inputs(bodt_inputs::Size::benchmark))
    {
      if(!only.empty() && std::find(only.begin(), only.end(), in.name) == only.end()) continue;
      if(auto* g = std::get_if<bodt_inputs::Generated_mesh>(&in.mesh)) run(in.name, g->c3t3);
    }
  for(const auto& f : offs)
  {
    auto in = surface_input(f, bodt_inputs::Size::benchmark);
    run(in.name, std::get<Surface_mesh>(in.mesh).c3t3);
  }
  return 0;
}
