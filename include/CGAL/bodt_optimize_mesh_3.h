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

/*!
 * \ingroup PkgBODT3Functions
 * \brief Smooths a tetrahedral mesh in place by boundary-optimized Delaunay
 * triangulation (B-ODT; Gao, Yu et al., Fig. 1), with flips, max-min steps and
 * vertex insertion, keeping its volume, boundary, features and subdomains.
 *
 * Called like `odt_optimize_mesh_3`, with the named parameters in CGAL 5.5's style
 * (`parameters::a = x, parameters::b = y`) or CGAL 6's (`parameters::a(x).b(y)`):
 * \code
 * CGAL::bodt_optimize_mesh_3(c3t3, CGAL::parameters::max_iteration_number = 20,
 *                                  CGAL::parameters::time_limit = 10);
 * CGAL::bodt_optimize_mesh_3(c3t3, CGAL::parameters::max_iteration_number(20).time_limit(10));
 * \endcode
 *
 * \tparam Mesh a `Mesh_complex_3_in_triangulation_3` (as `make_mesh_3` returns it:
 *   the cells in the complex are the mesh, each subdomain keeps its volume, the
 *   protected curves and corners stay on their curves and in place) or a
 *   `Triangulation_3` (`Delaunay_triangulation_3`, `Regular_triangulation_3`: the
 *   finite cells are the mesh, the convex hull its boundary, which stays convex).
 * \tparam Params named parameters, in one of the two styles.
 *
 * \param mesh the mesh, changed in place: points move, cells are flipped and a few
 *   vertices are inserted (at most `max_vertex_insertions`).
 * \param params a sequence of named parameters among those listed below.
 *
 * \cgalNamedParamsBegin
 *   \cgalParamNBegin{time_limit}
 *     \cgalParamDescription{seconds after which the run stops, checked after each iteration}
 *     \cgalParamType{`double`} \cgalParamDefault{0: no limit}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{max_iteration_number}
 *     \cgalParamDescription{iterations of the main phase, and the most each later phase runs;
 *       0: until an iteration changes nothing or `convergence` is reached, at most 1000}
 *     \cgalParamType{`std::size_t`} \cgalParamDefault{20 (the paper's)}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{convergence}
 *     \cgalParamDescription{stop when no vertex moved by more than this fraction of its local size}
 *     \cgalParamType{`double`} \cgalParamDefault{0: off (0.02 when `max_iteration_number` is 0)}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{freeze_bound}
 *     \cgalParamDescription{a vertex whose move is shorter than this fraction of its local size stays put
 *       until a neighbour moves (as in CGAL's optimizers); 0: every vertex moves every time}
 *     \cgalParamType{`double`} \cgalParamDefault{0.0003}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{moving_vertices}
 *     \cgalParamDescription{`ALL` (B-ODT), `INTERIOR` (the original ODT, the paper's baseline) or
 *       `NONE` (topology optimization and insertion alone)}
 *     \cgalParamType{`CGAL::BODT_3::Moving_vertices`} \cgalParamDefault{`ALL`}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{smoothing_method}
 *     \cgalParamDescription{`BODT`, or `NODT` (Natural ODT projected back on the input's boundary,
 *       which does not keep the volume)}
 *     \cgalParamType{`CGAL::BODT_3::Smoothing_method`} \cgalParamDefault{`BODT`}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{preserve_features}
 *     \cgalParamDescription{keep feature vertices on their curves and corners in place}
 *     \cgalParamType{`bool`} \cgalParamDefault{`true`}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{max_boundary_distance}
 *     \cgalParamDescription{how far the boundary and the interfaces may go from the input's, as a fraction
 *       of the largest side of the input surface's bounding box (like MMG's `-hausd`, relative): a step
 *       that would take a point of the surface farther from the input's, or leave a point of the input's
 *       surface farther from the mesh's, is refused (both tested exactly, up to rounding).
 *       With B-ODT only (NODT projects onto the input's surface); 0: no bound}
 *     \cgalParamType{`double`} \cgalParamDefault{0: no bound}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{quality_guard}
 *     \cgalParamDescription{refuse a move that worsens the worst cells around the vertex}
 *     \cgalParamType{`bool`} \cgalParamDefault{`true`}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{topology_optimization}
 *     \cgalParamDescription{flips after each sweep (edge removal, multi-face removal, coplanar boundary flips)}
 *     \cgalParamType{`bool`} \cgalParamDefault{`true`}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{vertex_insertion}
 *     \cgalParamDescription{splits of spades, caps, slivers and wedges (paper, Sec. 2.3)}
 *     \cgalParamType{`bool`} \cgalParamDefault{`true`}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{max_vertex_insertions}
 *     \cgalParamDescription{at most this many new vertices; negative: 5% of the input's vertices}
 *     \cgalParamType{`long long`} \cgalParamDefault{-1}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{worst_cell_phase}
 *     \cgalParamDescription{after the last phase, max-min steps and flips at the cells within 2 degrees of
 *       the mesh's worst, until an iteration raises neither extreme angle}
 *     \cgalParamType{`bool`} \cgalParamDefault{`true`}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{edge_contraction}
 *     \cgalParamDescription{in the last phase, vertices inside a subdomain or on a flat part of the surface
 *       are removed by contracting an edge where that raises the worst cell around them}
 *     \cgalParamType{`bool`} \cgalParamDefault{`false`}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{max_vertex_removals}
 *     \cgalParamDescription{at most this many vertices removed; negative: 5% of the input's vertices}
 *     \cgalParamType{`long long`} \cgalParamDefault{-1}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{max_min_threshold}
 *     \cgalParamDescription{minimum dihedral sine below which a cell's vertices take max-min steps after
 *       the flips; 0: off}
 *     \cgalParamType{`double`} \cgalParamDefault{0.34 (about 20 degrees)}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{largest_angle_phase}
 *     \cgalParamDescription{after the iterations, a phase decided by the largest dihedral angle, then a
 *       last one by the minimum sine, both without insertion}
 *     \cgalParamType{`bool`} \cgalParamDefault{`true`}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{largest_angle_threshold}
 *     \cgalParamDescription{degrees: in that phase, cells with a larger angle get flips and max-min steps}
 *     \cgalParamType{`double`} \cgalParamDefault{120}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{number_of_threads}
 *     \cgalParamDescription{threads of the sweeps and of the set-up; 0: every core the process may use.
 *       The result does not depend on it}
 *     \cgalParamType{`int`} \cgalParamDefault{0}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{feature_edge_ratio, feature_corner_ratio}
 *     \cgalParamDescription{tensor-voting thresholds, used where the mesh carries no feature information}
 *     \cgalParamType{`double`} \cgalParamDefault{0.05, 0.05}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{progress_visitor}
 *     \cgalParamDescription{an object with `after_classification(const BODT_3::Smoothing_result&)` and
 *       `after_iteration(const BODT_3::Iteration_stats&)`, copied}
 *     \cgalParamType{a class} \cgalParamDefault{none}
 *   \cgalParamNEnd
 * \cgalNamedParamsEnd
 * CGAL's `do_freeze` and `sliver_bound` are compile errors that say why.
 *
 * \return `MAX_ITERATION_NUMBER_REACHED`, `TIME_LIMIT_REACHED`, `CONVERGENCE_REACHED`, or
 *   `CANT_IMPROVE_ANYMORE` when an iteration changed nothing; `std::cout << code` prints its name.
 *
 * \pre `mesh`'s triangulation has dimension 3 and its geometric traits compute in `double`
 *   (`FT` is `double`, as with `Exact_predicates_inexact_constructions_kernel` and Mesh_3's
 *   default triangulation): the constructions are done in doubles, every orientation test with
 *   CGAL's exact predicates. Checked at compile time.
 * \post No cell of the mesh is inverted or flat (exact orientation); every subdomain's volume is
 *   kept to round-off; corners stay in place, curve vertices on their curve; no dihedral angle
 *   leaves the range the input had.
 *
 * doc/manual.md describes every parameter and what the result contains.
 */
template <class Mesh, class... Params>
std::enable_if_t<(BODT_3::internal::is_parameter<Params> && ...), Mesh_optimization_return_code>
bodt_optimize_mesh_3(Mesh& mesh, const Params&... params)
{
  return BODT_3::internal::optimize(mesh, params...);
}

/*!
 * \ingroup PkgBODT3Functions
 * \brief The same with the domain of `odt_optimize_mesh_3(c3t3, domain, ...)`, so that a call to
 * CGAL's optimizer can be changed by its name alone.
 *
 * \tparam Domain a model of `MeshDomain_3`. It is not used: B-ODT moves a boundary vertex in the
 *   tangent plane of the current boundary, which keeps every subdomain's volume exactly and needs no
 *   oracle. A second argument that is neither a domain nor a named parameter does not compile.
 */
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
