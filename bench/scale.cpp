// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// How the whole `bodt smooth` process scales with the mesh and the threads. For
// jittered grids of growing size (bench/jittered_grid.h) and, with --mesh3,
// Mesh_3 meshes of the two-subdomain ball refined step by step, the mesh is
// written as .mesh, then `bodt smooth IN -o OUT --iterations I --threads T
// --report R -q` runs as a child process for each thread count. Per run: wall
// time, the phases from the JSON report (read, quality, conversion to the
// triangulation and back, set-up, sweeps, flips, max-min steps, insertion, re-reads;
// writing is the rest of the wall time), tetrahedron-iterations per second of
// smoothing, peak resident memory of the child (GNU time's %M) per tetrahedron,
// and whether the output has the same bytes as the one-thread run.
// Prints a Markdown table and writes a log-log plot (SVG) of wall time and
// smoothing time against the number of tetrahedra.
//
//   scale [--grids 20,30,45,60,75,95] [--mesh3 1,2,3] [--threads 1,2] [--iterations 5]
//         [--folder /tmp] [--svg FILE] [--bodt PATH]
#include "jittered_grid.h"
#include "inputs/generated_inputs.h"

#include <CGAL/BODT_3/Tet_mesh_conversion.h>
#include <CGAL/BODT_3/IO/mesh_io.h>

#include <nlohmann/json.hpp>

#include <spawn.h>
#include <sys/wait.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

extern char** environ;

namespace fs = std::filesystem;
namespace BODT = CGAL::BODT_3;

namespace {

struct Run
{
  std::string input;
  std::size_t tets = 0, iterations = 0;
  int threads = 0;
  double wall = 0, read = 0, quality = 0, smoothing = 0;
  nlohmann::json phases;
  double peak_mb = 0;
  bool same_bytes = true;
};

std::vector<double> parse_list(const char* text)
{
  std::vector<double> values;
  std::stringstream in(text);
  std::string item;
  while(std::getline(in, item, ','))
    if(!item.empty()) values.push_back(std::stod(item));
  return values;
}

bool same_file(const fs::path& a, const fs::path& b)
{
  std::ifstream fa(a, std::ios::binary), fb(b, std::ios::binary);
  return std::equal(std::istreambuf_iterator<char>(fa), std::istreambuf_iterator<char>(),
                    std::istreambuf_iterator<char>(fb), std::istreambuf_iterator<char>());
}

// Runs `args` as a child; returns its wall time and peak resident set (MB). The
// peak comes from GNU time (/usr/bin/time -f %M), whose own process is small: a
// child spawned from this process directly would report this process's resident
// set (the generated mesh) while it shares its memory before exec.
std::pair<double, double> run_child(std::vector<std::string> args, const fs::path& folder)
{
  const fs::path peak_file = folder / "scale_peak.txt";
  args.insert(args.begin(), {"/usr/bin/time", "-f", "%M", "-o", peak_file.string()});
  std::vector<char*> argv;
  for(const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  const auto start = std::chrono::steady_clock::now();
  pid_t pid;
  if(posix_spawn(&pid, argv[0], nullptr, nullptr, argv.data(), environ) != 0)
    throw std::runtime_error("cannot start " + args[0]);
  int status = 0;
  if(waitpid(pid, &status, 0) != pid || !WIFEXITED(status) || WEXITSTATUS(status) != 0)
    throw std::runtime_error(args[5] + " failed on " + args[7]);
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  double kilobytes = 0;
  std::ifstream(peak_file) >> kilobytes;
  fs::remove(peak_file);
  return {wall, kilobytes / 1024.0};
}

std::vector<Run> measure(const std::string& name, const BODT::Tet_mesh& mesh, const std::vector<double>& threads,
                         int iterations, const fs::path& folder, const std::string& bodt)
{
  const fs::path input = folder / ("scale_" + name + ".mesh");
  BODT::IO::write_mesh(input.string(), mesh);
  std::vector<Run> runs;
  for(double t : threads)
  {
    Run r;
    r.input = name;
    r.tets = mesh.tets.size();
    r.threads = static_cast<int>(t);
    const fs::path output = folder / ("scale_" + name + "_t" + std::to_string(r.threads) + ".mesh");
    const fs::path report = folder / ("scale_" + name + ".json");
    std::tie(r.wall, r.peak_mb) =
        run_child({bodt, "smooth", input.string(), "-o", output.string(), "--iterations", std::to_string(iterations),
                   "--threads", std::to_string(r.threads), "--report", report.string(), "-q"},
                  folder);
    std::ifstream in(report);
    const nlohmann::json j = nlohmann::json::parse(in);
    r.read = j["process_seconds"]["read"];
    r.quality = j["process_seconds"]["quality_before_and_after"];
    r.smoothing = j["process_seconds"]["smoothing"];
    r.phases = j["result"]["phase_seconds"];
    r.iterations = j["result"]["iterations"];
    const fs::path first = folder / ("scale_" + name + "_t" + std::to_string(static_cast<int>(threads.front())) + ".mesh");
    r.same_bytes = same_file(first, output);
    fs::remove(report);
    runs.push_back(r);
    std::printf("| %s | %zu | %d | %.2f | %.2f | %.2f | %.2f | %.2f | %.2f | %.2f | %.2f | %.2f | %.2f | %.2f | %.2f "
                "| %.2f | %.0f | %.0f | %s |\n",
                name.c_str(), r.tets, r.threads, r.wall, r.read, r.quality, double(r.phases["conversion"]),
                double(r.phases["setup"]), double(r.phases["sweeps"]), double(r.phases["flips"]),
                double(r.phases["max_min"]), double(r.phases["insertion"]), double(r.phases["reread"]),
                r.wall - r.read - r.quality - r.smoothing, r.smoothing,
                double(r.tets * r.iterations) / r.smoothing / 1e6, r.peak_mb, r.peak_mb * 1048576.0 / double(r.tets),
                r.same_bytes ? "yes" : "NO");
    std::fflush(stdout);
  }
  for(double t : threads)
    fs::remove(folder / ("scale_" + name + "_t" + std::to_string(static_cast<int>(t)) + ".mesh"));
  fs::remove(input);
  return runs;
}

// Log-log plot: seconds against tetrahedra, one line per (series, threads).
std::string svg_plot(const std::vector<Run>& runs, const std::vector<double>& threads)
{
  const double W = 640, H = 420, left = 70, right = 20, top = 30, bottom = 50;
  double x0 = 1e300, x1 = 0, y0 = 1e300, y1 = 0;
  for(const Run& r : runs)
  {
    x0 = std::min(x0, double(r.tets)), x1 = std::max(x1, double(r.tets));
    y0 = std::min(y0, r.smoothing), y1 = std::max(y1, r.wall);
  }
  const double lx0 = std::floor(std::log10(x0)), lx1 = std::ceil(std::log10(x1));
  const double ly0 = std::floor(std::log10(y0)), ly1 = std::ceil(std::log10(y1));
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
  const char* colours[] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd"};
  int line = 0;
  std::vector<std::string> inputs_kinds = {"grid", "mesh3"};
  for(const std::string& kind : inputs_kinds)
    for(std::size_t ti = 0; ti < threads.size(); ++ti)
      for(int what = 0; what < 2; ++what)
      {
        std::vector<const Run*> line_runs;
        for(const Run& r : runs)
          if(r.input.rfind(kind, 0) == 0 && r.threads == int(threads[ti])) line_runs.push_back(&r);
        if(line_runs.size() < 2) continue;
        std::sort(line_runs.begin(), line_runs.end(), [](const Run* a, const Run* b) { return a->tets < b->tets; });
        const char* colour = colours[ti % 4];
        s << "<polyline fill='none' stroke='" << colour << "' stroke-width='2'"
          << (what == 1 ? " stroke-dasharray='5,4'" : "") << (kind == "mesh3" ? " opacity='0.5'" : "") << " points='";
        for(const Run* r : line_runs) s << X(double(r->tets)) << "," << Y(what == 0 ? r->wall : r->smoothing) << " ";
        s << "'/>\n";
        s << "<text x='" << left + 10 << "' y='" << top + 14 * (line + 1) << "' fill='" << colour << "'>" << kind
          << ", " << int(threads[ti]) << " thread" << (threads[ti] > 1 ? "s" : "") << ": "
          << (what == 0 ? "whole process (solid)" : "smoothing (dashed)") << "</text>\n";
        ++line;
      }
  // Linear growth for reference, through the smallest grid's whole-process time.
  const Run& base = runs.front();
  s << "<line x1='" << X(double(base.tets)) << "' y1='" << Y(base.wall) << "' x2='" << X(x1) << "' y2='"
    << Y(base.wall * x1 / double(base.tets)) << "' stroke='black' stroke-dasharray='2,3'/>\n"
    << "<text x='" << X(x1) - 110 << "' y='" << Y(base.wall * x1 / double(base.tets)) - 6
    << "'>linear (dotted)</text>\n</svg>\n";
  return s.str();
}

} // namespace

int main(int argc, char** argv)
{
  std::vector<double> grids = {20, 30, 45, 60, 75, 95}, mesh3, threads = {1, 2};
  int iterations = 5;
  fs::path folder = "/tmp";
  std::string svg;
  std::string bodt = (fs::canonical("/proc/self/exe").parent_path().parent_path() / "bodt").string();
  for(int i = 1; i + 1 < argc; i += 2)
  {
    const std::string option = argv[i];
    if(option == "--grids") grids = parse_list(argv[i + 1]);
    else if(option == "--mesh3") mesh3 = parse_list(argv[i + 1]);
    else if(option == "--threads") threads = parse_list(argv[i + 1]);
    else if(option == "--iterations") iterations = std::atoi(argv[i + 1]);
    else if(option == "--folder") folder = argv[i + 1];
    else if(option == "--svg") svg = argv[i + 1];
    else if(option == "--bodt") bodt = argv[i + 1];
    else
    {
      std::fprintf(stderr, "unknown option %s\n", argv[i]);
      return 2;
    }
  }
  if(threads.empty()) threads = {1};
  std::printf("`bodt smooth --iterations %d`, default pipeline; seconds (wall); memory: peak resident set\n\n",
              iterations);
  std::printf("| input | tets | threads | wall | read | quality | conversion | set-up | sweeps | flips | max-min | "
              "insertion | re-reads | write, exit | smoothing | M tet-its/s | peak MB | bytes/tet | same bytes |\n");
  std::printf("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|\n");
  std::vector<Run> all;
  try
  {
    for(double n : grids)
    {
      const auto runs = measure("grid" + std::to_string(int(n)), bodt_bench::jittered_grid(int(n)), threads,
                                iterations, folder, bodt);
      all.insert(all.end(), runs.begin(), runs.end());
    }
    for(double refinement : mesh3)
    {
      char name[32];
      std::snprintf(name, sizeof name, "mesh3_x%g", refinement);
      const auto input = bodt_inputs::make_input(bodt_inputs::Shape::two_subdomains, bodt_inputs::Size::benchmark,
                                                 refinement);
      const auto runs = measure(name, BODT::c3t3_to_tet_mesh(input.c3t3), threads, iterations, folder, bodt);
      all.insert(all.end(), runs.begin(), runs.end());
    }
  }
  catch(const std::exception& e)
  {
    std::fprintf(stderr, "scale: %s\n", e.what());
    return 1;
  }
  if(!svg.empty() && !all.empty()) std::ofstream(svg) << svg_plot(all, threads);
  return 0;
}
