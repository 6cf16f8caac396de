// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef BODT_REPORT_HTML_REPORT_H
#define BODT_REPORT_HTML_REPORT_H

#include "report/mesh_pictures.h"
#include "report/svg_histogram.h"

#include <CGAL/BODT_3/mesh_quality.h>

#include <cstdio>
#include <string>
#include <vector>

namespace CGAL {
namespace BODT_3 {

/// One item of the run summary of an HTML report, e.g. {"iterations", "20"}.
struct Report_entry
{
  std::string name;
  std::string value;
};

/// Colours of the two histograms of an HTML report.
inline constexpr const char* report_before_colour = "#8c8c8c";
inline constexpr const char* report_after_colour = "#1f77b4";

/// `text` made safe as HTML element content and as a quoted attribute value.
inline std::string html_escape(const std::string& text)
{
  std::string e;
  for(char ch : text)
  {
    switch(ch)
    {
    case '&': e += "&amp;"; break;
    case '<': e += "&lt;"; break;
    case '>': e += "&gt;"; break;
    case '"': e += "&quot;"; break;
    case '\'': e += "&#39;"; break;
    default: e += ch;
    }
  }
  return e;
}

namespace internal {

inline std::string report_format(const char* fmt, double x)
{
  char buf[64];
  std::snprintf(buf, sizeof buf, fmt, x);
  return buf;
}

inline std::string report_count(std::size_t n) { return std::to_string(n); }

// The histogram figure: both series on one axis. Inline SVG needs no namespace
// declaration in HTML, and dropping it leaves the page free of any URL.
inline std::string report_figure(const Quality_report& before, const Quality_report& after)
{
  Histogram_style style;
  style.overlay = true;
  style.log_counts = true;
  style.small_angle = before.options.small_angle;
  style.large_angle = before.options.large_angle;
  std::string svg = histogram_svg("Dihedral angles before and after",
                                  {histogram_series("before", report_before_colour, before),
                                   histogram_series("after", report_after_colour, after)},
                                  900, 360, style);
  const std::string xmlns = " xmlns=\"http://www.w3.org/2000/svg\"";
  const std::size_t at = svg.find(xmlns);
  if(at != std::string::npos) svg.erase(at, xmlns.size());
  const double bin = before.histogram.empty() ? 180.0 : 180.0 / static_cast<double>(before.histogram.size());
  const std::string small = report_format("%g", before.options.small_angle);
  const std::string large = report_format("%g", before.options.large_angle);
  return "<figure>\n<div class=\"plot\"><span class=\"ylabel\">number of dihedral angles (log scale)</span>\n" +
         svg + "</div>\n<figcaption>All six dihedral angles of each tetrahedron in bins of " +
         report_format("%g", bin) + "&deg;, before (grey, wide bars) and after (blue, narrow bars) on one axis. "
         "The count axis is logarithmic, so that a single angle shows; the shaded tails are the angles below " +
         small + "&deg; and above " + large + "&deg;. <span class=\"tails\">Tetrahedra with an angle below " + small +
         "&deg;: " + report_count(before.tets_below_small) + " before, " + report_count(after.tets_below_small) +
         " after; above " + large + "&deg;: " + report_count(before.tets_above_large) + " before, " +
         report_count(after.tets_above_large) + " after.</span></figcaption>\n</figure>\n";
}

} // namespace internal

/// A self-contained HTML page (inline CSS and SVG, no scripts, fonts or other
/// files) reporting a smoothing run: `title` (typically the input file name) as
/// heading, the quality table before and after (with the bad tetrahedra by where
/// they are), the `run` summary items, the volume of every subdomain before and
/// after, and the dihedral-angle histograms before (grey) and after (blue)
/// overlaid on one log-scale axis with the tails below 10 and above 170 degrees
/// shaded and counted, then `pictures`, HTML put in as it is (the section of
/// bodt_report::mesh_pictures_html; empty: none). All text given is escaped.
inline std::string html_report(const std::string& title, const Quality_report& before, const Quality_report& after,
                               const std::vector<Report_entry>& run, const std::string& pictures = std::string())
{
  using internal::report_count;
  using internal::report_format;
  std::string h;
  h += "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
       "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n<title>bodt smooth: " +
       html_escape(title) + "</title>\n";
  h += "<style>\n"
       "body { font-family: sans-serif; color: #222; background: #fff; max-width: 1240px; margin: 20px auto; "
       "padding: 0 16px; }\n"
       "h1 { font-size: 22px; margin: 0 0 4px; overflow-wrap: anywhere; }\n"
       "h2 { font-size: 17px; margin: 20px 0 6px; }\n"
       "p.what { color: #555; margin: 0 0 12px; }\n"
       "table { border-collapse: collapse; font-size: 15px; }\n"
       "th, td { padding: 5px 16px; border-bottom: 1px solid #ddd; }\n"
       "thead th { border-bottom: 2px solid #444; text-align: right; }\n"
       "tbody th { text-align: left; font-weight: normal; }\n"
       "td { text-align: right; font-variant-numeric: tabular-nums; }\n"
       "ul.run { list-style: none; padding: 0; margin: 12px 0; display: flex; flex-wrap: wrap; gap: 4px 28px; "
       "font-size: 15px; }\n"
       "ul.run b { color: #555; font-weight: normal; }\n"
       "figure { margin: 0; }\n"
       ".plot { display: flex; align-items: center; }\n"
       ".ylabel { writing-mode: vertical-rl; transform: rotate(180deg); font-size: 12px; }\n"
       "svg { display: block; max-width: 100%; height: auto; }\n"
       "figcaption { font-size: 14px; max-width: 900px; margin: 4px 0 0 18px; }\n"
       ".pictures { display: grid; grid-template-columns: repeat(2, minmax(0, 1fr)); gap: 14px 20px; }\n"
       ".pictures figcaption { margin: 4px 0 0; }\n"
       "svg.mesh-picture { width: 100%; }\n"
       ".mesh-picture .cells path { stroke: #000; stroke-opacity: .25; stroke-width: .4; stroke-linejoin: round; }\n"
       ".mesh-picture.dense .cells path { stroke: none; }\n"
       ".mesh-picture .cells path.fe { fill: none; stroke: " + std::string(bodt_report::feature_edge_colour) +
       "; stroke-opacity: 1; stroke-width: 1.5; stroke-linecap: round; }\n"
       ".mesh-picture .worst circle { fill: none; stroke: " + std::string(bodt_report::worst_ring_colour) +
       "; stroke-width: 2.5; }\n"
       ".mesh-picture .worst circle.halo { stroke: #fff; stroke-width: 5.5; }\n"
       ".mesh-picture .worst text { font-size: 12px; font-weight: bold; fill: " +
       std::string(bodt_report::worst_ring_colour) + "; stroke: #fff; stroke-width: 3px; paint-order: stroke; }\n"
       "figure.legend { margin-top: 8px; }\n"
       "</style>\n</head>\n<body>\n";
  h += "<h1>" + html_escape(title) + "</h1>\n<p class=\"what\">B-ODT smoothing report (bodt smooth)</p>\n";

  h += "<h2>Mesh quality</h2>\n<table>\n<thead><tr><th></th><th>before</th><th>after</th></tr></thead>\n<tbody>\n";
  auto row = [&](const std::string& name, const std::string& b, const std::string& a) {
    h += "<tr><th scope=\"row\">" + name + "</th><td>" + b + "</td><td>" + a + "</td></tr>\n";
  };
  auto angle = [](double x) { return report_format("%.2f", x); };
  auto ratio = [](double x) { return report_format("%.4f", x); };
  auto volume = [](double x) { return report_format("%.10g", x); };
  row("vertices", report_count(before.num_vertices), report_count(after.num_vertices));
  row("tetrahedra", report_count(before.num_tets), report_count(after.num_tets));
  row("min dihedral angle (&deg;)", angle(before.min_dihedral_deg), angle(after.min_dihedral_deg));
  row("max dihedral angle (&deg;)", angle(before.max_dihedral_deg), angle(after.max_dihedral_deg));
  if(before.min_boundary_triangle_angle_deg >= 0 && after.min_boundary_triangle_angle_deg >= 0)
    row("smallest angle of a boundary or interface triangle (&deg;)", angle(before.min_boundary_triangle_angle_deg),
        angle(after.min_boundary_triangle_angle_deg));
  row("tets with an angle below " + report_format("%g", before.options.small_angle) + "&deg;",
      report_count(before.tets_below_small), report_count(after.tets_below_small));
  row("tets with an angle above " + report_format("%g", before.options.large_angle) + "&deg;",
      report_count(before.tets_above_large), report_count(after.tets_above_large));
  row("bad tets in the interior", report_count(before.bad_tets_interior), report_count(after.bad_tets_interior));
  row("bad tets touching the boundary", report_count(before.bad_tets_touching_boundary),
      report_count(after.bad_tets_touching_boundary));
  row("bad tets with all vertices on the boundary", report_count(before.bad_tets_all_vertices_on_boundary),
      report_count(after.bad_tets_all_vertices_on_boundary));
  row("mean radius ratio", ratio(before.mean_radius_ratio), ratio(after.mean_radius_ratio));
  row("min radius ratio", ratio(before.min_radius_ratio), ratio(after.min_radius_ratio));
  row("volume", volume(before.volume), volume(after.volume));
  row("inverted or flat tets", report_count(before.inverted_tets), report_count(after.inverted_tets));
  h += "</tbody>\n</table>\n";

  h += "<ul class=\"run\">\n";
  for(const auto& e : run) h += "<li><b>" + html_escape(e.name) + ":</b> " + html_escape(e.value) + "</li>\n";
  h += "</ul>\n";

  h += "<h2>Volume per subdomain</h2>\n<table class=\"volumes\">\n<thead><tr><th>subdomain</th><th>before</th>"
       "<th>after</th><th>relative change</th></tr></thead>\n<tbody>\n";
  for(const auto& kv : before.volume_per_subdomain)
  {
    const auto it = after.volume_per_subdomain.find(kv.first);
    const double a = it == after.volume_per_subdomain.end() ? 0.0 : it->second;
    h += "<tr><th scope=\"row\">" + std::to_string(kv.first) + "</th><td>" + volume(kv.second) + "</td><td>" +
         volume(a) + "</td><td>" + report_format("%.2e", (a - kv.second) / kv.second) + "</td></tr>\n";
  }
  h += "</tbody>\n</table>\n";

  h += "<h2>Dihedral angles</h2>\n" + internal::report_figure(before, after) + pictures + "</body>\n</html>\n";
  return h;
}

} // namespace BODT_3
} // namespace CGAL

#endif // BODT_REPORT_HTML_REPORT_H
