// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_BODT_3_INTERNAL_UTILITIES_PREFETCH_H
#define CGAL_BODT_3_INTERNAL_UTILITIES_PREFETCH_H

#include <cstddef>
#include <memory>

namespace CGAL {
namespace BODT_3 {
namespace internal {

/// Starts loading every cache line of the object `h` points to (a cell or a
/// vertex of the triangulation), without waiting. Walking around an edge or a
/// face chases pointers from cell to neighbouring cell, each in its own place in
/// memory: loading a cell's other lines (its labels) and its vertices' points
/// while the walk goes on made the flip pass about a fifth faster
/// (doc/stages.md). Only a hint: without compiler support it does nothing.
template <class Handle>
inline void prefetch(Handle h)
{
#if defined(__GNUC__) || defined(__clang__)
  const char* p = reinterpret_cast<const char*>(std::addressof(*h));
  for(std::size_t line = 0; line < sizeof(*h); line += 64) __builtin_prefetch(p + line);
#else
  (void)h;
#endif
}

} // namespace internal
} // namespace BODT_3
} // namespace CGAL

#endif // CGAL_BODT_3_INTERNAL_UTILITIES_PREFETCH_H
