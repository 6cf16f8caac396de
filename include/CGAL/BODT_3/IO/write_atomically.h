// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_BODT_3_IO_WRITE_ATOMICALLY_H
#define CGAL_BODT_3_IO_WRITE_ATOMICALLY_H

#include <CGAL/BODT_3/Mesh_io_error.h>

#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <ostream>
#include <streambuf>
#include <string>
#include <vector>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace CGAL {
namespace BODT_3 {
namespace internal {

/// A stream buffer writing to a file descriptor, keeping the first error's errno.
class Fd_streambuf : public std::streambuf
{
public:
  explicit Fd_streambuf(int fd) : fd_(fd), buf_(1 << 16) { setp(buf_.data(), buf_.data() + buf_.size()); }
  ~Fd_streambuf() override { sync(); }
  int error() const { return error_; }

protected:
  int_type overflow(int_type ch) override
  {
    if(!drain()) return traits_type::eof();
    if(!traits_type::eq_int_type(ch, traits_type::eof()))
    {
      *pptr() = traits_type::to_char_type(ch);
      pbump(1);
    }
    return traits_type::not_eof(ch);
  }

  std::streamsize xsputn(const char* s, std::streamsize n) override
  {
    if(n < epptr() - pptr())
    {
      std::memcpy(pptr(), s, static_cast<std::size_t>(n));
      pbump(static_cast<int>(n));
      return n;
    }
    if(!drain() || !write_all(s, static_cast<std::size_t>(n))) return 0;
    return n;
  }

  int sync() override { return drain() ? 0 : -1; }

private:
  bool drain()
  {
    const std::size_t n = static_cast<std::size_t>(pptr() - pbase());
    setp(buf_.data(), buf_.data() + buf_.size());
    return write_all(buf_.data(), n);
  }

  bool write_all(const char* s, std::size_t n)
  {
    while(n > 0 && error_ == 0)
    {
      const ssize_t w = ::write(fd_, s, n);
      if(w < 0 && errno == EINTR) continue;
      if(w <= 0) { error_ = w < 0 ? errno : EIO; break; }
      s += w;
      n -= static_cast<std::size_t>(w);
    }
    return error_ == 0;
  }

  int fd_;
  std::vector<char> buf_;
  int error_ = 0;
};

/// The temporary file being written, so that SIGINT, SIGTERM and SIGHUP can remove
/// it before the process dies: a fixed buffer, since a signal handler may not allocate.
/// One slot: when threads write files at the same time, only the last one started is
/// removed on a signal.
struct Pending_temp
{
  char path[4096] = {};
  std::atomic<bool> set{false};
  struct sigaction previous[3];
  static constexpr int signals[3] = {SIGINT, SIGTERM, SIGHUP};

  static Pending_temp& get()
  {
    static Pending_temp p;
    return p;
  }

  static void on_signal(int sig)
  {
    Pending_temp& p = get();
    if(p.set.load()) ::unlink(p.path);
    for(int i = 0; i < 3; ++i)
      if(signals[i] == sig) ::sigaction(sig, &p.previous[i], nullptr);
    ::raise(sig);
  }

  void install(const std::string& tmp)
  {
    std::snprintf(path, sizeof path, "%s", tmp.c_str());
    set.store(true);
    for(int i = 0; i < 3; ++i)
    {
      ::sigaction(signals[i], nullptr, &previous[i]);
      if(previous[i].sa_handler == SIG_IGN) continue;   // nohup and the like: respect it
      struct sigaction sa;
      std::memset(&sa, 0, sizeof sa);
      sa.sa_handler = &Pending_temp::on_signal;
      sigemptyset(&sa.sa_mask);
      ::sigaction(signals[i], &sa, nullptr);
    }
  }

  void uninstall()
  {
    for(int i = 0; i < 3; ++i)
      if(previous[i].sa_handler != SIG_IGN) ::sigaction(signals[i], &previous[i], nullptr);
    set.store(false);
  }
};

/// `path` with every symbolic link followed (a dangling link gives where it points):
/// writing through a link writes the file it points to and keeps the link.
inline std::filesystem::path follow_links(const std::string& path)
{
  namespace fs = std::filesystem;
  fs::path p = path;
  for(int depth = 0; depth < 40; ++depth)
  {
    std::error_code ec;
    if(!fs::is_symlink(fs::symlink_status(p, ec)) || ec) return p;
    const fs::path target = fs::read_symlink(p, ec);
    if(ec) return p;
    p = target.is_absolute() ? target : p.parent_path() / target;
  }
  throw Mesh_io_error(path, 0, "too many levels of symbolic links");
}

} // namespace internal

/// Writes a file through `write(std::ostream&)` into a temporary file in the
/// directory of the file `path` names (following symbolic links, so that a link
/// stays a link), flushes it to disk, gives it the permission bits of the file it
/// replaces, and renames it over that file. A failure (an exception from `write`, a
/// full disk) or SIGINT, SIGTERM or SIGHUP during the write removes the temporary
/// file and leaves any existing file untouched: no half-written or clobbered output
/// is ever left behind. An existing target that is not a regular file (a device such
/// as /dev/null, a pipe) is written directly, since it cannot be replaced.
template <class Writer>
void write_atomically(const std::string& path, Writer&& write)
{
  namespace fs = std::filesystem;
  const fs::path target = internal::follow_links(path);
  struct stat st;
  const bool exists = ::stat(target.c_str(), &st) == 0;
  if(exists && S_ISDIR(st.st_mode))
    throw Mesh_io_error(path, 0, "is a directory; cannot write a file there");

  auto write_to = [&](int fd, const std::string& shown) {
    internal::Fd_streambuf buf(fd);
    std::ostream out(&buf);
    write(out);
    out.flush();
    if(!out || buf.error() != 0)
      throw Mesh_io_error(shown, 0, std::string("error while writing the file: ") +
                                        std::strerror(buf.error() != 0 ? buf.error() : EIO));
  };

  if(exists && !S_ISREG(st.st_mode))
  {
    const int fd = ::open(target.c_str(), O_WRONLY | O_CLOEXEC);
    if(fd < 0)
      throw Mesh_io_error(path, 0, std::string("cannot open the file for writing: ") + std::strerror(errno));
    try { write_to(fd, path); } catch(...) { ::close(fd); throw; }
    ::close(fd);
    return;
  }

  static std::atomic<unsigned> counter{0};
  const fs::path dir = target.has_parent_path() ? target.parent_path() : fs::path(".");
  const std::string tmp = (dir / ("." + target.filename().string() + ".tmp." + std::to_string(::getpid()) + "." +
                                  std::to_string(counter++))).string();
  internal::Pending_temp& pending = internal::Pending_temp::get();
  pending.install(tmp);
  int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
  if(fd < 0)
  {
    const int e = errno;
    pending.uninstall();
    throw Mesh_io_error(path, 0, "cannot create a file in " + dir.string() + ": " + std::strerror(e));
  }
  try
  {
    write_to(fd, path);
    if(exists && ::fchmod(fd, st.st_mode & 07777) != 0)
      throw Mesh_io_error(path, 0, std::string("cannot keep the file's permissions: ") + std::strerror(errno));
    if(::fsync(fd) != 0)
      throw Mesh_io_error(path, 0, std::string("error while writing the file: ") + std::strerror(errno));
    const int closed = ::close(fd);
    fd = -1;
    if(closed != 0)
    {
      const int e = errno;
      throw Mesh_io_error(path, 0, std::string("error while writing the file: ") + std::strerror(e));
    }
    if(std::rename(tmp.c_str(), target.c_str()) != 0)
      throw Mesh_io_error(path, 0, std::string("cannot replace the file with the one just written: ") +
                                       std::strerror(errno));
  }
  catch(...)
  {
    if(fd >= 0) ::close(fd);
    ::unlink(tmp.c_str());
    pending.uninstall();
    throw;
  }
  pending.uninstall();
}

} // namespace BODT_3
} // namespace CGAL

#endif // CGAL_BODT_3_IO_WRITE_ATOMICALLY_H
