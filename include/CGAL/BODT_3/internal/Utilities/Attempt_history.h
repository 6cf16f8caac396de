// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_BODT_3_INTERNAL_UTILITIES_ATTEMPT_HISTORY_H
#define CGAL_BODT_3_INTERNAL_UTILITIES_ATTEMPT_HISTORY_H

#include <CGAL/BODT_3/internal/Utilities/Id_tuple_map.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <limits>
#include <vector>

namespace CGAL {
namespace BODT_3 {
namespace internal {

/// What earlier passes (flips, insertion) learnt: the cells (by sorted vertex
/// ids) tried in vain, when and how many times in a row, and per vertex when it
/// or a vertex sharing an edge with it last changed (moved, or got a new star),
/// and when its connectivity last changed (a new star by a flip or an
/// insertion), on a clock that the caller advances at each sweep and the pass at
/// each change. A cell tried in vain is tried again only once its neighbourhood
/// changed (what a pass can do with it depends on nothing else, except for
/// multi-face removals reaching further), and, after k failures in a row, only
/// every 2^(k-1) passes (at most 8): smoothing keeps moving the vertices of a bad
/// region a little, and such cells would otherwise be retried every pass. After
/// `retries_after_moves` failures, moves alone no longer make it worth trying:
/// only a new connectivity around it does (doc/stages.md measures both).
struct Attempt_history
{
  // When a cell last failed, in 8 bytes (a map slot is 24, with the sorted ids):
  // on a Mesh_3 mesh the largest-angle phase's first pass tries nearly every cell.
  // Each field saturates, which only lets a cell be tried sooner: a clock past
  // 2^40 changes, a pass past 65535, and `count` past 255 (so `retries_after_moves`
  // of 255 or more acts as never).
  class Failure
  {
  public:
    Failure() = default;
    Failure(std::size_t clock, std::size_t pass, std::size_t count)
      : bits_(std::min<std::uint64_t>(clock, max_clock) << 24 | std::min<std::uint64_t>(pass, 0xFFFF) << 8 |
              std::min<std::uint64_t>(count, 0xFF))
    {}
    std::size_t clock() const { return static_cast<std::size_t>(bits_ >> 24); }
    std::size_t pass() const { return static_cast<std::size_t>(bits_ >> 8 & 0xFFFF); }
    std::size_t count() const { return static_cast<std::size_t>(bits_ & 0xFF); }

  private:
    static constexpr std::uint64_t max_clock = (std::uint64_t(1) << 40) - 1;
    std::uint64_t bits_ = 0;
  };
  std::size_t clock = 0;
  std::size_t pass = 0;   // set by the caller
  std::size_t retries_after_moves = std::numeric_limits<std::size_t>::max();
  std::vector<std::size_t> region_stamp;     // last change within one edge
  std::vector<std::size_t> topology_stamp;   // last connectivity change within one edge
  Id_tuple_map<4, Failure> failed;

  static std::size_t stamp(const std::vector<std::size_t>& stamps, int v)
  {
    return v >= 0 && v < static_cast<int>(stamps.size()) ? stamps[v] : 0;
  }

  /// Marks vertex `v`'s star changed now (a flip or an insertion).
  void star_changed(int v)
  {
    for(std::vector<std::size_t>* stamps : {&region_stamp, &topology_stamp})
    {
      if(v >= static_cast<int>(stamps->size())) stamps->resize(v + 1, 0);
      (*stamps)[v] = clock;
    }
  }

  bool worth_trying(const std::array<int, 4>& ids) const
  {
    const Failure* found = failed.find(ids);
    if(!found) return true;
    const Failure& f = *found;
    const std::size_t wait = std::size_t(1) << std::min<std::size_t>(f.count() - 1, 3);
    if(pass < f.pass() + wait) return false;
    const std::vector<std::size_t>& changes = f.count() > retries_after_moves ? topology_stamp : region_stamp;
    for(int v : ids)
      if(stamp(changes, v) > f.clock()) return true;
    return false;
  }

  void record_failure(const std::array<int, 4>& ids)
  {
    bool inserted;
    Failure& f = failed.find_or_insert(ids, Failure(clock, pass, 1), inserted);
    if(!inserted) f = Failure(clock, pass, f.count() + 1);
  }
};

} // namespace internal
} // namespace BODT_3
} // namespace CGAL

#endif // CGAL_BODT_3_INTERNAL_UTILITIES_ATTEMPT_HISTORY_H
