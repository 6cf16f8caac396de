// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
#include "cli/commands.h"

#include "compare/compare.h"

#include <filesystem>
#include <iostream>
#include <set>

namespace bodt_cli {

namespace {

const char* const compare_help =
    "usage: bodt compare [options] [MESH...]   (or bench/compare [options] [MESH...])\n\n"
    "Runs every smoothing method side by side and measures the results: the input,\n"
    "interior-only ODT, B-ODT basic (Algorithm 2) and advanced (Algorithm 3, the\n"
    "default), and on Mesh_3 outputs CGAL's odt_optimize_mesh_3, lloyd_optimize_mesh_3,\n"
    "perturb_mesh_3 + exude_mesh_3 and tetrahedral_isotropic_remeshing. Inputs: the\n"
    "generated Mesh_3 meshes and the random sphere, CGAL's data surfaces found in the\n"
    "data folder (meshed by Mesh_3 with their sharp edges), and the files named: .mesh\n"
    "or .msh meshes (our methods only) or closed .off surfaces (meshed, every method).\n"
    "Reports dihedral angles, tetrahedra below 10 and above 170 degrees, vertices\n"
    "added, volume change, relative Hausdorff distance of the boundary, and time. At\n"
    "the benchmark size this takes a long while: CGAL's optimizers are slow.\n\n"
    "  --small            small inputs (a few thousand tetrahedra): a quick run\n"
    "  --output-dir DIR   write DIR/results.md, DIR/results.json and DIR/results/*.svg\n"
    "                     (default: print the Markdown on stdout)\n"
    "  --data-dir DIR     where to look for CGAL's surfaces (default: build/data in the\n"
    "                     source tree, where scripts/setup.sh extracts them)\n"
    "  --iterations N     iterations of every iterative method (default 20)\n"
    "  --no-generated     leave out the generated inputs and the random sphere\n"
    "  --no-surfaces      leave out CGAL's data surfaces\n"
    "  --quiet            no progress on stderr\n";

} // namespace

int compare(const std::vector<std::string>& args, const std::string& program)
{
  Arguments a(args);
  if(a.flag("--help") || a.flag("-h"))
  {
    std::cout << compare_help;
    return 0;
  }
  const bool small = a.flag("--small");
  const bool generated = !a.flag("--no-generated");
  const bool surfaces = !a.flag("--no-surfaces");
  const bool quiet = a.flag("--quiet");
  std::string output_dir, data_dir = bodt_compare::default_data_dir(), iterations_text;
  a.option("--output-dir", output_dir);
  a.option("--data-dir", data_dir);
  bodt_compare::Options options;
  if(a.option("--iterations", iterations_text))
  {
    std::size_t pos = 0;
    long long n = 0;
    try { n = std::stoll(iterations_text, &pos); } catch(...) {}
    if(pos != iterations_text.size() || n < 1 || n > 10000)
      throw Usage_error("--iterations must be an integer from 1 to 10000");
    options.iterations = static_cast<std::size_t>(n);
  }
  const std::vector<std::string> files = a.positionals();

  if(!quiet) options.log = [](const std::string& line) { std::cerr << "compare: " << line << std::endl; };
  const bodt_inputs::Size size = small ? bodt_inputs::Size::small : bodt_inputs::Size::benchmark;

  bodt_compare::Comparison comparison;
  comparison.command = program;
  for(const std::string& arg : args) comparison.command += " " + arg;
  comparison.size = small ? "small" : "benchmark";
  comparison.iterations = options.iterations;
  comparison.machine = bodt_compare::this_machine();

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
      const std::filesystem::path path = std::filesystem::path(data_dir) / s.file;
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
  for(const std::string& file : files)
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
    comparison.inputs.push_back(bodt_compare::compare(input, bodt_compare::methods(), options));

  if(output_dir.empty())
    std::cout << bodt_compare::markdown(comparison, bodt_compare::methods(), "results");
  else
  {
    bodt_compare::write_results(comparison, bodt_compare::methods(), output_dir);
    options.log("wrote " + (std::filesystem::path(output_dir) / "results.md").string());
  }
  return 0;
}

} // namespace bodt_cli
