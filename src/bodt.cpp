// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// bodt: the command-line tool. Each subcommand is a function taking its own
// arguments; main() only dispatches and turns exceptions into exit statuses
// (0 success, 1 bad input or failed run, 2 wrong usage).

#include "cli/commands.h"

#include <cstring>
#include <exception>
#include <iostream>
#include <new>
#include <string>
#include <vector>

namespace {

const char* const usage =
    "usage: bodt <command> [options]\n"
    "\n"
    "Tetrahedral mesh smoothing by boundary-optimized Delaunay triangulation (B-ODT).\n"
    "\n"
    "commands:\n"
    "  quality MESH [--json]   dihedral angles, volume and validity of a mesh\n"
    "  convert IN OUT          convert between .mesh (Medit), .msh (Gmsh) and .vtu (VTK)\n"
    "  smooth IN -o OUT        improve a mesh by B-ODT smoothing\n"
    "  compare [MESH...]       B-ODT beside ODT and CGAL's optimizers: tables and histograms\n"
    "\n"
    "'bodt <command> --help' describes a command.\n";

} // namespace

int main(int argc, char** argv)
{
  if(argc < 2 || !std::strcmp(argv[1], "--help") || !std::strcmp(argv[1], "-h") ||
     !std::strcmp(argv[1], "help"))
  {
    (argc < 2 ? std::cerr : std::cout) << usage;
    return argc < 2 ? 2 : 0;
  }
  const std::string command = argv[1];
  const std::vector<std::string> args(argv + 2, argv + argc);
  try
  {
    if(command == "quality") return bodt_cli::quality(args);
    if(command == "convert") return bodt_cli::convert(args);
    if(command == "smooth") return bodt_cli::smooth(args);
    if(command == "compare") return bodt_cli::compare(args);
    std::cerr << "bodt: unknown command '" << command << "'\n\n" << usage;
    return 2;
  }
  catch(const bodt_cli::Usage_error& e)
  {
    std::cerr << "bodt " << command << ": " << e.what() << "\n(see 'bodt " << command << " --help')\n";
    return 2;
  }
  catch(const std::bad_alloc&)
  {
    std::cerr << "bodt " << command << ": error: out of memory\n";
    return 1;
  }
  catch(const std::exception& e)
  {
    std::cerr << "bodt " << command << ": error: " << e.what() << "\n";
    return 1;
  }
}
