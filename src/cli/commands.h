// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef BODT_CLI_COMMANDS_H
#define BODT_CLI_COMMANDS_H

// The subcommands of `bodt`. Each one declares its options on a CLI11 (sub)command
// and runs from the values parsed; main() only dispatches and turns exceptions
// into exit statuses (0 success, 1 bad input or failed run, 2 wrong usage).

#include "cli/usage_error.h"

#include <CLI/CLI.hpp>

#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace bodt_cli {

/// Declares a subcommand's options on `command`; the function returned runs it
/// with the values parsed and returns the exit status.
using Command = std::function<int()>;

Command add_quality(CLI::App& command);
Command add_convert(CLI::App& command);
Command add_smooth(CLI::App& command);
/// `command_line` is the command as invoked, which the results record.
Command add_compare(CLI::App& command, const std::string& command_line);

/// "bodt 0.1.0 (CGAL 5.5.1)".
std::string version_text();

/// Runs `app` on the command line: parses it, runs the command chosen, and turns
/// errors into messages on stderr and exit statuses. `commands` maps each
/// subcommand (or `app` itself, for a program with no subcommands) to what runs it.
int run(CLI::App& app, int argc, char** argv, const std::vector<std::pair<CLI::App*, Command>>& commands);

} // namespace bodt_cli

#endif // BODT_CLI_COMMANDS_H
