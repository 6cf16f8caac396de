// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The comparison as Markdown (the paper's Tables 1 to 3, histograms, and text
// generated from the measured numbers), as JSON, and as SVG histograms.
#include "compare/compare.h"

#include "report/json_report.h"
#include "report/svg_histogram.h"

#include <CGAL/BODT_3/IO/write_atomically.h>
#include <CGAL/version.h>

#include <algorithm>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <thread>

namespace bodt_compare {

namespace {

std::string format(const char* fmt, ...) __attribute__((format(printf, 1, 2)));
std::string format(const char* fmt, ...)
{
  va_list args, copy;
  va_start(args, fmt);
  va_copy(copy, args);
  std::string out(std::max(0, std::vsnprintf(nullptr, 0, fmt, copy)), '\0');
  va_end(copy);
  std::vsnprintf(out.data(), out.size() + 1, fmt, args);
  va_end(args);
  return out;
}

const char* const not_applicable = "n/a";

std::string angles(const BODT::Quality_report& q)
{
  return format("%.2f / %.2f", q.min_dihedral_deg, q.max_dihedral_deg);
}

std::string ratio_text(double r)
{
  return std::isfinite(r) ? format("%.2f×", r) : std::string(not_applicable);
}

std::string distance_text(double d)
{
  return d == 0 ? std::string("0") : format("%.2e", d);
}

std::vector<const Method*> family(const std::vector<Method>& table, Family f)
{
  std::vector<const Method*> out;
  for(const Method& m : table)
    if(m.family == f) out.push_back(&m);
  return out;
}

// The CGAL method with the largest minimum angle (then the smallest maximum).
const Measurement* best_cgal(const Input_result& r, const std::vector<Method>& table)
{
  const Measurement* best = nullptr;
  for(const Method* m : family(table, Family::cgal))
  {
    const Measurement* row = r.row(m->name);
    if(!row) continue;
    if(!best || row->quality.min_dihedral_deg > best->quality.min_dihedral_deg ||
       (row->quality.min_dihedral_deg == best->quality.min_dihedral_deg &&
        row->quality.max_dihedral_deg < best->quality.max_dihedral_deg))
      best = row;
  }
  return best;
}

double throughput_ratio(const Input_result& r)
{
  const Measurement* ours = r.row(bodt_name);
  const Measurement* odt = r.row(cgal_odt_name);
  return ours && odt ? ours->throughput() / odt->throughput() : std::nan("");
}

std::string table_header(const std::vector<Method>& table)
{
  std::string head = "| input |", rule = "|---|";
  for(const Method& m : table)
  {
    head += " " + m.name + " |";
    rule += "---|";
  }
  return head + "\n" + rule + "\n";
}

// Why a method has no result on an input, empty if it has one or does not apply.
std::string why_not_run(const Input_result& r, const std::string& method)
{
  for(const Measurement& m : r.rows)
    if(m.method == method) return m.not_run;
  return "";
}

// One row per input, one column per method; `cell` formats an applied method.
template <class Cell>
std::string wide_table(const Comparison& c, const std::vector<Method>& table, Cell cell)
{
  std::string out = table_header(table);
  for(const Input_result& r : c.inputs)
  {
    out += "| " + r.name + " |";
    for(const Method& m : table)
    {
      const Measurement* row = r.row(m.name);
      const char* missing = why_not_run(r, m.name).empty() ? not_applicable : "not run";
      out += " " + (row ? cell(r, *row) : std::string(missing)) + " |";
    }
    out += "\n";
  }
  return out;
}

// -- The text: every claim is a comparison of numbers measured in this run --

std::string input_sentence(const Input_result& r, const std::vector<Method>& table)
{
  const Measurement* ours = r.row(bodt_name);
  if(!ours) return "";
  std::string s = format("- **%s**: %s takes the dihedral angles from %.2f° / %.2f° to %.2f° / %.2f°",
                         r.name.c_str(), bodt_name, r.before.min_dihedral_deg, r.before.max_dihedral_deg,
                         ours->quality.min_dihedral_deg, ours->quality.max_dihedral_deg);
  const Measurement* best = best_cgal(r, table);
  if(!best)
  {
    const Measurement* odt = r.row(odt_interior_name);
    if(odt)
      s += format("; interior-only ODT without flips reaches %.2f° / %.2f° with the boundary fixed",
                  odt->quality.min_dihedral_deg, odt->quality.max_dihedral_deg);
    s += " (CGAL's optimizers need a Mesh_3 domain and do not apply)";
  }
  else
  {
    const double dmin = ours->quality.min_dihedral_deg - best->quality.min_dihedral_deg;
    const double dmax = best->quality.max_dihedral_deg - ours->quality.max_dihedral_deg;
    s += format("; the best CGAL method by minimum angle, %s, reaches %.2f° / %.2f°. Ours is %s on the minimum "
                "angle by %.2f° and %s on the maximum angle by %.2f°",
                best->method.c_str(), best->quality.min_dihedral_deg, best->quality.max_dihedral_deg,
                dmin >= 0 ? "ahead" : "behind", std::abs(dmin), dmax >= 0 ? "ahead" : "behind", std::abs(dmax));
    s += format("; it moves the boundary by %s of the bounding box against %s, and changes the volume by %.1e "
                "against %.1e",
                distance_text(ours->relative_hausdorff).c_str(), distance_text(best->relative_hausdorff).c_str(),
                ours->relative_volume_change, best->relative_volume_change);
    const double ratio = throughput_ratio(r);
    if(std::isfinite(ratio))
      s += format(". Its throughput is %.2f× that of CGAL ODT", ratio);
  }
  if(const Measurement* st = r.row(stellar_name))
    s += format(". Stellar reaches %.2f° / %.2f° with %zu vertices (ours %zu, the input %zu), boundary distance "
                "%s (ours %s), in %.2f CPU s (ours %.2f)",
                st->quality.min_dihedral_deg, st->quality.max_dihedral_deg, st->quality.num_vertices,
                ours->quality.num_vertices, r.before.num_vertices, distance_text(st->relative_hausdorff).c_str(),
                distance_text(ours->relative_hausdorff).c_str(), st->cpu_seconds, ours->cpu_seconds);
  return s + ".\n";
}

// Every place where a method other than the default pipeline does better on one measure.
std::string losses(const Comparison& c, const std::vector<Method>& table)
{
  std::vector<std::string> items;
  for(const Input_result& r : c.inputs)
  {
    const Measurement* ours = r.row(bodt_name);
    if(!ours) continue;
    for(const Method& m : table)
    {
      const Measurement* other = r.row(m.name);
      if(!other || m.family == Family::reference || m.name == bodt_name) continue;
      std::vector<std::string> better;
      if(other->quality.min_dihedral_deg > ours->quality.min_dihedral_deg)
        better.push_back(format("minimum angle %.2f° vs %.2f°", other->quality.min_dihedral_deg,
                                ours->quality.min_dihedral_deg));
      if(other->quality.max_dihedral_deg < ours->quality.max_dihedral_deg)
        better.push_back(format("maximum angle %.2f° vs %.2f°", other->quality.max_dihedral_deg,
                                ours->quality.max_dihedral_deg));
      if(other->quality.tets_below_small < ours->quality.tets_below_small)
        better.push_back(format("%zu vs %zu tetrahedra below 10°", other->quality.tets_below_small,
                                ours->quality.tets_below_small));
      if(other->quality.tets_above_large < ours->quality.tets_above_large)
        better.push_back(format("%zu vs %zu tetrahedra above 170°", other->quality.tets_above_large,
                                ours->quality.tets_above_large));
      if(m.family != Family::ours && other->relative_hausdorff < ours->relative_hausdorff)
        better.push_back(format("boundary distance %s vs %s", distance_text(other->relative_hausdorff).c_str(),
                                distance_text(ours->relative_hausdorff).c_str()));
      if(m.family == Family::cgal && other->throughput() > ours->throughput())
        better.push_back(format("throughput %.3g vs %.3g tets·it/s", other->throughput(), ours->throughput()));
      if(better.empty()) continue;
      std::string item = "- " + r.name + ", " + m.name + ": ";
      for(std::size_t i = 0; i < better.size(); ++i) item += (i ? "; " : "") + better[i];
      items.push_back(item + ".\n");
    }
  }
  if(items.empty())
    return format("No other method beat %s on any input on the minimum or maximum angle, the counts of "
                  "tetrahedra below 10° or above 170°, or (for CGAL's methods) the boundary distance or the "
                  "throughput.\n",
                  bodt_name);
  std::string out = format("Every place where another method beat %s on one measure (first value: the other "
                           "method; ours are listed too, since the variants trade quality against feature "
                           "preservation, and the order of the stages matters):\n\n",
                           bodt_name);
  for(const std::string& i : items) out += i;
  return out;
}

std::string summary(const Comparison& c, const std::vector<Method>& table)
{
  std::size_t with_cgal = 0, min_wins = 0, max_wins = 0, improved = 0, measured = 0;
  std::size_t above_no_flips_min = 0, below_no_flips_max = 0, closer_than_basic = 0, farther_than_basic = 0;
  std::size_t after_pe = 0, after_pe_min_wins = 0, after_pe_max_wins = 0, raw_min_vs_odt = 0, raw_max_vs_odt = 0;
  double ratio_lo = INFINITY, ratio_hi = -INFINITY, worst_volume = 0, worst_cgal_volume = 0, worst_cgal_vertices = 0;
  double most_vertices_added = 0;
  std::map<std::string, std::size_t> best_counts;
  for(const Input_result& r : c.inputs)
  {
    const Measurement* ours = r.row(bodt_name);
    if(!ours) continue;
    ++measured;
    if(ours->quality.min_dihedral_deg > r.before.min_dihedral_deg &&
       ours->quality.max_dihedral_deg < r.before.max_dihedral_deg)
      ++improved;
    for(const Measurement& row : r.rows)
      if(row.applied && row.method != after_perturb_exude_name)
        for(const Method* m : family(table, Family::ours))
          if(m->name == row.method)
          {
            // NODT projects the boundary back onto the input surface and does not keep the volume.
            if(m->name != nodt_name) worst_volume = std::max(worst_volume, std::abs(row.relative_volume_change));
            most_vertices_added =
                std::max(most_vertices_added, double(row.vertices_added) / double(r.before.num_vertices));
          }
    if(const Measurement* smooth = r.row(bodt_no_flips_name))
    {
      if(ours->quality.min_dihedral_deg > smooth->quality.min_dihedral_deg) ++above_no_flips_min;
      if(ours->quality.max_dihedral_deg < smooth->quality.max_dihedral_deg) ++below_no_flips_max;
    }
    if(const Measurement* basic = r.row(bodt_basic_name))
    {
      if(ours->relative_hausdorff < basic->relative_hausdorff) ++closer_than_basic;
      if(ours->relative_hausdorff > basic->relative_hausdorff) ++farther_than_basic;
    }
    const Measurement* pe_ours = r.row(after_perturb_exude_name);
    const Measurement* odt_pe = r.row(cgal_odt_perturb_exude_name);
    if(pe_ours && odt_pe)
    {
      ++after_pe;
      if(pe_ours->quality.min_dihedral_deg > odt_pe->quality.min_dihedral_deg) ++after_pe_min_wins;
      if(pe_ours->quality.max_dihedral_deg < odt_pe->quality.max_dihedral_deg) ++after_pe_max_wins;
    }
    if(const Measurement* odt = r.row(cgal_odt_name))
    {
      if(ours->quality.min_dihedral_deg >= odt->quality.min_dihedral_deg) ++raw_min_vs_odt;
      if(ours->quality.max_dihedral_deg <= odt->quality.max_dihedral_deg) ++raw_max_vs_odt;
    }
    const Measurement* best = best_cgal(r, table);
    if(!best) continue;
    ++with_cgal;
    ++best_counts[best->method];
    if(ours->quality.min_dihedral_deg >= best->quality.min_dihedral_deg) ++min_wins;
    bool lowest_max = true;
    for(const Method* m : family(table, Family::cgal))
      if(const Measurement* row = r.row(m->name))
      {
        lowest_max = lowest_max && ours->quality.max_dihedral_deg <= row->quality.max_dihedral_deg;
        worst_cgal_volume = std::max(worst_cgal_volume, std::abs(row->relative_volume_change));
        worst_cgal_vertices =
            std::max(worst_cgal_vertices, std::abs(double(row->vertices_added)) / double(r.before.num_vertices));
      }
    if(lowest_max) ++max_wins;
    const double ratio = throughput_ratio(r);
    if(std::isfinite(ratio))
    {
      ratio_lo = std::min(ratio_lo, ratio);
      ratio_hi = std::max(ratio_hi, ratio);
    }
  }
  std::string s = format("%s (the default) raised the minimum and lowered the maximum dihedral angle on "
                         "%zu of %zu inputs; our volume-preserving methods (all but NODT) changed no volume by more "
                         "than %.1e (relative) and added at most %.1f%% vertices. ",
                         bodt_name, improved, measured, worst_volume, 100. * most_vertices_added);
  s += format("Against B-ODT smoothing without flips, its minimum angle is larger on %zu and its maximum angle "
              "smaller on %zu of the %zu inputs; against the basic pipeline, which moves feature vertices like "
              "surface vertices, its boundary stays closer to the input on %zu, farther on %zu, and as close "
              "elsewhere. ",
              above_no_flips_min, below_no_flips_max, measured, closer_than_basic, farther_than_basic);
  if(with_cgal)
  {
    s += format("On the %zu inputs where CGAL's optimizers apply, its minimum angle is at least CGAL ODT's on %zu "
                "and its maximum angle at most CGAL ODT's on %zu; its minimum angle is at least the best CGAL "
                "method's on %zu and its maximum angle is at most every CGAL method's on %zu. The best CGAL method "
                "by minimum angle was",
                with_cgal, raw_min_vs_odt, raw_max_vs_odt, min_wins, max_wins);
    std::size_t k = 0;
    for(const auto& [method, count] : best_counts)
      s += format("%s %s on %zu", k++ == 0 ? "" : (k == best_counts.size() ? " and" : ","), method.c_str(), count);
    s += format("; CGAL's methods changed the volume by up to %.1e (relative) and the number of vertices by up to "
                "%.1f%%. ",
                worst_cgal_volume, 100. * worst_cgal_vertices);
    if(after_pe)
      s += format("Started from what `make_mesh_3` gives by default (perturb+exude), our pipeline beats CGAL's "
                  "ODT + perturb+exude (`make_mesh_3` with `odt()`) on the minimum angle on %zu and on the maximum "
                  "angle on %zu of %zu inputs. ",
                  after_pe_min_wins, after_pe_max_wins, after_pe);
    if(std::isfinite(ratio_lo))
      s += format("The throughput of %s (tetrahedra times iterations per CPU second) is %.2f× to %.2f× that of "
                  "CGAL ODT.",
                  bodt_name, ratio_lo, ratio_hi);
  }
  return s + "\n";
}

// -- The paper's reported figures --------------------------------------------

struct Paper_model
{
  const char* model;
  double before_min, before_max, after_min, after_max;
  const char* ours;   // our closest input, empty if none
};

const Paper_model paper_models[] = {
    {"Random Sphere", 5.86, 164.70, 15.20, 150.25, "random_sphere"},
    {"2CMP", 5.57, 163.24, 18.10, 152.66, ""},
    {"Retinal", 1.25, 173.85, 15.10, 164.58, ""},
    {"RyR", 6.19, 170.74, 18.52, 149.25, ""},
    {"2Torus", 5.96, 164.92, 16.92, 152.05, "double-torus-example"},
    {"FanDisk", 6.04, 164.98, 16.80, 160.53, "fandisk"}};

std::string paper_section(const Comparison& c)
{
  std::string out =
      "The paper (figure captions; its tables were lost in the text we have) reports the minimum / maximum "
      "dihedral angle before and after B-ODT. Its meshes are not available except the FanDisk surface, which it "
      "meshed itself: our inputs are our own meshes, so the numbers stand side by side, not as a reproduction. "
      "Our Random Sphere is rebuilt as the paper describes it (642 random points on the unit sphere, 87 inner "
      "points, Delaunay, sliver removal), so its input is close to the paper's but not the same mesh.\n\n"
      "| paper model | paper before | paper after B-ODT | our input | ours before | ours after B-ODT pipeline |\n"
      "|---|---|---|---|---|---|\n";
  std::string sentences;
  for(const Paper_model& p : paper_models)
  {
    const Input_result* r = nullptr;
    for(const Input_result& i : c.inputs)
      if(p.ours[0] && i.name == p.ours) r = &i;
    const Measurement* ours = r ? r->row(bodt_name) : nullptr;
    out += format("| %s | %.2f / %.2f | %.2f / %.2f | %s | %s | %s |\n", p.model, p.before_min, p.before_max,
                  p.after_min, p.after_max, ours ? p.ours : "none", ours ? angles(r->before).c_str() : not_applicable,
                  ours ? angles(ours->quality).c_str() : not_applicable);
    if(!ours) continue;
    const double gain = ours->quality.min_dihedral_deg - r->before.min_dihedral_deg;
    const double paper_gain = p.after_min - p.before_min;
    sentences += format("- %s: the paper raises the minimum angle by %.2f° to %.2f°; our pipeline changes ours "
                        "by %+.2f° to %.2f°, %s the paper's final value.\n",
                        p.model, paper_gain, p.after_min, gain, ours->quality.min_dihedral_deg,
                        ours->quality.min_dihedral_deg >= p.after_min ? "at or above" : "below");
  }
  return out + "\n" + sentences;
}

// Whether Stellar ran, and where it gave no mesh.
std::string stellar_section(const Comparison& c)
{
  if(c.stellar.empty())
    return c.benchmark ? "Klingner and Shewchuk's Stellar was not run. To run it beside the other methods, build it "
                         "from its sources with `bash scripts/build_stellar.sh SRC_DIR` and pass `--stellar "
                         "build/stellar/Stellar` (`scripts/results.sh` does when that file exists); doc/stellar.md "
                         "has a run at the small size.\n\n"
                       : "";
  std::string out = "Stellar (`" + c.stellar + "`) ran as an external program on every input with one subdomain";
  std::string missing;
  for(const Input_result& r : c.inputs)
    if(const std::string why = why_not_run(r, stellar_name); !why.empty())
      missing += "- " + r.name + ": " + why + "\n";
  return out + (missing.empty() ? ".\n\n" : "; it gave no mesh on:\n\n" + missing + "\n");
}

} // namespace

std::string file_stem(const std::string& name)
{
  std::string out;
  for(char ch : name) out += std::isalnum(static_cast<unsigned char>(ch)) || ch == '-' || ch == '_' ? ch : '_';
  return out;
}

Machine this_machine()
{
  Machine m;
  std::ifstream cpuinfo("/proc/cpuinfo");
  std::string line;
  while(std::getline(cpuinfo, line))
  {
    const std::size_t colon = line.find(':');
    if(colon == std::string::npos) continue;
    const std::string key = line.substr(0, line.find_last_not_of(" \t", colon - 1) + 1);
    if(key == "model name" && m.cpu.empty()) m.cpu = line.substr(line.find_first_not_of(" ", colon + 1));
    if(key == "processor") ++m.cores;
  }
  if(m.cpu.empty()) m.cpu = "unknown";
  if(m.cores == 0) m.cores = std::thread::hardware_concurrency();
#if defined(__clang__)
  m.compiler = "Clang " __clang_version__;
#elif defined(__GNUC__)
  m.compiler = "GCC " __VERSION__;
#else
  m.compiler = "unknown";
#endif
  m.cgal = CGAL_VERSION_STR;
  const std::time_t now = std::time(nullptr);
  char date[32];
  std::strftime(date, sizeof date, "%Y-%m-%d %H:%M UTC", std::gmtime(&now));
  m.date = date;
  return m;
}

std::string markdown(const Comparison& c, const std::vector<Method>& table, const std::string& svg_dir)
{
  std::ostringstream md;
  if(c.benchmark)
    md << "<!-- Generated by `" << c.command << "`; do not edit: regenerate with `bash scripts/results.sh`. -->\n"
       << "# B-ODT beside CGAL's mesh optimizers\n\n"
       << "This file was generated by `" << c.command << "` (src/bodt_compare.cpp, also `bodt compare`), with "
       << "the histograms in `" << svg_dir << "/` and every number in `results.json`; `bash scripts/results.sh` "
       << "regenerates them. Every row was measured in that run: CGAL's rows come from CGAL's functions called "
       << "on the same inputs.\n\n";
  else
    md << "# Smoothing methods compared on your meshes\n\n"
       << "Measured by `" << c.command << "`. CGAL's optimizers run only on meshes this run built with "
       << "Mesh_3 (from `.off` surfaces); a mesh read from a file is smoothed by our methods only.\n\n";

  md << "## Machine\n\n| | |\n|---|---|\n"
     << "| CPU | " << c.machine.cpu << " |\n| cores | " << c.machine.cores << " |\n| compiler | "
     << c.machine.compiler << " |\n| CGAL | " << c.machine.cgal << " |\n| date | " << c.machine.date << " |\n"
     << "| iterations | " << c.iterations << " for every iterative method |\n\n"
     << "Times are CPU (user) seconds of the process in the method's call, one core (ours with "
     << "`number_of_threads = 1`, as CGAL's sequential optimizers); the machine may have "
     << "been shared, so compare times as ratios within this file. Throughput is the input's tetrahedra times "
     << "the iterations run, per CPU second. An external program's time is the user time of its process.\n\n";

  md << "## Inputs\n\n| input | built by | tetrahedra | vertices | min / max dihedral (°) |\n|---|---|---|---|---|\n";
  for(const Input_result& r : c.inputs)
    md << "| " << r.name << " | " << r.origin << " | " << r.before.num_tets << " | " << r.before.num_vertices
       << " | " << angles(r.before) << " |\n";
  if(c.benchmark)
    md << "\nThe inputs are of the " << c.size << " size. The Mesh_3 inputs are raw refinement outputs "
          "(`no_perturb`, `no_exude`), so every method starts from the same mesh. Surfaces are meshed with edge "
          "and facet size h, facet distance h / 10, cell size 1.25 h, facet angle 25° and radius-edge ratio 3, "
          "where h is searched for to give about 40,000 tetrahedra (4,000 at the small size).\n";
  for(const std::string& n : c.notes) md << "\n" << n << "\n";

  md << "\n## Methods\n\n| method | applies to | call and settings |\n|---|---|---|\n";
  for(const Method& m : table)
    md << "| " << m.name << " | "
       << (m.applies_to == Applies_to::every_mesh      ? "every input"
           : m.applies_to == Applies_to::mesh_3_output ? "Mesh_3 outputs"
                                                       : "inputs with one subdomain")
       << " | " << m.settings << " |\n";
  md << "\nOur methods other than NODT keep the volume of every subdomain and the boundary surface (flips "
        "change boundary facets only where they are exactly coplanar; an inserted vertex lies on the edge or face "
        "it splits), never invert a tetrahedron, and change the mesh (a move, a flip, an insertion) only where the "
        "worst tetrahedron it touches gets better (by the minimum sine of its dihedral angles) and neither extreme "
        "angle of the input gets worse. Only the pipelines with insertion add vertices, at most 5% of the input's. "
        "NODT moves boundary vertices off the surface and projects them back onto the input's boundary triangles: "
        "it does not keep the volume.\n\n";

  md << stellar_section(c);

  md << "## What the numbers say\n\n" << summary(c, table) << "\n";
  for(const Input_result& r : c.inputs) md << input_sentence(r, table);
  md << "\n### Where " << bodt_name << " loses\n\n" << losses(c, table) << "\n";

  md << "## Table 1. Dihedral angles, min / max (degrees)\n\n"
     << "The largest minimum and the smallest maximum among the smoothing methods are in bold.\n\n"
     << wide_table(c, table, [&](const Input_result& r, const Measurement& row) {
          double best_min = -INFINITY, best_max = INFINITY;
          for(const Measurement& m : r.rows)
            if(m.applied && m.method != original_name)
            {
              best_min = std::max(best_min, m.quality.min_dihedral_deg);
              best_max = std::min(best_max, m.quality.max_dihedral_deg);
            }
          const bool own = row.method != original_name;
          const std::string lo = format("%.2f", row.quality.min_dihedral_deg);
          const std::string hi = format("%.2f", row.quality.max_dihedral_deg);
          return (own && row.quality.min_dihedral_deg == best_min ? "**" + lo + "**" : lo) + " / " +
                 (own && row.quality.max_dihedral_deg == best_max ? "**" + hi + "**" : hi);
        })
     << "\n### Table 1b. Tetrahedra with a dihedral angle below 10° / above 170°\n\n"
     << wide_table(c, table, [](const Input_result&, const Measurement& row) {
          return format("%zu / %zu", row.quality.tets_below_small, row.quality.tets_above_large);
        })
     << "\n### Table 1c. Those tetrahedra by where they are: no vertex on the boundary / some / all four\n\n"
     << "A tetrahedron whose four vertices lie on the boundary or an interface cannot be opened by moving points "
        "along the surface; flips remove many, and vertex insertion can split the rest (a new vertex on the surface edge or face, then smoothed).\n\n"
     << wide_table(c, table, [](const Input_result&, const Measurement& row) {
          return format("%zu / %zu / %zu", row.quality.bad_tets_interior, row.quality.bad_tets_touching_boundary,
                        row.quality.bad_tets_all_vertices_on_boundary);
        })
     << "\n## Table 2. Relative Hausdorff distance between the boundary surfaces before and after\n\n"
     << "The Hausdorff distance between the boundary and interface triangles before and after, divided by "
        "the largest side of the input's bounding box (the paper's ψ), sampled on each triangle.\n\n"
     << wide_table(c, table, [](const Input_result&, const Measurement& row) {
          return distance_text(row.relative_hausdorff);
        });

  md << "\n## Table 3. Running time\n\n"
     << "| input | method | iterations | CPU s | s / iteration | throughput (tets·it/s) | vs CGAL ODT |\n"
     << "|---|---|---|---|---|---|---|\n";
  for(const Input_result& r : c.inputs)
  {
    const Measurement* odt = r.row(cgal_odt_name);
    for(const Measurement& row : r.rows)
    {
      if(!row.applied || row.method == original_name) continue;
      const bool iterative = row.run.iterations > 0;
      md << "| " << r.name << " | " << row.method << " | " << row.run.iterations << " | "
         << format("%.2f", row.cpu_seconds) << " | "
         << (iterative ? format("%.4f", row.seconds_per_iteration()) : std::string(not_applicable)) << " | "
         << (iterative ? format("%.0f", row.throughput()) : std::string(not_applicable)) << " | "
         << (odt && iterative ? ratio_text(row.throughput() / odt->throughput()) : std::string(not_applicable))
         << " |\n";
    }
  }

  md << "\n## Vertices added, volume change, flips, outcome\n\n"
     << "Flips of our methods: 2-3 / 3-2 / edge removals (4 cells and more) / multi-face removals (2 faces and "
        "more), and of those, the flips of exactly coplanar boundary or interface facets.\n\n"
     << "| input | method | vertices added | relative volume change | inverted tetrahedra | flips | outcome |\n"
     << "|---|---|---|---|---|---|---|\n";
  for(const Input_result& r : c.inputs)
    for(const Measurement& row : r.rows)
      if(row.applied && row.method != original_name)
      {
        const auto& f = row.run.flips;
        md << "| " << r.name << " | " << row.method << " | " << row.vertices_added << " | "
           << format("%.2e", row.relative_volume_change) << " | " << row.quality.inverted_tets << " | "
           << (f.total() ? format("%zu / %zu / %zu / %zu (%zu)", f.flips_2_3, f.flips_3_2, f.edge_removals,
                                  f.multi_face_removals, f.boundary_flips)
                         : std::string("0"))
           << " | " << row.run.outcome << " |\n";
      }

  md << "\n## Dihedral-angle histograms\n\n"
     << "All six dihedral angles of every tetrahedron, in 5° bins: the input, " << bodt_name << ", and the CGAL "
        "method with the largest minimum angle where CGAL's methods apply.\n\n";
  for(const Input_result& r : c.inputs)
  {
    const Measurement* ours = r.row(bodt_name);
    if(!ours) continue;
    md << "### " << r.name << "\n\n![" << r.name << "](" << svg_dir << "/" << file_stem(r.name) << ".svg)\n\n"
       << "original " << angles(r.before) << "°, " << bodt_name << " " << angles(ours->quality) << "°";
    if(const Measurement* best = best_cgal(r, table))
      md << ", " << best->method << " " << angles(best->quality) << "°";
    md << ".\n\n";
  }

  if(c.benchmark) md << "## The paper's figures beside ours\n\n" << paper_section(c);
  return md.str();
}

std::string json(const Comparison& c, const std::vector<Method>& table)
{
  nlohmann::json j;
  j["command"] = c.command;
  j["machine"] = {{"cpu", c.machine.cpu},
                  {"cores", c.machine.cores},
                  {"compiler", c.machine.compiler},
                  {"cgal", c.machine.cgal},
                  {"date", c.machine.date}};
  j["benchmark"] = c.benchmark;
  j["size"] = c.size;
  j["iterations"] = c.iterations;
  j["methods"] = nlohmann::json::array();
  for(const Method& m : table)
    j["methods"].push_back({{"name", m.name},
                            {"applies_to", m.applies_to == Applies_to::every_mesh      ? "every_mesh"
                                           : m.applies_to == Applies_to::mesh_3_output ? "mesh_3_output"
                                                                                       : "one_subdomain"},
                            {"settings", m.settings}});
  j["notes"] = c.notes;
  j["stellar"] = c.stellar;
  j["inputs"] = nlohmann::json::array();
  for(const Input_result& r : c.inputs)
  {
    nlohmann::json input = {{"name", r.name}, {"origin", r.origin}, {"before", r.before}};
    input["results"] = nlohmann::json::array();
    for(const Measurement& row : r.rows)
      if(!row.not_run.empty())
        input["results"].push_back({{"method", row.method}, {"not_run", row.not_run}});
      else if(row.applied)
        input["results"].push_back({{"method", row.method},
                                    {"iterations", row.run.iterations},
                                    {"outcome", row.run.outcome},
                                    {"cpu_seconds", row.cpu_seconds},
                                    {"wall_seconds", row.wall_seconds},
                                    {"seconds_per_iteration", row.seconds_per_iteration()},
                                    {"throughput_tets_iterations_per_second", row.throughput()},
                                    {"vertices_added", row.vertices_added},
                                    {"relative_volume_change", row.relative_volume_change},
                                    {"relative_hausdorff_distance", row.relative_hausdorff},
                                    {"flips", row.run.flips},
                                    {"quality", row.quality}});
    j["inputs"].push_back(input);
  }
  return j.dump(1) + "\n";
}

std::string input_histogram_svg(const Input_result& r, const std::vector<Method>& table)
{
  std::vector<BODT::Histogram_series> series{BODT::histogram_series(original_name, "#9e9e9e", r.before)};
  if(const Measurement* ours = r.row(bodt_name))
    series.push_back(BODT::histogram_series(bodt_name, "#1f77b4", ours->quality));
  if(const Measurement* best = best_cgal(r, table))
    series.push_back(BODT::histogram_series(best->method, "#ff7f0e", best->quality));
  return BODT::histogram_svg(r.name + ": dihedral angles", series);
}

void write_results(const Comparison& c, const std::vector<Method>& table, const std::string& dir)
{
  const std::filesystem::path root(dir), images = root / "results";
  std::filesystem::create_directories(images);
  auto write = [](const std::filesystem::path& path, const std::string& text) {
    BODT::write_atomically(path.string(), [&](std::ostream& out) { out << text; });
  };
  write(root / "results.md", markdown(c, table, "results"));
  write(root / "results.json", json(c, table));
  for(const Input_result& r : c.inputs)
    if(r.row(bodt_name)) write(images / (file_stem(r.name) + ".svg"), input_histogram_svg(r, table));
}

std::string default_data_dir()
{
  return BODT_DATA_DIR;
}

} // namespace bodt_compare
