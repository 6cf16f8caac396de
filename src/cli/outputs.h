// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef BODT_CLI_OUTPUTS_H
#define BODT_CLI_OUTPUTS_H

// What the commands write: the output format, checks that every output path is
// usable before any work starts, and side files (reports) that appear only if the
// mesh is written too.

#include <CGAL/BODT_3/IO/mesh_io.h>
#include <CGAL/BODT_3/Tet_mesh.h>

#include <string>
#include <utility>
#include <vector>

namespace bodt_cli {

/// The mesh format of an output: the one `--format` names, or else (`forced`
/// false) the one the file name asks for, in the input's variant when it is the
/// same format (`IO::output_format`).
struct Output_format
{
  bool forced = false;
  CGAL::BODT_3::IO::Mesh_file_format format;

  /// The format to write, once the input's is known.
  CGAL::BODT_3::IO::Mesh_file_format resolve(const std::string& path,
                                             const CGAL::BODT_3::IO::Mesh_file_format& input) const;
};

/// A CLI11 check of a `--format` name (`IO::parse_format_name`).
std::string check_format_name(const std::string& name);

/// The format for `path`: `format_option` if given (and then the file name must not
/// ask for another format), otherwise the one the file name asks for. Throws
/// `Usage_error` when neither tells, before any work.
Output_format choose_output_format(const std::string& path, const std::string& format_option);

/// Writes the mesh in `format`, atomically (temporary file, then rename).
void write_output(const std::string& path, const CGAL::BODT_3::Tet_mesh& mesh,
                  const CGAL::BODT_3::IO::Mesh_file_format& format, int threads = 1);

/// Refuses an input that is a folder (the readers would fail without saying which
/// file), with a `Mesh_io_error` naming it.
void check_input_path(const std::string& input);

/// Refuses, with `Usage_error` and before any work, output paths that cannot work:
/// a missing or unwritable folder, a folder given as a file, a file that is not
/// writable, an output that is the input, two outputs that are the same file.
/// `outputs` holds (option, path) pairs; empty paths are skipped.
void check_output_paths(const std::string& input, const std::vector<std::pair<std::string, std::string>>& outputs);

/// Files written next to their targets and renamed over them only by `commit()`,
/// so that reports appear only once the mesh they describe is written. A symbolic
/// link is followed (the file it points to is replaced), and an existing file
/// keeps its permissions. Temporary files not committed are removed.
class Staged_files
{
public:
  Staged_files() = default;
  Staged_files(const Staged_files&) = delete;
  Staged_files& operator=(const Staged_files&) = delete;
  ~Staged_files();

  void stage(const std::string& path, const std::string& content);
  void commit();

private:
  struct File
  {
    std::string target, temporary;
  };
  std::vector<File> files_;
};

} // namespace bodt_cli

#endif // BODT_CLI_OUTPUTS_H
