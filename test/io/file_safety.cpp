// Files as a careful user meets them: writing through a symbolic link writes the file
// it points to, an output keeps its permission bits, a failed or interrupted write
// leaves nothing behind and the old file untouched; a directory, /dev/zero or a huge
// garbage file as input is refused by name, at once and without eating memory.
#include <CGAL/BODT_3/IO/mesh_io.h>
#include <CGAL/BODT_3/IO/write_atomically.h>

#include "io_test_meshes.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

namespace fs = std::filesystem;
using namespace bodt_test;
namespace IO = CGAL::BODT_3::IO;
using CGAL::BODT_3::Mesh_io_error;
using CGAL::BODT_3::Tet_mesh;

namespace {

bool has_temp_file(const fs::path& dir)
{
  for(const auto& f : fs::directory_iterator(dir))
    if(f.path().filename().string().find(".tmp.") != std::string::npos) return true;
  return false;
}

std::string error_of(const std::string& path)
{
  std::ostringstream warnings;
  try
  {
    IO::read_mesh(path, warnings);
  }
  catch(const Mesh_io_error& e)
  {
    return e.what();
  }
  return "";
}

long peak_rss_kb()
{
  struct rusage u;
  getrusage(RUSAGE_SELF, &u);
  return u.ru_maxrss;
}

} // namespace

TEST(WriteAtomically, WritingThroughASymlinkKeepsTheLink)
{
  const fs::path dir = tmp_dir();
  const fs::path real = write_file("real.mesh", "old");
  fs::create_directories(dir / "links");
  const fs::path link = dir / "links" / "link.mesh";
  fs::remove(link);
  fs::create_symlink("../real.mesh", link);
  IO::write_mesh(link.string(), grid_mesh());
  EXPECT_TRUE(fs::is_symlink(fs::symlink_status(link)));
  EXPECT_EQ(fs::read_symlink(link), fs::path("../real.mesh"));
  std::ostringstream warnings;
  EXPECT_EQ(IO::read_mesh(real.string(), warnings).tets.size(), grid_mesh().tets.size());
  // The temporary file lived next to the target, not next to the link, and is gone.
  EXPECT_FALSE(has_temp_file(dir));
  EXPECT_FALSE(has_temp_file(dir / "links"));
}

TEST(WriteAtomically, ExistingOutputKeepsItsPermissionBits)
{
  const fs::path p = write_file("private.mesh", "old");
  fs::permissions(p, fs::perms::owner_read | fs::perms::owner_write);
  IO::write_mesh(p.string(), grid_mesh());
  EXPECT_EQ(fs::status(p).permissions() & fs::perms::mask, fs::perms::owner_read | fs::perms::owner_write);

  // A new file gets the usual 0666 less the umask.
  const fs::path q = tmp_dir() / "new.mesh";
  fs::remove(q);
  const mode_t mask = ::umask(022);
  IO::write_mesh(q.string(), grid_mesh());
  ::umask(mask);
  EXPECT_EQ(fs::status(q).permissions() & fs::perms::mask,
            fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read | fs::perms::others_read);
}

TEST(WriteAtomically, FailureLeavesTheOldFileAndNoTemporary)
{
  const fs::path p = write_file("keep.txt", "precious");
  EXPECT_THROW(CGAL::BODT_3::write_atomically(p.string(), [](std::ostream& out) {
                 out << "half";
                 throw std::runtime_error("writer failed");
               }),
               std::runtime_error);
  EXPECT_EQ(read_text(p), "precious");
  EXPECT_FALSE(has_temp_file(tmp_dir()));
  // A directory as output is refused by name.
  try
  {
    CGAL::BODT_3::write_atomically(tmp_dir().string(), [](std::ostream& out) { out << "x"; });
    ADD_FAILURE() << "wrote over a directory";
  }
  catch(const Mesh_io_error& e)
  {
    EXPECT_NE(std::string(e.what()).find("is a directory"), std::string::npos) << e.what();
  }
  // A missing directory: an error naming the file.
  const fs::path missing = tmp_dir() / "no_such_dir" / "out.mesh";
  try
  {
    IO::write_mesh(missing.string(), grid_mesh());
    ADD_FAILURE() << "wrote into a missing directory";
  }
  catch(const Mesh_io_error& e)
  {
    EXPECT_NE(std::string(e.what()).find(missing.string()), std::string::npos) << e.what();
  }
}

TEST(WriteAtomically, SignalDuringTheWriteRemovesTheTemporary)
{
  for(int sig : {SIGINT, SIGTERM})
  {
    const fs::path dir = tmp_dir(std::to_string(sig));
    const fs::path p = dir / "out.mesh";
    std::ofstream(p) << "precious";
    const pid_t child = fork();
    ASSERT_GE(child, 0);
    if(child == 0)
    {
      // Half-way through the write, the signal arrives.
      CGAL::BODT_3::write_atomically(p.string(), [&](std::ostream& out) {
        out << std::string(1 << 20, 'x');
        out.flush();
        ::raise(sig);
        out << "never";
      });
      _exit(0);
    }
    int status = 0;
    ASSERT_EQ(waitpid(child, &status, 0), child);
    ASSERT_TRUE(WIFSIGNALED(status)) << "the child exited normally";
    EXPECT_EQ(WTERMSIG(status), sig);
    EXPECT_EQ(read_text(p), "precious");
    EXPECT_FALSE(has_temp_file(dir));
  }
}

TEST(WriteAtomically, DeviceOutputIsWrittenDirectly)
{
  // /dev/null cannot be replaced by a rename, and must not be.
  CGAL::BODT_3::write_atomically("/dev/null", [](std::ostream& out) { out << "discarded"; });
  struct stat st;
  ASSERT_EQ(::stat("/dev/null", &st), 0);
  EXPECT_TRUE(S_ISCHR(st.st_mode));
}

TEST(InputSafety, DirectoryIsRefusedByName)
{
  const fs::path d = tmp_dir("folder.mesh");
  const std::string e = error_of(d.string());
  EXPECT_NE(e.find(d.string()), std::string::npos) << e;
  EXPECT_NE(e.find("is a directory"), std::string::npos) << e;
}

TEST(InputSafety, DevZeroIsRefusedAtOnce)
{
  if(!fs::exists("/dev/zero")) GTEST_SKIP() << "no /dev/zero";
  // Through a link whose name gives the format: the device itself has no extension.
  for(const char* name : {"zero.mesh", "zero.msh", "zero.meshb", "zero.vtu", "zero.vtk", "zero.node"})
  {
    const fs::path link = tmp_dir() / name;
    fs::remove(link);
    fs::create_symlink("/dev/zero", link);
    const std::string e = error_of(link.string());
    EXPECT_NE(e.find(link.string()), std::string::npos) << name << ": " << e;
    EXPECT_NE(e.find("does not start as"), std::string::npos) << name << ": " << e;
  }
  // Refused from its first 64 KiB: nothing like the quarter of the memory a stream may take.
  EXPECT_LT(peak_rss_kb(), 512 * 1024);
}

TEST(InputSafety, HugeGarbageFileIsRefusedWithoutReadingIt)
{
  // A 5 GiB sparse file of zero bytes (past 32-bit sizes), and one whose header is right but whose
  // count is absurd: both fail at their first bytes, mapped, not read.
  const fs::path zeros = tmp_dir() / "huge.mesh";
  { std::ofstream(zeros) << ""; }
  fs::resize_file(zeros, std::uintmax_t(5) << 30);
  std::string e = error_of(zeros.string());
  EXPECT_NE(e.find(zeros.string() + ":1: "), std::string::npos) << e;
  EXPECT_NE(e.find("not a text mesh file"), std::string::npos) << e;

  const fs::path counted = tmp_dir() / "counted.mesh";
  { std::ofstream(counted) << "MeshVersionFormatted 2\nDimension 3\nVertices\n4000000000000\n"; }
  fs::resize_file(counted, std::uintmax_t(5) << 30);
  e = error_of(counted.string());
  EXPECT_NE(e.find("more entries than the rest of the file can hold"), std::string::npos) << e;
  EXPECT_LT(peak_rss_kb(), 512 * 1024);
  fs::remove(zeros);
  fs::remove(counted);
}

TEST(InputSafety, PipeInputIsRead)
{
  // A named pipe has no size: it is read as a stream, the same mesh as from a file.
  const fs::path fifo = tmp_dir() / "pipe.mesh";
  fs::remove(fifo);
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  const fs::path src = tmp_dir() / "src.mesh";
  IO::write_mesh(src.string(), grid_mesh());
  const pid_t child = fork();
  ASSERT_GE(child, 0);
  if(child == 0)
  {
    const std::string text = read_text(src);
    std::ofstream(fifo) << text;
    _exit(0);
  }
  std::ostringstream warnings;
  const Tet_mesh m = IO::read_mesh(fifo.string(), warnings);
  waitpid(child, nullptr, 0);
  expect_same_mesh_content(grid_mesh(), m);
}

TEST(InputSafety, CommandLineNamesTheDirectoryAndRefusesDevZero)
{
  const fs::path d = tmp_dir("input_folder.mesh");
  std::string output;
  EXPECT_EQ(run_bodt("quality " + shell_quoted(d), output), 1) << output;
  EXPECT_NE(output.find(d.string() + ": is a directory"), std::string::npos) << output;
  if(fs::exists("/dev/zero"))
  {
    const fs::path link = tmp_dir() / "zero_cli.mesh";
    fs::remove(link);
    fs::create_symlink("/dev/zero", link);
    EXPECT_EQ(run_bodt("quality " + shell_quoted(link), output), 1) << output;
    EXPECT_NE(output.find(link.string() + ": does not start as a Medit mesh file does"), std::string::npos) << output;
  }
}
