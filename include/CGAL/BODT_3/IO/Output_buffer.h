// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_BODT_3_IO_OUTPUT_BUFFER_H
#define CGAL_BODT_3_IO_OUTPUT_BUFFER_H

#include <charconv>
#include <cstring>
#include <ostream>
#include <string_view>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace BODT_3 {
namespace internal {

/// Formats text and binary data into a large buffer handed to the stream in
/// blocks, so that writing a mesh is a loop of `to_chars` calls and no stream
/// formatting. Numbers are written in the shortest form that reads back to the
/// same double, bit for bit.
class Output_buffer
{
public:
  explicit Output_buffer(std::ostream& out) : out_(out), buf_(1 << 20) {}
  Output_buffer(const Output_buffer&) = delete;
  Output_buffer& operator=(const Output_buffer&) = delete;
  ~Output_buffer() { flush(); }

  Output_buffer& put(std::string_view s)
  {
    if(s.size() > buf_.size() - n_)
    {
      flush();
      if(s.size() > buf_.size())
      {
        out_.write(s.data(), static_cast<std::streamsize>(s.size()));
        flushed_ += s.size();
        return *this;
      }
    }
    std::memcpy(buf_.data() + n_, s.data(), s.size());
    n_ += s.size();
    return *this;
  }

  Output_buffer& put(char c)
  {
    room(1);
    buf_[n_++] = c;
    return *this;
  }

  template <class Int, std::enable_if_t<std::is_integral_v<Int>, int> = 0>
  Output_buffer& put_int(Int v)
  {
    room(24);
    n_ = static_cast<std::size_t>(std::to_chars(buf_.data() + n_, buf_.data() + buf_.size(), v).ptr - buf_.data());
    return *this;
  }

  /// Shortest round-trip decimal form.
  Output_buffer& put_double(double v)
  {
    room(32);
    n_ = static_cast<std::size_t>(std::to_chars(buf_.data() + n_, buf_.data() + buf_.size(), v).ptr - buf_.data());
    return *this;
  }

  /// The bytes of `v` as the machine holds them (little-endian on the machines we build for).
  template <class T>
  Output_buffer& put_binary(const T& v)
  {
    static_assert(std::is_trivially_copyable_v<T>);
    room(sizeof(T));
    std::memcpy(buf_.data() + n_, &v, sizeof(T));
    n_ += sizeof(T);
    return *this;
  }

  /// Bytes written so far, flushed or not.
  std::size_t written() const { return flushed_ + n_; }

  void flush()
  {
    if(n_ > 0) out_.write(buf_.data(), static_cast<std::streamsize>(n_));
    flushed_ += n_;
    n_ = 0;
  }

private:
  void room(std::size_t k)
  {
    if(buf_.size() - n_ < k) flush();
  }

  std::ostream& out_;
  std::vector<char> buf_;
  std::size_t n_ = 0;
  std::size_t flushed_ = 0;
};

} // namespace internal
} // namespace BODT_3
} // namespace CGAL

#endif // CGAL_BODT_3_IO_OUTPUT_BUFFER_H
