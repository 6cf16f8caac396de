// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
#include "cli/commands.h"

#include <CGAL/BODT_3/IO/mesh_io.h>
#include <CGAL/BODT_3/mesh_quality.h>

#include <iostream>

namespace bodt_cli {

namespace IO = CGAL::BODT_3::IO;

int quality(const std::vector<std::string>& argv)
{
  Arguments args(argv);
  if(args.flag("--help") || args.flag("-h"))
  {
    std::cout << "usage: bodt quality MESH [--json] [--bins N]\n\n"
                 "Measures a tetrahedral mesh (.mesh, .msh): number of vertices and tetrahedra,\n"
                 "minimum and maximum dihedral angle, tetrahedra below 10 and above 170 degrees,\n"
                 "radius ratio, total volume and volume per subdomain, inverted or flat tetrahedra\n"
                 "(exact orientation predicates) and a dihedral-angle histogram.\n"
                 "In a Medit file, tetrahedra labelled 0 are outside the mesh unless all are 0.\n\n"
                 "  --json     print one JSON object instead of text\n"
                 "  --bins N   histogram bins over [0, 180] degrees (default 36)\n";
    return 0;
  }
  const bool json = args.flag("--json");
  CGAL::BODT_3::Quality_options opt;
  std::string bins;
  if(args.option("--bins", bins))
  {
    try { opt.histogram_bins = std::stoi(bins); } catch(...) { opt.histogram_bins = 0; }
    if(opt.histogram_bins < 1 || opt.histogram_bins > 18000)
      throw Usage_error("--bins must be an integer from 1 to 18000");
  }
  const auto files = args.positionals();
  if(files.size() != 1) throw Usage_error("expected exactly one mesh file");
  const CGAL::BODT_3::Tet_mesh mesh = IO::read_mesh(files[0]);
  const auto report = CGAL::BODT_3::mesh_quality(mesh, opt);
  if(json)
    std::cout << CGAL::BODT_3::to_json(report) << "\n";
  else
    CGAL::BODT_3::print_report(std::cout, report);
  return 0;
}

int convert(const std::vector<std::string>& argv)
{
  Arguments args(argv);
  if(args.flag("--help") || args.flag("-h"))
  {
    std::cout << "usage: bodt convert IN OUT\n\n"
                 "Converts a tetrahedral mesh between Medit (.mesh), Gmsh (.msh) and VTK (.vtu,\n"
                 "write only); the format follows each file name. Vertices, tetrahedra and their\n"
                 "labels, boundary triangles and feature edges are kept. OUT is written to a\n"
                 "temporary file and renamed, so a failed run leaves no partial output.\n";
    return 0;
  }
  const auto files = args.positionals();
  if(files.size() != 2) throw Usage_error("expected an input and an output file");
  if(IO::format_of(files[1]) == IO::Mesh_format::unknown)
    throw Usage_error("cannot tell the output format from '" + files[1] + "'");
  const CGAL::BODT_3::Tet_mesh mesh = IO::read_mesh(files[0]);
  IO::write_mesh(files[1], mesh);
  return 0;
}

} // namespace bodt_cli
