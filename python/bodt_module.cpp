// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The compiled part of the Python module `bodt`: NumPy arrays in, the same C++
// entry point as `bodt smooth` (CGAL::BODT_3::smooth on a Tet_mesh), NumPy arrays
// and the JSON report out. bodt/__init__.py adds meshio meshes and the dict.

#include "report/json_report.h"

#include <CGAL/BODT_3/IO/check_tet_mesh.h>
#include <CGAL/BODT_3/Tet_mesh.h>
#include <CGAL/BODT_3/mesh_quality.h>
#include <CGAL/BODT_3/smooth.h>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

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

BODT::Smoothing_options options_of(const py::dict& given)
{
  BODT::Smoothing_options o;
  for(const auto& item : given)
  {
    const std::string key = item.first.cast<std::string>();
    const py::handle v = item.second;
    if(key == "max_iteration_number" || key == "iterations")
    {
      const long long n = v.cast<long long>();
      if(n < 0) throw py::value_error(key + " must not be negative");
      o.max_iteration_number = static_cast<std::size_t>(n);
    }
    else if(key == "time_limit") o.time_limit = v.cast<double>();
    else if(key == "convergence") o.convergence = v.cast<double>();
    else if(key == "method")
    {
      const std::string m = v.cast<std::string>();
      if(m == "bodt") o.moving_vertices = BODT::Moving_vertices::ALL;
      else if(m == "odt") o.moving_vertices = BODT::Moving_vertices::INTERIOR;
      else if(m == "flips") o.moving_vertices = BODT::Moving_vertices::NONE;
      else if(m == "nodt") o.smoothing_method = BODT::Smoothing_method::NODT;
      else throw py::value_error("method must be 'bodt', 'odt', 'flips' or 'nodt', not '" + m + "'");
    }
    else if(key == "preserve_features") o.preserve_features = v.cast<bool>();
    else if(key == "quality_guard") o.quality_guard = v.cast<bool>();
    else if(key == "topology_optimization") o.topology_optimization = v.cast<bool>();
    else if(key == "vertex_insertion") o.vertex_insertion = v.cast<bool>();
    else if(key == "max_vertex_insertions") o.max_vertex_insertions = v.cast<long long>();
    else if(key == "max_min_threshold") o.max_min_threshold = v.cast<double>();
    else if(key == "largest_angle_phase") o.largest_angle_phase = v.cast<bool>();
    else if(key == "largest_angle_threshold") o.largest_angle_threshold = v.cast<double>();
    else if(key == "threads")
    {
      o.threads = v.cast<int>();
      if(o.threads < 0) throw py::value_error("threads must be 0 (every core) or more");
    }
    else if(key == "feature_edge_ratio") o.tensor_voting.edge_ratio = v.cast<double>();
    else if(key == "feature_corner_ratio") o.tensor_voting.corner_ratio = v.cast<double>();
    else throw py::type_error("smooth() got an unexpected option '" + key + "'");
  }
  return o;
}

// Keeps the statistics of every sweep for the report.
struct Recorder
{
  std::vector<BODT::Iteration_stats> iterations;
  void after_classification(const BODT::Smoothing_result&) {}
  void after_iteration(const BODT::Iteration_stats& s) { iterations.push_back(s); }
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

py::tuple smooth_arrays(const Real_array& points, const Index_array& tets, const py::object& labels,
                        const py::object& triangles, const py::object& triangle_labels, const py::object& edges,
                        const py::dict& options)
{
  BODT::Smoothing_options opt = options_of(options);
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

  // The checks the file readers make; "mesh" stands for the file name in messages.
  std::ostringstream warnings;
  BODT::Tet_mesh_source source;
  source.file = "mesh";
  try
  {
    BODT::check_and_orient(mesh, source, warnings);
  }
  catch(const BODT::Mesh_io_error& e)
  {
    throw py::value_error(e.what());
  }
  const BODT::Quality_report before = BODT::mesh_quality(mesh);
  if(before.inverted_tets > 0)
    throw py::value_error("mesh: " + std::to_string(before.inverted_tets) +
                          " tetrahedra are flat; smoothing needs a valid mesh");

  Recorder recorder;
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

} // namespace

PYBIND11_MODULE(_bodt, m)
{
  m.doc() = "B-ODT tetrahedral mesh smoothing (the compiled part of the module bodt)";
  m.def("smooth_arrays", &smooth_arrays, py::arg("points"), py::arg("tets"), py::arg("labels"),
        py::arg("triangles"), py::arg("triangle_labels"), py::arg("edges"), py::arg("options"),
        "Smooths the mesh given as arrays; returns (points, tets, labels, triangles, triangle_labels, edges, "
        "report JSON, warnings).");
  m.attr("__version__") = BODT_VERSION;
}
