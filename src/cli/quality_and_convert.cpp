// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
#include "cli/commands.h"
#include "cli/outputs.h"
#include "report/json_report.h"

#include <CGAL/BODT_3/IO/mesh_io.h>
#include <CGAL/BODT_3/mesh_quality.h>

#include <iostream>
#include <memory>
#include <sstream>

namespace bodt_cli {

namespace BODT = CGAL::BODT_3;
namespace IO = CGAL::BODT_3::IO;

namespace {

// The readers say that a section they skip "will not be written back", which is
// true of commands that write the mesh; `quality` writes nothing, so it says only
// that the section is not used.
void print_warnings_of_reading_only(const std::string& warnings)
{
  const std::string written_back = " and will not be written back";
  std::istringstream in(warnings);
  for(std::string line; std::getline(in, line);)
  {
    const std::size_t at = line.find(written_back);
    if(at != std::string::npos) line.erase(at, written_back.size());
    std::cerr << line << "\n";
  }
}

struct Quality_options
{
  std::string input;
  bool json = false;
  BODT::Quality_options quality;
};

int run_quality(const Quality_options& o)
{
  check_input_path(o.input);
  std::ostringstream warnings;
  const BODT::Tet_mesh mesh = IO::read_mesh(o.input, warnings);
  print_warnings_of_reading_only(warnings.str());
  const BODT::Quality_report report = BODT::mesh_quality(mesh, o.quality);
  if(o.json)
    std::cout << BODT::to_json(report) << "\n";
  else
    BODT::print_report(std::cout, report);
  return 0;
}

struct Convert_options
{
  std::string input, output, format;
};

int run_convert(const Convert_options& o)
{
  check_input_path(o.input);
  check_output_paths(o.input, {{"OUT", o.output}});
  const Output_format format = choose_output_format(o.output, o.format);
  IO::Mesh_file_format input_format;
  const BODT::Tet_mesh mesh = IO::read_mesh(o.input, input_format);
  write_output(o.output, mesh, format.resolve(o.output, input_format));
  return 0;
}

} // namespace

Command add_quality(CLI::App& command)
{
  auto o = std::make_shared<Quality_options>();
  command.footer(
      "Measures a tetrahedral mesh (.mesh, .msh): number of vertices and tetrahedra, minimum and maximum\n"
      "dihedral angle, tetrahedra below 10 and above 170 degrees (and where they are: interior, touching\n"
      "the boundary, all four vertices on it), radius ratio, total volume and volume per subdomain,\n"
      "inverted or flat tetrahedra (exact orientation predicates) and a dihedral-angle histogram.\n"
      "In a Medit file, tetrahedra labelled 0 are outside the mesh unless all are 0.");
  command.add_option("mesh", o->input, "the mesh")->required();
  command.add_flag("--json", o->json, "print one JSON object instead of text");
  command.add_option("--bins", o->quality.histogram_bins, "histogram bins over [0, 180] degrees (default 36)")
      ->check(CLI::Range(1, 18000));
  return [o]() { return run_quality(*o); };
}

Command add_convert(CLI::App& command)
{
  auto o = std::make_shared<Convert_options>();
  command.footer(
      "Converts a tetrahedral mesh between Medit (.mesh, .meshb), Gmsh (.msh 2.2 and 4.1, ASCII and\n"
      "binary), VTK (.vtu, legacy .vtk) and TetGen (.node/.ele/.face); the format follows each file name\n"
      "(keeping the input's variant when it is the same format), or --format. Vertices, tetrahedra and\n"
      "their labels, boundary triangles and feature edges are kept where the format can hold them\n"
      "(doc/formats.md). OUT is written to a temporary file and renamed, so a failed run leaves no\n"
      "partial output.");
  command.add_option("IN", o->input, "input mesh")->required();
  command.add_option("OUT", o->output, "output mesh")->required();
  command.add_option("--format", o->format, std::string("output format whatever the name: ") + IO::format_names())
      ->check(CLI::Validator(check_format_name, "FORMAT"));
  return [o]() { return run_convert(*o); };
}

} // namespace bodt_cli
