// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The pipeline's stages measured one by one, in one run: B-ODT smoothing alone,
// flips alone, flips with and without the max-min fallback and insertion (the
// last variant is the default pipeline), on the generated Mesh_3 inputs (and mesh
// files given on the command line). For each: the extreme dihedral angles, the bad
// tetrahedra (below 10 or above 170 degrees) by where they are, the flips by kind,
// the mean time of a smoothing sweep and of a flip pass per iteration, and the
// largest relative change of a subdomain's volume.
//
// Closed surfaces (.off) given on the command line are meshed with Mesh_3 first,
// as the comparison does. `--worst N` lists the N worst tetrahedra left by the
// last variant: their shape and how many of their faces and vertices are on the
// boundary.
//
//   bench_pipeline [--small] [--iterations N] [--flip-threshold Q] [--flip-outside] [--worst N] [--retries-after-moves K]
//                  [--only GENERATED_INPUT] [--threads N] [mesh or .off files...]
#include "compare/compare.h"
#include "inputs/generated_inputs.h"

#include <CGAL/BODT_3/internal/Insertion/Bad_tet_shape.h>

#include <CGAL/BODT_3/IO/mesh_io.h>
#include <CGAL/BODT_3/mesh_quality.h>
#include <CGAL/BODT_3/smooth.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <iterator>
#include <string>
#include <vector>

using namespace bodt_inputs;
namespace BODT = CGAL::BODT_3;

namespace {

struct Totals
{
  double sweep = 0, flips = 0, insertion = 0;
  std::size_t iterations = 0;
  void after_classification(const BODT::Smoothing_result&) {}
  void after_iteration(const BODT::Iteration_stats& s)
  {
    sweep += s.sweep_seconds;
    flips += s.topology.seconds;
    insertion += s.insertion.seconds;
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
  std::printf("| input | method | vertices / tets | min deg | max deg | bad: interior / touching / all on boundary | "
              "2-3 / 3-2 / edge rem. / multi-face / of which boundary | splits: spade / cap / sliver | its | "
              "sweep ms/it | flips ms/it | insertion ms/it | max rel. subdomain vol. change |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
}

void row(const std::string& input, const char* method, const BODT::Quality_report& before,
         const BODT::Quality_report& q, const BODT::Smoothing_result* r, const Totals* t)
{
  std::printf("| %s | %s | %zu / %zu | %.2f | %.2f | %zu / %zu / %zu |", input.c_str(), method, q.num_vertices, q.num_tets,
              q.min_dihedral_deg, q.max_dihedral_deg, q.bad_tets_interior, q.bad_tets_touching_boundary,
              q.bad_tets_all_vertices_on_boundary);
  if(r && t && t->iterations)
    std::printf(" %zu / %zu / %zu / %zu / %zu | %zu / %zu / %zu (%zu undone) | %zu | %.2f | %.2f | %.2f | %.1e |\n",
                r->topology.flips_2_3,
                r->topology.flips_3_2, r->topology.edge_removals, r->topology.multi_face_removals,
                r->topology.boundary_flips, r->insertion.spade_splits + r->insertion.wedge_splits, r->insertion.cap_splits,
                r->insertion.sliver_splits, r->insertion.undone, t->iterations, 1e3 * t->sweep / double(t->iterations),
                1e3 * t->flips / double(t->iterations), 1e3 * t->insertion / double(t->iterations),
                max_subdomain_change(before, q));
  else
    std::printf(" | | | | | | |\n");
}

struct Variant
{
  const char* name;
  BODT::Moving_vertices moving;
  bool flips;
  bool max_min;   // the max-min fallback after the flips
  bool insertion;
};
const Variant variants[] = {{"B-ODT, no flips", BODT::Moving_vertices::ALL, false, false, false},
                            {"flips alone", BODT::Moving_vertices::NONE, true, false, false},
                            {"B-ODT + flips", BODT::Moving_vertices::ALL, true, false, false},
                            {"B-ODT + flips + max-min", BODT::Moving_vertices::ALL, true, true, false},
                            {"B-ODT + flips + insertion", BODT::Moving_vertices::ALL, true, false, true},
                            {"B-ODT + flips + max-min + insertion", BODT::Moving_vertices::ALL, true, true, true}};

BODT::Flip_options flip_options;
std::size_t worst_listed = 0;
int threads = 1;   // the tables compare stages on one thread; --threads 0: every core

// The worst tetrahedra of a C3T3's complex: angles, shape, faces and vertices on the boundary.
template <class C3T3>
std::enable_if_t<BODT::internal::Is_c3t3<C3T3>::value> list_worst(const C3T3& c3t3)
{
  const auto& tr = c3t3.triangulation();
  auto cp = tr.geom_traits().construct_point_3_object();
  std::vector<std::pair<double, typename C3T3::Cell_handle>> cells;
  for(auto c = c3t3.cells_in_complex_begin(); c != c3t3.cells_in_complex_end(); ++c)
  {
    const auto mm = BODT::internal::min_max_dihedral_angle(cp(c->vertex(0)->point()), cp(c->vertex(1)->point()),
                                                 cp(c->vertex(2)->point()), cp(c->vertex(3)->point()));
    cells.emplace_back(std::min(mm.first, 180 - mm.second), c);
  }
  std::sort(cells.begin(), cells.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  BODT::Bad_tet_options shapes;
  shapes.small_angle = 30;
  shapes.large_angle = 150;
  for(std::size_t k = 0; k < worst_listed && k < cells.size(); ++k)
  {
    const auto c = cells[k].second;
    int faces = 0, vertices = 0;
    std::string dims;
    for(int i = 0; i < 4; ++i)
    {
      faces += c3t3.is_in_complex(c, i) ? 1 : 0;
      vertices += c3t3.in_dimension(c->vertex(i)) < 3 ? 1 : 0;
      dims += std::to_string(c3t3.in_dimension(c->vertex(i)));
    }
    const auto p0 = cp(c->vertex(0)->point()), p1 = cp(c->vertex(1)->point()), p2 = cp(c->vertex(2)->point()),
               p3 = cp(c->vertex(3)->point());
    const auto mm = BODT::internal::min_max_dihedral_angle(p0, p1, p2, p3);
    std::printf("|   | worst %zu: %.2f / %.2f, %s, %d faces and %d vertices on the boundary (dimensions %s) | | | | | | | | | | |\n",
                k + 1, mm.first, mm.second, BODT::internal::name(BODT::internal::classify_bad_tet(p0, p1, p2, p3, shapes).shape), faces,
                vertices, dims.c_str());
  }
}
void list_worst(const BODT::Tet_mesh&) {}

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
    opt.vertex_insertion = v.insertion;
    if(!v.max_min) opt.max_min_threshold = 0;
    opt.flips = flip_options;
    opt.threads = threads;
    Totals t;
    const auto r = BODT::smooth(m, opt, t);
    row(label, v.name, before, BODT::mesh_quality(m), &r, &t);
    if(&v == &variants[std::size(variants) - 1]) list_worst(m);
  }
}

} // namespace

int main(int argc, char** argv)
{
  Size size = Size::benchmark;
  std::size_t iterations = 20;
  std::vector<std::string> files;
  std::string only;   // one generated input by name
  for(int i = 1; i < argc; ++i)
  {
    if(!std::strcmp(argv[i], "--small")) size = Size::small;
    else if(!std::strcmp(argv[i], "--iterations") && i + 1 < argc) iterations = std::stoul(argv[++i]);
    else if(!std::strcmp(argv[i], "--flip-threshold") && i + 1 < argc) flip_options.quality_threshold = std::stod(argv[++i]);
    else if(!std::strcmp(argv[i], "--flip-outside")) flip_options.flip_outside = true;
    else if(!std::strcmp(argv[i], "--retries-after-moves") && i + 1 < argc)
      flip_options.retries_after_moves = std::stoul(argv[++i]);
    else if(!std::strcmp(argv[i], "--worst") && i + 1 < argc) worst_listed = std::stoul(argv[++i]);
    else if(!std::strcmp(argv[i], "--only") && i + 1 < argc) only = argv[++i];
    else if(!std::strcmp(argv[i], "--threads") && i + 1 < argc) threads = std::stoi(argv[++i]);
    else files.push_back(argv[i]);
  }
  header();
  if(files.empty())
    for(Shape shape : all_shapes())
      if(only.empty() || only == name(shape)) run(name(shape), make_input(shape, size).c3t3, iterations);
  for(const auto& f : files)
  {
    const std::string label = f.substr(f.find_last_of('/') + 1);
    if(label.size() > 4 && label.compare(label.size() - 4, 4, ".off") == 0)
      run(label, std::get<bodt_compare::Surface_mesh>(bodt_compare::surface_input(f, size).mesh).c3t3, iterations);
    else
      run(label, BODT::IO::read_mesh(f), iterations);
  }
  return 0;
}
