// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_BODT_3_IO_HTML_REPORT_H
#define CGAL_BODT_3_IO_HTML_REPORT_H

#include <CGAL/BODT_3/IO/svg_histogram.h>
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

// One histogram figure. Inline SVG needs no namespace declaration in HTML, and
// dropping it leaves the page free of any URL.
inline std::string report_figure(const std::string& heading, const std::string& label, const char* colour,
                                 const Quality_report& r, const std::string& caption)
{
  std::string svg = histogram_svg(heading, {histogram_series(label, colour, r)}, 580, 320);
  const std::string xmlns = " xmlns=\"http://www.w3.org/2000/svg\"";
  const std::size_t at = svg.find(xmlns);
  if(at != std::string::npos) svg.erase(at, xmlns.size());
  return "<figure>\n<div class=\"plot\"><span class=\"ylabel\">number of dihedral angles</span>\n" + svg +
         "</div>\n<figcaption>" + caption + "</figcaption>\n</figure>\n";
}

inline std::string report_caption(const char* which, const Quality_report& r)
{
  const double bin = r.histogram.empty() ? 180.0 : 180.0 / static_cast<double>(r.histogram.size());
  return std::string(which) + ": the " + report_count(6 * r.num_tets) + " dihedral angles of " +
         report_count(r.num_tets) + " tetrahedra in bins of " + report_format("%g", bin) + "&deg;; smallest " +
         report_format("%.2f", r.min_dihedral_deg) + "&deg;, largest " + report_format("%.2f", r.max_dihedral_deg) +
         "&deg;.";
}

} // namespace internal

/// A self-contained HTML page (inline CSS and SVG, no scripts, fonts or other
/// files) reporting a smoothing run: `title` (typically the input file name) as
/// heading, the quality table before and after, the `run` summary items, and the
/// dihedral-angle histograms before (grey) and after (blue) side by side.
/// All text given is escaped.
inline std::string html_report(const std::string& title, const Quality_report& before, const Quality_report& after,
                               const std::vector<Report_entry>& run)
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
       ".figures { display: flex; flex-wrap: wrap; gap: 24px; }\n"
       "figure { margin: 0; }\n"
       ".plot { display: flex; align-items: center; }\n"
       ".ylabel { writing-mode: vertical-rl; transform: rotate(180deg); font-size: 12px; }\n"
       "svg { display: block; max-width: 100%; height: auto; }\n"
       "figcaption { font-size: 14px; max-width: 580px; margin: 4px 0 0 18px; }\n"
       "p.note { color: #555; font-size: 14px; margin: 16px 0; }\n"
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
  row("tets with an angle below " + report_format("%g", before.options.small_angle) + "&deg;",
      report_count(before.tets_below_small), report_count(after.tets_below_small));
  row("tets with an angle above " + report_format("%g", before.options.large_angle) + "&deg;",
      report_count(before.tets_above_large), report_count(after.tets_above_large));
  row("mean radius ratio", ratio(before.mean_radius_ratio), ratio(after.mean_radius_ratio));
  row("min radius ratio", ratio(before.min_radius_ratio), ratio(after.min_radius_ratio));
  row("volume", volume(before.volume), volume(after.volume));
  row("inverted or flat tets", report_count(before.inverted_tets), report_count(after.inverted_tets));
  h += "</tbody>\n</table>\n";

  h += "<ul class=\"run\">\n";
  for(const auto& e : run) h += "<li><b>" + html_escape(e.name) + ":</b> " + html_escape(e.value) + "</li>\n";
  h += "</ul>\n";

  h += "<h2>Dihedral angles</h2>\n<div class=\"figures\">\n";
  h += internal::report_figure("Before smoothing", "before", report_before_colour, before,
                               internal::report_caption("Before smoothing", before));
  h += internal::report_figure("After smoothing", "after", report_after_colour, after,
                               internal::report_caption("After smoothing", after));
  h += "</div>\n<p class=\"note\">Both histograms count the same angles; each has its own vertical scale.</p>\n"
       "</body>\n</html>\n";
  return h;
}

} // namespace BODT_3
} // namespace CGAL

#endif // CGAL_BODT_3_IO_HTML_REPORT_H
