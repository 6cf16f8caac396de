// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Side-by-side comparison of smoothing methods (ours, CGAL's and, when built,
// Stellar) on the same inputs, in the same run: the inputs, the table of
// methods, the measurements, and the reports (Markdown, JSON, SVG histograms).
// Used by `bodt compare` (src/cli/compare.cpp) and test/cli/compare.cpp.
#ifndef BODT_COMPARE_COMPARE_H
#define BODT_COMPARE_COMPARE_H

#include "inputs/generated_inputs.h"

#include <CGAL/BODT_3/Smoothing_options.h>
#include <CGAL/BODT_3/Smoothing_result.h>
#include <CGAL/BODT_3/Tet_mesh.h>
#include <CGAL/BODT_3/mesh_quality.h>
#include <CGAL/Mesh_optimization_return_code.h>
#include <CGAL/Mesh_polyhedron_3.h>
#include <CGAL/Polyhedral_mesh_domain_with_features_3.h>

#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <variant>
#include <vector>

namespace bodt_compare {

namespace BODT = CGAL::BODT_3;
using bodt_inputs::K;

// Mesh_3 on a closed triangulated surface with its sharp edges detected.
using Polyhedron = CGAL::Mesh_polyhedron_3<K>::type;
using Surface_domain = CGAL::Polyhedral_mesh_domain_with_features_3<K>;
using Surface_tr = CGAL::Mesh_triangulation_3<Surface_domain, CGAL::Default, CGAL::Sequential_tag>::type;
using Surface_c3t3 = CGAL::Mesh_complex_3_in_triangulation_3<Surface_tr, Surface_domain::Corner_index,
                                                             Surface_domain::Curve_index>;

/// A Mesh_3 output from a surface, with the domain kept for CGAL's optimizers.
struct Surface_mesh
{
  std::shared_ptr<Surface_domain> domain;
  Surface_c3t3 c3t3;
  double h = 0;   // the length of every Mesh_3 size criterion (mesh_3.cpp)
};

/// Every kind of input: Mesh_3 outputs of an implicit domain and of a surface
/// (CGAL's optimizers apply to both), a Delaunay triangulation, a mesh file.
using Mesh = std::variant<bodt_inputs::Generated_mesh, Surface_mesh, bodt_inputs::Delaunay, BODT::Tet_mesh>;

inline bool built_by_mesh_3(const Mesh& m)
{
  return std::holds_alternative<bodt_inputs::Generated_mesh>(m) || std::holds_alternative<Surface_mesh>(m);
}

struct Input
{
  std::string name;     // short, also the file name of its histogram
  std::string origin;   // how it was built, for the report
  Mesh mesh;
};

/// The generated inputs (generated_inputs.h), the paper's Random Sphere rebuilt,
/// and a Delaunay triangulation of points on the sphere (a Triangulation_3 input).
std::vector<Input> generated_inputs(bodt_inputs::Size size);

/// CGAL's data surfaces looked for in the data folder, with what they stand for.
struct Data_surface
{
  std::string file;
  std::string note;
};
const std::vector<Data_surface>& data_surfaces();

/// A Mesh_3 mesh (features detected, no perturbation, no exudation) of the closed
/// surface in `off_path`, sized for about 40,000 tetrahedra (`Size::benchmark`) or
/// 4,000 (`Size::small`). Throws std::runtime_error if the surface is not closed.
Input surface_input(const std::string& off_path, bodt_inputs::Size size);
/// The same for about `target_cells` tetrahedra (within 15% unless the surface's
/// features need more). Beyond 40,000 the size is calibrated on a mesh of 40,000.
Input surface_input(const std::string& off_path, double target_cells);
/// The mesh `surface_input` made with the size `h` it found (`Surface_mesh::h`):
/// Mesh_3 gives the same mesh for the same surface and size.
Input surface_input_with_size(const std::string& off_path, double h);

/// A mesh file (.mesh, .msh), named after its stem.
Input file_input(const std::string& path);

// -- Methods ---------------------------------------------------------------

enum class Family { reference, ours, cgal, external };
enum class Applies_to { every_mesh, mesh_3_output, one_subdomain };

/// How a CGAL optimizer ended, as text ("max_iteration_number_reached", ...).
std::string outcome_name(CGAL::Mesh_optimization_return_code code);

/// What a method run reports besides the mesh: the number of iterations it ran
/// (0 for a method without iterations) and how it ended.
struct Run
{
  Run(std::size_t n = 0, std::string how = std::string()) : iterations(n), outcome(std::move(how)) {}

  std::size_t iterations = 0;
  std::string outcome;
  BODT::Topology_stats flips;        // our methods: flips done
  double child_cpu_seconds = 0;      // an external program: the user time of its process
};

/// One row of the comparison: a name (a column of the tables), where it applies,
/// what exactly is called, and the call, which modifies its copy of the input.
struct Method
{
  std::string name;
  Family family;
  Applies_to applies_to;
  std::string settings;
  std::function<Run(Mesh&, std::size_t iterations)> run;
};

/// The methods compared, in table order. Adding a method is adding a line there.
const std::vector<Method>& methods();

// Names the reports single out.
extern const char* const original_name;                 // the input, unchanged
extern const char* const odt_interior_name;             // the paper's baseline: interior ODT, no flips
extern const char* const bodt_no_flips_name;            // B-ODT smoothing alone
extern const char* const flips_name;                    // topology optimization alone
extern const char* const nodt_name;                     // Natural ODT smoothing alone (the paper's comparison)
extern const char* const bodt_flips_name;               // the default pipeline without vertex insertion
extern const char* const bodt_basic_name;               // the default pipeline, Algorithm 2 on every boundary vertex
extern const char* const bodt_name;                     // the default pipeline
extern const char* const after_perturb_exude_name;      // the default pipeline after make_mesh_3's default
extern const char* const cgal_odt_name;                 // the reference for throughput ratios
extern const char* const cgal_odt_perturb_exude_name;   // make_mesh_3 with odt()

/// Klingner and Shewchuk's Stellar (`executable`), run as a child process on the
/// input written as TetGen .node/.ele, with the boundary kept (stellar.cpp). The
/// run throws std::runtime_error, which `compare` reports, when Stellar fails.
Method stellar_method(const std::string& executable);
extern const char* const stellar_name;

// CGAL's methods on Mesh_3 outputs (compiled in mesh_3.cpp with the other Mesh_3 code).
Run cgal_odt(Mesh& mesh, std::size_t iterations);
Run cgal_lloyd(Mesh& mesh, std::size_t iterations);
Run cgal_perturb_exude(Mesh& mesh, std::size_t iterations);
Run cgal_remeshing(Mesh& mesh, std::size_t iterations);

// -- Measurements ----------------------------------------------------------

struct Measurement
{
  std::string method;
  bool applied = false;             // false: the method does not apply to this input, or did not run
  std::string not_run;              // why an external method gave no mesh: it failed, or several subdomains
  Run run;
  BODT::Quality_report quality;
  long long vertices_added = 0;
  double relative_volume_change = 0;   // (after - before) / before
  double relative_hausdorff = 0;       // boundary before vs after, over the largest bbox side
  double cpu_seconds = 0;              // user time of the process spent in the call
  double wall_seconds = 0;
  std::size_t input_tets = 0;

  double seconds_per_iteration() const;   // NaN without iterations
  double throughput() const;              // input tets x iterations / CPU second; NaN without iterations
};

struct Input_result
{
  std::string name;
  std::string origin;
  BODT::Quality_report before;
  std::vector<Measurement> rows;   // one per method, in table order

  const Measurement* row(const std::string& method) const;   // null if absent or not applied
};

struct Options
{
  std::size_t iterations = 20;
  std::function<void(const std::string&)> log = [](const std::string&) {};
};

/// Runs every applicable method on a copy of `input` and measures the result. An
/// external method that throws gets a row with `not_run` set; other errors propagate.
Input_result compare(const Input& input, const std::vector<Method>& table, const Options& options);

// -- Reports ---------------------------------------------------------------

struct Machine
{
  std::string cpu;
  unsigned cores = 0;
  std::string compiler;
  std::string cgal;
  std::string date;   // "YYYY-MM-DD HH:MM UTC"
};
Machine this_machine();

struct Comparison
{
  std::string command;   // the command line that produced it
  /// The benchmark's inputs (generated, CGAL's surfaces) are in; false when the
  /// comparison is on the user's own files only, which the text then says.
  bool benchmark = true;
  std::string size;      // "benchmark" or "small"
  std::size_t iterations = 20;
  Machine machine;
  std::vector<Input_result> inputs;
  std::vector<std::string> notes;   // inputs skipped, and why
  std::string stellar;              // Stellar's executable as given; empty: Stellar was not run
};

/// The whole results file: tables, histograms (as `svg_dir`/NAME.svg), text.
std::string markdown(const Comparison& c, const std::vector<Method>& table, const std::string& svg_dir);
std::string json(const Comparison& c, const std::vector<Method>& table);
/// The dihedral-angle histograms of one input: original, B-ODT advanced and the
/// CGAL method with the largest minimum angle.
std::string input_histogram_svg(const Input_result& r, const std::vector<Method>& table);
/// The input's name as a file name.
std::string file_stem(const std::string& name);

/// Writes `dir`/results.md, `dir`/results.json and `dir`/results/NAME.svg,
/// creating the folders.
void write_results(const Comparison& c, const std::vector<Method>& table, const std::string& dir);

/// Where scripts/setup.sh extracts CGAL's data files (build/data in the source tree).
std::string default_data_dir();

} // namespace bodt_compare

#endif // BODT_COMPARE_COMPARE_H
