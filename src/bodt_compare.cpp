// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// bodt-compare (also run as `bodt compare`): B-ODT beside ODT and CGAL's
// optimizers. A program of its own because it instantiates CGAL's Mesh_3 and its
// optimizers, which `bodt smooth` never needs.

#include "cli/commands.h"

int main(int argc, char** argv)
{
  // `bodt compare` runs this program with argv[0] = "bodt compare".
  const std::string program = argc > 0 ? argv[0] : "bodt-compare";
  // The results record the command that made them.
  std::string command_line = program;
  for(int i = 1; i < argc; ++i) command_line += std::string(" ") + argv[i];
  CLI::App app("", program);
  app.set_version_flag("--version", bodt_cli::version_text());
  const bodt_cli::Command compare = bodt_cli::add_compare(app, command_line);
  return bodt_cli::run(app, argc, argv, {{&app, compare}});
}
