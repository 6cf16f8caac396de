// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_BODT_3_IO_WRITE_ATOMICALLY_H
#define CGAL_BODT_3_IO_WRITE_ATOMICALLY_H

#include <CGAL/BODT_3/IO/Mesh_io_error.h>

#include <cstdio>
#include <fstream>
#include <string>
#include <unistd.h>

namespace CGAL {
namespace BODT_3 {

/// Writes a file through `write(std::ostream&)` into a temporary file next to
/// `path`, then renames it over `path`. A failure (an exception from `write`, a
/// full disk) removes the temporary file and leaves any existing `path` untouched,
/// so no half-written or clobbered output is ever left behind.
template <class Writer>
void write_atomically(const std::string& path, Writer&& write)
{
  const std::string tmp = path + ".tmp." + std::to_string(::getpid());
  try
  {
    {
      std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
      if(!out)
        throw Mesh_io_error(path, 0, "cannot open the file for writing");
      write(out);
      out.flush();
      if(!out)
        throw Mesh_io_error(path, 0, "error while writing the file (disk full?)");
    }
    if(std::rename(tmp.c_str(), path.c_str()) != 0)
      throw Mesh_io_error(path, 0, "cannot replace the file with the one just written");
  }
  catch(...)
  {
    std::remove(tmp.c_str());
    throw;
  }
}

} // namespace BODT_3
} // namespace CGAL

#endif // CGAL_BODT_3_IO_WRITE_ATOMICALLY_H
