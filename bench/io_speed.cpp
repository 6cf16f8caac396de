// Reading and writing speed of every mesh format on a generated mesh: a jittered
// grid of N^3 cubes, six tetrahedra each (N = 60 by default: 1.3 M tetrahedra), two
// subdomains, labelled boundary triangles. Prints, per format, the file size and
// MB/s for writing (through write_mesh: temporary file, fsync, rename) and reading
// (read_mesh from the page cache, including the mesh checks), and the read time
// without the checks (check_and_orient timed alone and subtracted).
//
// usage: io_speed [N] [folder] [threads]   (folder: where the files go, default /tmp;
// threads: of the ASCII Medit reader, checks and writer, default 1; the others use one)
#include "jittered_grid.h"

#include <CGAL/BODT_3/IO/mesh_io.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <sstream>
#include <string>

namespace IO = CGAL::BODT_3::IO;
using CGAL::BODT_3::Tet_mesh;
using bodt_bench::jittered_grid;

namespace {

double seconds_since(std::chrono::steady_clock::time_point t)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

} // namespace

int main(int argc, char** argv)
{
  const int n = argc > 1 ? std::atoi(argv[1]) : 60;
  const std::filesystem::path folder = argc > 2 ? argv[2] : "/tmp";
  const int threads = argc > 3 ? std::atoi(argv[3]) : 1;
  const Tet_mesh mesh = jittered_grid(n);
  std::printf("jittered grid, N = %d: %zu vertices, %zu tetrahedra, %zu triangles; %d thread(s) for .mesh\n\n", n,
              mesh.points.size(), mesh.tets.size(), mesh.triangles.size(), threads);
  std::printf("| format | size (MB) | write (s) | write MB/s | read (s) | read MB/s | read without checks (s) | MB/s |\n");
  std::printf("|---|---:|---:|---:|---:|---:|---:|---:|\n");
  for(const char* name : {"mesh", "meshb", "msh41", "msh22", "msh41-binary", "msh22-binary", "vtu", "vtu-ascii",
                          "vtk", "vtk-binary", "tetgen"})
  {
    const IO::Mesh_file_format format = IO::parse_format_name(name);
    const std::string ext = format.format == IO::Mesh_format::medit ? ".mesh"
                            : format.format == IO::Mesh_format::meshb ? ".meshb"
                            : format.format == IO::Mesh_format::gmsh ? ".msh"
                            : format.format == IO::Mesh_format::vtu ? ".vtu"
                            : format.format == IO::Mesh_format::vtk ? ".vtk" : ".node";
    const std::filesystem::path file = folder / (std::string("io_speed_") + name + ext);
    auto t = std::chrono::steady_clock::now();
    // Only the ASCII Medit reader, its checks and writer take threads.
    const int format_threads = format.format == IO::Mesh_format::medit ? threads : 1;
    IO::write_mesh(file.string(), mesh, format, format_threads);
    const double write = seconds_since(t);
    std::uintmax_t bytes = 0;
    for(const char* e : {".node", ".ele", ".face", ".edge"})
      if(format.format == IO::Mesh_format::tetgen) bytes += std::filesystem::file_size(folder / (std::string("io_speed_") + name + e));
    if(format.format != IO::Mesh_format::tetgen) bytes = std::filesystem::file_size(file);

    std::ostringstream warnings;
    t = std::chrono::steady_clock::now();
    IO::Mesh_file_format read_format;
    const Tet_mesh back = IO::read_mesh(file.string(), read_format, warnings, format_threads);
    const double read = seconds_since(t);
    if(back.tets != mesh.tets || back.points.size() != mesh.points.size())
    {
      std::fprintf(stderr, "%s: the mesh read back differs\n", name);
      return 1;
    }
    // The checks every reader ends with (check_and_orient), timed alone.
    Tet_mesh copy = back;
    CGAL::BODT_3::internal::Tet_mesh_source source;
    source.file = file.string();
    t = std::chrono::steady_clock::now();
    CGAL::BODT_3::internal::check_and_orient(copy, source, warnings, format_threads);
    const double check = seconds_since(t);
    const double mb = static_cast<double>(bytes) / 1e6;
    std::printf("| %s | %.1f | %.2f | %.0f | %.2f | %.0f | %.2f | %.0f |\n", name, mb, write, mb / write, read,
                mb / read, read - check, mb / (read - check));
    std::fflush(stdout);
    std::filesystem::remove(file);
    for(const char* e : {".node", ".ele", ".face", ".edge"})
      std::filesystem::remove(folder / (std::string("io_speed_") + name + e));
  }
  return 0;
}
