// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_BODT_3_INTERNAL_MESH_CELL_CHANGE_LOG_H
#define CGAL_BODT_3_INTERNAL_MESH_CELL_CHANGE_LOG_H

#include <vector>

namespace CGAL {
namespace BODT_3 {
namespace internal {

/// The cells that `replace_cells` removed or created since the log was last
/// taken, while it is on: a flat view that follows the changes re-reads those
/// cells and their neighbours instead of the whole triangulation. Part of the
/// triangulation adapters, through which every change of the cells goes.
template <class Cell_handle>
class Cell_change_log
{
public:
  /// Starts (or restarts, empty) the log.
  void start_logging()
  {
    logging_ = true;
    changed_.clear();
  }

  bool logging() const { return logging_; }

  /// Records a cell about to be removed or just created; its slot is what counts.
  void changed(Cell_handle c)
  {
    if(logging_) changed_.push_back(c);
  }

  /// Moves the log into `out` and empties it; logging goes on.
  void take_changes(std::vector<Cell_handle>& out)
  {
    out.clear();
    out.swap(changed_);
  }

private:
  bool logging_ = false;
  std::vector<Cell_handle> changed_;
};

} // namespace internal
} // namespace BODT_3
} // namespace CGAL

#endif // CGAL_BODT_3_INTERNAL_MESH_CELL_CHANGE_LOG_H
