// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_BODT_3_INTERNAL_UTILITIES_CANDIDATE_QUEUE_H
#define CGAL_BODT_3_INTERNAL_UTILITIES_CANDIDATE_QUEUE_H

#include <algorithm>
#include <cstddef>
#include <queue>
#include <utility>
#include <vector>

namespace CGAL {
namespace BODT_3 {
namespace internal {

/// The cells a pass will try (`Flip_candidate`s, or any type whose `operator<`
/// means "tried after"), in the order one heap of them all would give: the
/// starting cells sorted once, and a heap of the cells queued during the pass
/// (few: the new cells and those put back); each pop takes the front that goes
/// first. On a Mesh_3 mesh the largest-angle phase's first flip pass starts from
/// two thirds of the cells, and one heap of them spent more in its pops than the
/// sort does.
template <class Candidate>
class Candidate_queue
{
public:
  /// Takes `start` over.
  explicit Candidate_queue(std::vector<Candidate>&& start) : start_(std::move(start))
  {
    std::sort(start_.begin(), start_.end(), [](const Candidate& a, const Candidate& b) { return b < a; });
  }

  bool empty() const { return next_ == start_.size() && queued_.empty(); }

  /// Removes and returns the cell to try next. Of two equal candidates (the same
  /// vertices and quality) either may come first: both name the cell those
  /// vertices make now, if any.
  Candidate pop()
  {
    if(next_ < start_.size() && (queued_.empty() || !(start_[next_] < queued_.top()))) return start_[next_++];
    const Candidate c = queued_.top();
    queued_.pop();
    return c;
  }

  void push(const Candidate& c) { queued_.push(c); }

private:
  std::vector<Candidate> start_;
  std::size_t next_ = 0;
  std::priority_queue<Candidate> queued_;
};

} // namespace internal
} // namespace BODT_3
} // namespace CGAL

#endif // CGAL_BODT_3_INTERNAL_UTILITIES_CANDIDATE_QUEUE_H
