// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// bodt: the command-line tool. `bodt compare` is a program of its own,
// bodt-compare, installed beside bodt: it instantiates CGAL's Mesh_3 and its
// optimizers, which `smooth` never needs, and would make bodt slow to build.

#include "cli/commands.h"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <malloc.h>
#include <string>
#include <unistd.h>
#include <vector>

namespace {

// Replaces this process by bodt-compare from bodt's own folder; returns only on failure.
int exec_compare(int argc, char** argv)
{
  std::error_code ec;
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", ec);
  const std::filesystem::path compare = (ec ? std::filesystem::path(argv[0]) : self).parent_path() / "bodt-compare";
  std::vector<char*> args;
  std::string name = "bodt compare";
  args.push_back(name.data());
  for(int i = 2; i < argc; ++i) args.push_back(argv[i]);
  args.push_back(nullptr);
  ::execv(compare.c_str(), args.data());
  std::cerr << "bodt compare: error: cannot run " << compare.string() << ": " << std::strerror(errno)
            << "\n(bodt compare is the program bodt-compare; build it with 'cmake --build build --target "
               "bodt-compare')\n";
  return 1;
}

} // namespace

int main(int argc, char** argv)
{
  if(argc >= 2 && std::string(argv[1]) == "compare") return exec_compare(argc, argv);
  // glibc raises its mmap threshold after large blocks are freed, so the arrays a
  // run rebuilds (flip passes, re-reads) then come from the heap and their freed
  // space stays resident: on a 187,000-tetrahedron mesh the peak was 20 MB (20%)
  // above what the heap held. A fixed threshold keeps large blocks mapped and
  // returns them when freed.
  mallopt(M_MMAP_THRESHOLD, 128 * 1024);

  CLI::App app("Tetrahedral mesh smoothing by boundary-optimized Delaunay triangulation (B-ODT).", "bodt");
  app.set_version_flag("--version", bodt_cli::version_text());
  app.require_subcommand(0, 1);
  app.footer("'bodt <command> --help' describes a command.");
  std::vector<std::pair<CLI::App*, bodt_cli::Command>> commands;
  auto add = [&](const char* name, const char* what, auto declare) {
    CLI::App* command = app.add_subcommand(name, what);
    commands.emplace_back(command, declare(*command));
  };
  add("quality", "dihedral angles, volume and validity of a mesh", bodt_cli::add_quality);
  add("convert", "convert between .mesh (Medit), .msh (Gmsh) and .vtu (VTK)", bodt_cli::add_convert);
  add("smooth", "improve a mesh by B-ODT smoothing, flips and vertex insertion", bodt_cli::add_smooth);
  // Listed for the help only: main() hands `compare` to bodt-compare before parsing.
  app.add_subcommand("compare", "B-ODT beside ODT and CGAL's optimizers (the program bodt-compare)")
      ->prefix_command();
  if(argc < 2)
  {
    std::cerr << app.help();
    return 2;
  }
  return bodt_cli::run(app, argc, argv, commands);
}
