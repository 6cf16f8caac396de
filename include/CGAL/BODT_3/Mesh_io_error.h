// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_BODT_3_MESH_IO_ERROR_H
#define CGAL_BODT_3_MESH_IO_ERROR_H

#include <stdexcept>
#include <string>

namespace CGAL {
namespace BODT_3 {

/// Thrown for any unreadable or invalid mesh file. `what()` reads
/// "FILE:LINE: MESSAGE" (or "FILE: MESSAGE" when no line applies, "MESSAGE" for a
/// mesh that came from no file), the form compilers use, so that editors and
/// terminals can jump to the place.
class Mesh_io_error : public std::runtime_error
{
public:
  Mesh_io_error(const std::string& file, long line, const std::string& message)
    : std::runtime_error(format(file, line, message)), file_(file), line_(line), message_(message)
  {}

  const std::string& file() const { return file_; }
  long line() const { return line_; }          // 0 when no line applies
  const std::string& message() const { return message_; }

private:
  static std::string format(const std::string& file, long line, const std::string& message)
  {
    if(file.empty()) return message;
    return line > 0 ? file + ":" + std::to_string(line) + ": " + message : file + ": " + message;
  }

  std::string file_;
  long line_;
  std::string message_;
};

} // namespace BODT_3
} // namespace CGAL

#endif // CGAL_BODT_3_MESH_IO_ERROR_H
