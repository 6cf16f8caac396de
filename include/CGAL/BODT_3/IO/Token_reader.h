// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_BODT_3_IO_TOKEN_READER_H
#define CGAL_BODT_3_IO_TOKEN_READER_H

#include <CGAL/BODT_3/IO/Mesh_io_error.h>

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <limits>
#include <sstream>
#include <string>

namespace CGAL {
namespace BODT_3 {
namespace internal {

/// Whitespace-separated tokens of a text file, each with its line number, so that
/// every parse error can name the line. The whole file is read at once: mesh files
/// are read in one pass and this keeps the parser free of stream state.
class Token_reader
{
public:
  explicit Token_reader(const std::string& file, char comment = '#') : file_(file), comment_(comment)
  {
    std::ifstream in(file, std::ios::binary);
    if(!in)
      throw Mesh_io_error(file, 0, "cannot open the file for reading");
    text_.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    if(in.bad())
      throw Mesh_io_error(file, 0, "error while reading the file");
    bool blank = true;
    for(char ch : text_)
      if(!std::isspace(static_cast<unsigned char>(ch))) { blank = false; break; }
    if(blank)
      throw Mesh_io_error(file, 0, "the file is empty");
  }

  const std::string& file() const { return file_; }

  /// Line of the token returned last.
  long line() const { return token_line_; }

  bool at_end()
  {
    skip_space();
    return pos_ >= text_.size();
  }

  /// The next token; throws at the end of the file, saying what was expected.
  std::string next(const char* expected)
  {
    skip_space();
    // At the end, the error names the line of the last token: where the file was cut.
    if(pos_ >= text_.size())
      error(std::string("the file ends where ") + expected + " was expected; it is truncated");
    token_line_ = line_;
    const std::size_t begin = pos_;
    while(pos_ < text_.size() && !std::isspace(static_cast<unsigned char>(text_[pos_])))
      ++pos_;
    last_ = text_.substr(begin, pos_ - begin);
    return last_;
  }

  /// The token returned last.
  const std::string& peek_last() const { return last_; }

  /// Looks at the next token without consuming it ("" at the end of the file).
  std::string peek()
  {
    const std::size_t p = pos_;
    const long l = line_, tl = token_line_;
    const std::string previous = last_;
    std::string t = at_end() ? std::string() : next("a token");
    pos_ = p; line_ = l; token_line_ = tl; last_ = previous;
    return t;
  }

  /// Consumes the rest of the current line (for line-oriented formats).
  std::string rest_of_line()
  {
    while(pos_ < text_.size() && (text_[pos_] == ' ' || text_[pos_] == '\t' || text_[pos_] == '\r'))
      ++pos_;
    const std::size_t begin = pos_;
    while(pos_ < text_.size() && text_[pos_] != '\n') ++pos_;
    std::string s = text_.substr(begin, pos_ - begin);
    while(!s.empty() && (s.back() == '\r' || s.back() == ' ' || s.back() == '\t')) s.pop_back();
    return s;
  }

  long long next_integer(const char* what)
  {
    const std::string t = next(what);
    errno = 0;
    char* end = nullptr;
    const long long v = std::strtoll(t.c_str(), &end, 10);
    if(end == t.c_str() || *end != '\0' || errno == ERANGE)
      error(std::string("expected ") + what + " (an integer), found '" + t + "'");
    return v;
  }

  int next_int(const char* what)
  {
    const long long v = next_integer(what);
    if(v < std::numeric_limits<int>::min() || v > std::numeric_limits<int>::max())
      error(std::string(what) + " " + std::to_string(v) + " is out of range");
    return static_cast<int>(v);
  }

  /// A count of entries: a non-negative integer no larger than the file could hold.
  std::size_t next_count(const char* what, std::size_t tokens_per_entry)
  {
    const long long v = next_integer(what);
    if(v < 0)
      error(std::string(what) + " is negative (" + std::to_string(v) + ")");
    if(tokens_per_entry > 0 &&
       static_cast<unsigned long long>(v) > (text_.size() - pos_) / (2 * tokens_per_entry) + 1)
      error(std::string(what) + " is " + std::to_string(v) +
            ", more entries than the rest of the file can hold; the file is truncated or the count is wrong");
    return static_cast<std::size_t>(v);
  }

  double next_double(const char* what)
  {
    const std::string t = next(what);
    errno = 0;
    char* end = nullptr;
    const double v = std::strtod(t.c_str(), &end);
    if(end == t.c_str() || *end != '\0')
      error(std::string("expected ") + what + " (a number), found '" + t + "'");
    if(!std::isfinite(v))
      error(std::string(what) + " is '" + t + "', not a finite number");
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
      else if(std::isspace(static_cast<unsigned char>(ch))) ++pos_;
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
  std::string text_;
  std::size_t pos_ = 0;
  long line_ = 1;
  long token_line_ = 1;
  std::string last_;
};

} // namespace internal
} // namespace BODT_3
} // namespace CGAL

#endif // CGAL_BODT_3_IO_TOKEN_READER_H
