// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_BODT_3_IO_INTERNAL_BYTE_READER_H
#define CGAL_BODT_3_IO_INTERNAL_BYTE_READER_H

#include <CGAL/BODT_3/Mesh_io_error.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>
#include <type_traits>

namespace CGAL {
namespace BODT_3 {
namespace IO {
namespace internal {

template <class T>
T byte_swapped(T v)
{
  unsigned char b[sizeof(T)];
  std::memcpy(b, &v, sizeof(T));
  std::reverse(b, b + sizeof(T));
  std::memcpy(&v, b, sizeof(T));
  return v;
}

/// Binary values read from bytes held in memory, each read bounds-checked, in the
/// file's byte order (`swap` when it is not the machine's). Errors name the byte
/// offset, binary files having no lines.
class Byte_reader
{
public:
  Byte_reader(const std::string& file, std::string_view bytes, bool swap = false)
    : file_(file), bytes_(bytes), swap_(swap)
  {}

  const std::string& file() const { return file_; }
  std::string_view bytes() const { return bytes_; }
  std::size_t position() const { return pos_; }
  std::size_t remaining() const { return bytes_.size() - pos_; }
  void set_swap(bool swap) { swap_ = swap; }

  void seek(std::size_t pos, const char* what)
  {
    if(pos > bytes_.size())
      error(std::string(what) + " points to byte " + std::to_string(pos) + ", past the end of the file (" +
            std::to_string(bytes_.size()) + " bytes)");
    pos_ = pos;
  }

  template <class T>
  T get(const char* what)
  {
    static_assert(std::is_trivially_copyable_v<T>);
    if(remaining() < sizeof(T))
      error(std::string("the file ends where ") + what + " was expected; it is truncated");
    T v;
    std::memcpy(&v, bytes_.data() + pos_, sizeof(T));
    pos_ += sizeof(T);
    return swap_ ? byte_swapped(v) : v;
  }

  void skip(std::size_t n, const char* what)
  {
    if(remaining() < n)
      error(std::string("the file ends inside ") + what + "; it is truncated");
    pos_ += n;
  }

  /// A count of entries of `bytes_per_entry` bytes each that must fit in the rest of
  /// the file: a larger count is a damaged file, and believing it would reserve
  /// memory the file cannot fill.
  void check_count(const char* what, unsigned long long count, std::size_t bytes_per_entry) const
  {
    if(bytes_per_entry > 0 && count > remaining() / bytes_per_entry)
      error(std::string(what) + " is " + std::to_string(count) + ", but the rest of the file holds at most " +
            std::to_string(remaining() / bytes_per_entry) + " such entries; it is truncated or the count is wrong");
  }

  [[noreturn]] void error(const std::string& message) const
  {
    throw Mesh_io_error(file_, 0, "at byte " + std::to_string(pos_) + ": " + message);
  }

private:
  std::string file_;
  std::string_view bytes_;
  std::size_t pos_ = 0;
  bool swap_;
};

} // namespace internal
} // namespace IO
} // namespace BODT_3
} // namespace CGAL

#endif // CGAL_BODT_3_IO_INTERNAL_BYTE_READER_H
