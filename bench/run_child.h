// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Runs a program as a child of GNU time, for the benches that time `bodt`.
#ifndef BODT_BENCH_RUN_CHILD_H
#define BODT_BENCH_RUN_CHILD_H

#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

extern char** environ;

namespace bodt_bench {

struct Child_times
{
  double wall = 0, user = 0, sys = 0, peak_mb = 0;
};

/// Runs `args` (a program's path and its arguments) under GNU time, which reports
/// its CPU time and peak resident set through `times_file` (removed after): a
/// child spawned from the bench directly would count the bench's resident set (a
/// generated mesh) while it shares its memory before exec. Throws if the program
/// cannot start or does not exit with status 0.
inline Child_times run_child(std::vector<std::string> args, const std::filesystem::path& times_file)
{
  std::string command = args.at(0);
  for(std::size_t k = 1; k < args.size(); ++k) command += " " + args[k];
  args.insert(args.begin(), {"/usr/bin/time", "-f", "%U %S %M", "-o", times_file.string()});
  std::vector<char*> argv;
  for(const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  const auto start = std::chrono::steady_clock::now();
  pid_t pid;
  if(posix_spawn(&pid, argv[0], nullptr, nullptr, argv.data(), environ) != 0)
    throw std::runtime_error("cannot start " + args[0]);
  int status = 0;
  if(waitpid(pid, &status, 0) != pid) throw std::runtime_error("lost the child running " + command);
  if(!WIFEXITED(status) || WEXITSTATUS(status) != 0)
    throw std::runtime_error(command + " failed (" +
                             (WIFEXITED(status) ? "exit status " + std::to_string(WEXITSTATUS(status))
                                                : "signal " + std::to_string(WTERMSIG(status))) + ")");
  Child_times t;
  t.wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  double kilobytes = 0;
  if(!(std::ifstream(times_file) >> t.user >> t.sys >> kilobytes))
    throw std::runtime_error("cannot read GNU time's " + times_file.string());
  t.peak_mb = kilobytes / 1024.0;
  std::filesystem::remove(times_file);
  return t;
}

} // namespace bodt_bench

#endif // BODT_BENCH_RUN_CHILD_H
