// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_BODT_3_INTERNAL_UTILITIES_THREAD_WORKERS_H
#define CGAL_BODT_3_INTERNAL_UTILITIES_THREAD_WORKERS_H

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/info.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <vector>
#include <cstddef>

namespace CGAL {
namespace BODT_3 {
namespace internal {

/// The number of threads a run uses: `requested`, or with 0 every core the
/// process may use (TBB's default concurrency, which respects CPU affinity).
inline int thread_count(int requested)
{
  return requested > 0 ? requested : std::max(1, tbb::info::default_concurrency());
}

/// Items per block of the whole-mesh scans that run in blocks (`for_blocks`).
constexpr std::size_t scan_block = std::size_t(1) << 14;

/// The number of blocks of `block` items that cover `n` items.
inline int block_count(std::size_t n, std::size_t block = scan_block)
{
  return static_cast<int>((n + block - 1) / block);
}

/// Loops over index ranges on a fixed number of threads (TBB, in its own arena),
/// each thread with its own `Worker` (scratch space and counters). With one
/// thread the same code runs on the one thread. Callers make the
/// iterations independent; what the workers count must not depend on which
/// worker counted it (sums, maxima), so that results do not depend on threads.
template <class Worker>
class Thread_workers
{
public:
  explicit Thread_workers(int threads) : threads_(thread_count(threads)), arena_(threads_) {}

  int threads() const { return threads_; }

  /// Calls f(worker, i) for every i in [begin, end), and returns when all are done;
  /// `grain`: iterations per task (the default suits a vertex move, a few microseconds).
  template <class F>
  void for_each(int begin, int end, const F& f, int grain = 32)
  {
    if(begin >= end) return;
    arena_.execute([&] {
      tbb::parallel_for(tbb::blocked_range<int>(begin, end, grain), [&](const tbb::blocked_range<int>& r) {
        Worker& w = workers_.local();
        for(int i = r.begin(); i != r.end(); ++i) f(w, i);
      });
    });
  }

  /// Calls f(worker, b, begin, end) for the blocks b, [begin, end), of `block`
  /// consecutive indices that cover [0, n), one task per block: results kept per
  /// block and merged in block order are the same on any number of threads.
  template <class F>
  void for_blocks(std::size_t n, const F& f, std::size_t block = scan_block)
  {
    for_each(0, block_count(n, block), [&](Worker& w, int b) {
      const std::size_t begin = static_cast<std::size_t>(b) * block;
      f(w, b, begin, std::min(n, begin + block));
    }, 1);
  }

  /// The indices i in [0, n) for which `keep(i)` holds, in increasing order,
  /// found in blocks (`for_blocks`): the same list on any number of threads.
  template <class Keep>
  std::vector<std::size_t> indices_where(std::size_t n, const Keep& keep)
  {
    std::vector<std::vector<std::size_t>> found(static_cast<std::size_t>(block_count(n)));
    for_blocks(n, [&](Worker&, int b, std::size_t begin, std::size_t end) {
      for(std::size_t i = begin; i < end; ++i)
        if(keep(i)) found[static_cast<std::size_t>(b)].push_back(i);
    });
    std::size_t total = 0;
    for(const auto& f : found) total += f.size();
    std::vector<std::size_t> out;
    out.reserve(total);
    for(const auto& f : found) out.insert(out.end(), f.begin(), f.end());
    return out;
  }

  /// Visits every worker (in no particular order).
  template <class G>
  void each_worker(const G& g)
  {
    for(Worker& w : workers_) g(w);
  }

private:
  int threads_;
  tbb::task_arena arena_;
  tbb::enumerable_thread_specific<Worker> workers_;
};

} // namespace internal
} // namespace BODT_3
} // namespace CGAL

#endif // CGAL_BODT_3_INTERNAL_UTILITIES_THREAD_WORKERS_H
