// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The whole `bodt smooth` process against mesh size, threads and binaries. Each
// input is written as .mesh, then `bodt smooth IN -o OUT --iterations I --threads
// T --report R -q` runs as a child of GNU time for every binary and thread count.
// Per run: wall, CPU (user + sys) and peak resident memory from GNU time; from the
// JSON report the process's read, quality and smoothing, the smoothing's
// conversion, set-up and passes, and per phase (main, largest angle, last, worst cells) the
// seconds of each pass (sweep, flips, max-min steps, insertion, re-read) summed
// over the phase's iterations; the extreme dihedral angles before and after; the
// speed-up over the run on the first thread count, and whether the output has the
// same bytes as that run's (and as the first binary's on as many threads).
// With --cgal-odt, CGAL's odt_optimize_mesh_3 runs in this process on the Mesh_3
// inputs' own complex, for as many iterations, timed beside the B-ODT runs.
//
// Prints Markdown tables (summary, per phase and pass, CGAL ODT) on standard
// output and progress on standard error; --json writes every figure, --svg a
// log-log plot of wall and smoothing time against tetrahedra.
#include "compare/compare.h"
#include "jittered_grid.h"
#include "run_child.h"

#include <CGAL/BODT_3/IO/mesh_io.h>
#include <CGAL/BODT_3/Tet_mesh_conversion.h>
#include <CGAL/BODT_3/mesh_quality.h>

#include <nlohmann/json.hpp>

#include <sys/resource.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <map>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <variant>
#include <vector>

namespace fs = std::filesystem;
namespace BODT = CGAL::BODT_3;
using nlohmann::json;

namespace {

const char* const usage =
    "usage: scale INPUTS [--threads 1,2] [--iterations N] [--cgal-odt] [--bodt PATH]...\n"
    "             [--folder DIR] [--data DIR] [--json FILE] [--svg FILE]\n"
    "inputs (at least one set):\n"
    "  --grids N,...        unit cube in N^3 cubes of 6 tets, 2% jitter, two subdomains, labelled faces\n"
    "  --hard-grids N,...   the same with 15% jitter, one subdomain, no triangles (N = 60: 1.3 M tets)\n"
    "  --mesh3 R,...        Mesh_3 of the two-subdomain ball, every size criterion divided by R\n"
    "  --surfaces S,...     Mesh_3 of CGAL's surfaces (eight, fandisk: DATA/S.off) or .off paths,\n"
    "  --sizes M,...        at about M million tets each (default 0.2); cached in DIR\n"
    "  --smoke              a quick check: --hard-grids 12 --surfaces eight --sizes 0.02 --threads 1,2\n"
    "                       --cgal-odt\n"
    "options:\n"
    "  --threads T,...      bodt's --threads; speed-up and same bytes against the first (default 1,2)\n"
    "  --iterations N       bodt's --iterations (default 5 on grids and mesh3, 20 on surfaces)\n"
    "  --cgal-odt           CGAL's odt_optimize_mesh_3 on the Mesh_3 inputs, as many iterations\n"
    "  --bodt PATH          the bodt binary (default: beside build/bench); twice or more: compared\n"
    "  --folder DIR         inputs, outputs and the surfaces' cached meshes (default: this program's)\n"
    "  --data DIR           where the surfaces' .off files are (default: build/data)\n"
    "  --json FILE          every figure; --svg FILE: wall and smoothing time against tets\n";

// Exit status 2, with the usage, for a command line this program cannot run.
struct Bad_option : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

const char* const phase_names[4] = {"main", "largest angle", "last", "worst cells"};
const char* const pass_names[5] = {"sweep", "flips", "max_min", "insertion", "reread"};   // JSON keys

struct Binary
{
  std::string label;   // A, B, ... in the tables
  std::string path;
};

struct Input_mesh
{
  std::string name;     // hard60, eight_0.2M, ...
  std::string series;   // one line of the plot: grid, hard, mesh3, or the surface
  std::string origin;
  fs::path file;        // the .mesh every binary reads
  bool cached = false;       // kept for the next run
  bool from_cache = false;   // made by an earlier run
  std::size_t tets = 0;
  int iterations = 0;
  double make_seconds = 0;   // generating, or Mesh_3, and writing; 0 from the cache
};

struct Extremes
{
  double min = 0, max = 0;
  std::size_t vertices = 0, tets = 0;
};

Extremes extremes(const json& quality)
{
  return {quality.at("min_dihedral_deg"), quality.at("max_dihedral_deg"), quality.at("num_vertices"),
          quality.at("num_tets")};
}

Extremes extremes(const BODT::Quality_report& q)
{
  return {q.min_dihedral_deg, q.max_dihedral_deg, q.num_vertices, q.num_tets};
}

struct Phase_passes
{
  std::size_t iterations = 0;
  std::array<double, 5> seconds{};   // in the order of pass_names
};

struct Run
{
  std::string input, series, binary;
  std::size_t tets = 0;
  int threads = 0;
  double wall = 0, user = 0, sys = 0, peak_mb = 0;
  double read = 0, quality = 0, smoothing = 0, conversion = 0, setup = 0;
  std::array<double, 5> passes{};   // phase_seconds: sweeps, flips, max_min, insertion, reread
  std::array<Phase_passes, 4> phases;
  Extremes before, after;
  std::size_t iterations = 0, flips = 0, inserted = 0;
  double speed_up = 1;
  bool same_bytes = true;
  std::optional<bool> same_as_first_binary;
  double load_before = 0, load_after = 0;

  double cpu() const { return user + sys; }
  double passes_total() const { return passes[0] + passes[1] + passes[2] + passes[3] + passes[4]; }
  // Smoothing time in none of the report's phases.
  double other() const { return smoothing - conversion - setup - passes_total(); }
  double write_and_exit() const { return wall - read - quality - smoothing; }
  double bytes_per_tet() const { return peak_mb * 1048576.0 / double(tets); }
};

struct Cgal_odt_run
{
  std::string input;
  std::size_t tets = 0, iterations = 0;
  double cpu = 0, wall = 0;
  Extremes before, after;
  std::string outcome;
  double load_before = 0, load_after = 0;
};

struct Options
{
  std::vector<int> grids, hard_grids, threads = {1, 2};
  std::vector<double> mesh3, sizes = {0.2};
  std::vector<std::string> surfaces;
  int iterations = 0;   // 0: 5 on grids and mesh3, 20 on surfaces
  bool cgal_odt = false;
  std::vector<Binary> binaries;
  fs::path folder, data, json_file, svg_file;
};

// -- Command line ------------------------------------------------------------

std::vector<std::string> split(const std::string& option, const std::string& text)
{
  std::vector<std::string> items;
  std::stringstream in(text);
  std::string item;
  while(std::getline(in, item, ','))
  {
    if(item.empty()) throw Bad_option(option + " " + text + ": an empty item");
    items.push_back(item);
  }
  if(items.empty()) throw Bad_option(option + ": an empty list");
  return items;
}

double positive_number(const std::string& option, const std::string& text)
{
  char* end = nullptr;
  const double x = std::strtod(text.c_str(), &end);
  if(text.empty() || *end != '\0' || !(x > 0) || !std::isfinite(x))
    throw Bad_option(option + " " + text + ": not a positive number");
  return x;
}

int positive_integer(const std::string& option, const std::string& text, int at_most)
{
  const double x = positive_number(option, text);
  if(x != std::floor(x) || x > at_most)
    throw Bad_option(option + " " + text + ": not an integer from 1 to " + std::to_string(at_most));
  return int(x);
}

std::vector<int> integers(const std::string& option, const std::string& text, int at_most)
{
  std::vector<int> values;
  for(const std::string& item : split(option, text)) values.push_back(positive_integer(option, item, at_most));
  return values;
}

std::vector<double> numbers(const std::string& option, const std::string& text)
{
  std::vector<double> values;
  for(const std::string& item : split(option, text)) values.push_back(positive_number(option, item));
  return values;
}

// A surface by name in the data folder, or an .off path.
fs::path surface_path(const std::string& surface, const fs::path& data)
{
  const bool path = surface.find('/') != std::string::npos || fs::path(surface).extension() == ".off";
  const fs::path file = path ? fs::path(surface) : data / (surface + ".off");
  if(!fs::is_regular_file(file))
    throw Bad_option("--surfaces " + surface + ": no file " + file.string() +
                     (path ? std::string()
                           : "; CGAL's surfaces come with: tar -xzf /usr/share/doc/libcgal-dev/data.tar.gz -C " +
                                 data.string() + " --strip-components=2 data/meshes/" + surface + ".off"));
  return file;
}

Options parse(int argc, char** argv)
{
  Options o;
  const fs::path here = fs::canonical("/proc/self/exe").parent_path();
  o.folder = here;
  o.data = bodt_compare::default_data_dir();
  bool smoke = false, any_input = false, sizes_given = false;
  for(int i = 1; i < argc; ++i)
  {
    const std::string option = argv[i];
    if(option == "--cgal-odt")
    {
      o.cgal_odt = true;
      continue;
    }
    if(option == "--smoke")
    {
      smoke = true;
      continue;
    }
    if(i + 1 == argc) throw Bad_option(option + ": a value is missing, or the option is unknown");
    const std::string value = argv[++i];
    any_input = any_input || option == "--grids" || option == "--hard-grids" || option == "--mesh3" ||
                option == "--surfaces";
    if(option == "--grids") o.grids = integers(option, value, 400);
    else if(option == "--hard-grids") o.hard_grids = integers(option, value, 400);
    else if(option == "--mesh3") o.mesh3 = numbers(option, value);
    else if(option == "--surfaces") o.surfaces = split(option, value);
    else if(option == "--sizes") o.sizes = numbers(option, value), sizes_given = true;
    else if(option == "--threads") o.threads = integers(option, value, 1024);
    else if(option == "--iterations") o.iterations = positive_integer(option, value, 1000);
    else if(option == "--bodt") o.binaries.push_back({std::string(1, char('A' + o.binaries.size())), value});
    else if(option == "--folder") o.folder = value;
    else if(option == "--data") o.data = value;
    else if(option == "--json") o.json_file = value;
    else if(option == "--svg") o.svg_file = value;
    else throw Bad_option("unknown option " + option);
  }
  if(smoke)
  {
    if(any_input || sizes_given) throw Bad_option("--smoke chooses the inputs: give no input set with it");
    o.hard_grids = {12};
    o.surfaces = {"eight"};
    o.sizes = {0.02};
    o.threads = {1, 2};
    o.cgal_odt = true;
  }
  else if(!any_input)
    throw Bad_option("nothing to measure: give --grids, --hard-grids, --mesh3, --surfaces or --smoke");
  if(sizes_given && o.surfaces.empty()) throw Bad_option("--sizes are the surfaces' sizes: give --surfaces");
  if(o.cgal_odt && o.mesh3.empty() && o.surfaces.empty())
    throw Bad_option("--cgal-odt runs on Mesh_3 meshes: give --mesh3 or --surfaces");
  if(o.binaries.empty()) o.binaries.push_back({"A", (here.parent_path() / "bodt").string()});
  if(o.binaries.size() > 26) throw Bad_option("--bodt: at most 26 binaries");
  for(const Binary& b : o.binaries)
    if(::access(b.path.c_str(), X_OK) != 0) throw Bad_option("--bodt " + b.path + ": not an executable file");
  if(!fs::is_directory(o.folder)) throw Bad_option("--folder " + o.folder.string() + ": not a folder");
  for(const std::string& s : o.surfaces) surface_path(s, o.data);
  if(::access("/usr/bin/time", X_OK) != 0)
    throw std::runtime_error("GNU time is needed for the CPU time and the peak memory: /usr/bin/time "
                             "(Debian package `time`)");
  return o;
}

// -- Measuring ---------------------------------------------------------------

double load_average()
{
  double one_minute = 0;
  std::ifstream("/proc/loadavg") >> one_minute;
  return one_minute;
}

double seconds_since(std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

bool same_file(const fs::path& a, const fs::path& b)
{
  if(fs::file_size(a) != fs::file_size(b)) return false;
  std::ifstream fa(a, std::ios::binary), fb(b, std::ios::binary);
  return std::equal(std::istreambuf_iterator<char>(fa), std::istreambuf_iterator<char>(),
                    std::istreambuf_iterator<char>(fb), std::istreambuf_iterator<char>());
}

Run read_report(const fs::path& report)
{
  std::ifstream in(report);
  const json j = json::parse(in);
  Run r;
  const json& process = j.at("process_seconds");
  r.read = process.at("read");
  r.quality = process.at("quality_before_and_after");
  r.smoothing = process.at("smoothing");
  const json& result = j.at("result");
  const json& phases = result.at("phase_seconds");
  r.conversion = phases.at("conversion");
  r.setup = phases.at("setup");
  r.passes = {phases.at("sweeps"), phases.at("flips"), phases.at("max_min"), phases.at("insertion"),
              phases.at("reread")};
  r.iterations = result.at("iterations");
  r.flips = result.at("topology").at("total");
  r.inserted = result.at("insertion").at("vertices_added");
  for(const json& it : j.at("per_iteration"))
  {
    Phase_passes& p = r.phases.at(it.at("phase").get<std::size_t>());
    ++p.iterations;
    const double seconds[5] = {it.at("sweep_seconds"), it.at("topology").at("seconds"), it.at("max_min_seconds"),
                               it.at("insertion").at("seconds"), it.at("reread_seconds")};
    for(int k = 0; k < 5; ++k) p.seconds[k] += seconds[k];
  }
  r.before = extremes(j.at("before"));
  r.after = extremes(j.at("after"));
  return r;
}

std::string run_file(const Input_mesh& input, const Binary& b, int threads)
{
  return "scale_out_" + input.name + "_" + b.label + "_t" + std::to_string(threads) + ".mesh";
}

// Every binary on every thread count; the outputs are compared, then removed.
std::vector<Run> measure(const Input_mesh& input, const Options& o)
{
  std::vector<Run> runs;
  const fs::path report = o.folder / "scale_report.json";
  for(const Binary& b : o.binaries)
    for(int threads : o.threads)
    {
      const fs::path output = o.folder / run_file(input, b, threads);
      const double load_before = load_average();
      const bodt_bench::Child_times t =
          bodt_bench::run_child({b.path, "smooth", input.file.string(), "-o", output.string(), "--iterations",
                     std::to_string(input.iterations), "--threads", std::to_string(threads), "--report",
                     report.string(), "-q"},
                    o.folder / "scale_times.txt");
      Run r = read_report(report);
      fs::remove(report);
      r.input = input.name;
      r.series = input.series;
      r.binary = b.label;
      r.tets = input.tets;
      r.threads = threads;
      r.wall = t.wall;
      r.user = t.user;
      r.sys = t.sys;
      r.peak_mb = t.peak_mb;
      r.load_before = load_before;
      r.load_after = load_average();
      const auto first = std::find_if(runs.begin(), runs.end(), [&](const Run& e) { return e.binary == b.label; });
      if(first != runs.end())
      {
        r.speed_up = first->wall / r.wall;
        r.same_bytes = same_file(o.folder / run_file(input, b, first->threads), output);
      }
      if(&b != &o.binaries.front())
        r.same_as_first_binary = same_file(o.folder / run_file(input, o.binaries.front(), threads), output);
      std::fprintf(stderr, "  %s, bodt %s, %d thread%s: %.2f s wall, %.2f s CPU, %.0f MB, %.2f / %.2f deg\n",
                   input.name.c_str(), b.label.c_str(), threads, threads > 1 ? "s" : "", r.wall, r.cpu(), r.peak_mb,
                   r.after.min, r.after.max);
      runs.push_back(r);
    }
  for(const Binary& b : o.binaries)
    for(int threads : o.threads) fs::remove(o.folder / run_file(input, b, threads));
  return runs;
}

double cpu_seconds_of_this_process()
{
  rusage u;
  getrusage(RUSAGE_SELF, &u);
  return double(u.ru_utime.tv_sec + u.ru_stime.tv_sec) + 1e-6 * double(u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

template <class F>
auto on_c3t3(bodt_compare::Mesh& mesh, F f)
{
  if(auto* g = std::get_if<bodt_inputs::Generated_mesh>(&mesh)) return f(g->c3t3);
  return f(std::get<bodt_compare::Surface_mesh>(mesh).c3t3);
}

// CGAL's ODT, as the comparison calls it, on the Mesh_3 complex itself (its last use).
Cgal_odt_run run_cgal_odt(const Input_mesh& input, bodt_compare::Mesh& mesh)
{
  Cgal_odt_run c;
  c.input = input.name;
  c.iterations = std::size_t(input.iterations);
  auto quality = [](const auto& c3t3) { return extremes(BODT::mesh_quality(c3t3)); };
  c.before = on_c3t3(mesh, quality);
  c.tets = c.before.tets;
  c.load_before = load_average();
  const double cpu = cpu_seconds_of_this_process();
  const auto start = std::chrono::steady_clock::now();
  c.outcome = bodt_compare::cgal_odt(mesh, c.iterations).outcome;
  c.wall = seconds_since(start);
  c.cpu = cpu_seconds_of_this_process() - cpu;
  c.load_after = load_average();
  c.after = on_c3t3(mesh, quality);
  std::fprintf(stderr, "  %s, CGAL ODT: %.2f s wall, %.2f s CPU, %.2f / %.2f deg\n", input.name.c_str(), c.wall,
               c.cpu, c.after.min, c.after.max);
  return c;
}

// -- Inputs ------------------------------------------------------------------

// An input made in this run: its file, and for a Mesh_3 input the complex when
// CGAL's ODT is to run on it.
struct Made
{
  Input_mesh input;
  std::optional<bodt_compare::Mesh> mesh;
};

void write_input(Input_mesh& input, const BODT::Tet_mesh& mesh)
{
  input.tets = mesh.tets.size();
  BODT::IO::write_mesh(input.file.string(), mesh);
}

Made grid_input(int n, bodt_bench::Grid_kind kind, const Options& o)
{
  const auto start = std::chrono::steady_clock::now();
  const bool hard = kind == bodt_bench::Grid_kind::hard;
  Made m;
  m.input.name = (hard ? "hard" : "grid") + std::to_string(n);
  m.input.series = hard ? "hard" : "grid";
  m.input.origin = "unit cube in " + std::to_string(n) + "^3 cubes of 6 tets, " +
                   (hard ? "15% jitter, one subdomain, no triangles" : "2% jitter, two subdomains, labelled faces");
  m.input.file = o.folder / ("scale_" + m.input.name + ".mesh");
  m.input.iterations = o.iterations ? o.iterations : 5;
  write_input(m.input, bodt_bench::jittered_grid(n, kind));
  m.input.make_seconds = seconds_since(start);
  return m;
}

Made mesh3_input(double refinement, const Options& o)
{
  const auto start = std::chrono::steady_clock::now();
  Made m;
  char name[32];
  std::snprintf(name, sizeof name, "mesh3_x%g", refinement);
  m.input.name = name;
  m.input.series = "mesh3";
  m.input.origin = "Mesh_3 of the two-subdomain ball, size criteria divided by " + std::to_string(refinement);
  m.input.file = o.folder / ("scale_" + m.input.name + ".mesh");
  m.input.iterations = o.iterations ? o.iterations : 5;
  CGAL::get_default_random() = CGAL::Random(0);   // Mesh_3 draws from it: the same mesh every run
  bodt_inputs::Generated_mesh g =
      bodt_inputs::make_input(bodt_inputs::Shape::two_subdomains, bodt_inputs::Size::benchmark, refinement);
  write_input(m.input, BODT::c3t3_to_tet_mesh(g.c3t3));
  if(o.cgal_odt) m.mesh = std::move(g);
  m.input.make_seconds = seconds_since(start);
  return m;
}

// A surface's Mesh_3 mesh, cached in the folder as .mesh with a .json of its
// size criterion: a Mesh_3 run at millions of tets takes minutes. CGAL's ODT needs
// the complex, which Mesh_3 makes again at the cached size (one run, no search).
Made surface_input(const std::string& surface, double millions, const Options& o)
{
  const auto start = std::chrono::steady_clock::now();
  const fs::path off = surface_path(surface, o.data);
  char name[96];
  std::snprintf(name, sizeof name, "%s_%gM", off.stem().c_str(), millions);
  Made m;
  m.input.name = name;
  m.input.series = off.stem().string();
  m.input.file = o.folder / ("scale_" + m.input.name + ".mesh");
  m.input.cached = true;
  m.input.iterations = o.iterations ? o.iterations : 20;
  const fs::path about = o.folder / ("scale_" + m.input.name + ".json");
  if(fs::exists(m.input.file) && fs::exists(about))
  {
    const json cached = json::parse(std::ifstream(about));
    m.input.origin = cached.at("origin").get<std::string>();
    m.input.tets = cached.at("tets");
    m.input.from_cache = true;
    if(!o.cgal_odt) return m;
    std::fprintf(stderr, "  %s: Mesh_3 again at the cached size, for CGAL's ODT\n", m.input.name.c_str());
    bodt_compare::Input again = bodt_compare::surface_input_with_size(off.string(), cached.at("h"));
    const std::size_t tets = std::get<bodt_compare::Surface_mesh>(again.mesh).c3t3.number_of_cells_in_complex();
    if(tets == m.input.tets)
    {
      m.mesh = std::move(again.mesh);
      m.input.make_seconds = seconds_since(start);
      return m;
    }
    std::fprintf(stderr, "  %s: Mesh_3 made %zu tets at the cached size, not %zu: the cache is made again\n",
                 m.input.name.c_str(), tets, m.input.tets);
    m.input.from_cache = false;
  }
  std::fprintf(stderr, "  %s: Mesh_3 of %s for %g M tets (minutes at millions)\n", m.input.name.c_str(),
               off.c_str(), millions);
  bodt_compare::Input made = bodt_compare::surface_input(off.string(), millions * 1e6);
  const auto& surface_mesh = std::get<bodt_compare::Surface_mesh>(made.mesh);
  m.input.origin = made.origin;
  write_input(m.input, BODT::c3t3_to_tet_mesh(surface_mesh.c3t3));
  std::ofstream(about) << json{{"surface", off.string()},
                               {"target_tets", millions * 1e6},
                               {"h", surface_mesh.h},
                               {"tets", m.input.tets},
                               {"origin", made.origin},
                               {"seconds", seconds_since(start)}}
                              .dump(1)
                       << "\n";
  if(o.cgal_odt) m.mesh = std::move(made.mesh);
  m.input.make_seconds = seconds_since(start);
  return m;
}

// -- Reports -----------------------------------------------------------------

std::string fixed(double x, int digits = 2)
{
  char s[32];
  std::snprintf(s, sizeof s, "%.*f", digits, x);
  return s;
}

std::string angles(const Extremes& e) { return fixed(e.min) + " / " + fixed(e.max); }

std::string phase_iterations(const Run& r)
{
  std::string s = std::to_string(r.phases[0].iterations);
  for(int p = 1; p < 4; ++p) s += "+" + std::to_string(r.phases[p].iterations);
  return s;
}

struct Report
{
  std::string command, date;
  bodt_compare::Machine machine;
  double load_start = 0, load_end = 0;
  std::vector<Input_mesh> inputs;
  std::vector<Run> runs;
  std::vector<Cgal_odt_run> cgal;
  double seconds_inputs = 0, seconds_cgal = 0, seconds_bodt = 0, seconds_total = 0;
};

std::string markdown(const Report& rep, const Options& o)
{
  const bool several = o.binaries.size() > 1;
  const std::string bodt_column = several ? " bodt |" : "";
  const std::string bodt_rule = several ? "---|" : "";
  std::ostringstream s;
  s << "Measured by `" << rep.command << "` on " << rep.date << ": " << rep.machine.cpu << ", " << rep.machine.cores
    << " cores, " << rep.machine.compiler << ", CGAL " << rep.machine.cgal << ". Load average (1 min) "
    << fixed(rep.load_start) << " at the start, " << fixed(rep.load_end)
    << " at the end: on a shared machine, compare figures within one run only.\n\n";
  for(const Binary& b : o.binaries) s << "- bodt " << b.label << ": `" << b.path << "`\n";
  s << "\n`bodt smooth IN -o OUT --iterations I --threads T --report R -q`, default pipeline. Seconds of wall time "
       "unless said; CPU: user + sys (GNU time); peak: resident set (GNU time); its: iterations of the main, "
       "largest-angle, last and worst-cell phases; passes: sweeps, flips, max-min steps, insertion and re-reads (next "
       "table); other: smoothing time in no reported phase; speed-up: wall of the run on "
    << o.threads.front() << " thread" << (o.threads.front() > 1 ? "s" : "")
    << " over this run's; same bytes: the output is that run's";
  if(several) s << "; = A: the output is bodt A's on as many threads";
  s << ".\n\n| input | tets |" << bodt_column
    << " threads | its | wall | CPU | speed-up | peak MB | bytes/tet | read | quality | conversion | set-up | "
       "passes | other | write, exit | min / max before | min / max after | vertices after | same bytes |"
    << (several ? " = A |" : "") << "\n|---|---:|" << bodt_rule
    << "---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|---|---:|---|"
    << (several ? "---|" : "") << "\n";
  for(const Run& r : rep.runs)
  {
    s << "| " << r.input << " | " << r.tets << " |" << (several ? " " + r.binary + " |" : "") << " " << r.threads
      << " | " << phase_iterations(r) << " | " << fixed(r.wall) << " | " << fixed(r.cpu()) << " | "
      << fixed(r.speed_up) << " | " << fixed(r.peak_mb, 0) << " | " << fixed(r.bytes_per_tet(), 0) << " | "
      << fixed(r.read) << " | " << fixed(r.quality) << " | " << fixed(r.conversion) << " | " << fixed(r.setup)
      << " | " << fixed(r.passes_total()) << " | " << fixed(r.other()) << " | " << fixed(r.write_and_exit())
      << " | " << angles(r.before) << " | " << angles(r.after) << " | " << r.after.vertices << " | "
      << (r.same_bytes ? "yes" : "NO") << " |";
    if(several) s << " " << (r.same_as_first_binary ? (*r.same_as_first_binary ? "yes" : "no") : "") << " |";
    s << "\n";
  }
  s << "\nPer phase, each pass's seconds summed over the phase's iterations:\n\n| input |" << bodt_column
    << " threads | phase | its | sweep | flips | max-min | insertion | re-read | phase |\n|---|" << bodt_rule
    << "---:|---|---:|---:|---:|---:|---:|---:|---:|\n";
  for(const Run& r : rep.runs)
    for(int p = 0; p < 4; ++p)
    {
      const Phase_passes& phase = r.phases[p];
      if(phase.iterations == 0) continue;
      s << "| " << r.input << " |" << (several ? " " + r.binary + " |" : "") << " " << r.threads << " | "
        << phase_names[p] << " | " << phase.iterations;
      double total = 0;
      for(double x : phase.seconds)
      {
        s << " | " << fixed(x);
        total += x;
      }
      s << " | " << fixed(total) << " |\n";
    }
  if(!rep.cgal.empty())
  {
    s << "\nCGAL's `odt_optimize_mesh_3` (`convergence = 0`, `freeze_bound = 0`, sequential) on the same Mesh_3 "
         "complex in this process, beside the whole `bodt smooth` process on the same mesh written as .mesh, on "
      << o.threads.front() << " thread" << (o.threads.front() > 1 ? "s" : "")
      << " (CPU seconds; B-ODT's iterations are per phase):\n\n| input | tets | its | CGAL ODT CPU | CGAL ODT wall "
         "| CGAL ODT min / max |"
      << bodt_column << " B-ODT CPU | B-ODT smoothing | CPU ratio B-ODT / CGAL | B-ODT min / max |\n|---|---:|---:|"
      << "---:|---:|---|" << bodt_rule << "---:|---:|---:|---|\n";
    for(const Cgal_odt_run& c : rep.cgal)
      for(const Run& r : rep.runs)
        if(r.input == c.input && r.threads == o.threads.front())
          s << "| " << c.input << " | " << c.tets << " | " << c.iterations << " | " << fixed(c.cpu) << " | "
            << fixed(c.wall) << " | " << angles(c.after) << " |" << (several ? " " + r.binary + " |" : "") << " "
            << fixed(r.cpu()) << " | " << fixed(r.smoothing) << " | " << fixed(r.cpu() / c.cpu) << " | "
            << angles(r.after) << " |\n";
  }
  s << "\nBench: " << fixed(rep.seconds_total, 0) << " s (inputs made or read from the cache "
    << fixed(rep.seconds_inputs, 0) << " s, bodt runs " << fixed(rep.seconds_bodt, 0) << " s, CGAL ODT "
    << fixed(rep.seconds_cgal, 0) << " s).\n";
  return s.str();
}

json to_json(const Extremes& e)
{
  return {{"min_dihedral_deg", e.min}, {"max_dihedral_deg", e.max}, {"vertices", e.vertices}, {"tets", e.tets}};
}

json to_json(const Report& rep, const Options& o)
{
  json j;
  j["command"] = rep.command;
  j["date"] = rep.date;
  j["machine"] = {{"cpu", rep.machine.cpu},
                  {"cores", rep.machine.cores},
                  {"compiler", rep.machine.compiler},
                  {"cgal", rep.machine.cgal}};
  j["load_average_1min"] = {{"start", rep.load_start}, {"end", rep.load_end}};
  j["bench_seconds"] = {{"total", rep.seconds_total},
                        {"inputs", rep.seconds_inputs},
                        {"bodt_runs", rep.seconds_bodt},
                        {"cgal_odt", rep.seconds_cgal}};
  for(const Binary& b : o.binaries) j["binaries"].push_back({{"label", b.label}, {"path", b.path}});
  for(const Input_mesh& in : rep.inputs)
    j["inputs"].push_back({{"name", in.name},
                           {"series", in.series},
                           {"origin", in.origin},
                           {"tets", in.tets},
                           {"iterations", in.iterations},
                           {"cached", in.cached},
                           {"from_cache", in.from_cache},
                           {"make_seconds", in.make_seconds}});
  for(const Run& r : rep.runs)
  {
    json phases = json::array();
    for(int p = 0; p < 4; ++p)
    {
      json phase = {{"phase", phase_names[p]}, {"iterations", r.phases[p].iterations}};
      for(int k = 0; k < 5; ++k) phase["seconds"][pass_names[k]] = r.phases[p].seconds[k];
      phases.push_back(phase);
    }
    json run = {{"input", r.input},
                {"bodt", r.binary},
                {"threads", r.threads},
                {"tets", r.tets},
                {"wall_seconds", r.wall},
                {"cpu_seconds", {{"user", r.user}, {"sys", r.sys}, {"total", r.cpu()}}},
                {"peak_mb", r.peak_mb},
                {"bytes_per_tet", r.bytes_per_tet()},
                {"speed_up", r.speed_up},
                {"same_bytes", r.same_bytes},
                {"process_seconds",
                 {{"read", r.read},
                  {"quality", r.quality},
                  {"smoothing", r.smoothing},
                  {"write_and_exit", r.write_and_exit()}}},
                {"smoothing_seconds",
                 {{"conversion", r.conversion},
                  {"setup", r.setup},
                  {"sweeps", r.passes[0]},
                  {"flips", r.passes[1]},
                  {"max_min", r.passes[2]},
                  {"insertion", r.passes[3]},
                  {"reread", r.passes[4]},
                  {"other", r.other()}}},
                {"phases", phases},
                {"iterations", r.iterations},
                {"flips", r.flips},
                {"vertices_inserted", r.inserted},
                {"before", to_json(r.before)},
                {"after", to_json(r.after)},
                {"load_average_1min", {{"before", r.load_before}, {"after", r.load_after}}}};
    if(r.same_as_first_binary) run["same_bytes_as_first_bodt"] = *r.same_as_first_binary;
    j["runs"].push_back(run);
  }
  for(const Cgal_odt_run& c : rep.cgal)
    j["cgal_odt"].push_back({{"input", c.input},
                             {"tets", c.tets},
                             {"iterations", c.iterations},
                             {"cpu_seconds", c.cpu},
                             {"wall_seconds", c.wall},
                             {"outcome", c.outcome},
                             {"before", to_json(c.before)},
                             {"after", to_json(c.after)},
                             {"load_average_1min", {{"before", c.load_before}, {"after", c.load_after}}}});
  return j;
}

// Log-log plot: seconds against tetrahedra, one line per series, binary and thread
// count with two sizes or more: the whole process solid, the smoothing dashed.
std::string svg_plot(const std::vector<Run>& runs)
{
  const double W = 640, H = 420, left = 70, right = 20, top = 30, bottom = 50;
  double x0 = 1e300, x1 = 0, y0 = 1e300, y1 = 0;
  for(const Run& r : runs)
  {
    x0 = std::min(x0, double(r.tets)), x1 = std::max(x1, double(r.tets));
    y0 = std::min(y0, r.smoothing), y1 = std::max(y1, r.wall);
  }
  const double lx0 = std::floor(std::log10(x0)), lx1 = std::max(lx0 + 1, std::ceil(std::log10(x1)));
  const double ly0 = std::floor(std::log10(y0)), ly1 = std::max(ly0 + 1, std::ceil(std::log10(y1)));
  auto X = [&](double x) { return left + (std::log10(x) - lx0) / (lx1 - lx0) * (W - left - right); };
  auto Y = [&](double y) { return H - bottom - (std::log10(y) - ly0) / (ly1 - ly0) * (H - top - bottom); };
  std::ostringstream s;
  s << "<svg xmlns='http://www.w3.org/2000/svg' width='" << W << "' height='" << H
    << "' font-family='sans-serif' font-size='12'>\n<rect width='100%' height='100%' fill='white'/>\n";
  for(double e = lx0; e <= lx1; ++e)
    s << "<line x1='" << X(std::pow(10, e)) << "' y1='" << top << "' x2='" << X(std::pow(10, e)) << "' y2='"
      << H - bottom << "' stroke='#ddd'/><text x='" << X(std::pow(10, e)) - 12 << "' y='" << H - bottom + 16
      << "'>1e" << e << "</text>\n";
  for(double e = ly0; e <= ly1; ++e)
    s << "<line x1='" << left << "' y1='" << Y(std::pow(10, e)) << "' x2='" << W - right << "' y2='"
      << Y(std::pow(10, e)) << "' stroke='#ddd'/><text x='" << left - 45 << "' y='" << Y(std::pow(10, e)) + 4
      << "'>" << std::pow(10, e) << " s</text>\n";
  s << "<text x='" << W / 2 - 40 << "' y='" << H - 12 << "'>tetrahedra</text>\n";
  const char* colours[] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#8c564b", "#e377c2", "#17becf"};
  // Lines in the order their runs came.
  std::vector<std::string> keys;
  std::map<std::string, std::vector<const Run*>> lines;
  for(const Run& r : runs)
  {
    const std::string key = r.series + ", bodt " + r.binary + ", " + std::to_string(r.threads) + " thread" +
                            (r.threads > 1 ? "s" : "");
    if(!lines.count(key)) keys.push_back(key);
    lines[key].push_back(&r);
  }
  int line = 0;
  for(const std::string& key : keys)
  {
    std::vector<const Run*>& line_runs = lines[key];
    if(line_runs.size() < 2) continue;
    std::sort(line_runs.begin(), line_runs.end(), [](const Run* a, const Run* b) { return a->tets < b->tets; });
    const char* colour = colours[line % 8];
    for(int what = 0; what < 2; ++what)
    {
      s << "<polyline fill='none' stroke='" << colour << "' stroke-width='2'"
        << (what == 1 ? " stroke-dasharray='5,4'" : "") << " points='";
      for(const Run* r : line_runs) s << X(double(r->tets)) << "," << Y(what == 0 ? r->wall : r->smoothing) << " ";
      s << "'/>\n";
    }
    s << "<text x='" << left + 10 << "' y='" << top + 14 * (line + 1) << "' fill='" << colour << "'>" << key
      << ": whole process (solid), smoothing (dashed)</text>\n";
    ++line;
  }
  // Linear growth for reference, through the smallest input's whole-process time.
  const Run& base = *std::min_element(runs.begin(), runs.end(), [](const Run& a, const Run& b) {
    return a.tets < b.tets || (a.tets == b.tets && a.wall < b.wall);
  });
  s << "<line x1='" << X(double(base.tets)) << "' y1='" << Y(base.wall) << "' x2='" << X(x1) << "' y2='"
    << Y(base.wall * x1 / double(base.tets)) << "' stroke='black' stroke-dasharray='2,3'/>\n"
    << "<text x='" << X(x1) - 110 << "' y='" << Y(base.wall * x1 / double(base.tets)) - 6
    << "'>linear (dotted)</text>\n</svg>\n";
  return s.str();
}

} // namespace

int main(int argc, char** argv)
{
  Options o;
  try
  {
    if(argc == 2 && (std::string(argv[1]) == "--help" || std::string(argv[1]) == "-h"))
    {
      std::fputs(usage, stdout);
      return 0;
    }
    o = parse(argc, argv);
  }
  catch(const Bad_option& e)
  {
    std::fprintf(stderr, "scale: %s\n%s", e.what(), usage);
    return 2;
  }
  catch(const std::exception& e)
  {
    std::fprintf(stderr, "scale: %s\n", e.what());
    return 1;
  }
  const auto start = std::chrono::steady_clock::now();
  Report rep;
  rep.command = "scale";
  for(int i = 1; i < argc; ++i) rep.command += std::string(" ") + argv[i];
  rep.machine = bodt_compare::this_machine();
  rep.date = rep.machine.date;
  rep.load_start = load_average();
  try
  {
    std::vector<std::function<Made()>> makers;
    for(int n : o.grids) makers.push_back([n, &o] { return grid_input(n, bodt_bench::Grid_kind::easy, o); });
    for(int n : o.hard_grids) makers.push_back([n, &o] { return grid_input(n, bodt_bench::Grid_kind::hard, o); });
    for(double r : o.mesh3) makers.push_back([r, &o] { return mesh3_input(r, o); });
    for(const std::string& surface : o.surfaces)
      for(double m : o.sizes) makers.push_back([surface, m, &o] { return surface_input(surface, m, o); });
    for(const auto& make : makers)
    {
      Made made = make();
      rep.seconds_inputs += made.input.make_seconds;
      std::fprintf(stderr, "%s: %zu tets, %d iterations%s (%.1f s)\n", made.input.name.c_str(), made.input.tets,
                   made.input.iterations, made.input.from_cache ? ", from the cache" : "",
                   made.input.make_seconds);
      if(made.mesh)
      {
        rep.cgal.push_back(run_cgal_odt(made.input, *made.mesh));
        rep.seconds_cgal += rep.cgal.back().wall;
        made.mesh.reset();   // the bodt runs get the machine's memory
      }
      const auto runs_start = std::chrono::steady_clock::now();
      const std::vector<Run> runs = measure(made.input, o);
      rep.seconds_bodt += seconds_since(runs_start);
      rep.runs.insert(rep.runs.end(), runs.begin(), runs.end());
      if(!made.input.cached) fs::remove(made.input.file);
      rep.inputs.push_back(made.input);
    }
  }
  catch(const std::exception& e)
  {
    std::fprintf(stderr, "scale: %s\n", e.what());
    return 1;
  }
  rep.load_end = load_average();
  rep.seconds_total = seconds_since(start);
  const std::string tables = markdown(rep, o);
  std::fputs(tables.c_str(), stdout);
  if(!o.json_file.empty()) std::ofstream(o.json_file) << to_json(rep, o).dump(1) << "\n";
  if(!o.svg_file.empty()) std::ofstream(o.svg_file) << svg_plot(rep.runs);
  return 0;
}
