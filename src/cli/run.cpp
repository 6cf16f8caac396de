// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
#include "cli/commands.h"

#include <CGAL/version.h>

#include <exception>
#include <iostream>
#include <new>

namespace bodt_cli {

std::string version_text() { return std::string("bodt ") + BODT_VERSION + " (BODT_3, CGAL " + CGAL_VERSION_STR + ")"; }

int run(CLI::App& app, int argc, char** argv, const std::vector<std::pair<CLI::App*, Command>>& commands)
{
  // The name of the command that failed, for messages: "bodt smooth".
  auto who = [&]() {
    for(const auto& c : commands)
      if(c.first != &app && c.first->parsed()) return app.get_name() + " " + c.first->get_name();
    return app.get_name();
  };
  try
  {
    app.parse(argc, argv);
  }
  catch(const CLI::ParseError& e)
  {
    if(e.get_exit_code() == 0) return app.exit(e);   // --help, --version
    std::cerr << who() << ": " << e.what() << "\n(see '" << who() << " --help')\n";
    return 2;
  }
  try
  {
    for(const auto& c : commands)
      if(c.first->parsed()) return c.second();
    std::cerr << app.help();
    return 2;
  }
  catch(const Usage_error& e)
  {
    std::cerr << who() << ": " << e.what() << "\n(see '" << who() << " --help')\n";
    return 2;
  }
  catch(const std::bad_alloc&)
  {
    std::cerr << who() << ": error: out of memory\n";
    return 1;
  }
  catch(const std::exception& e)
  {
    std::cerr << who() << ": error: " << e.what() << "\n";
    return 1;
  }
}

} // namespace bodt_cli
