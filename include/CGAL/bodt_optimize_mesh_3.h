// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_BODT_OPTIMIZE_MESH_3_H
#define CGAL_BODT_OPTIMIZE_MESH_3_H

#include <CGAL/BODT_3/Optimization_parameters.h>
#include <CGAL/BODT_3/Return_code.h>
#include <CGAL/BODT_3/smooth.h>

#include <CGAL/Mesh_optimization_return_code.h>
#include <CGAL/Named_function_parameters.h>

#include <boost/parameter/aux_/is_tagged_argument.hpp>

#include <type_traits>

namespace CGAL {
namespace BODT_3 {
namespace internal {

template <class T>
using Is_boost_argument = boost::parameter::aux::is_tagged_argument<T>;

template <class T> struct Is_chain : std::false_type {};
template <class V> struct Is_chain<Optimization_parameters<V>> : std::true_type {};

// CGAL 6's `parameters::default_values()`, which CGAL 5.5 has too: no parameter.
template <class T> struct Is_no_parameter : std::false_type {};
template <>
struct Is_no_parameter<CGAL::parameters::Default_named_parameters> : std::true_type {};

template <class T, class = void> struct Is_mesh_domain : std::false_type {};
template <class T>
struct Is_mesh_domain<T, std::void_t<typename T::Subdomain_index, typename T::Surface_patch_index,
                                     typename T::Is_in_domain>> : std::true_type {};

template <class T>
constexpr bool is_parameter = Is_boost_argument<T>::value || Is_chain<T>::value || Is_no_parameter<T>::value;

template <class Arg>
void apply_parameter(Smoothing_options& options, const Arg& arg)
{
  if constexpr(Is_boost_argument<Arg>::value)
  {
    using Tag = typename Arg::key_type;
    static_assert(is_known_tag<Tag>, "this named parameter is not a parameter of bodt_optimize_mesh_3 "
                                     "(see the list in CGAL/bodt_optimize_mesh_3.h)");
    if constexpr(!std::is_same<Tag, tag::progress_visitor_>::value)
      set_parameter(options, Tag(), arg.get_value());
  }
  else if constexpr(Is_chain<Arg>::value)
    options = arg.options();
}

template <class Arg>
constexpr bool has_visitor()
{
  if constexpr(Is_chain<Arg>::value)
    return !std::is_same<std::decay_t<decltype(std::declval<Arg>().visitor())>, Null_smoothing_visitor>::value;
  else if constexpr(Is_boost_argument<Arg>::value)
    return std::is_same<typename Arg::key_type, tag::progress_visitor_>::value;
  else
    return false;
}

template <class Arg>
auto visitor_of(const Arg& arg)
{
  if constexpr(has_visitor<Arg>())
  {
    if constexpr(Is_chain<Arg>::value)
      return arg.visitor();
    else
      return arg.get_value();
  }
  else
    return Null_smoothing_visitor();
}

// The visitor among the parameters (the last one given), or one that does nothing.
inline Null_smoothing_visitor find_visitor() { return Null_smoothing_visitor(); }
template <class Arg, class... Rest>
auto find_visitor(const Arg& arg, const Rest&... rest)
{
  if constexpr((has_visitor<Rest>() || ...))
    return find_visitor(rest...);
  else
    return visitor_of(arg);
}

template <class Mesh, class... Params>
Mesh_optimization_return_code optimize(Mesh& mesh, const Params&... params)
{
  static_assert((is_parameter<Params> && ...),
                "bodt_optimize_mesh_3(mesh[, domain], parameters...): every argument after the mesh (and the "
                "optional domain) must be a named parameter, e.g. CGAL::parameters::time_limit = 10 or "
                "CGAL::parameters::time_limit(10).max_iteration_number(20)");
  static_assert((Is_chain<Params>::value + ... + 0) <= 1 &&
                    ((Is_chain<Params>::value + ... + 0) == 0 || (Is_boost_argument<Params>::value + ... + 0) == 0),
                "bodt_optimize_mesh_3: give the parameters in one style, either as one chain "
                "parameters::a(x).b(y) or as separate arguments parameters::a = x, parameters::b = y");
  Smoothing_options options;
  (apply_parameter(options, params), ...);
  auto visitor = find_visitor(params...);
  return smooth(mesh, options, visitor).code;
}

} // namespace internal
} // namespace BODT_3

/// Smooths a tetrahedral mesh in place by boundary-optimized Delaunay triangulation
/// (B-ODT), keeping its volume, features and subdomains. `mesh` is a
/// `Mesh_complex_3_in_triangulation_3` (as `make_mesh_3` returns it) or a
/// `Triangulation_3`. Called like `odt_optimize_mesh_3`, in CGAL 5.5's or CGAL 6's
/// style:
///
///   CGAL::bodt_optimize_mesh_3(c3t3, CGAL::parameters::max_iteration_number = 20,
///                                    CGAL::parameters::time_limit = 10);
///   CGAL::bodt_optimize_mesh_3(c3t3, CGAL::parameters::max_iteration_number(20).time_limit(10));
///
/// Parameters (doc/manual.md describes each):
///  - `time_limit` (seconds, default 0: none), `max_iteration_number` (default 20;
///    0: until a sweep moves nothing or `convergence` is reached, at most 1000
///    sweeps, as CGAL's optimizers), `convergence` (stop when no vertex moves by
///    more than this fraction of its local size; default 0: off);
///  - `moving_vertices`: `BODT_3::Moving_vertices::ALL` (B-ODT, default), `INTERIOR`
///    (the original ODT, the paper's baseline) or `NONE` (no smoothing: topology
///    optimization and insertion alone);
///  - `preserve_features` (default true), `quality_guard` (default true);
///  - `topology_optimization` (default true), `vertex_insertion` (default true),
///    `max_vertex_insertions` (default -1: 5% of the input's vertices),
///    `max_min_threshold` (default 0.34: stars whose worst dihedral sine is below it
///    get max-min steps after the flips; 0: off);
///  - `largest_angle_phase` (default true): after the iterations, a phase decided
///    by the largest dihedral angle (flips and max-min steps at the cells with an
///    angle above `largest_angle_threshold`, default 120 degrees, within the smallest
///    and largest angles reached), then one decided by the minimum sine again;
///  - `smoothing_method`: `BODT_3::Smoothing_method::BODT` (default) or `NODT`;
///  - `number_of_threads` (default 0: every core the process may use): the
///    smoothing sweeps run in parallel; the result does not depend on it;
///  - `feature_edge_ratio`, `feature_corner_ratio`: tensor voting thresholds;
///  - `progress_visitor`: an object with `after_classification(const BODT_3::Smoothing_result&)`
///    and `after_iteration(const BODT_3::Iteration_stats&)`, copied.
/// CGAL's `freeze_bound`, `do_freeze` and `sliver_bound` are compile errors that say why.
/// Returns `MAX_ITERATION_NUMBER_REACHED`, `TIME_LIMIT_REACHED`, `CONVERGENCE_REACHED`, or
/// `CANT_IMPROVE_ANYMORE` when a sweep changed nothing; `std::cout << code` prints the name.
template <class Mesh, class... Params>
std::enable_if_t<(BODT_3::internal::is_parameter<Params> && ...), Mesh_optimization_return_code>
bodt_optimize_mesh_3(Mesh& mesh, const Params&... params)
{
  return BODT_3::internal::optimize(mesh, params...);
}

/// The same with the domain of `odt_optimize_mesh_3(c3t3, domain, ...)`, so that a
/// call to CGAL's optimizer can be changed by its name alone. The domain is not used:
/// B-ODT moves a boundary vertex in the tangent plane of the current boundary (which
/// keeps every subdomain's volume exactly) and needs no oracle. A later version may
/// use it to project boundary vertices back onto the domain's surface.
template <class Mesh, class Domain, class... Params>
std::enable_if_t<!BODT_3::internal::is_parameter<Domain>, Mesh_optimization_return_code>
bodt_optimize_mesh_3(Mesh& mesh, const Domain&, const Params&... params)
{
  static_assert(BODT_3::internal::Is_mesh_domain<Domain>::value,
                "bodt_optimize_mesh_3(mesh, domain, parameters...): the second argument is neither a mesh domain "
                "(a model of MeshDomain_3) nor a named parameter; write CGAL::parameters::time_limit = 10, not 10");
  return BODT_3::internal::optimize(mesh, params...);
}

} // namespace CGAL

#endif // CGAL_BODT_OPTIMIZE_MESH_3_H
