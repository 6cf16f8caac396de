// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
#include "cli/commands.h"

#include "compare/compare.h"

#include <filesystem>
#include <iostream>
#include <memory>
#include <set>

namespace bodt_cli {

namespace {

struct Compare_options
{
  std::string program;
  std::vector<std::string> files;
  bool small = false, no_generated = false, no_surfaces = false, quiet = false;
  std::string output_dir, data_dir = bodt_compare::default_data_dir(), stellar;
  std::size_t iterations = 20;
};

int run_compare(const Compare_options& o)
{
  bodt_compare::Options options;
  options.iterations = o.iterations;
  if(!o.quiet) options.log = [](const std::string& line) { std::cerr << "compare: " << line << std::endl; };
  const bodt_inputs::Size size = o.small ? bodt_inputs::Size::small : bodt_inputs::Size::benchmark;
  // Files named: a comparison on the user's own meshes, without the benchmark inputs.
  const bool generated = o.files.empty() && !o.no_generated;
  const bool surfaces = o.files.empty() && !o.no_surfaces;

  bodt_compare::Comparison comparison;
  comparison.command = o.program;
  comparison.benchmark = generated || surfaces;
  comparison.size = o.small ? "small" : "benchmark";
  comparison.iterations = options.iterations;
  comparison.machine = bodt_compare::this_machine();
  comparison.stellar = o.stellar;
  std::vector<bodt_compare::Method> table = bodt_compare::methods();
  if(!o.stellar.empty()) table.push_back(bodt_compare::stellar_method(o.stellar));

  // Every input is built before any method runs, so that the inputs do not depend
  // on what the methods did before them.
  std::vector<bodt_compare::Input> inputs;
  if(generated)
  {
    options.log("meshing the generated inputs");
    inputs = bodt_compare::generated_inputs(size);
  }
  if(surfaces)
    for(const bodt_compare::Data_surface& s : bodt_compare::data_surfaces())
    {
      const std::filesystem::path path = std::filesystem::path(o.data_dir) / s.file;
      if(!std::filesystem::exists(path))
      {
        comparison.notes.push_back("`" + s.file + "` (" + s.note + ") was not found in the data folder: run "
                                   "`bash scripts/setup.sh` to extract it.");
        continue;
      }
      options.log("meshing " + path.string());
      inputs.push_back(bodt_compare::surface_input(path.string(), size));
      inputs.back().origin += ": " + s.note;
    }
  for(const std::string& file : o.files)
  {
    options.log("reading " + file);
    const bool surface = file.size() > 4 && file.compare(file.size() - 4, 4, ".off") == 0;
    inputs.push_back(surface ? bodt_compare::surface_input(file, size) : bodt_compare::file_input(file));
  }
  if(inputs.empty()) throw Usage_error("no input: name mesh files or leave the generated inputs in");
  // Names become file names: two inputs must not share one.
  std::set<std::string> names;
  for(bodt_compare::Input& input : inputs)
  {
    const std::string base = input.name;
    for(int k = 2; !names.insert(input.name).second; ++k) input.name = base + "_" + std::to_string(k);
  }

  for(const bodt_compare::Input& input : inputs)
    comparison.inputs.push_back(bodt_compare::compare(input, table, options));

  if(o.output_dir.empty())
    std::cout << bodt_compare::markdown(comparison, table, "results");
  else
  {
    bodt_compare::write_results(comparison, table, o.output_dir);
    options.log("wrote " + (std::filesystem::path(o.output_dir) / "results.md").string());
  }
  return 0;
}

} // namespace

Command add_compare(CLI::App& command, const std::string& command_line)
{
  auto o = std::make_shared<Compare_options>();
  o->program = command_line;
  command.footer(
      "Runs every smoothing method side by side and measures the results: the input, interior-only ODT,\n"
      "flips alone, NODT, B-ODT smoothing alone, the pipeline without insertion, the basic and the default\n"
      "pipeline (B-ODT, flips, max-min, insertion), and on Mesh_3 outputs CGAL's\n"
      "odt_optimize_mesh_3, lloyd_optimize_mesh_3, perturb_mesh_3 + exude_mesh_3 and\n"
      "tetrahedral_isotropic_remeshing. With no file named, the inputs are the benchmark's: the generated\n"
      "Mesh_3 meshes, the random sphere, and CGAL's data surfaces found in the data folder (meshed by\n"
      "Mesh_3 with their sharp edges). With files named, only those: .mesh or .msh meshes (our methods\n"
      "only) or closed .off surfaces (meshed, every method). Reports dihedral angles, tetrahedra below 10\n"
      "and above 170 degrees, vertices added, volume change, relative Hausdorff distance of the boundary,\n"
      "and time. The benchmark takes a long while: CGAL's optimizers are slow. With --stellar, Klingner and\n"
      "Shewchuk's Stellar runs too, as an external program on every input with one subdomain (build it with\n"
      "scripts/build_stellar.sh); it takes minutes per input at the benchmark size (doc/stellar.md).");
  command.add_option("MESH", o->files, "your own meshes (.mesh, .msh) or closed surfaces (.off)");
  command.add_flag("--small", o->small, "small inputs (a few thousand tetrahedra): a quick run");
  command.add_option("--output-dir", o->output_dir,
                     "write DIR/results.md, DIR/results.json and DIR/results/*.svg (default: print the Markdown)");
  command.add_option("--data-dir", o->data_dir, "where to look for CGAL's surfaces (default: build/data)");
  command.add_option("--iterations", o->iterations, "iterations of every iterative method (default 20)")
      ->check(CLI::Range(1, 10000));
  command.add_flag("--no-generated", o->no_generated, "leave out the generated inputs and the random sphere");
  command.add_flag("--no-surfaces", o->no_surfaces, "leave out CGAL's data surfaces");
  command.add_option("--stellar", o->stellar, "also run Stellar, this executable, on every input with one subdomain")
      ->check(CLI::ExistingFile);
  command.add_flag("-q,--quiet", o->quiet, "no progress on stderr");
  return [o]() { return run_compare(*o); };
}

} // namespace bodt_cli
