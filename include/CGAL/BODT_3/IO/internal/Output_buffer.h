// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_BODT_3_IO_INTERNAL_OUTPUT_BUFFER_H
#define CGAL_BODT_3_IO_INTERNAL_OUTPUT_BUFFER_H

#include <CGAL/BODT_3/internal/Utilities/Thread_workers.h>

#include <algorithm>
#include <charconv>
#include <cstring>
#include <ostream>
#include <string_view>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace BODT_3 {
namespace IO {
namespace internal {

/// The formatting calls of `Output_buffer` and `Text_block`, into the character
/// buffer they hold: `Sink::room(k)` makes room for k more bytes (a full buffer is
/// flushed by one and grown by the other). Numbers are written with `to_chars`,
/// doubles in the shortest form that reads back to the same double, bit for bit.
template <class Sink>
class Formatter
{
public:
  Sink& put(std::string_view s)
  {
    sink().room(s.size());
    std::memcpy(buf_.data() + n_, s.data(), s.size());
    n_ += s.size();
    return sink();
  }

  Sink& put(char c)
  {
    sink().room(1);
    buf_[n_++] = c;
    return sink();
  }

  template <class Int, std::enable_if_t<std::is_integral_v<Int>, int> = 0>
  Sink& put_int(Int v)
  {
    sink().room(24);
    n_ = static_cast<std::size_t>(std::to_chars(buf_.data() + n_, buf_.data() + buf_.size(), v).ptr - buf_.data());
    return sink();
  }

  /// Shortest round-trip decimal form.
  Sink& put_double(double v)
  {
    sink().room(32);
    n_ = static_cast<std::size_t>(std::to_chars(buf_.data() + n_, buf_.data() + buf_.size(), v).ptr - buf_.data());
    return sink();
  }

  /// The bytes of `v` as the machine holds them (little-endian on the machines we build for).
  template <class T>
  Sink& put_binary(const T& v)
  {
    static_assert(std::is_trivially_copyable_v<T>);
    sink().room(sizeof(T));
    std::memcpy(buf_.data() + n_, &v, sizeof(T));
    n_ += sizeof(T);
    return sink();
  }

protected:
  explicit Formatter(std::size_t capacity) : buf_(capacity) {}

  // Room for k more bytes by growing the buffer.
  void grow_for(std::size_t k)
  {
    if(buf_.size() - n_ < k) buf_.resize(std::max(2 * buf_.size(), n_ + k + 4096));
  }

  std::vector<char> buf_;
  std::size_t n_ = 0;

private:
  Sink& sink() { return static_cast<Sink&>(*this); }
};

/// Formats text and binary data into a large buffer handed to the stream in
/// blocks, so that writing a mesh is a loop of `to_chars` calls and no stream
/// formatting.
class Output_buffer : public Formatter<Output_buffer>
{
public:
  explicit Output_buffer(std::ostream& out) : Formatter(1 << 20), out_(out) {}
  Output_buffer(const Output_buffer&) = delete;
  Output_buffer& operator=(const Output_buffer&) = delete;
  ~Output_buffer() { flush(); }

  /// Bytes written so far, flushed or not.
  std::size_t written() const { return flushed_ + n_; }

  void flush()
  {
    if(n_ > 0) out_.write(buf_.data(), static_cast<std::streamsize>(n_));
    flushed_ += n_;
    n_ = 0;
  }

private:
  friend class Formatter<Output_buffer>;

  // A full buffer goes to the stream; what does not fit an empty one grows it.
  void room(std::size_t k)
  {
    if(buf_.size() - n_ < k) flush();
    grow_for(k);
  }

  std::ostream& out_;
  std::size_t flushed_ = 0;
};

/// Text formatted in memory, with `Output_buffer`'s calls, for `put_rows`.
class Text_block : public Formatter<Text_block>
{
public:
  Text_block() : Formatter(0) {}

  std::string_view text() const { return std::string_view(buf_.data(), n_); }
  void clear() { n_ = 0; }

private:
  friend class Formatter<Text_block>;

  void room(std::size_t k) { grow_for(k); }
};

/// Writes rows 0 to n - 1 to `out`, `row(block, i)` formatting row i into a
/// `Text_block`: blocks of rows are formatted on `threads` threads (0: all
/// cores), a few at a time, and written in order, so the bytes are those of one
/// loop over the rows.
template <class Row>
void put_rows(Output_buffer& out, std::size_t n, int threads, const Row& row)
{
  constexpr std::size_t rows_per_block = 1 << 13;
  const std::size_t blocks = (n + rows_per_block - 1) / rows_per_block;
  BODT_3::internal::Thread_workers<char> workers(threads);
  const std::size_t window = 4 * static_cast<std::size_t>(workers.threads());
  std::vector<Text_block> text(window);
  for(std::size_t first = 0; first < blocks; first += window)
  {
    const std::size_t count = std::min(window, blocks - first);
    workers.for_each(0, static_cast<int>(count), [&](char&, int k) {
      Text_block& block = text[static_cast<std::size_t>(k)];
      block.clear();
      const std::size_t begin = (first + static_cast<std::size_t>(k)) * rows_per_block;
      for(std::size_t i = begin; i < std::min(n, begin + rows_per_block); ++i) row(block, i);
    }, 1);
    for(std::size_t k = 0; k < count; ++k) out.put(text[k].text());
  }
}

} // namespace internal
} // namespace IO
} // namespace BODT_3
} // namespace CGAL

#endif // CGAL_BODT_3_IO_INTERNAL_OUTPUT_BUFFER_H
