// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_BODT_3_INTERNAL_UTILITIES_ID_KEYS_H
#define CGAL_BODT_3_INTERNAL_UTILITIES_ID_KEYS_H

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <utility>

namespace CGAL {
namespace BODT_3 {
namespace internal {

// Keys of edges, faces and cells by vertex ids, the same whatever order the
// vertices come in.

template <std::size_t N>
std::array<int, N> sorted(std::array<int, N> ids)
{
  std::sort(ids.begin(), ids.end());
  return ids;
}

/// The same for a face written as a braced list.
inline std::array<int, 3> sorted(const std::array<int, 3>& ids) { return sorted<3>(ids); }

/// Whether two id tuples are equal, compared inline: `==` on arrays of a few ints
/// calls memcmp, which took 4% of the flip passes in their map lookups and checks.
template <std::size_t N>
bool same_ids(const std::array<int, N>& a, const std::array<int, N>& b)
{
  bool same = true;
  for(std::size_t k = 0; k < N; ++k) same &= a[k] == b[k];
  return same;
}

inline std::pair<int, int> edge_key(int a, int b) { return a < b ? std::make_pair(a, b) : std::make_pair(b, a); }

/// An edge key packed in one integer, for maps keyed by `std::uint64_t`.
inline std::uint64_t packed_edge_key(int a, int b)
{
  if(b < a) std::swap(a, b);
  return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32) | static_cast<std::uint32_t>(b);
}

/// A hash of id tuples for unordered containers: h = h * phi ^ id, id by id.
struct Id_hash
{
  template <std::size_t N>
  std::size_t operator()(const std::array<int, N>& ids) const
  {
    std::size_t h = static_cast<std::size_t>(ids[0]);
    for(std::size_t k = 1; k < N; ++k) h = h * 0x9E3779B97F4A7C15ull ^ static_cast<std::size_t>(ids[k]);
    return h;
  }
  std::size_t operator()(const std::pair<int, int>& e) const { return (*this)(std::array<int, 2>{e.first, e.second}); }
};

} // namespace internal
} // namespace BODT_3
} // namespace CGAL

#endif // CGAL_BODT_3_INTERNAL_UTILITIES_ID_KEYS_H
