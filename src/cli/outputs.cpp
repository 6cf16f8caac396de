// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
#include "cli/outputs.h"

#include "cli/usage_error.h"

#include <CGAL/BODT_3/Mesh_io_error.h>
#include <CGAL/BODT_3/IO/mesh_io.h>

#include <cstdio>
#include <stdexcept>
#include <filesystem>
#include <fstream>
#include <sys/stat.h>
#include <unistd.h>

namespace bodt_cli {

namespace fs = std::filesystem;
namespace IO = CGAL::BODT_3::IO;

IO::Mesh_file_format Output_format::resolve(const std::string& path, const IO::Mesh_file_format& input) const
{
  return forced ? format : IO::output_format(path, input);
}

std::string check_format_name(const std::string& name)
{
  try
  {
    IO::parse_format_name(name);
    return std::string();
  }
  catch(const std::invalid_argument& e)
  {
    return e.what();
  }
}

Output_format choose_output_format(const std::string& path, const std::string& format_option)
{
  const IO::Mesh_format by_name = IO::format_of(path);
  if(format_option.empty())
  {
    if(by_name == IO::Mesh_format::unknown)
      throw Usage_error("cannot tell the output format from '" + path +
                        "': name it .mesh, .meshb, .msh, .vtu, .vtk or .node, or give --format");
    return {false, IO::default_file_format(by_name)};
  }
  const IO::Mesh_file_format f = IO::parse_format_name(format_option);
  if(by_name != IO::Mesh_format::unknown && by_name != f.format)
    throw Usage_error("--format " + format_option + " contradicts the file name '" + path + "'");
  return {true, f};
}

void write_output(const std::string& path, const CGAL::BODT_3::Tet_mesh& mesh, const IO::Mesh_file_format& format,
                  int threads)
{
  IO::write_mesh(path, mesh, format, threads);
}

namespace {

// The file a path names, for comparisons: absolute, without '.', '..' or links.
fs::path identity(const std::string& path)
{
  std::error_code ec;
  const fs::path p = fs::weakly_canonical(fs::absolute(path), ec);
  return ec ? fs::absolute(path).lexically_normal() : p;
}

} // namespace

void check_input_path(const std::string& input)
{
  std::error_code ec;
  if(fs::is_directory(input, ec)) throw CGAL::BODT_3::Mesh_io_error(input, 0, "is a directory, not a mesh file");
}

void check_output_paths(const std::string& input, const std::vector<std::pair<std::string, std::string>>& outputs)
{
  std::vector<std::pair<std::string, fs::path>> seen;
  if(!input.empty()) seen.emplace_back("the input", identity(input));
  for(const auto& [option, path] : outputs)
  {
    if(path.empty()) continue;
    const std::string what = option + " " + path;
    std::error_code ec;
    const fs::path p(path);
    if(fs::is_directory(p, ec)) throw Usage_error(what + ": is a folder; give a file name");
    const fs::path folder = p.has_parent_path() ? p.parent_path() : fs::path(".");
    if(!fs::exists(folder, ec)) throw Usage_error(what + ": the folder '" + folder.string() + "' does not exist");
    if(!fs::is_directory(folder, ec)) throw Usage_error(what + ": '" + folder.string() + "' is not a folder");
    if(::access(folder.c_str(), W_OK | X_OK) != 0)
      throw Usage_error(what + ": cannot create files in the folder '" + folder.string() + "'");
    if(fs::exists(p, ec) && ::access(p.c_str(), W_OK) != 0)
      throw Usage_error(what + ": the file exists and is not writable");
    const fs::path id = identity(path);
    for(const auto& [other, other_id] : seen)
      if(id == other_id) throw Usage_error(what + ": is the same file as " + other);
    seen.emplace_back(option, id);
  }
}

Staged_files::~Staged_files()
{
  for(const File& f : files_) std::remove(f.temporary.c_str());
}

void Staged_files::stage(const std::string& path, const std::string& content)
{
  std::error_code ec;
  const fs::path target = fs::is_symlink(path, ec) ? fs::canonical(path, ec) : fs::path(path);
  File f{ec ? path : target.string(), ""};
  f.temporary = f.target + ".tmp." + std::to_string(::getpid());
  files_.push_back(f);
  {
    std::ofstream out(f.temporary, std::ios::binary | std::ios::trunc);
    if(!out) throw CGAL::BODT_3::Mesh_io_error(path, 0, "cannot open the file for writing");
    out << content;
    out.flush();
    if(!out) throw CGAL::BODT_3::Mesh_io_error(path, 0, "error while writing the file (disk full?)");
  }
  struct stat st;
  if(::stat(f.target.c_str(), &st) == 0) ::chmod(f.temporary.c_str(), st.st_mode & 07777);
}

void Staged_files::commit()
{
  for(File& f : files_)
  {
    if(std::rename(f.temporary.c_str(), f.target.c_str()) != 0)
      throw CGAL::BODT_3::Mesh_io_error(f.target, 0, "cannot replace the file with the one just written");
    f.temporary.clear();
  }
  files_.clear();
}

} // namespace bodt_cli
