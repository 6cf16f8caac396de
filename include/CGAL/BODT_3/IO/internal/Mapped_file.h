// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_BODT_3_IO_INTERNAL_MAPPED_FILE_H
#define CGAL_BODT_3_IO_INTERNAL_MAPPED_FILE_H

#include <CGAL/BODT_3/Mesh_io_error.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <string>
#include <string_view>

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

namespace CGAL {
namespace BODT_3 {
namespace IO {
namespace internal {

/// The bytes of an input file, read-only. A regular file is memory-mapped, so
/// reading costs no copy and a huge file costs no memory until it is parsed (and
/// garbage stops the parser at its first bytes). A pipe or a device has no size:
/// its first bytes are shown to `looks_right` before anything more is read (so
/// `/dev/zero` is refused at once), and it may hold at most a quarter of the
/// machine's memory. A directory is refused by name.
class Mapped_file
{
public:
  using Check = bool (*)(std::string_view head);

  Mapped_file(const std::string& path, const char* what, Check looks_right = nullptr)
  {
    fd_ = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if(fd_ < 0)
      throw Mesh_io_error(path, 0, std::string("cannot open the file for reading: ") + std::strerror(errno));
    struct stat st;
    if(::fstat(fd_, &st) != 0)
      fail(path, std::string("cannot read the file: ") + std::strerror(errno));
    if(S_ISDIR(st.st_mode))
      fail(path, std::string("is a directory, not ") + what);
    if(S_ISREG(st.st_mode))
    {
      size_ = static_cast<std::size_t>(st.st_size);
      if(size_ > 0)
      {
        void* p = ::mmap(nullptr, size_, PROT_READ, MAP_PRIVATE, fd_, 0);
        if(p == MAP_FAILED)
          fail(path, std::string("cannot map the file into memory: ") + std::strerror(errno));
        map_ = static_cast<const char*>(p);
        ::madvise(p, size_, MADV_SEQUENTIAL);
      }
      return;
    }
    read_stream(path, what, looks_right);
  }

  Mapped_file(const Mapped_file&) = delete;
  Mapped_file& operator=(const Mapped_file&) = delete;

  ~Mapped_file()
  {
    if(map_) ::munmap(const_cast<char*>(map_), size_);
    if(fd_ >= 0) ::close(fd_);
  }

  std::string_view bytes() const
  {
    return map_ ? std::string_view(map_, size_) : std::string_view(stream_);
  }

private:
  [[noreturn]] void fail(const std::string& path, const std::string& message)
  {
    ::close(fd_);
    fd_ = -1;
    throw Mesh_io_error(path, 0, message);
  }

  void read_stream(const std::string& path, const char* what, Check looks_right)
  {
    const long pages = ::sysconf(_SC_PHYS_PAGES), page = ::sysconf(_SC_PAGE_SIZE);
    const std::size_t cap = pages > 0 && page > 0 ? static_cast<std::size_t>(pages) * page / 4 : (std::size_t(1) << 32);
    const std::size_t head = 1 << 16;
    bool checked = looks_right == nullptr;
    for(;;)
    {
      if(!checked && stream_.size() >= head)
      {
        if(!looks_right(stream_)) fail(path, std::string("does not start as ") + what + " does");
        checked = true;
      }
      if(stream_.size() >= cap)
        fail(path, "more than " + std::to_string(cap >> 20) +
                       " MiB come from this file, which is not a regular file (a pipe or a device); "
                       "reading stopped there, since a quarter of the machine's memory is the most it may take");
      const std::size_t old = stream_.size();
      stream_.resize(std::min(cap, old + std::max<std::size_t>(head, old / 2)));
      const std::size_t want = checked ? stream_.size() - old : std::min(stream_.size(), head) - old;
      const ssize_t got = ::read(fd_, &stream_[old], want);
      if(got < 0 && errno == EINTR) { stream_.resize(old); continue; }
      if(got < 0) fail(path, std::string("error while reading the file: ") + std::strerror(errno));
      stream_.resize(old + static_cast<std::size_t>(got));
      if(got == 0) break;
    }
    if(!checked && !stream_.empty() && !looks_right(stream_))
      fail(path, std::string("does not start as ") + what + " does");
  }

  int fd_ = -1;
  const char* map_ = nullptr;
  std::size_t size_ = 0;
  std::string stream_;
};

} // namespace internal
} // namespace IO
} // namespace BODT_3
} // namespace CGAL

#endif // CGAL_BODT_3_IO_INTERNAL_MAPPED_FILE_H
