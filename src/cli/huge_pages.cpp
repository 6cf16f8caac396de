// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The programs' operator new: large blocks on transparent huge pages.
//
// A run makes and frees arrays of megabytes again and again (the re-reads after
// flips, the flip passes' maps), and glibc maps each anew (bodt.cpp fixes its
// mmap threshold so that freed blocks go back): every 4 KB page of them faults
// on its first touch. In this machine's virtual machine a fault costs several
// microseconds; on the 1.3 M-tetrahedron hard grid of doc/scaling.md a 17.8 s
// run spent 2.3 s in the kernel, mostly on 375,000 faults, and two threads
// gained only 1.35 times (doc/scaling.md, "Huge pages").
// Asked for 2 MB pages (MADV_HUGEPAGE, which the default "madvise" setting of
// /sys/kernel/mm/transparent_hugepage/enabled honours), a block faults once per
// 2 MB. Only the whole 2 MB pages inside a block are asked for, and the heap of
// small blocks is left alone (glibc's own hugetlb tunable puts that heap on 2 MB
// pages too, which cost 2-3% of the peak); the bench's peaks moved by -2% to +2%.
// Replacing operator new, not only the library's allocations, is what a program
// can do: a library cannot choose its user's allocator.
#include <cstdint>
#include <cstdlib>
#include <new>

#include <sys/mman.h>

namespace {

constexpr std::uintptr_t huge_page = std::uintptr_t(2) << 20;

void* allocate(std::size_t size)
{
  void* p = std::malloc(size > 0 ? size : 1);
  if(p == nullptr) throw std::bad_alloc();
  const std::uintptr_t begin = reinterpret_cast<std::uintptr_t>(p);
  const std::uintptr_t first = (begin + huge_page - 1) & ~(huge_page - 1);
  const std::uintptr_t last = (begin + size) & ~(huge_page - 1);
  // A hint: where the kernel refuses it, the block stays on 4 KB pages.
  if(first < last) ::madvise(reinterpret_cast<void*>(first), last - first, MADV_HUGEPAGE);
  return p;
}

} // namespace

// The whole family, so that every block goes back the way it came (malloc and
// free) even where another runtime, a sanitizer's, would pair them otherwise.
void* operator new(std::size_t size) { return allocate(size); }
void* operator new[](std::size_t size) { return allocate(size); }
void* operator new(std::size_t size, const std::nothrow_t&) noexcept
{
  try
  {
    return allocate(size);
  }
  catch(const std::bad_alloc&)
  {
    return nullptr;
  }
}
void* operator new[](std::size_t size, const std::nothrow_t& tag) noexcept { return operator new(size, tag); }
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }
void operator delete(void* p, const std::nothrow_t&) noexcept { std::free(p); }
void operator delete[](void* p, const std::nothrow_t&) noexcept { std::free(p); }
