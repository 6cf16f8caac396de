// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef BODT_REPORT_SVG_HISTOGRAM_H
#define BODT_REPORT_SVG_HISTOGRAM_H

#include <CGAL/BODT_3/mesh_quality.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace CGAL {
namespace BODT_3 {

/// One distribution drawn in a histogram: the dihedral-angle histogram of a
/// `Quality_report`, with a legend label and a colour ("#rrggbb").
struct Histogram_series
{
  std::string label;
  std::string colour;
  std::vector<std::size_t> counts;   // equal bins over [0, 180] degrees
};

/// How a histogram is drawn.
struct Histogram_style
{
  /// Series drawn over each other in each bin, the first widest, so that every
  /// series shows on one axis (the paper's figures); otherwise side by side.
  bool overlay = false;
  /// Counts on a log(1 + n) axis, so that a single tetrahedron among 100,000 still
  /// shows as a bar; otherwise linear.
  bool log_counts = false;
  /// Angles (degrees) below and above which the tails are shaded; negative: none.
  double small_angle = -1;
  double large_angle = -1;
};

/// An SVG picture (as text, for a file or to inline in HTML) of dihedral-angle
/// histograms, the paper's figures: the series over a degree axis with ticks every
/// 30 degrees, with a legend, drawn as `style` says; `title` goes on top. Every
/// series must have the same bins.
inline std::string histogram_svg(const std::string& title, const std::vector<Histogram_series>& series,
                                 int width = 640, int height = 320, const Histogram_style& style = Histogram_style())
{
  const double left = 60, right = 20, top = 40, bottom = 45;
  const double pw = width - left - right, ph = height - top - bottom;
  std::size_t bins = 0, peak = 1;
  for(const auto& s : series)
  {
    bins = std::max(bins, s.counts.size());
    for(std::size_t c : s.counts) peak = std::max(peak, c);
  }
  // Height of a count as a fraction of the plot's.
  auto scale = [&](double n) {
    return style.log_counts ? std::log10(1 + n) / std::log10(1 + static_cast<double>(peak))
                            : n / static_cast<double>(peak);
  };
  std::string out;
  char buf[512];
  auto add = [&](const char* fmt, auto... args) {
    std::snprintf(buf, sizeof buf, fmt, args...);
    out += buf;
  };
  auto escaped = [](const std::string& s) {
    std::string e;
    for(char ch : s)
      e += ch == '<' ? std::string("&lt;") : ch == '>' ? std::string("&gt;") : ch == '&' ? std::string("&amp;")
                                                                                         : std::string(1, ch);
    return e;
  };
  add("<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%d\" height=\"%d\" viewBox=\"0 0 %d %d\" "
      "font-family=\"sans-serif\" font-size=\"12\">\n",
      width, height, width, height);
  add("<rect width=\"%d\" height=\"%d\" fill=\"white\"/>\n", width, height);
  add("<text x=\"%g\" y=\"22\" font-size=\"15\" text-anchor=\"middle\">", width / 2.0);
  out += escaped(title) + "</text>\n";
  // The tails, shaded behind everything else.
  auto shade = [&](double from_deg, double to_deg) {
    add("<rect class=\"tail\" x=\"%.2f\" y=\"%g\" width=\"%.2f\" height=\"%g\" fill=\"#fbe3e3\"/>\n",
        left + pw * from_deg / 180.0, top, pw * (to_deg - from_deg) / 180.0, ph);
  };
  if(style.small_angle > 0) shade(0, style.small_angle);
  if(style.large_angle > 0 && style.large_angle < 180) shade(style.large_angle, 180);
  if(style.log_counts)
  {
    // Ticks at 0, 1, 10, 100, ...
    for(double y = 0; y <= peak; y = y == 0 ? 1 : y * 10)
    {
      const double py = top + ph - ph * scale(y);
      add("<line x1=\"%g\" y1=\"%g\" x2=\"%g\" y2=\"%g\" stroke=\"#ddd\"/>\n", left, py, left + pw, py);
      add("<text x=\"%g\" y=\"%g\" text-anchor=\"end\">%.0f</text>\n", left - 5, py + 4, y);
    }
  }
  else
  {
    // The smallest step of the form 1, 2 or 5 times a power of ten giving at most six ticks.
    double step = 1;
    for(double m = 1; peak / step > 6; m *= 10)
      for(double f : {1.0, 2.0, 5.0})
        if(peak / (f * m) <= 6 && peak / step > 6) step = f * m;
    for(double y = 0; y <= peak; y += step)
    {
      const double py = top + ph - ph * scale(y);
      add("<line x1=\"%g\" y1=\"%g\" x2=\"%g\" y2=\"%g\" stroke=\"#ddd\"/>\n", left, py, left + pw, py);
      add("<text x=\"%g\" y=\"%g\" text-anchor=\"end\">%.0f</text>\n", left - 5, py + 4, y);
    }
  }
  if(bins > 0 && !series.empty())
  {
    const double bw = pw / static_cast<double>(bins);
    for(std::size_t k = 0; k < series.size(); ++k)
    {
      // Overlaid: each series narrower than the one before, centred in the bin.
      const double w = style.overlay ? bw * (1.0 - 0.45 * static_cast<double>(k) / std::max<std::size_t>(1, series.size() - 1))
                                     : bw / static_cast<double>(series.size());
      const double offset = style.overlay ? (bw - w) / 2 : w * static_cast<double>(k);
      for(std::size_t b = 0; b < series[k].counts.size(); ++b)
      {
        const double h = ph * scale(static_cast<double>(series[k].counts[b]));
        if(h <= 0) continue;
        add("<rect x=\"%.2f\" y=\"%.2f\" width=\"%.2f\" height=\"%.2f\" fill=\"%s\"/>\n", left + b * bw + offset,
            top + ph - h, w, h, series[k].colour.c_str());
      }
    }
  }
  for(int deg = 0; deg <= 180; deg += 30)
  {
    const double px = left + pw * deg / 180.0;
    add("<line x1=\"%g\" y1=\"%g\" x2=\"%g\" y2=\"%g\" stroke=\"black\"/>\n", px, top + ph, px, top + ph + 5);
    add("<text x=\"%g\" y=\"%g\" text-anchor=\"middle\">%d</text>\n", px, top + ph + 18, deg);
  }
  add("<line x1=\"%g\" y1=\"%g\" x2=\"%g\" y2=\"%g\" stroke=\"black\"/>\n", left, top + ph, left + pw, top + ph);
  add("<line x1=\"%g\" y1=\"%g\" x2=\"%g\" y2=\"%g\" stroke=\"black\"/>\n", left, top, left, top + ph);
  add("<text x=\"%g\" y=\"%d\" text-anchor=\"middle\">dihedral angle (degrees)</text>\n", left + pw / 2,
      height - 8);
  for(std::size_t k = 0; k < series.size(); ++k)
  {
    const double lx = left + pw - 170, ly = top + 8 + 18 * static_cast<double>(k);
    add("<rect x=\"%g\" y=\"%g\" width=\"12\" height=\"12\" fill=\"%s\"/>\n", lx, ly, series[k].colour.c_str());
    add("<text x=\"%g\" y=\"%g\">", lx + 18, ly + 10);
    out += escaped(series[k].label) + "</text>\n";
  }
  out += "</svg>\n";
  return out;
}

/// The histogram series of a quality report.
inline Histogram_series histogram_series(const std::string& label, const std::string& colour,
                                         const Quality_report& report)
{
  return {label, colour, report.histogram};
}

} // namespace BODT_3
} // namespace CGAL

#endif // BODT_REPORT_SVG_HISTOGRAM_H
