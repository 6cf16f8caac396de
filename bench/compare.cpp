// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The side-by-side comparison (`bodt compare`) as a benchmark program:
//   compare [--small] [--output-dir DIR] [MESH...]   ('compare --help' for all options)
// Exit status: 0 success, 1 failed run, 2 wrong usage.
#include "cli/commands.h"

#include <exception>
#include <iostream>
#include <new>

int main(int argc, char** argv)
{
  const std::string program = argv[0];
  try
  {
    return bodt_cli::compare(std::vector<std::string>(argv + 1, argv + argc), program);
  }
  catch(const bodt_cli::Usage_error& e)
  {
    std::cerr << program << ": " << e.what() << "\n(see '" << program << " --help')\n";
    return 2;
  }
  catch(const std::bad_alloc&)
  {
    std::cerr << program << ": error: out of memory\n";
    return 1;
  }
  catch(const std::exception& e)
  {
    std::cerr << program << ": error: " << e.what() << "\n";
    return 1;
  }
}
