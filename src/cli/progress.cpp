// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
#include "cli/progress.h"

#include <algorithm>
#include <string>
#include <unistd.h>

namespace bodt_cli {

namespace BODT = CGAL::BODT_3;

Progress::Progress(bool quiet, const BODT::Smoothing_options& options, std::FILE* out)
  : quiet_(quiet),
    terminal_(::isatty(::fileno(out)) != 0),
    // The later phases run at most as many iterations each as the main phase.
    phases_(options.largest_angle_phase && options.smoothing_method != BODT::Smoothing_method::NODT
                ? (options.worst_cell_phase ? 4 : 3)
                : 1),
    total_((options.max_iteration_number == 0 ? 1000 : options.max_iteration_number) * phases_),
    capped_(options.max_iteration_number == 0),
    time_limit_(options.time_limit),
    out_(out)
{
}

void Progress::after_classification(const BODT::Smoothing_result& r)
{
  if(quiet_) return;
  std::fprintf(out_, "bodt smooth: %zu interior, %zu surface, %zu feature and %zu fixed vertices%s\n",
               r.interior_vertices, r.surface_vertices, r.feature_vertices, r.fixed_vertices,
               r.used_tensor_voting ? " (features by tensor voting)" : "");
  if(r.crack_vertices > 0)
    std::fprintf(out_, "bodt smooth: %zu vertices fixed on cracks (coincident vertices stay coincident)\n",
                 r.crack_vertices);
  if(r.embedded_triangles > 0)
    std::fprintf(out_, "bodt smooth: %zu triangles inside subdomains kept as embedded surfaces\n",
                 r.embedded_triangles);
}

void Progress::after_iteration(const BODT::Iteration_stats& s)
{
  iterations_.push_back(s);
  if(quiet_ || s.seconds < 1.0) return;
  // The time left if the coming sweeps take as long as the past ones on average.
  double left = s.seconds / static_cast<double>(s.iteration) * static_cast<double>(total_ - std::min(total_, s.iteration));
  if(time_limit_ > 0) left = std::min(left, std::max(0.0, time_limit_ - s.seconds));
  static const char* const phase_names[4] = {"", ", largest-angle phase", ", last phase", ", worst-cell phase"};
  const std::string of = (capped_ ? " (until convergence, at most " + std::to_string(total_) + ")"
                                  : (phases_ > 1 ? " of at most " : " of ") + std::to_string(total_)) +
                         phase_names[std::min<std::size_t>(s.phase, 3)];
  if(terminal_)
  {
    const int width = 24;
    const int done = static_cast<int>(width * std::min(1.0, static_cast<double>(s.iteration) / total_));
    std::fprintf(out_, "\r\033[Kbodt smooth: [%s%s] sweep %zu%s, %.1f s, about %.0f s left", std::string(done, '#').c_str(),
                 std::string(width - done, '.').c_str(), s.iteration, of.c_str(), s.seconds, left);
    line_open_ = true;
  }
  else
    std::fprintf(out_,
                 "bodt smooth: sweep %zu%s: %zu vertices moved, %zu refused, %zu flips, %zu vertices inserted; "
                 "%.1f s, about %.0f s left\n",
                 s.iteration, of.c_str(), s.moved, s.refused, s.topology.total(), s.insertion.vertices_added,
                 s.seconds, left);
  std::fflush(out_);
}

void Progress::finish()
{
  if(line_open_) std::fputc('\n', out_);
  line_open_ = false;
}

} // namespace bodt_cli
