// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef BODT_CLI_COMMANDS_H
#define BODT_CLI_COMMANDS_H

#include <stdexcept>
#include <string>
#include <vector>

namespace bodt_cli {

/// Wrong command-line usage: exit status 2.
struct Usage_error : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

/// Command-line arguments of one subcommand: flags, options with a value, and
/// positional arguments, with errors for anything unknown or missing.
class Arguments
{
public:
  explicit Arguments(const std::vector<std::string>& args) : args_(args), used_(args.size(), false) {}

  bool flag(const std::string& name);
  bool option(const std::string& name, std::string& value);
  std::vector<std::string> positionals();   // call last: rejects unknown options

private:
  std::vector<std::string> args_;
  std::vector<bool> used_;
};

int quality(const std::vector<std::string>& args);
int convert(const std::vector<std::string>& args);
int smooth(const std::vector<std::string>& args);
/// `program` is how the command was invoked, for the header of the results.
int compare(const std::vector<std::string>& args, const std::string& program = "bodt compare");

} // namespace bodt_cli

#endif // BODT_CLI_COMMANDS_H
