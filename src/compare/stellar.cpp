// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Klingner and Shewchuk's Stellar as a method of the comparison: the input goes
// to Stellar as TetGen files, Stellar runs as a child process, and its output is
// read back. No Stellar code is in this project: the user builds it from its
// sources (scripts/build_stellar.sh).
#include "compare/compare.h"

#include <CGAL/BODT_3/IO/tetgen.h>
#include <CGAL/BODT_3/Tet_mesh_conversion.h>

#include <array>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <sys/resource.h>
#include <sys/wait.h>
#include <type_traits>
#include <unistd.h>
#include <variant>

namespace bodt_compare {

const char* const stellar_name = "Stellar";

namespace {

namespace fs = std::filesystem;

// Stellar's options (described in its EXAMPLE_CONFIG); the others keep Stellar's
// defaults. Quadric smoothing is on by default in its code: off, the vertices of
// curved boundary stay where they are, as the boundary-keeping methods here.
const std::pair<const char*, const char*> stellar_config[] = {
    {"qualmeasure", "0"},   // the minimum sine of the dihedral angles (its default)
    {"usequadrics", "0"},
    {"verbosity", "0"},
    {"minsineout", "0"},    // no quality file beside the mesh
};

// The tetrahedra of `cells` on the points they use, renumbered, mirrored: Stellar
// reads CGAL's positive orientation as inverted.
BODT::Tet_mesh stellar_input(const std::vector<BODT::Tet_mesh::Point>& points,
                             const std::vector<std::array<int, 4>>& cells)
{
  BODT::Tet_mesh out;
  std::vector<int> index(points.size(), -1);
  for(const auto& c : cells)
  {
    std::array<int, 4> t;
    for(int k = 0; k < 4; ++k)
    {
      int& i = index[static_cast<std::size_t>(c[k])];
      if(i < 0)
      {
        i = static_cast<int>(out.points.size());
        out.points.push_back(points[static_cast<std::size_t>(c[k])]);
      }
      t[k] = i;
    }
    std::swap(t[0], t[1]);
    out.tets.push_back(t);
  }
  out.vertex_refs.assign(out.points.size(), 0);
  out.tet_labels.assign(out.tets.size(), 1);
  return out;
}

BODT::Tet_mesh stellar_input(const Mesh& mesh)
{
  return std::visit(
      [](const auto& m) {
        using M = std::decay_t<decltype(m)>;
        BODT::Tet_mesh t;
        if constexpr(std::is_same_v<M, BODT::Tet_mesh>)
        {
          const bool all_zero = m.all_labels_zero();
          t.points = m.points;
          for(std::size_t c = 0; c < m.tets.size(); ++c)
            if(m.in_mesh(c, all_zero)) t.tets.push_back(m.tets[c]);
        }
        else if constexpr(std::is_same_v<M, bodt_inputs::Delaunay>)
        {
          std::map<bodt_inputs::Delaunay::Vertex_handle, int> index;
          for(auto v : m.finite_vertex_handles())
          {
            index.emplace(v, static_cast<int>(t.points.size()));
            t.points.push_back(v->point());
          }
          for(auto c : m.finite_cell_handles())
            t.tets.push_back({index.at(c->vertex(0)), index.at(c->vertex(1)), index.at(c->vertex(2)),
                              index.at(c->vertex(3))});
        }
        else
          t = BODT::c3t3_to_tet_mesh(m.c3t3);
        return stellar_input(t.points, t.tets);
      },
      mesh);
}

// The last non-empty line of Stellar's output: its error message when it fails.
std::string last_line(const fs::path& log)
{
  std::ifstream in(log);
  std::string line, last;
  while(std::getline(in, line))
    if(line.find_first_not_of(" \t\r") != std::string::npos) last = line;
  return last.empty() ? "no output" : last;
}

// Runs `executable -s CONFIG in` in `dir`, its output in `dir`/stellar.log; returns
// its user time. Throws if it cannot start or does not end with status 0.
double run_stellar(const fs::path& executable, const fs::path& dir)
{
  const std::string exe = executable.string(), config = (dir / "stellar.config").string(),
                    log = (dir / "stellar.log").string(), work = dir.string();
  // Everything the child needs is built before fork: it only calls async-signal-safe functions.
  const char* argv[] = {exe.c_str(), "-s", config.c_str(), "in", nullptr};
  const pid_t pid = fork();
  if(pid < 0) throw std::runtime_error(std::string("cannot start Stellar: ") + std::strerror(errno));
  if(pid == 0)
  {
    const int fd = open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if(fd < 0 || chdir(work.c_str()) != 0 || dup2(fd, STDOUT_FILENO) < 0 || dup2(fd, STDERR_FILENO) < 0) _exit(126);
    execv(argv[0], const_cast<char* const*>(argv));
    _exit(127);
  }
  int status = 0;
  rusage usage{};
  while(wait4(pid, &status, 0, &usage) < 0)
    if(errno != EINTR) throw std::runtime_error(std::string("waiting for Stellar: ") + std::strerror(errno));
  if(WIFEXITED(status) && WEXITSTATUS(status) == 127)
    throw std::runtime_error("cannot execute `" + exe + "`");
  if(!WIFEXITED(status) || WEXITSTATUS(status) != 0)
    throw std::runtime_error(
        (WIFSIGNALED(status) ? "Stellar was killed by signal " + std::to_string(WTERMSIG(status))
                             : "Stellar exited with status " + std::to_string(WEXITSTATUS(status))) +
        ": " + last_line(log));
  return double(usage.ru_utime.tv_sec) + 1e-6 * double(usage.ru_utime.tv_usec);
}

// A fresh folder for one run, removed with everything in it when the run ends.
struct Temporary_folder
{
  fs::path path;
  Temporary_folder()
  {
    std::string pattern = (fs::temp_directory_path() / "bodt-stellar-XXXXXX").string();
    if(!mkdtemp(pattern.data())) throw std::runtime_error(std::string("no temporary folder: ") + std::strerror(errno));
    path = pattern;
  }
  ~Temporary_folder()
  {
    std::error_code ignored;
    fs::remove_all(path, ignored);
  }
};

Run improve_with_stellar(const fs::path& executable, Mesh& mesh)
{
  Temporary_folder dir;
  BODT::IO::write_tetgen((dir.path / "in").string(), stellar_input(mesh));
  {
    std::ofstream config(dir.path / "stellar.config");
    for(const auto& [option, value] : stellar_config) config << option << ' ' << value << '\n';
  }
  Run run{0, "exit status 0"};
  run.child_cpu_seconds = run_stellar(executable, dir.path);
  // Stellar writes its boundary faces numbered from 0; the boundary is measured from the tetrahedra anyway.
  fs::remove(dir.path / "in.1.face");
  std::ostringstream reoriented;   // the reader turns Stellar's orientation back, with a warning
  mesh = BODT::IO::read_tetgen((dir.path / "in.1.node").string(), reoriented);
  return run;
}

std::string stellar_settings()
{
  std::string options;
  for(const auto& [option, value] : stellar_config)
    options += std::string(options.empty() ? "" : ", ") + "`" + option + " " + value + "`";
  return "**external program**: Klingner and Shewchuk's Stellar (\"Aggressive tetrahedral mesh improvement\", 2007), "
         "run as a child process on the input written as TetGen .node/.ele. Config " +
         options +
         ", every other option at Stellar's default: optimization-based smoothing, edge removal, multi-face "
         "removal, 2-2 flips, edge contraction and vertex insertion (interior, facets, segments); boundary vertices "
         "move only within flat facets and along straight segments (no quadric smoothing), vertices of curved "
         "boundary stay; no goal angle and no time limit: it runs until its passes stop improving. CPU time is "
         "Stellar's user time. Not run on inputs with several subdomains: Stellar knows no labels";
}

} // namespace

Method stellar_method(const std::string& executable)
{
  // Stellar runs in a temporary folder: a relative path must not depend on it.
  const fs::path exe = fs::absolute(executable);
  return {stellar_name, Family::external, Applies_to::one_subdomain, stellar_settings(),
          [exe](Mesh& mesh, std::size_t) { return improve_with_stellar(exe, mesh); }};
}

} // namespace bodt_compare
