// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_BODT_3_IO_TOKEN_READER_H
#define CGAL_BODT_3_IO_TOKEN_READER_H

#include <CGAL/BODT_3/IO/Mesh_io_error.h>

#include <charconv>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <string_view>
#include <system_error>

namespace CGAL {
namespace BODT_3 {
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
} // namespace BODT_3
} // namespace CGAL

#endif // CGAL_BODT_3_IO_TOKEN_READER_H
