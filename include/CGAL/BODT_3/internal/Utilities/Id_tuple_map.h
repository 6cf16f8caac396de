// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_BODT_3_INTERNAL_UTILITIES_ID_TUPLE_MAP_H
#define CGAL_BODT_3_INTERNAL_UTILITIES_ID_TUPLE_MAP_H

#include <CGAL/BODT_3/internal/Utilities/first_touch.h>
#include <CGAL/BODT_3/internal/Utilities/id_keys.h>

#include <CGAL/assertions.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

namespace CGAL {
namespace BODT_3 {
namespace internal {

/// A map from tuples of N vertex ids (edges, faces, cells) to values: open
/// addressing with linear probing, entries stored inline. The flip pass looks
/// such keys up several times per cell it tries; with `std::unordered_map`
/// (a node per entry) those lookups took a tenth of the pass. Entries are only
/// inserted or updated, never erased; the order of iteration is never used.
template <std::size_t N, class Value>
class Id_tuple_map
{
public:
  using Key = std::array<int, N>;

  std::size_t size() const { return size_; }

  void clear()
  {
    for(Slot& s : slots_) s.key[0] = empty;
    size_ = 0;
  }

  /// Makes room for `n` keys in all, so that up to that many are inserted
  /// without growing; never shrinks. The new slots' pages are made resident on
  /// `threads` threads (a flip pass reserves megabytes at its start).
  void reserve(std::size_t n, int threads = 1)
  {
    const std::size_t slots = n + n / 3 + 1;   // at most three quarters full
    if(slots > slots_.size()) rehash(slots, threads);
  }

  /// The value of `key`, or null.
  const Value* find(const Key& key) const
  {
    if(slots_.empty()) return nullptr;
    for(std::size_t s = slot(key);; s = next(s))
    {
      const Slot& x = slots_[s];
      if(x.key[0] == empty) return nullptr;
      if(same_ids(x.key, key)) return &x.value;
    }
  }

  /// Starts loading the slot where a search for `key` begins, without waiting:
  /// a caller about to look up several keys of a large map issues them all first.
  void prefetch(const Key& key) const
  {
#if defined(__GNUC__) || defined(__clang__)
    if(!slots_.empty()) __builtin_prefetch(&slots_[slot(key)]);
#else
    (void)key;
#endif
  }

  /// The value of `key`, inserted as `initial` if absent; `inserted` tells which.
  Value& find_or_insert(const Key& key, const Value& initial, bool& inserted)
  {
    CGAL_precondition(key[0] != empty);
    if(4 * (size_ + 1) > 3 * slots_.size()) grow();
    for(std::size_t s = slot(key);; s = next(s))
    {
      Slot& x = slots_[s];
      if(same_ids(x.key, key))
      {
        inserted = false;
        return x.value;
      }
      if(x.key[0] == empty)
      {
        x = Slot{key, initial};
        ++size_;
        inserted = true;
        return x.value;
      }
    }
  }

  /// Sets the value of `key`.
  void assign(const Key& key, const Value& value)
  {
    bool inserted;
    find_or_insert(key, value, inserted) = value;
  }

private:
  // An empty slot has `empty` as its first id (ids are never negative): no flag,
  // so a slot is no larger than its key and value.
  static constexpr int empty = std::numeric_limits<int>::min();
  struct Slot
  {
    Key key;
    Value value;
  };

  std::size_t slot(const Key& key) const
  {
    std::uint64_t h = 0;
    for(int x : key) h = (h ^ static_cast<std::uint32_t>(x)) * 0x9E3779B97F4A7C15ull;
    // The hash's high 32 bits scaled to the number of slots, which need not be a power of two.
    return static_cast<std::size_t>(((h >> 32) * slots_.size()) >> 32);
  }

  std::size_t next(std::size_t s) const { return s + 1 == slots_.size() ? 0 : s + 1; }

  // By half again, not twice: the flip pass's maps are its largest arrays, and
  // doubled they were three eighths to three quarters full (now half to three quarters).
  // At least 64 slots: a map reserved for few keys has fewer, which half again would not grow.
  void grow() { rehash(std::max<std::size_t>(64, slots_.size() + slots_.size() / 2)); }

  void rehash(std::size_t slots, int threads = 1)
  {
    std::vector<Slot> old;
    old.swap(slots_);
    assign_fresh(slots_, slots, Slot{empty_key(), Value()}, threads);
    size_ = 0;
    for(const Slot& x : old)
      if(x.key[0] != empty)
      {
        bool inserted;
        find_or_insert(x.key, x.value, inserted);
      }
  }

  static Key empty_key()
  {
    Key k{};
    k[0] = empty;
    return k;
  }

  std::vector<Slot> slots_;   // at most three quarters full
  std::size_t size_ = 0;
};

} // namespace internal
} // namespace BODT_3
} // namespace CGAL

#endif // CGAL_BODT_3_INTERNAL_UTILITIES_ID_TUPLE_MAP_H
