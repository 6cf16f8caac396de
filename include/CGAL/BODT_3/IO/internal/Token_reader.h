// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_BODT_3_IO_INTERNAL_TOKEN_READER_H
#define CGAL_BODT_3_IO_INTERNAL_TOKEN_READER_H

#include <CGAL/BODT_3/internal/Utilities/Thread_workers.h>
#include <CGAL/BODT_3/Mesh_io_error.h>

#include <algorithm>
#include <atomic>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

namespace CGAL {
namespace BODT_3 {
namespace IO {
namespace internal {

inline bool is_space(char ch)
{
  return ch == ' ' || ch == '\n' || ch == '\t' || ch == '\r' || ch == '\v' || ch == '\f';
}

/// `t` as an error message may quote it: at most 40 characters, non-printable
/// bytes shown as '?', since a token of a garbage file may be anything.
inline std::string printable(std::string_view t)
{
  std::string s;
  for(std::size_t i = 0; i < t.size() && i < 40; ++i)
    s += (t[i] >= 32 && t[i] < 127) ? t[i] : '?';
  if(t.size() > 40) s += "...";
  return s;
}

/// Parses all of `t` as a decimal integer, sign allowed; false on anything else,
/// including a value beyond 64 bits (never wrapped).
inline bool parse_integer(std::string_view t, long long& v)
{
  const char* p = t.data();
  const char* end = p + t.size();
  if(p != end && *p == '+' && ++p != end && (*p < '0' || *p > '9')) return false;
  const std::from_chars_result r = std::from_chars(p, end, v);
  return r.ec == std::errc() && r.ptr == end && p != end;
}

/// Parses all of `t` as a decimal number ("1", "-2.5e-3", "inf", "nan", a leading
/// '+'); false on anything else. Shortest round-trip output of `to_chars` reads
/// back bit for bit.
inline bool parse_double(std::string_view t, double& v)
{
  const char* p = t.data();
  const char* end = p + t.size();
  if(p != end && *p == '+' && ++p != end && *p == '-') return false;
  const std::from_chars_result r = std::from_chars(p, end, v);
  if(r.ec == std::errc::result_out_of_range)
  {
    v = std::numeric_limits<double>::infinity();   // reported as not finite by the callers
    return r.ptr == end;
  }
  return r.ec == std::errc() && r.ptr == end && p != end;
}

/// The first token of `head` (the start of a file), skipping blanks and lines that
/// start with `comment`; "" when there is none.
inline std::string_view first_token(std::string_view head, char comment)
{
  std::size_t p = 0;
  for(;;)
  {
    while(p < head.size() && is_space(head[p])) ++p;
    if(p < head.size() && comment != '\0' && head[p] == comment)
    {
      while(p < head.size() && head[p] != '\n') ++p;
      continue;
    }
    break;
  }
  std::size_t e = p;
  while(e < head.size() && !is_space(head[e])) ++e;
  return head.substr(p, e - p);
}

/// Whitespace-separated tokens of a text held in memory, each with its line number,
/// so that every parse error can name the line. Tokens are views into the text:
/// no copy, no allocation, which keeps parsing at disk speed.
class Token_reader
{
public:
  /// A token longer than this is no number or keyword of any mesh format.
  static constexpr std::size_t max_token = 4096;

  Token_reader(const std::string& file, std::string_view text, char comment = '#')
    : file_(file), comment_(comment), text_(text)
  {
    bool blank = true;
    for(char ch : text_)
      if(!is_space(ch)) { blank = false; break; }
    if(blank)
      throw Mesh_io_error(file, 0, "the file is empty");
  }

  const std::string& file() const { return file_; }
  std::string_view text() const { return text_; }

  /// Line of the token returned last.
  long line() const { return token_line_; }

  /// Byte offset of the next character to read, and the line it is on.
  std::size_t position() const { return pos_; }
  long current_line() const { return line_; }
  void set_position(std::size_t pos, long line) { pos_ = pos; line_ = line; }

  bool at_end()
  {
    skip_space();
    return pos_ >= text_.size();
  }

  /// The next token; throws at the end of the file, saying what was expected.
  std::string_view next(const char* expected)
  {
    skip_space();
    // At the end, the error names the line of the last token: where the file was cut.
    if(pos_ >= text_.size())
      error(std::string("the file ends where ") + expected + " was expected; it is truncated");
    token_line_ = line_;
    const std::size_t begin = pos_;
    while(pos_ < text_.size() && !is_space(text_[pos_]))
      if(++pos_ - begin > max_token)
        error("a token of more than " + std::to_string(max_token) + " characters where " + expected +
              " was expected: this is not a text mesh file");
    last_ = text_.substr(begin, pos_ - begin);
    return last_;
  }

  /// The token returned last.
  std::string_view peek_last() const { return last_; }

  /// The first character of the next token, 0 at the end of the file.
  char peek_char()
  {
    skip_space();
    return pos_ < text_.size() ? text_[pos_] : '\0';
  }

  /// Whether the next token starts with a letter (a section keyword).
  bool next_is_word()
  {
    const char ch = peek_char();
    return (ch >= 'a' && ch <= 'z') || (ch >= 'A' && ch <= 'Z');
  }

  /// The rest of the current line, without surrounding blanks (for line-oriented formats).
  std::string_view rest_of_line()
  {
    while(pos_ < text_.size() && (text_[pos_] == ' ' || text_[pos_] == '\t' || text_[pos_] == '\r'))
      ++pos_;
    const std::size_t begin = pos_;
    while(pos_ < text_.size() && text_[pos_] != '\n') ++pos_;
    std::size_t end = pos_;
    while(end > begin && (text_[end - 1] == '\r' || text_[end - 1] == ' ' || text_[end - 1] == '\t')) --end;
    return text_.substr(begin, end - begin);
  }

  /// True when nothing but blanks is left on the current line (cheap: no copy).
  bool line_is_done()
  {
    std::size_t p = pos_;
    while(p < text_.size() && (text_[p] == ' ' || text_[p] == '\t' || text_[p] == '\r')) ++p;
    return p >= text_.size() || text_[p] == '\n';
  }

  long long next_integer(const char* what)
  {
    const std::string_view t = next(what);
    long long v;
    if(!parse_integer(t, v))
    {
      double d;
      if(parse_double(t, d) && t.find_first_of(".eE") == std::string_view::npos && !std::isnan(d))
        error(std::string(what) + " " + printable(t) + " is out of range (more than 64 bits)");
      error(std::string("expected ") + what + " (an integer), found '" + printable(t) + "'");
    }
    return v;
  }

  int next_int(const char* what)
  {
    const long long v = next_integer(what);
    if(v < std::numeric_limits<int>::min() || v > std::numeric_limits<int>::max())
      error(std::string(what) + " " + std::to_string(v) + " is out of range");
    return static_cast<int>(v);
  }

  /// A count of entries: a non-negative integer no larger than the rest of the file
  /// could hold, at two characters (a digit and a blank) per token of an entry. A
  /// larger count would have the reader reserve memory the file cannot fill.
  std::size_t next_count(const char* what, std::size_t tokens_per_entry)
  {
    const long long v = next_integer(what);
    if(v < 0)
      error(std::string(what) + " is negative (" + std::to_string(v) + ")");
    check_count(what, static_cast<unsigned long long>(v), tokens_per_entry);
    return static_cast<std::size_t>(v);
  }

  void check_count(const char* what, unsigned long long v, std::size_t tokens_per_entry) const
  {
    const std::size_t rest = text_.size() - pos_;
    if(tokens_per_entry > 0 && v > 0 && (tokens_per_entry > rest || v > rest / (2 * tokens_per_entry) + 1))
      error(std::string(what) + " is " + std::to_string(v) +
            ", more entries than the rest of the file can hold; the file is truncated or the count is wrong");
  }

  double next_double(const char* what)
  {
    const std::string_view t = next(what);
    double v;
    if(!parse_double(t, v))
      error(std::string("expected ") + what + " (a number), found '" + printable(t) + "'");
    if(!std::isfinite(v))
      error(std::string(what) + " is '" + printable(t) + "', not a finite number");
    return v;
  }

  /// Reads `n` entries of `tokens` tokens each, on `threads` threads, when they are
  /// laid out one entry per line from the line after the current one (as every
  /// writer lays them out): `row(i, line, fields)` gets entry i, the line it is on
  /// and its `tokens` token views, and returns false when any is not what the
  /// caller expects. Returns false, having consumed nothing, when the layout is
  /// another (entries across lines, blank or comment lines) or a row was refused:
  /// the caller then reads the entries token by token, which yields the same values
  /// and reports any error exactly. On success the reader is past the last entry.
  template <class Row>
  bool read_rows(std::size_t n, std::size_t tokens, int threads, const Row& row)
  {
    constexpr std::size_t most_tokens = 8;
    if(n == 0 || tokens == 0 || tokens > most_tokens) return false;
    std::size_t p = pos_;
    for(; p < text_.size() && text_[p] != '\n'; ++p)
      if(!is_space(text_[p])) return false;
    if(p >= text_.size()) return false;
    ++p;
    // Where every block of rows starts: found with memchr, which runs at memory speed.
    constexpr std::size_t rows_per_block = 4096;
    std::vector<std::size_t> block_start;
    block_start.reserve(n / rows_per_block + 1);
    std::size_t last_end = p;
    for(std::size_t i = 0; i < n; ++i)
    {
      if(i % rows_per_block == 0) block_start.push_back(p);
      const void* nl = p < text_.size() ? std::memchr(text_.data() + p, '\n', text_.size() - p) : nullptr;
      last_end = nl ? static_cast<std::size_t>(static_cast<const char*>(nl) - text_.data()) : text_.size();
      if(!nl && i + 1 < n) return false;
      p = last_end + 1;
    }
    const long first_line = line_ + 1;
    std::atomic<bool> refused{false};
    BODT_3::internal::Thread_workers<char>(threads).for_each(0, static_cast<int>(block_start.size()), [&](char&, int b) {
      std::size_t q = block_start[static_cast<std::size_t>(b)];
      const std::size_t end_row = std::min(n, (static_cast<std::size_t>(b) + 1) * rows_per_block);
      std::string_view fields[most_tokens];
      for(std::size_t i = static_cast<std::size_t>(b) * rows_per_block; i < end_row; ++i)
      {
        if(refused.load(std::memory_order_relaxed)) return;
        std::size_t found = 0;
        while(q < text_.size() && text_[q] != '\n')
        {
          if(is_space(text_[q])) { ++q; continue; }
          const std::size_t begin = q;
          while(q < text_.size() && !is_space(text_[q])) ++q;
          if(found == tokens || q - begin > max_token) { found = tokens + 1; break; }
          fields[found++] = text_.substr(begin, q - begin);
        }
        const char lead = found > 0 ? fields[0][0] : '\0';
        const bool word = (lead >= 'a' && lead <= 'z') || (lead >= 'A' && lead <= 'Z') || lead == comment_;
        if(found != tokens || word || !row(i, first_line + static_cast<long>(i), fields))
        {
          refused.store(true, std::memory_order_relaxed);
          return;
        }
        ++q;
      }
    }, 1);
    if(refused) return false;
    pos_ = last_end;
    line_ = first_line + static_cast<long>(n) - 1;
    token_line_ = line_;
    return true;
  }

  [[noreturn]] void error(const std::string& message) const
  {
    throw Mesh_io_error(file_, token_line_, message);
  }

private:
  void skip_space()
  {
    while(pos_ < text_.size())
    {
      const char ch = text_[pos_];
      if(ch == '\n') { ++line_; ++pos_; }
      else if(is_space(ch)) ++pos_;
      else if(comment_ != '\0' && ch == comment_ && at_line_start())
        while(pos_ < text_.size() && text_[pos_] != '\n') ++pos_;
      else break;
    }
  }

  bool at_line_start() const
  {
    for(std::size_t p = pos_; p > 0; --p)
    {
      const char ch = text_[p - 1];
      if(ch == '\n') return true;
      if(ch != ' ' && ch != '\t' && ch != '\r') return false;
    }
    return true;
  }

  std::string file_;
  char comment_;
  std::string_view text_;
  std::size_t pos_ = 0;
  long line_ = 1;
  long token_line_ = 1;
  std::string_view last_;
};

} // namespace internal
} // namespace IO
} // namespace BODT_3
} // namespace CGAL

#endif // CGAL_BODT_3_IO_INTERNAL_TOKEN_READER_H
