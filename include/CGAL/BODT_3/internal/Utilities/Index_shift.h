// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_BODT_3_INTERNAL_UTILITIES_INDEX_SHIFT_H
#define CGAL_BODT_3_INTERNAL_UTILITIES_INDEX_SHIFT_H

#include <algorithm>
#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL {
namespace BODT_3 {
namespace internal {

/// How the indices of an ordered array change when some elements leave (`gone`,
/// their indices, ascending) and new ones come in, each before a given old index:
/// the index now of a kept element (`now`), and the arrays per element moved in
/// place (`relocate`), so that a few changes cost neither a copy nor fresh pages.
class Index_shift
{
public:
  std::vector<int> gone;   // old indices, ascending, filled before `prepare`

  /// `before`: for each new element in order, the old index it goes before
  /// (ascending; `n` for the end); `n`: the old number of elements.
  void prepare(const std::vector<std::size_t>& before, std::size_t n)
  {
    n_ = n;
    // The shift changes by -1 after each gone element and by +1 at each new one's place.
    std::vector<std::pair<std::size_t, int>> events;
    events.reserve(gone.size() + before.size());
    for(int g : gone) events.push_back({static_cast<std::size_t>(g) + 1, -1});
    for(std::size_t b : before) events.push_back({b, 1});
    std::sort(events.begin(), events.end());
    positions_.clear();
    shifts_.clear();
    int shift = 0;
    for(const auto& [position, change] : events)
    {
      shift += change;
      if(!positions_.empty() && positions_.back() == position)
        shifts_.back() = shift;
      else
      {
        positions_.push_back(position);
        shifts_.push_back(shift);
      }
    }
    // Per block of indices: the shift at its start, and whether it changes within
    // the block or the block holds a gone element (then looked up).
    const std::size_t blocks = (n >> block_bits) + 1;
    block_shift_.assign(blocks, 0);
    mixed_.assign(blocks, 0);
    std::size_t e = 0;
    shift = 0;
    for(std::size_t b = 0; b < blocks; ++b)
    {
      const std::size_t first = b << block_bits;
      while(e < positions_.size() && positions_[e] <= first) shift = shifts_[e++];
      block_shift_[b] = shift;
    }
    for(std::size_t p : positions_)
      if((p & block_mask) != 0 && (p >> block_bits) < blocks) mixed_[p >> block_bits] = 1;
    for(int g : gone) mixed_[static_cast<std::size_t>(g) >> block_bits] = 1;
  }

  bool is_gone(int j) const
  {
    return mixed_[static_cast<std::size_t>(j) >> block_bits] && std::binary_search(gone.begin(), gone.end(), j);
  }

  /// The index now of kept element `j`.
  int now(int j) const
  {
    const std::size_t b = static_cast<std::size_t>(j) >> block_bits;
    if(!mixed_[b]) return j + block_shift_[b];
    const auto at = std::upper_bound(positions_.begin(), positions_.end(), static_cast<std::size_t>(j));
    return at == positions_.begin() ? j : j + shifts_[static_cast<std::size_t>(at - positions_.begin()) - 1];
  }

  /// The number of gone elements before old index `j`.
  std::size_t gone_before(std::size_t j) const
  {
    return static_cast<std::size_t>(std::lower_bound(gone.begin(), gone.end(), static_cast<int>(j)) - gone.begin());
  }

  /// Moves the kept elements of `a` (`width` entries each) where they go among
  /// `nc` elements, leaving room for new element f before the kept element of
  /// rank `kept_before[f]` (ascending); the caller writes the new ones. Grows `a`
  /// with a little spare room, so that the next few changes fit.
  template <class T>
  void relocate(std::vector<T>& a, std::size_t width, const std::vector<std::size_t>& kept_before,
                std::size_t nc) const
  {
    // Drop the gone elements, from the left.
    std::size_t out = gone.empty() ? n_ : static_cast<std::size_t>(gone[0]);
    for(std::size_t g = 0; g < gone.size(); ++g)
    {
      const std::size_t from = static_cast<std::size_t>(gone[g]) + 1;
      const std::size_t to = g + 1 < gone.size() ? static_cast<std::size_t>(gone[g + 1]) : n_;
      std::move(a.begin() + width * from, a.begin() + width * to, a.begin() + width * out);
      out += to - from;
    }
    if(width * nc > a.capacity()) a.reserve(width * (nc + nc / 64));
    if(width * nc > a.size()) a.resize(width * nc);
    // Open the new elements' places, from the right.
    std::size_t end = out;
    for(std::size_t f = kept_before.size(); f-- > 0;)
    {
      const std::size_t at = kept_before[f];
      std::move_backward(a.begin() + width * at, a.begin() + width * end, a.begin() + width * (end + f + 1));
      end = at;
    }
    a.resize(width * nc);
  }

private:
  static constexpr std::size_t block_bits = 6;   // blocks of 64: a few changes leave most alone
  static constexpr std::size_t block_mask = (std::size_t(1) << block_bits) - 1;
  std::size_t n_ = 0;
  std::vector<std::size_t> positions_;   // where the shift changes, ascending
  std::vector<int> shifts_;              // the shift from there on
  std::vector<int> block_shift_;
  std::vector<char> mixed_;
};

} // namespace internal
} // namespace BODT_3
} // namespace CGAL

#endif // CGAL_BODT_3_INTERNAL_UTILITIES_INDEX_SHIFT_H
