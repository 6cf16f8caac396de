// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
#include "cli/commands.h"

namespace bodt_cli {

bool Arguments::flag(const std::string& name)
{
  bool found = false;
  for(std::size_t i = 0; i < args_.size(); ++i)
    if(!used_[i] && args_[i] == name) { used_[i] = true; found = true; }
  return found;
}

bool Arguments::option(const std::string& name, std::string& value)
{
  for(std::size_t i = 0; i < args_.size(); ++i)
  {
    if(used_[i]) continue;
    if(args_[i] == name)
    {
      if(i + 1 >= args_.size()) throw Usage_error("option " + name + " needs a value");
      used_[i] = used_[i + 1] = true;
      value = args_[i + 1];
      return true;
    }
    if(args_[i].compare(0, name.size() + 1, name + "=") == 0)
    {
      used_[i] = true;
      value = args_[i].substr(name.size() + 1);
      return true;
    }
  }
  return false;
}

std::vector<std::string> Arguments::positionals()
{
  std::vector<std::string> out;
  for(std::size_t i = 0; i < args_.size(); ++i)
  {
    if(used_[i]) continue;
    if(args_[i].size() > 1 && args_[i][0] == '-')
      throw Usage_error("unknown option '" + args_[i] + "'");
    out.push_back(args_[i]);
  }
  return out;
}

} // namespace bodt_cli
