// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef BODT_CLI_PROGRESS_H
#define BODT_CLI_PROGRESS_H

#include <CGAL/BODT_3/Smoothing_options.h>
#include <CGAL/BODT_3/Smoothing_result.h>

#include <cstddef>
#include <cstdio>
#include <vector>

namespace bodt_cli {

/// The smoothing visitor of `bodt smooth`: keeps every iteration's statistics for
/// the report and shows progress on stderr. Nothing is shown with `quiet`, nor
/// during the first second (short runs stay quiet). On a terminal, one line is
/// redrawn: a bar, sweeps done of the total, time, and an estimate of the time
/// left; otherwise one line is printed per sweep.
class Progress
{
public:
  Progress(bool quiet, const CGAL::BODT_3::Smoothing_options& options, std::FILE* out = stderr);

  void after_classification(const CGAL::BODT_3::Smoothing_result& r);
  void after_iteration(const CGAL::BODT_3::Iteration_stats& s);
  /// Ends the progress line, if one was drawn.
  void finish();

  const std::vector<CGAL::BODT_3::Iteration_stats>& iterations() const { return iterations_; }

private:
  bool quiet_;
  bool terminal_;
  std::size_t phases_;       // 1, or 3 with the largest-angle phases
  std::size_t total_;        // sweeps at most
  bool capped_;              // total_ is the cap of a run "until convergence"
  double time_limit_;
  std::FILE* out_;
  bool line_open_ = false;
  std::vector<CGAL::BODT_3::Iteration_stats> iterations_;
};

} // namespace bodt_cli

#endif // BODT_CLI_PROGRESS_H
