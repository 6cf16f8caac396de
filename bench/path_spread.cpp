// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The spread of `bodt smooth`'s final extreme dihedral angles over slightly
// perturbed copies of each input, per binary: on Mesh_3 outputs the result depends
// strongly on the path (moving interior vertices by 1e-11 moves the final minimum
// angle by degrees), so versions of the program are compared over several draws.
// Copy 0 is the input file; copy s > 0 moves every interior vertex by up to E times
// the bounding box's largest side per coordinate (std::mt19937_64 seeded with s).
// Every binary smooths every copy under GNU time; Markdown tables on standard
// output, progress on standard error, every run's figures with --json.
#include "run_child.h"

#include <CGAL/BODT_3/IO/mesh_io.h>
#include <CGAL/BODT_3/Tet_mesh.h>
#include <CGAL/Bbox_3.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace fs = std::filesystem;
namespace BODT = CGAL::BODT_3;
using nlohmann::json;

namespace {

const char* const usage =
    "usage: path_spread MESH... --bodt PATH [--bodt PATH]... [--seeds N] [--jitter E] [--threads T]\n"
    "                   [--folder DIR] [--json FILE] [-- EXTRA BODT ARGS...]\n"
    "  MESH          Medit .mesh inputs\n"
    "  --bodt PATH   a bodt binary, labelled A, B, C... in order (at least one)\n"
    "  --seeds N     copies per input: 0 is the input, 1..N-1 perturbed (default 6)\n"
    "  --jitter E    interior vertices move by up to E times the bounding box's largest side\n"
    "                per coordinate (default 1e-11)\n"
    "  --threads T   bodt's --threads (default 2)\n"
    "  --folder DIR  for the copies and outputs (default: a temporary folder, removed at the end)\n"
    "  --json FILE   every run's figures\n"
    "  -- ARGS       passed to every `bodt smooth` after the others\n";

struct Binary
{
  std::string label, path;
};

struct Options
{
  std::vector<std::string> inputs, extra;
  std::vector<Binary> binaries;
  int seeds = 6, threads = 2;
  double jitter = 1e-11;
  fs::path folder, json_file;
};

struct Run
{
  std::size_t input = 0;   // index in Options::inputs
  std::string binary;
  int seed = 0;
  double min = 0, max = 0, user = 0, sys = 0, wall = 0;
  double cpu() const { return user + sys; }
};

// A number from `low` to `high` (a whole one if `integer`), or a clear refusal.
double number(const std::string& option, const std::string& text, double low, double high, bool integer)
{
  char* end = nullptr;
  const double x = std::strtod(text.c_str(), &end);
  if(!text.empty() && *end == '\0' && x >= low && x <= high && (!integer || x == std::floor(x))) return x;
  char range[64];
  std::snprintf(range, sizeof range, " from %g to %g", low, high);
  throw std::runtime_error(option + " " + text + ": not " + (integer ? "an integer" : "a number") + range);
}

Options parse(int argc, char** argv)
{
  Options o;
  for(int i = 1; i < argc; ++i)
  {
    const std::string option = argv[i];
    if(option == "--")
    {
      o.extra.assign(argv + i + 1, argv + argc);
      break;
    }
    if(option.rfind("--", 0) != 0)
    {
      o.inputs.push_back(option);
      continue;
    }
    if(i + 1 == argc) throw std::runtime_error(option + ": a value is missing, or the option is unknown");
    const std::string value = argv[++i];
    if(option == "--bodt") o.binaries.push_back({std::string(1, char('A' + o.binaries.size())), value});
    else if(option == "--seeds") o.seeds = int(number(option, value, 1, 1e6, true));
    else if(option == "--threads") o.threads = int(number(option, value, 1, 1024, true));
    else if(option == "--jitter") o.jitter = number(option, value, 0, 1e-3, false);   // beyond: other meshes
    else if(option == "--folder") o.folder = value;
    else if(option == "--json") o.json_file = value;
    else throw std::runtime_error("unknown option " + option);
  }
  if(o.inputs.empty()) throw std::runtime_error("no input mesh");
  if(o.binaries.empty()) throw std::runtime_error("no binary: give --bodt PATH");
  if(o.binaries.size() > 26) throw std::runtime_error("--bodt: at most 26 binaries");
  for(const std::string& in : o.inputs)
    if(BODT::IO::format_of(in) != BODT::IO::Mesh_format::medit || !fs::is_regular_file(in))
      throw std::runtime_error(in + (fs::exists(in) ? ": not a .mesh file" : ": no such file"));
  for(const Binary& b : o.binaries)
    if(::access(b.path.c_str(), X_OK) != 0) throw std::runtime_error("--bodt " + b.path + ": not an executable file");
  if(!o.folder.empty() && !fs::is_directory(o.folder))
    throw std::runtime_error("--folder " + o.folder.string() + ": not a folder");
  if(!o.json_file.empty() && !fs::is_directory(fs::absolute(o.json_file).parent_path()))   // said before the runs
    throw std::runtime_error("--json " + o.json_file.string() + ": no such folder");
  if(::access("/usr/bin/time", X_OK) != 0)
    throw std::runtime_error("GNU time is needed for the CPU time: /usr/bin/time (Debian package `time`)");
  return o;
}

// The working folder: a temporary one is removed at the end, a given one keeps
// all but this program's files, whatever happened.
struct Folder
{
  fs::path path;
  bool own = false;
  fs::path file(int k) const
  {
    const char* names[4] = {"path_spread_copy.mesh", "path_spread_out.mesh", "path_spread_report.json",
                            "path_spread_times.txt"};
    return path / names[k];
  }
  ~Folder()
  {
    std::error_code ignored;
    if(own) fs::remove_all(path, ignored);
    for(int k = 0; !own && !path.empty() && k < 4; ++k) fs::remove(file(k), ignored);
  }
};

double load_average()
{
  double one_minute = 0;
  std::ifstream("/proc/loadavg") >> one_minute;
  return one_minute;
}

// Interior vertices, in index order: in a tetrahedron of the mesh, on no boundary
// face (a face of one such tetrahedron, or of two of different labels) and in no
// triangle, edge, corner or required vertex of the file.
std::vector<int> interior_vertices(const BODT::Tet_mesh& mesh)
{
  const bool all_zero = mesh.all_labels_zero();
  std::vector<std::pair<std::array<int, 3>, int>> faces;   // sorted vertices, label
  std::vector<char> in_tet(mesh.points.size(), 0), fixed(mesh.points.size(), 0);
  for(std::size_t t = 0; t < mesh.tets.size(); ++t)
  {
    if(!mesh.in_mesh(t, all_zero)) continue;   // outside the mesh: its faces with the mesh are boundary
    const auto& c = mesh.tets[t];
    for(int k = 0; k < 4; ++k)
    {
      in_tet[c[k]] = 1;
      std::array<int, 3> f = {c[(k + 1) % 4], c[(k + 2) % 4], c[(k + 3) % 4]};
      std::sort(f.begin(), f.end());
      faces.push_back({f, mesh.tet_labels[t]});
    }
  }
  std::sort(faces.begin(), faces.end());
  for(std::size_t i = 0, j; i < faces.size(); i = j)
  {
    for(j = i + 1; j < faces.size() && faces[j].first == faces[i].first;) ++j;
    if(j - i != 2 || faces[i].second != faces[i + 1].second)
      for(int v : faces[i].first) fixed[v] = 1;
  }
  for(const auto& t : mesh.triangles) fixed[t[0]] = fixed[t[1]] = fixed[t[2]] = 1;
  for(const auto& e : mesh.edges) fixed[e[0]] = fixed[e[1]] = 1;
  for(int v : mesh.corners) fixed[v] = 1;
  for(int v : mesh.required_vertices) fixed[v] = 1;
  std::vector<int> interior;
  for(std::size_t v = 0; v < mesh.points.size(); ++v)
    if(in_tet[v] && !fixed[v]) interior.push_back(int(v));
  return interior;
}

double largest_side(const BODT::Tet_mesh& mesh)
{
  const CGAL::Bbox_3 box = CGAL::bbox_3(mesh.points.begin(), mesh.points.end());
  return std::max({box.xmax() - box.xmin(), box.ymax() - box.ymin(), box.zmax() - box.zmin()});
}

// Copy `seed` of `input` written to `file`; returns how many vertices moved. The
// top 53 bits of the engine's output give [-1, 1) alike on every platform, which
// std::uniform_real_distribution does not promise.
std::size_t write_copy(const std::string& input, const BODT::Tet_mesh& mesh, const std::vector<int>& interior,
                       double offset, int seed, const fs::path& file)
{
  BODT::Tet_mesh copy = mesh;
  std::mt19937_64 engine(static_cast<std::uint64_t>(seed));
  auto draw = [&] { return offset * (2.0 * std::ldexp(double(engine() >> 11), -53) - 1.0); };
  std::size_t moved = 0;
  for(int v : interior)
  {
    const auto& p = mesh.points[v];
    const double x = p.x() + draw(), y = p.y() + draw(), z = p.z() + draw();   // in this order
    copy.points[v] = BODT::Tet_mesh::Point(x, y, z);
    moved += copy.points[v] != p;
  }
  // Exact orientations: an inverted tetrahedron would make another mesh, not another path.
  auto orientation = [](const std::vector<BODT::Tet_mesh::Point>& p, const std::array<int, 4>& c) {
    return CGAL::orientation(p[c[0]], p[c[1]], p[c[2]], p[c[3]]);
  };
  for(std::size_t t = 0; t < mesh.tets.size(); ++t)
  {
    const auto& c = mesh.tets[t];
    if(orientation(copy.points, c) != orientation(mesh.points, c))
      throw std::runtime_error(input + ", seed " + std::to_string(seed) + ": tetrahedron " + std::to_string(t + 1) +
                               " (vertices " + std::to_string(c[0] + 1) + " " + std::to_string(c[1] + 1) + " " +
                               std::to_string(c[2] + 1) + " " + std::to_string(c[3] + 1) +
                               ") changes orientation: give a smaller --jitter");
  }
  BODT::IO::write_mesh(file.string(), copy);
  // The writer's shortest round-trip decimals must give the same doubles back.
  if(BODT::IO::read_mesh(file.string()).points != copy.points)
    throw std::runtime_error(file.string() + ": the coordinates do not read back the same");
  return moved;
}

std::string fixed(double x)
{
  char s[32];
  std::snprintf(s, sizeof s, "%.2f", x);
  return s;
}

// Lowest | median | mean | highest, as table cells.
std::string spread(std::vector<double> x)
{
  std::sort(x.begin(), x.end());
  const std::size_t n = x.size();
  double sum = 0;
  for(double v : x) sum += v;
  return fixed(x.front()) + " | " + fixed(n % 2 ? x[n / 2] : (x[n / 2 - 1] + x[n / 2]) / 2) + " | " +
         fixed(sum / double(n)) + " | " + fixed(x.back());
}

struct Report
{
  std::string command, date;
  double load_start = 0, load_end = 0;
  std::vector<std::size_t> tets;   // per input
  std::vector<Run> runs;
};

// Every copy of input `i` by every binary, copy after copy, so that a change of
// the machine's load falls on all binaries alike.
void measure(std::size_t i, const Options& o, const Folder& folder, Report& rep)
{
  const std::string& input = o.inputs[i];
  const BODT::Tet_mesh mesh = BODT::IO::read_mesh(input);
  const std::vector<int> interior = interior_vertices(mesh);
  const double offset = o.jitter * largest_side(mesh);
  rep.tets.push_back(mesh.tets.size());
  std::fprintf(stderr, "%s: %zu tets, %zu interior vertices of %zu, offsets up to %g\n", input.c_str(),
               mesh.tets.size(), interior.size(), mesh.points.size(), offset);
  for(int seed = 0; seed < o.seeds; ++seed)
  {
    const fs::path copy = seed == 0 ? fs::path(input) : folder.file(0);
    if(seed > 0)
      std::fprintf(stderr, "  seed %d: %zu vertices moved\n", seed,
                   write_copy(input, mesh, interior, offset, seed, copy));
    for(const Binary& b : o.binaries)
    {
      std::vector<std::string> args = {b.path, "smooth", copy.string(), "-o", folder.file(1).string(), "--threads",
                                       std::to_string(o.threads), "--report", folder.file(2).string(), "-q"};
      args.insert(args.end(), o.extra.begin(), o.extra.end());
      const bodt_bench::Child_times t = bodt_bench::run_child(args, folder.file(3));
      Run r{i, b.label, seed};
      r.wall = t.wall;
      const json after = json::parse(std::ifstream(folder.file(2))).at("after");
      r.min = after.at("min_dihedral_deg"), r.max = after.at("max_dihedral_deg"), r.user = t.user, r.sys = t.sys;
      for(int k = 1; k < 3; ++k) fs::remove(folder.file(k));
      std::fprintf(stderr, "  seed %d, bodt %s: %.2f / %.2f deg, %.2f s CPU\n", seed, b.label.c_str(), r.min, r.max,
                   r.cpu());
      rep.runs.push_back(r);
    }
  }
  fs::remove(folder.file(0));
}

std::string markdown(const Report& rep, const Options& o)
{
  std::ostringstream s;
  s << "`" << rep.command << "` on " << rep.date << ", load average (1 min) " << fixed(rep.load_start)
    << " at the start, " << fixed(rep.load_end) << " at the end.\n\n";
  for(const Binary& b : o.binaries) s << "- bodt " << b.label << ": `" << b.path << "`\n";
  s << "\nFinal dihedral angles (degrees) of `bodt smooth COPY --threads " << o.threads;
  for(const std::string& a : o.extra) s << " " << a;
  s << "` over " << o.seeds << " copies per input: copy 0 the input, the others with interior vertices moved by up "
    << "to " << o.jitter << " times the bounding box's largest side per coordinate. CPU: user + sys.\n\n"
    << "| input | bodt | tets | seeds | min lowest | min median | min mean | min highest | max lowest | max median "
       "| max mean | max highest | mean CPU s |\n|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  for(std::size_t i = 0; i < o.inputs.size(); ++i)
    for(const Binary& b : o.binaries)
    {
      std::vector<double> min, max;
      double cpu = 0;
      for(const Run& r : rep.runs)
        if(r.input == i && r.binary == b.label) min.push_back(r.min), max.push_back(r.max), cpu += r.cpu();
      s << "| " << o.inputs[i] << " | " << b.label << " | " << rep.tets[i] << " | " << o.seeds << " | "
        << spread(min) << " | " << spread(max) << " | " << fixed(cpu / double(min.size())) << " |\n";
    }
  s << "\n| input | seed | bodt | min | max | CPU s |\n|---|---:|---|---:|---:|---:|\n";
  for(const Run& r : rep.runs)
    s << "| " << o.inputs[r.input] << " | " << r.seed << " | " << r.binary << " | " << fixed(r.min) << " | "
      << fixed(r.max) << " | " << fixed(r.cpu()) << " |\n";
  return s.str();
}

json to_json(const Report& rep, const Options& o)
{
  json j = {{"command", rep.command}, {"date", rep.date}, {"seeds", o.seeds}, {"jitter", o.jitter},
            {"threads", o.threads}, {"extra_args", o.extra},
            {"load_average_1min", {{"start", rep.load_start}, {"end", rep.load_end}}}};
  for(const Binary& b : o.binaries) j["binaries"].push_back({{"label", b.label}, {"path", b.path}});
  for(std::size_t i = 0; i < o.inputs.size(); ++i)
    j["inputs"].push_back({{"file", o.inputs[i]}, {"tets", rep.tets[i]}});
  for(const Run& r : rep.runs)
    j["runs"].push_back({{"input", o.inputs[r.input]}, {"seed", r.seed}, {"bodt", r.binary},
                         {"min_dihedral_deg", r.min}, {"max_dihedral_deg", r.max}, {"wall_seconds", r.wall},
                         {"cpu_seconds", {{"user", r.user}, {"sys", r.sys}, {"total", r.cpu()}}}});
  return j;
}

} // namespace

int main(int argc, char** argv)
{
  if(argc == 2 && (std::string(argv[1]) == "--help" || std::string(argv[1]) == "-h"))
    return std::fputs(usage, stdout), 0;
  Options o;
  Report rep;
  bool parsed = false;   // the usage follows a refused command line only
  try
  {
    o = parse(argc, argv);
    parsed = true;
    rep.command = "path_spread";
    for(int i = 1; i < argc; ++i) rep.command += std::string(" ") + argv[i];
    const std::time_t now = std::time(nullptr);
    char date[32];
    std::strftime(date, sizeof date, "%Y-%m-%d %H:%M UTC", std::gmtime(&now));
    rep.date = date;
    rep.load_start = load_average();
    Folder folder{o.folder};
    if(o.folder.empty())
    {
      std::string name = (fs::temp_directory_path() / "path_spread_XXXXXX").string();
      if(!::mkdtemp(name.data())) throw std::runtime_error("cannot make a temporary folder " + name);
      folder.path = name, folder.own = true;
    }
    for(std::size_t i = 0; i < o.inputs.size(); ++i) measure(i, o, folder, rep);
  }
  catch(const std::exception& e)
  {
    std::fprintf(stderr, "path_spread: %s\n%s", e.what(), parsed ? "" : usage);
    return 1;
  }
  rep.load_end = load_average();
  std::fputs(markdown(rep, o).c_str(), stdout);
  if(o.json_file.empty()) return 0;
  std::ofstream out(o.json_file);
  if(out << to_json(rep, o).dump(1) << "\n" << std::flush) return 0;
  std::fprintf(stderr, "path_spread: cannot write %s\n", o.json_file.c_str());
  return 1;
}
