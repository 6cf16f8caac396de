// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The pipeline's stages measured one by one, in one run: B-ODT smoothing alone,
// flips alone, and the default pipeline, on the generated Mesh_3 inputs (and mesh
// files given on the command line). For each: the extreme dihedral angles, the bad
// tetrahedra (below 10 or above 170 degrees) by where they are, the flips by kind,
// the mean time of a smoothing sweep and of a flip pass per iteration, and the
// largest relative change of a subdomain's volume.
//
//   bench_pipeline [--small] [--iterations N] [--flip-threshold Q] [--flip-outside] [mesh files...]
#include "inputs/generated_inputs.h"

#include <CGAL/BODT_3/IO/mesh_io.h>
#include <CGAL/BODT_3/mesh_quality.h>
#include <CGAL/BODT_3/smooth.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

using namespace bodt_inputs;
namespace BODT = CGAL::BODT_3;

namespace {

struct Totals
{
  double sweep = 0, flips = 0;
  std::size_t iterations = 0;
  void after_classification(const BODT::Smoothing_result&) {}
  void after_iteration(const BODT::Iteration_stats& s)
  {
    sweep += s.sweep_seconds;
    flips += s.topology.seconds;
    iterations = s.iteration;
  }
};

double max_subdomain_change(const BODT::Quality_report& a, const BODT::Quality_report& b)
{
  double worst = 0;
  for(const auto& kv : a.volume_per_subdomain)
  {
    const auto it = b.volume_per_subdomain.find(kv.first);
    const double after = it == b.volume_per_subdomain.end() ? 0 : it->second;
    worst = std::max(worst, std::abs(after - kv.second) / std::abs(kv.second));
  }
  return worst;
}

void header()
{
  std::printf("| input | method | tets | min deg | max deg | bad: interior / touching / all on boundary | "
              "2-3 / 3-2 / edge rem. / multi-face / of which boundary | its | sweep ms/it | flips ms/it | "
              "max rel. subdomain vol. change |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|---|\n");
}

void row(const std::string& input, const char* method, const BODT::Quality_report& before,
         const BODT::Quality_report& q, const BODT::Smoothing_result* r, const Totals* t)
{
  std::printf("| %s | %s | %zu | %.2f | %.2f | %zu / %zu / %zu |", input.c_str(), method, q.num_tets,
              q.min_dihedral_deg, q.max_dihedral_deg, q.bad_tets_interior, q.bad_tets_touching_boundary,
              q.bad_tets_all_vertices_on_boundary);
  if(r && t && t->iterations)
    std::printf(" %zu / %zu / %zu / %zu / %zu | %zu | %.2f | %.2f | %.1e |\n", r->topology.flips_2_3,
                r->topology.flips_3_2, r->topology.edge_removals, r->topology.multi_face_removals,
                r->topology.boundary_flips, t->iterations, 1e3 * t->sweep / double(t->iterations),
                1e3 * t->flips / double(t->iterations), max_subdomain_change(before, q));
  else
    std::printf(" | | | | |\n");
}

struct Variant
{
  const char* name;
  BODT::Moving_vertices moving;
  bool flips;
};
const Variant variants[] = {{"B-ODT, no flips", BODT::Moving_vertices::ALL, false},
                            {"flips alone", BODT::Moving_vertices::NONE, true},
                            {"B-ODT + flips", BODT::Moving_vertices::ALL, true}};

BODT::Flip_options flip_options;

template <class Mesh>
void run(const std::string& label, const Mesh& input, std::size_t iterations)
{
  const auto before = BODT::mesh_quality(input);
  row(label, "input", before, before, nullptr, nullptr);
  for(const Variant& v : variants)
  {
    Mesh m = input;
    BODT::Smoothing_options opt;
    opt.max_iteration_number = iterations;
    opt.moving_vertices = v.moving;
    opt.topology_optimization = v.flips;
    opt.vertex_insertion = false;
    opt.flips = flip_options;
    Totals t;
    const auto r = BODT::smooth(m, opt, t);
    row(label, v.name, before, BODT::mesh_quality(m), &r, &t);
  }
}

} // namespace

int main(int argc, char** argv)
{
  Size size = Size::benchmark;
  std::size_t iterations = 20;
  std::vector<std::string> files;
  for(int i = 1; i < argc; ++i)
  {
    if(!std::strcmp(argv[i], "--small")) size = Size::small;
    else if(!std::strcmp(argv[i], "--iterations") && i + 1 < argc) iterations = std::stoul(argv[++i]);
    else if(!std::strcmp(argv[i], "--flip-threshold") && i + 1 < argc) flip_options.quality_threshold = std::stod(argv[++i]);
    else if(!std::strcmp(argv[i], "--flip-outside")) flip_options.flip_outside = true;
    else files.push_back(argv[i]);
  }
  header();
  if(files.empty())
    for(Shape shape : all_shapes()) run(name(shape), make_input(shape, size).c3t3, iterations);
  for(const auto& f : files) run(f.substr(f.find_last_of('/') + 1), BODT::IO::read_mesh(f), iterations);
  return 0;
}
