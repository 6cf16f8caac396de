// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_BODT_3_INTERNAL_UTILITIES_FIRST_TOUCH_H
#define CGAL_BODT_3_INTERNAL_UTILITIES_FIRST_TOUCH_H

#include <CGAL/BODT_3/internal/Utilities/Thread_workers.h>

#include <algorithm>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace BODT_3 {
namespace internal {

/// Writes one byte of every page of the `bytes` bytes at `p`, on `threads`
/// threads. The kernel clears a fresh page in the thread that first writes it,
/// and on a virtual machine that costs more than filling it: a large array that
/// one thread would fill (`resize`, `assign`, `push_back`) is made resident by
/// all threads first. Below a few megabytes this is not worth a parallel loop.
inline void touch_pages(void* p, std::size_t bytes, int threads)
{
  constexpr std::size_t page = 4096;
  constexpr std::size_t pages_per_task = 256;   // one 1 MB stretch per task
  if(bytes < (std::size_t(4) << 20) || thread_count(threads) < 2) return;
  volatile unsigned char* const base = static_cast<unsigned char*>(p);
  const std::size_t pages = (bytes + page - 1) / page;
  Thread_workers<char> workers(threads);
  workers.for_each(0, block_count(pages, pages_per_task), [&](char&, int b) {
    const std::size_t first = static_cast<std::size_t>(b) * pages_per_task;
    const std::size_t last = std::min(pages, first + pages_per_task);
    for(std::size_t q = first; q < last; ++q) base[q * page] = 0;
  }, 1);
}

/// Makes room for `n` elements of `v`. A `v` without that room is emptied first
/// (its elements are not copied) and gets storage for exactly `n`, its pages made
/// resident on `threads` threads (`touch_pages`); one with room keeps its elements.
template <class T>
void reserve_fresh(std::vector<T>& v, std::size_t n, int threads)
{
  if(n <= v.capacity()) return;
  std::vector<T>().swap(v);
  v.reserve(n);
  touch_pages(v.data(), n * sizeof(T), threads);
}

/// A size with room for what a few passes add to an array of `n` elements (flips
/// add one cell at a time, insertion a few): derived again in place after such a
/// pass, the array keeps its pages.
inline std::size_t with_room(std::size_t n) { return n + n / 64 + 64; }

/// Sets `v` to `n` elements that the caller then overwrites all: growing by
/// `resize` alone would double the capacity and copy the old elements, holding
/// both arrays at once; here a larger `v` is dropped first and made at its size.
template <class T>
void resize_for_overwrite(std::vector<T>& v, std::size_t n, int threads)
{
  reserve_fresh(v, n, threads);
  v.resize(n);
}

/// `v.assign(n, value)`, its pages made resident on `threads` threads first.
template <class T>
void assign_fresh(std::vector<T>& v, std::size_t n, const T& value, int threads)
{
  reserve_fresh(v, n, threads);
  v.assign(n, value);
}

} // namespace internal
} // namespace BODT_3
} // namespace CGAL

#endif // CGAL_BODT_3_INTERNAL_UTILITIES_FIRST_TOUCH_H
