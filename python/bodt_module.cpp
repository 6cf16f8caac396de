// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The compiled part of the Python module `bodt`: NumPy arrays in, the same C++
// entry points as `bodt smooth` (CGAL::BODT_3::smooth on a Tet_mesh) and `bodt
// quality`, NumPy arrays and the JSON reports out. bodt/__init__.py adds meshio
// meshes, the dicts and the documentation.

#include "cli/feature_angles.h"
#include "report/json_report.h"

#include <CGAL/BODT_3/internal/Mesh/check_tet_mesh.h>
#include <CGAL/BODT_3/Tet_mesh.h>
#include <CGAL/BODT_3/mesh_quality.h>
#include <CGAL/BODT_3/smooth.h>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

namespace py = pybind11;
namespace BODT = CGAL::BODT_3;

namespace {

using Index_array = py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>;
using Real_array = py::array_t<double, py::array::c_style | py::array::forcecast>;

// Rows of `columns` integers, each a vertex index in [0, vertices).
template <std::size_t columns>
std::vector<std::array<int, columns>> index_rows(const Index_array& a, const char* name, std::size_t vertices)
{
  if(a.ndim() != 2 || a.shape(1) != static_cast<py::ssize_t>(columns))
    throw py::value_error(std::string(name) + " must be an array of shape (n, " + std::to_string(columns) + ")");
  std::vector<std::array<int, columns>> rows(static_cast<std::size_t>(a.shape(0)));
  const auto r = a.unchecked<2>();
  for(py::ssize_t i = 0; i < a.shape(0); ++i)
    for(std::size_t k = 0; k < columns; ++k)
    {
      const std::int64_t v = r(i, static_cast<py::ssize_t>(k));
      if(v < 0 || static_cast<std::uint64_t>(v) >= vertices)
        throw py::value_error(std::string(name) + "[" + std::to_string(i) + "] refers to vertex " +
                              std::to_string(v) + ", but vertex indices run from 0 to " +
                              std::to_string(vertices - 1));
      rows[static_cast<std::size_t>(i)][k] = static_cast<int>(v);
    }
  return rows;
}

std::vector<int> labels_of(const py::object& given, std::size_t n, const char* name, int fallback)
{
  if(given.is_none()) return std::vector<int>(n, fallback);
  const Index_array a = given.cast<Index_array>();
  if(a.ndim() != 1 || static_cast<std::size_t>(a.shape(0)) != n)
    throw py::value_error(std::string(name) + " must be an array of " + std::to_string(n) + " integers");
  std::vector<int> out(n);
  const auto r = a.unchecked<1>();
  for(std::size_t i = 0; i < n; ++i)
  {
    const std::int64_t v = r(static_cast<py::ssize_t>(i));
    if(v < std::numeric_limits<int>::min() || v > std::numeric_limits<int>::max())
      throw py::value_error(std::string(name) + "[" + std::to_string(i) + "] = " + std::to_string(v) +
                            " does not fit a 32-bit label");
    out[i] = static_cast<int>(v);
  }
  return out;
}

// A keyword option of smooth(): its name and how it sets the options.
struct Option
{
  const char* name;
  void (*set)(BODT::Smoothing_options&, py::handle);
};

// Degrees in (0, 90], the range of the feature and corner angles (cli/feature_angles.h).
double feature_angle_of(py::handle v, const char* name)
{
  const double a = v.cast<double>();
  if(!(a > 0 && a <= 90)) throw py::value_error(std::string(name) + " must be an angle above 0 and at most 90 degrees");
  return a;
}

void set_iterations(BODT::Smoothing_options& o, py::handle v)
{
  const long long n = v.cast<long long>();
  if(n < 0) throw py::value_error("max_iteration_number must not be negative");
  o.max_iteration_number = static_cast<std::size_t>(n);
}

// Every option smooth() accepts; bodt/__init__.py documents each one (a test checks).
const std::vector<Option>& smoothing_options()
{
  static const std::vector<Option> options = {
      {"max_iteration_number", set_iterations},
      {"iterations", set_iterations},
      {"time_limit", [](BODT::Smoothing_options& o, py::handle v) { o.time_limit = v.cast<double>(); }},
      {"convergence", [](BODT::Smoothing_options& o, py::handle v) { o.convergence = v.cast<double>(); }},
      {"freeze_bound", [](BODT::Smoothing_options& o, py::handle v) { o.freeze_bound = v.cast<double>(); }},
      {"max_boundary_distance",
       [](BODT::Smoothing_options& o, py::handle v) {
         o.max_boundary_distance = v.cast<double>();
         if(!(o.max_boundary_distance >= 0)) throw py::value_error("max_boundary_distance must be 0 (no bound) or more");
       }},
      {"method",
       [](BODT::Smoothing_options& o, py::handle v) {
         const std::string m = v.cast<std::string>();
         if(m == "bodt") o.moving_vertices = BODT::Moving_vertices::ALL;
         else if(m == "odt") o.moving_vertices = BODT::Moving_vertices::INTERIOR;
         else if(m == "flips") o.moving_vertices = BODT::Moving_vertices::NONE;
         else if(m == "nodt") o.smoothing_method = BODT::Smoothing_method::NODT;
         else throw py::value_error("method must be 'bodt', 'odt', 'flips' or 'nodt', not '" + m + "'");
       }},
      {"preserve_features", [](BODT::Smoothing_options& o, py::handle v) { o.preserve_features = v.cast<bool>(); }},
      {"quality_guard", [](BODT::Smoothing_options& o, py::handle v) { o.quality_guard = v.cast<bool>(); }},
      {"topology_optimization",
       [](BODT::Smoothing_options& o, py::handle v) { o.topology_optimization = v.cast<bool>(); }},
      {"vertex_insertion", [](BODT::Smoothing_options& o, py::handle v) { o.vertex_insertion = v.cast<bool>(); }},
      {"edge_contraction", [](BODT::Smoothing_options& o, py::handle v) { o.edge_contraction = v.cast<bool>(); }},
      {"worst_cell_phase", [](BODT::Smoothing_options& o, py::handle v) { o.worst_cell_phase = v.cast<bool>(); }},
      {"ear_splits", [](BODT::Smoothing_options& o, py::handle v) { o.ear_splits = v.cast<bool>(); }},
      {"cavity_insertion", [](BODT::Smoothing_options& o, py::handle v) { o.cavity_insertion = v.cast<bool>(); }},
      {"max_vertex_removals",
       [](BODT::Smoothing_options& o, py::handle v) { o.max_vertex_removals = v.cast<long long>(); }},
      {"max_vertex_insertions",
       [](BODT::Smoothing_options& o, py::handle v) { o.max_vertex_insertions = v.cast<long long>(); }},
      {"max_min_threshold", [](BODT::Smoothing_options& o, py::handle v) { o.max_min_threshold = v.cast<double>(); }},
      {"largest_angle_phase",
       [](BODT::Smoothing_options& o, py::handle v) { o.largest_angle_phase = v.cast<bool>(); }},
      {"largest_angle_threshold",
       [](BODT::Smoothing_options& o, py::handle v) { o.largest_angle_threshold = v.cast<double>(); }},
      {"threads",
       [](BODT::Smoothing_options& o, py::handle v) {
         o.threads = v.cast<int>();
         if(o.threads < 0) throw py::value_error("threads must be 0 (every core) or more");
       }},
      {"feature_edge_ratio",
       [](BODT::Smoothing_options& o, py::handle v) { o.tensor_voting.edge_ratio = v.cast<double>(); }},
      {"feature_corner_ratio",
       [](BODT::Smoothing_options& o, py::handle v) { o.tensor_voting.corner_ratio = v.cast<double>(); }},
      {"feature_angle",
       [](BODT::Smoothing_options& o, py::handle v) {
         o.tensor_voting.edge_ratio = bodt_cli::edge_ratio_of_angle(feature_angle_of(v, "feature_angle"));
       }},
      {"corner_angle",
       [](BODT::Smoothing_options& o, py::handle v) {
         o.tensor_voting.corner_ratio = bodt_cli::corner_ratio_of_angle(feature_angle_of(v, "corner_angle"));
       }},
  };
  return options;
}

BODT::Smoothing_options options_of(const py::dict& given)
{
  BODT::Smoothing_options o;
  bool angle = false, ratio = false;
  for(const auto& item : given)
  {
    const std::string key = item.first.cast<std::string>();
    const auto& table = smoothing_options();
    const auto it = std::find_if(table.begin(), table.end(), [&](const Option& opt) { return key == opt.name; });
    if(it == table.end()) throw py::type_error("smooth() got an unexpected option '" + key + "'");
    it->set(o, item.second);
    angle = angle || key == "feature_angle" || key == "corner_angle";
    ratio = ratio || key == "feature_edge_ratio" || key == "feature_corner_ratio";
  }
  if(angle && ratio)
    throw py::type_error("give the feature thresholds as angles (feature_angle, corner_angle) or as ratios "
                         "(feature_edge_ratio, feature_corner_ratio), not both");
  return o;
}

// Keeps the statistics of every sweep for the report, and shows each to the
// caller's `progress` (None or a callable taking the sweep's JSON). The smoothing
// runs without the GIL; it is taken back here, where Ctrl-C and an exception of
// `progress` stop the run.
struct Recorder
{
  std::vector<BODT::Iteration_stats> iterations;
  py::handle progress;   // borrowed: the caller's argument outlives the run

  void after_classification(const BODT::Smoothing_result&) {}
  void after_iteration(const BODT::Iteration_stats& s)
  {
    iterations.push_back(s);
    py::gil_scoped_acquire held;
    if(PyErr_CheckSignals() != 0) throw py::error_already_set();
    if(!progress.is_none()) progress(nlohmann::json(s).dump());
  }
};

template <std::size_t columns>
Index_array to_array(const std::vector<std::array<int, columns>>& rows)
{
  Index_array a({static_cast<py::ssize_t>(rows.size()), static_cast<py::ssize_t>(columns)});
  auto w = a.mutable_unchecked<2>();
  for(std::size_t i = 0; i < rows.size(); ++i)
    for(std::size_t k = 0; k < columns; ++k) w(static_cast<py::ssize_t>(i), static_cast<py::ssize_t>(k)) = rows[i][k];
  return a;
}

Index_array to_array(const std::vector<int>& v)
{
  Index_array a(static_cast<py::ssize_t>(v.size()));
  auto w = a.mutable_unchecked<1>();
  for(std::size_t i = 0; i < v.size(); ++i) w(static_cast<py::ssize_t>(i)) = v[i];
  return a;
}

// The mesh given as arrays, with the checks the file readers make ("mesh" stands
// for the file name in messages); what they warn about goes to `warnings`.
BODT::Tet_mesh checked_mesh(const Real_array& points, const Index_array& tets, const py::object& labels,
                            const py::object& triangles, const py::object& triangle_labels, const py::object& edges,
                            std::ostream& warnings)
{
  if(points.ndim() != 2 || points.shape(1) != 3) throw py::value_error("points must be an array of shape (n, 3)");
  BODT::Tet_mesh mesh;
  const std::size_t n = static_cast<std::size_t>(points.shape(0));
  const auto p = points.unchecked<2>();
  for(std::size_t i = 0; i < n; ++i)
    mesh.points.emplace_back(p(static_cast<py::ssize_t>(i), 0), p(static_cast<py::ssize_t>(i), 1),
                             p(static_cast<py::ssize_t>(i), 2));
  mesh.vertex_refs.assign(n, 0);
  mesh.tets = index_rows<4>(tets, "tets", n);
  mesh.tet_labels = labels_of(labels, mesh.tets.size(), "labels", 1);
  if(!triangles.is_none()) mesh.triangles = index_rows<3>(triangles.cast<Index_array>(), "triangles", n);
  mesh.triangle_labels = labels_of(triangle_labels, mesh.triangles.size(), "triangle_labels", 1);
  if(!edges.is_none()) mesh.edges = index_rows<2>(edges.cast<Index_array>(), "edges", n);
  mesh.edge_labels.assign(mesh.edges.size(), 1);
  BODT::internal::Tet_mesh_source source;
  source.file = "mesh";
  try
  {
    BODT::internal::check_and_orient(mesh, source, warnings);
  }
  catch(const BODT::Mesh_io_error& e)
  {
    throw py::value_error(e.what());
  }
  return mesh;
}

py::tuple smooth_arrays(const Real_array& points, const Index_array& tets, const py::object& labels,
                        const py::object& triangles, const py::object& triangle_labels, const py::object& edges,
                        const py::dict& options, const py::object& progress)
{
  const BODT::Smoothing_options opt = options_of(options);
  if(!progress.is_none() && !PyCallable_Check(progress.ptr()))
    throw py::type_error("progress must be a function of one argument, or None");
  std::ostringstream warnings;
  BODT::Tet_mesh mesh = checked_mesh(points, tets, labels, triangles, triangle_labels, edges, warnings);
  const BODT::Quality_report before = BODT::mesh_quality(mesh);
  if(before.inverted_tets > 0)
    throw py::value_error("mesh: " + std::to_string(before.inverted_tets) +
                          " tetrahedra are flat; smoothing needs a valid mesh");

  Recorder recorder;
  recorder.progress = progress;
  BODT::Smoothing_result result;
  {
    py::gil_scoped_release unlocked;
    result = BODT::smooth(mesh, opt, recorder);
  }
  const BODT::Quality_report after = BODT::mesh_quality(mesh);
  const std::string report = BODT::smoothing_report(opt, result, recorder.iterations, before, after).dump();

  Real_array out_points({static_cast<py::ssize_t>(mesh.points.size()), py::ssize_t(3)});
  auto w = out_points.mutable_unchecked<2>();
  for(std::size_t i = 0; i < mesh.points.size(); ++i)
    for(int k = 0; k < 3; ++k) w(static_cast<py::ssize_t>(i), k) = mesh.points[i][k];
  return py::make_tuple(out_points, to_array(mesh.tets), to_array(mesh.tet_labels), to_array(mesh.triangles),
                        to_array(mesh.triangle_labels), to_array(mesh.edges), report, warnings.str());
}

py::tuple quality_arrays(const Real_array& points, const Index_array& tets, const py::object& labels,
                         const py::dict& options)
{
  BODT::Quality_options q;
  for(const auto& item : options)
  {
    const std::string key = item.first.cast<std::string>();
    if(key == "bins")
    {
      q.histogram_bins = item.second.cast<int>();
      if(q.histogram_bins < 1 || q.histogram_bins > 18000) throw py::value_error("bins must be from 1 to 18000");
    }
    else if(key == "small_angle") q.small_angle = item.second.cast<double>();
    else if(key == "large_angle") q.large_angle = item.second.cast<double>();
    else if(key == "threads")
    {
      q.threads = item.second.cast<int>();
      if(q.threads < 0) throw py::value_error("threads must be 0 (every core) or more");
    }
    else throw py::type_error("quality() got an unexpected option '" + key + "'");
  }
  std::ostringstream warnings;
  const BODT::Tet_mesh mesh = checked_mesh(points, tets, labels, py::none(), py::none(), py::none(), warnings);
  return py::make_tuple(BODT::to_json(BODT::mesh_quality(mesh, q)), warnings.str());
}

py::list option_names()
{
  py::list names;
  for(const Option& o : smoothing_options()) names.append(o.name);
  return names;
}

} // namespace

PYBIND11_MODULE(_bodt, m)
{
  m.doc() = "B-ODT tetrahedral mesh smoothing (the compiled part of the module bodt)";
  m.def("smooth_arrays", &smooth_arrays, py::arg("points"), py::arg("tets"), py::arg("labels"),
        py::arg("triangles"), py::arg("triangle_labels"), py::arg("edges"), py::arg("options"), py::arg("progress"),
        "Smooths the mesh given as arrays; returns (points, tets, labels, triangles, triangle_labels, edges, "
        "report JSON, warnings). `progress` (None or a callable) gets each sweep's statistics as JSON.");
  m.def("quality_arrays", &quality_arrays, py::arg("points"), py::arg("tets"), py::arg("labels"), py::arg("options"),
        "Measures the mesh given as arrays; returns (quality report JSON, warnings).");
  m.def("option_names", &option_names, "The names of the options smooth_arrays takes.");
  m.attr("__version__") = BODT_VERSION;
}
