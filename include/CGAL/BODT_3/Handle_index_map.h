// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_BODT_3_HANDLE_INDEX_MAP_H
#define CGAL_BODT_3_HANDLE_INDEX_MAP_H

#include <cstddef>
#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

namespace CGAL {
namespace BODT_3 {

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
    slots_.assign(capacity, Slot{0, -1});
    size_ = 0;
  }

  std::size_t size() const { return size_; }

  /// Inserts (h, index) unless h is there; returns whether it was inserted.
  bool insert(Handle h, int index)
  {
    if(2 * (size_ + 1) > slots_.size()) grow();
    const std::uintptr_t key = address(h);
    for(std::size_t s = slot(key);; s = (s + 1) & (slots_.size() - 1))
    {
      if(slots_[s].key == key) return false;
      if(slots_[s].key == 0)
      {
        slots_[s] = Slot{key, index};
        ++size_;
        return true;
      }
    }
  }

  /// The index of h, or -1.
  int find(Handle h) const
  {
    if(slots_.empty()) return -1;
    const std::uintptr_t key = address(h);
    for(std::size_t s = slot(key);; s = (s + 1) & (slots_.size() - 1))
    {
      if(slots_[s].key == key) return slots_[s].index;
      if(slots_[s].key == 0) return -1;
    }
  }

private:
  struct Slot
  {
    std::uintptr_t key;   // 0: empty (no element lives at address 0)
    int index;
  };

  static std::uintptr_t address(Handle h) { return reinterpret_cast<std::uintptr_t>(std::addressof(*h)); }

  std::size_t slot(std::uintptr_t key) const
  {
    // Fibonacci hashing of the address; the low bits are alignment.
    const std::uint64_t mixed = (static_cast<std::uint64_t>(key) >> 3) * 0x9E3779B97F4A7C15ull;
    return static_cast<std::size_t>(mixed >> 32) & (slots_.size() - 1);
  }

  void grow()
  {
    std::vector<Slot> old = std::move(slots_);
    slots_.assign(old.empty() ? 16 : 2 * old.size(), Slot{0, -1});
    for(const Slot& x : old)
      if(x.key != 0)
        for(std::size_t s = slot(x.key);; s = (s + 1) & (slots_.size() - 1))
          if(slots_[s].key == 0)
          {
            slots_[s] = x;
            break;
          }
  }

  std::vector<Slot> slots_;
  std::size_t size_ = 0;
};

} // namespace BODT_3
} // namespace CGAL

#endif // CGAL_BODT_3_HANDLE_INDEX_MAP_H
