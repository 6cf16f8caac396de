// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_BODT_3_INTERNAL_UTILITIES_HANDLE_INDEX_MAP_H
#define CGAL_BODT_3_INTERNAL_UTILITIES_HANDLE_INDEX_MAP_H

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

namespace CGAL {
namespace BODT_3 {
namespace internal {

/// Index of a triangulation's vertex or cell handle, by the address of what it
/// points to: an open-addressing hash table (linear probing, no node per entry).
/// The flat view re-reads every cell after each pass that changes the
/// connectivity; with `std::unordered_map` that re-reading cost more than a
/// smoothing sweep. Lookups only: the order of iteration never matters.
template <class Handle>
class Handle_index_map
{
public:
  /// Empties the map and makes room for `n` entries without growing.
  void reset(std::size_t n)
  {
    std::size_t capacity = 16;
    while(capacity < 2 * n) capacity *= 2;
    allocate(capacity);
    size_ = 0;
  }

  std::size_t size() const { return size_; }

  /// Inserts (h, index) unless h is there; returns whether it was inserted.
  bool insert(Handle h, int index)
  {
    if(2 * (size_ + 1) > capacity_) grow();
    if(!place(address(h), index)) return false;
    ++size_;
    return true;
  }

  /// Sets the index of h, inserting it if it is not there.
  void assign(Handle h, int index)
  {
    if(2 * (size_ + 1) > capacity_) grow();
    const std::uintptr_t key = address(h);
    const std::size_t s = probe(key);
    if(keys_[s] == 0)
    {
      keys_[s] = key;
      ++size_;
    }
    index_[s] = index;
  }

  /// Starts loading the slots where a search for h begins, without waiting: a
  /// caller about to insert or look up many handles of a large map issues the
  /// next ones ahead, so that their cache misses overlap.
  void prefetch(Handle h) const
  {
#if defined(__GNUC__) || defined(__clang__)
    if(capacity_ == 0) return;
    const std::size_t s = slot(address(h));
    __builtin_prefetch(&keys_[s], 1);
    __builtin_prefetch(&index_[s], 1);
#else
    (void)h;
#endif
  }

  /// The index of h, or -1.
  int find(Handle h) const
  {
    if(capacity_ == 0) return -1;
    const std::uintptr_t key = address(h);
    const std::size_t s = probe(key);
    return keys_[s] == key ? index_[s] : -1;
  }

private:
  static std::uintptr_t address(Handle h) { return reinterpret_cast<std::uintptr_t>(std::addressof(*h)); }

  std::size_t slot(std::uintptr_t key) const
  {
    // Fibonacci hashing of the address; the low bits are alignment.
    const std::uint64_t mixed = (static_cast<std::uint64_t>(key) >> 3) * 0x9E3779B97F4A7C15ull;
    return static_cast<std::size_t>(mixed >> 32) & (capacity_ - 1);
  }

  // The slot that holds key, or else the free slot where it goes (key 0 marks a
  // free slot: no element lives at address 0).
  std::size_t probe(std::uintptr_t key) const
  {
    std::size_t s = slot(key);
    while(keys_[s] != key && keys_[s] != 0) s = (s + 1) & (capacity_ - 1);
    return s;
  }

  // Claims key's slot; false when the key is there already.
  bool place(std::uintptr_t key, int index)
  {
    const std::size_t s = probe(key);
    if(keys_[s] == key) return false;
    keys_[s] = key;
    index_[s] = index;
    return true;
  }

  void allocate(std::size_t capacity)
  {
    if(capacity != capacity_)
    {
      keys_.reset(new std::uintptr_t[capacity]);
      index_.reset(new int[capacity]);
      capacity_ = capacity;
    }
    std::fill(keys_.get(), keys_.get() + capacity_, std::uintptr_t(0));
  }

  void grow()
  {
    std::unique_ptr<std::uintptr_t[]> keys = std::move(keys_);
    std::unique_ptr<int[]> index = std::move(index_);
    const std::size_t old = capacity_;
    capacity_ = 0;
    allocate(old == 0 ? 16 : 2 * old);
    for(std::size_t s = 0; s < old; ++s)
    {
      if(keys[s] != 0) place(keys[s], index[s]);
    }
  }

  std::unique_ptr<std::uintptr_t[]> keys_;
  std::unique_ptr<int[]> index_;
  std::size_t capacity_ = 0;
  std::size_t size_ = 0;
};

} // namespace internal
} // namespace BODT_3
} // namespace CGAL

#endif // CGAL_BODT_3_INTERNAL_UTILITIES_HANDLE_INDEX_MAP_H
