// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_BODT_3_INTERNAL_UTILITIES_GROUP_BY_KEY_H
#define CGAL_BODT_3_INTERNAL_UTILITIES_GROUP_BY_KEY_H

#include <CGAL/BODT_3/internal/Utilities/Thread_workers.h>
#include <CGAL/BODT_3/internal/Utilities/first_touch.h>

#include <algorithm>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace BODT_3 {
namespace internal {

/// Groups values by an integer key in [0, `keys`), stably (a counting sort): the
/// values of key k are `values[begin[k]]` to `values[begin[k + 1] - 1]`, in the
/// order items emit them. `each(i, emit)` calls `emit(key, value)` for each value
/// of item i, in [0, `items`), the same way on both of its calls. The items are cut
/// into one contiguous part per thread, each counting its keys apart (at most 8
/// parts, which bounds the memory to 8 counts per key); the result is the same on
/// any number of threads.
template <class Value, class Each>
void group_by_key(std::size_t items, std::size_t keys, int threads, const Each& each, std::vector<int>& begin,
                  std::vector<Value>& values)
{
  const int parts = static_cast<int>(std::max<std::size_t>(1, std::min<std::size_t>({
      static_cast<std::size_t>(thread_count(threads)), 8, items / 4096 + 1})));
  const std::size_t per_part = (items + static_cast<std::size_t>(parts) - 1) / static_cast<std::size_t>(parts);
  std::vector<std::vector<int>> next(static_cast<std::size_t>(parts));
  Thread_workers<char> workers(parts);
  auto for_parts = [&](const auto& f) {
    workers.for_each(0, parts, [&](char&, int p) {
      const std::size_t first = static_cast<std::size_t>(p) * per_part;
      f(next[static_cast<std::size_t>(p)], first, std::min(items, first + per_part));
    }, 1);
  };
  for_parts([&](std::vector<int>& count, std::size_t first, std::size_t last) {
    count.assign(keys, 0);
    for(std::size_t i = first; i < last; ++i) each(i, [&count](std::size_t key, const Value&) { ++count[key]; });
  });
  // Where each part writes each key's values: after the parts before it.
  begin.assign(keys + 1, 0);
  int offset = 0;
  for(std::size_t k = 0; k < keys; ++k)
  {
    begin[k] = offset;
    for(std::vector<int>& count : next)
    {
      const int c = count[k];
      count[k] = offset;
      offset += c;
    }
  }
  begin[keys] = offset;
  resize_for_overwrite(values, static_cast<std::size_t>(offset), threads);
  for_parts([&](std::vector<int>& fill, std::size_t first, std::size_t last) {
    for(std::size_t i = first; i < last; ++i)
      each(i, [&](std::size_t key, const Value& v) { values[static_cast<std::size_t>(fill[key]++)] = v; });
  });
}

} // namespace internal
} // namespace BODT_3
} // namespace CGAL

#endif // CGAL_BODT_3_INTERNAL_UTILITIES_GROUP_BY_KEY_H
