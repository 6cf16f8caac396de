// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The experiment behind the default quality measure: the default pipeline run
// with each measure deciding the smoothing guard and the flips, on the generated
// Mesh_3 inputs (and mesh files given on the command line). Reports the extreme
// dihedral angles and the tetrahedra below 10 and above 170 degrees that each
// measure leaves.
//
//   quality_measures [--small] [mesh files...]
#include "inputs/generated_inputs.h"

#include <CGAL/BODT_3/IO/mesh_io.h>
#include <CGAL/BODT_3/mesh_quality.h>
#include <CGAL/BODT_3/smooth.h>

#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

using namespace bodt_inputs;
namespace BODT = CGAL::BODT_3;

namespace {

const std::pair<BODT::Quality_measure, const char*> measures[] = {
    {BODT::Quality_measure::min_dihedral_sine, "minimum dihedral sine"},
    {BODT::Quality_measure::min_dihedral_angle, "minimum dihedral angle"},
    {BODT::Quality_measure::radius_ratio, "radius ratio"}};

template <class Mesh>
void run(const std::string& label, const Mesh& input)
{
  const auto before = BODT::mesh_quality(input);
  std::printf("| %s | input | %.2f | %.2f | %zu | %zu |\n", label.c_str(), before.min_dihedral_deg,
              before.max_dihedral_deg, before.tets_below_small, before.tets_above_large);
  for(const auto& m : measures)
  {
    Mesh mesh = input;
    BODT::Smoothing_options opt;
    opt.quality_measure = m.first;
    opt.vertex_insertion = false;
    BODT::smooth(mesh, opt);
    const auto q = BODT::mesh_quality(mesh);
    std::printf("| %s | %s | %.2f | %.2f | %zu | %zu |\n", label.c_str(), m.second, q.min_dihedral_deg,
                q.max_dihedral_deg, q.tets_below_small, q.tets_above_large);
  }
}

} // namespace

int main(int argc, char** argv)
{
  Size size = Size::benchmark;
  std::vector<std::string> files;
  for(int i = 1; i < argc; ++i)
  {
    if(!std::strcmp(argv[i], "--small")) size = Size::small;
    else files.push_back(argv[i]);
  }
  std::printf("| input | measure deciding | min deg | max deg | tets < 10 deg | tets > 170 deg |\n|---|---|---|---|---|---|\n");
  for(Shape shape : all_shapes()) run(name(shape), make_input(shape, size).c3t3);
  for(const auto& f : files) run(f.substr(f.find_last_of('/') + 1), BODT::IO::read_mesh(f));
  return 0;
}
