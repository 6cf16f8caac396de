// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_BODT_3_OPTIMIZATION_PARAMETERS_H
#define CGAL_BODT_3_OPTIMIZATION_PARAMETERS_H

// The named parameters of `CGAL::bodt_optimize_mesh_3`, in both of CGAL's styles:
//
//   CGAL 5.5 (Boost.Parameter):  parameters::max_iteration_number = 20, parameters::time_limit = 10
//   CGAL 6 (chained):            parameters::max_iteration_number(20).time_limit(10)
//
// CGAL 5.5 declares `time_limit`, `max_iteration_number` and `convergence` as
// Boost.Parameter keyword objects, which cannot be called. So this header declares,
// in `CGAL::parameters`, objects of the same names that can be both assigned (giving
// exactly the Boost.Parameter argument CGAL's keyword gives, so that CGAL's own
// functions such as `odt_optimize_mesh_3` still take them) and called (starting a
// chain). Qualified names (`CGAL::parameters::time_limit`, or through a namespace
// alias) find these objects. After `using namespace CGAL::parameters;` an
// unqualified `time_limit` names both CGAL's keyword and this object, which C++
// calls ambiguous: qualify those three names in such code.

#include <CGAL/BODT_3/Smoothing_options.h>
#include <CGAL/BODT_3/Smoothing_result.h>

#include <CGAL/assertions.h>

#include <CGAL/boost/parameter.h>

#include <boost/parameter/name.hpp>

#include <cstddef>
#include <type_traits>

namespace CGAL {
namespace BODT_3 {
namespace internal {

// Tags of the package's own parameters; the keyword objects users write are in
// `CGAL::parameters` below.
CGAL_PRAGMA_DIAG_PUSH
CGAL_IGNORE_BOOST_PARAMETER_NAME_WARNINGS
BOOST_PARAMETER_NAME((moving_vertices_keyword, tag) moving_vertices_)
BOOST_PARAMETER_NAME((smoothing_method_keyword, tag) smoothing_method_)
BOOST_PARAMETER_NAME((preserve_features_keyword, tag) preserve_features_)
BOOST_PARAMETER_NAME((quality_guard_keyword, tag) quality_guard_)
BOOST_PARAMETER_NAME((topology_optimization_keyword, tag) topology_optimization_)
BOOST_PARAMETER_NAME((vertex_insertion_keyword, tag) vertex_insertion_)
BOOST_PARAMETER_NAME((max_vertex_insertions_keyword, tag) max_vertex_insertions_)
BOOST_PARAMETER_NAME((edge_contraction_keyword, tag) edge_contraction_)
BOOST_PARAMETER_NAME((worst_cell_phase_keyword, tag) worst_cell_phase_)
BOOST_PARAMETER_NAME((ear_splits_keyword, tag) ear_splits_)
BOOST_PARAMETER_NAME((cavity_insertion_keyword, tag) cavity_insertion_)
BOOST_PARAMETER_NAME((max_vertex_removals_keyword, tag) max_vertex_removals_)
BOOST_PARAMETER_NAME((max_min_threshold_keyword, tag) max_min_threshold_)
BOOST_PARAMETER_NAME((largest_angle_phase_keyword, tag) largest_angle_phase_)
BOOST_PARAMETER_NAME((largest_angle_threshold_keyword, tag) largest_angle_threshold_)
BOOST_PARAMETER_NAME((number_of_threads_keyword, tag) number_of_threads_)
BOOST_PARAMETER_NAME((feature_edge_ratio_keyword, tag) feature_edge_ratio_)
BOOST_PARAMETER_NAME((feature_corner_ratio_keyword, tag) feature_corner_ratio_)
BOOST_PARAMETER_NAME((max_boundary_distance_keyword, tag) max_boundary_distance_)
BOOST_PARAMETER_NAME((progress_visitor_keyword, tag) progress_visitor_)
CGAL_PRAGMA_DIAG_POP

template <class T> struct Always_false : std::false_type {};

namespace cgal_tag = CGAL::parameters::tag;

// One overload per parameter: the same code serves both styles.
inline void set_parameter(Smoothing_options& o, cgal_tag::time_limit_, double v) { o.time_limit = v; }
inline void set_parameter(Smoothing_options& o, cgal_tag::max_iteration_number_, long long v)
{
  CGAL_precondition(v >= 0);
  o.max_iteration_number = static_cast<std::size_t>(v);
}
inline void set_parameter(Smoothing_options& o, cgal_tag::convergence_, double v) { o.convergence = v; }
inline void set_parameter(Smoothing_options& o, cgal_tag::freeze_bound_, double v)
{
  CGAL_precondition(v >= 0);
  o.freeze_bound = v;
}
inline void set_parameter(Smoothing_options& o, tag::moving_vertices_, Moving_vertices v) { o.moving_vertices = v; }
inline void set_parameter(Smoothing_options& o, tag::smoothing_method_, Smoothing_method v) { o.smoothing_method = v; }
inline void set_parameter(Smoothing_options& o, tag::preserve_features_, bool v) { o.preserve_features = v; }
inline void set_parameter(Smoothing_options& o, tag::quality_guard_, bool v) { o.quality_guard = v; }
inline void set_parameter(Smoothing_options& o, tag::topology_optimization_, bool v) { o.topology_optimization = v; }
inline void set_parameter(Smoothing_options& o, tag::vertex_insertion_, bool v) { o.vertex_insertion = v; }
inline void set_parameter(Smoothing_options& o, tag::max_vertex_insertions_, long long v) { o.max_vertex_insertions = v; }
inline void set_parameter(Smoothing_options& o, tag::edge_contraction_, bool v) { o.edge_contraction = v; }
inline void set_parameter(Smoothing_options& o, tag::worst_cell_phase_, bool v) { o.worst_cell_phase = v; }
inline void set_parameter(Smoothing_options& o, tag::ear_splits_, bool v) { o.ear_splits = v; }
inline void set_parameter(Smoothing_options& o, tag::cavity_insertion_, bool v) { o.cavity_insertion = v; }
inline void set_parameter(Smoothing_options& o, tag::max_vertex_removals_, long long v) { o.max_vertex_removals = v; }
inline void set_parameter(Smoothing_options& o, tag::max_min_threshold_, double v)
{
  CGAL_precondition(v >= 0 && v <= 1);
  o.max_min_threshold = v;
}
inline void set_parameter(Smoothing_options& o, tag::largest_angle_phase_, bool v) { o.largest_angle_phase = v; }
inline void set_parameter(Smoothing_options& o, tag::largest_angle_threshold_, double v)
{
  CGAL_precondition(v >= 0 && v <= 180);
  o.largest_angle_threshold = v;
}
inline void set_parameter(Smoothing_options& o, tag::number_of_threads_, long long v)
{
  CGAL_precondition(v >= 0);
  o.threads = static_cast<int>(v);
}
inline void set_parameter(Smoothing_options& o, tag::feature_edge_ratio_, double v) { o.tensor_voting.edge_ratio = v; }
inline void set_parameter(Smoothing_options& o, tag::feature_corner_ratio_, double v) { o.tensor_voting.corner_ratio = v; }
inline void set_parameter(Smoothing_options& o, tag::max_boundary_distance_, double v)
{
  CGAL_precondition(v >= 0);
  o.max_boundary_distance = v;
}

// The Boost.Parameter tags `bodt_optimize_mesh_3` knows: its parameters, and those
// of CGAL's optimizers it refuses with a reason (below).
template <class Tag>
constexpr bool is_known_tag =
    std::is_same<Tag, cgal_tag::time_limit_>::value || std::is_same<Tag, cgal_tag::max_iteration_number_>::value ||
    std::is_same<Tag, cgal_tag::convergence_>::value || std::is_same<Tag, cgal_tag::freeze_bound_>::value ||
    std::is_same<Tag, cgal_tag::do_freeze_>::value || std::is_same<Tag, cgal_tag::sliver_bound_>::value ||
    std::is_same<Tag, tag::moving_vertices_>::value || std::is_same<Tag, tag::smoothing_method_>::value ||
    std::is_same<Tag, tag::preserve_features_>::value ||
    std::is_same<Tag, tag::quality_guard_>::value || std::is_same<Tag, tag::topology_optimization_>::value ||
    std::is_same<Tag, tag::vertex_insertion_>::value || std::is_same<Tag, tag::max_vertex_insertions_>::value ||
    std::is_same<Tag, tag::edge_contraction_>::value || std::is_same<Tag, tag::max_vertex_removals_>::value ||
    std::is_same<Tag, tag::worst_cell_phase_>::value || std::is_same<Tag, tag::ear_splits_>::value ||
    std::is_same<Tag, tag::cavity_insertion_>::value ||
    std::is_same<Tag, tag::max_min_threshold_>::value || std::is_same<Tag, tag::number_of_threads_>::value ||
    std::is_same<Tag, tag::largest_angle_phase_>::value || std::is_same<Tag, tag::largest_angle_threshold_>::value ||
    std::is_same<Tag, tag::feature_edge_ratio_>::value || std::is_same<Tag, tag::feature_corner_ratio_>::value ||
    std::is_same<Tag, tag::max_boundary_distance_>::value || std::is_same<Tag, tag::progress_visitor_>::value;

// Parameters of CGAL's optimizers that B-ODT has no use for are refused at compile
// time with the reason, instead of being silently ignored.
template <class T>
void set_parameter(Smoothing_options&, cgal_tag::do_freeze_, const T&)
{
  static_assert(Always_false<T>::value,
                "bodt_optimize_mesh_3 has no do_freeze: freezing is on while freeze_bound is above 0; "
                "freeze_bound = 0 turns it off.");
}
template <class T>
void set_parameter(Smoothing_options&, cgal_tag::sliver_bound_, const T&)
{
  static_assert(Always_false<T>::value,
                "bodt_optimize_mesh_3 has no sliver_bound: it is a parameter of perturb_mesh_3 and exude_mesh_3. "
                "B-ODT improves every tetrahedron it can, with no target angle.");
}

} // namespace internal

/// The parameters of `bodt_optimize_mesh_3` in CGAL 6's chained style: each member
/// function returns a copy with one more parameter set. Start a chain with one of
/// the functions of the same names in `CGAL::parameters`.
template <class Visitor = Null_smoothing_visitor>
class Optimization_parameters
{
public:
  Optimization_parameters() = default;
  Optimization_parameters(const Smoothing_options& o, const Visitor& v) : options_(o), visitor_(v) {}

  Optimization_parameters time_limit(double seconds) const { return with(CGAL::parameters::tag::time_limit_(), seconds); }
  Optimization_parameters max_iteration_number(long long n) const
  {
    return with(CGAL::parameters::tag::max_iteration_number_(), n);
  }
  Optimization_parameters convergence(double c) const { return with(CGAL::parameters::tag::convergence_(), c); }
  Optimization_parameters freeze_bound(double f) const { return with(CGAL::parameters::tag::freeze_bound_(), f); }
  Optimization_parameters moving_vertices(Moving_vertices m) const { return with(internal::tag::moving_vertices_(), m); }
  Optimization_parameters smoothing_method(Smoothing_method m) const
  {
    return with(internal::tag::smoothing_method_(), m);
  }
  Optimization_parameters preserve_features(bool b) const { return with(internal::tag::preserve_features_(), b); }
  Optimization_parameters quality_guard(bool b) const { return with(internal::tag::quality_guard_(), b); }
  Optimization_parameters topology_optimization(bool b) const
  {
    return with(internal::tag::topology_optimization_(), b);
  }
  Optimization_parameters vertex_insertion(bool b) const { return with(internal::tag::vertex_insertion_(), b); }
  Optimization_parameters edge_contraction(bool b) const { return with(internal::tag::edge_contraction_(), b); }
  Optimization_parameters worst_cell_phase(bool b) const { return with(internal::tag::worst_cell_phase_(), b); }
  Optimization_parameters ear_splits(bool b) const { return with(internal::tag::ear_splits_(), b); }
  Optimization_parameters cavity_insertion(bool b) const { return with(internal::tag::cavity_insertion_(), b); }
  Optimization_parameters max_vertex_removals(long long n) const
  {
    return with(internal::tag::max_vertex_removals_(), n);
  }
  Optimization_parameters max_vertex_insertions(long long n) const
  {
    return with(internal::tag::max_vertex_insertions_(), n);
  }
  Optimization_parameters max_min_threshold(double s) const { return with(internal::tag::max_min_threshold_(), s); }
  Optimization_parameters largest_angle_phase(bool b) const { return with(internal::tag::largest_angle_phase_(), b); }
  Optimization_parameters largest_angle_threshold(double degrees) const
  {
    return with(internal::tag::largest_angle_threshold_(), degrees);
  }
  Optimization_parameters number_of_threads(long long n) const { return with(internal::tag::number_of_threads_(), n); }
  Optimization_parameters feature_edge_ratio(double r) const { return with(internal::tag::feature_edge_ratio_(), r); }
  Optimization_parameters feature_corner_ratio(double r) const
  {
    return with(internal::tag::feature_corner_ratio_(), r);
  }
  Optimization_parameters max_boundary_distance(double d) const
  {
    return with(internal::tag::max_boundary_distance_(), d);
  }
  template <class V>
  Optimization_parameters<V> progress_visitor(const V& v) const
  {
    return Optimization_parameters<V>(options_, v);
  }
  template <class T>
  Optimization_parameters sliver_bound(const T& v) const { return with(CGAL::parameters::tag::sliver_bound_(), v); }

  /// A copy with the parameter of Boost.Parameter tag `Tag` set: what both styles
  /// come down to.
  template <class Tag, class T>
  auto with(Tag tag, const T& v) const
  {
    if constexpr(std::is_same<Tag, internal::tag::progress_visitor_>::value)
      return progress_visitor(v);
    else
    {
      Optimization_parameters p = *this;
      internal::set_parameter(p.options_, tag, v);
      return p;
    }
  }

  const Smoothing_options& options() const { return options_; }
  const Visitor& visitor() const { return visitor_; }

private:
  Smoothing_options options_;
  Visitor visitor_;
};

namespace internal {

// A parameter name that works in both styles: `name = value` gives CGAL 5.5's
// Boost.Parameter argument, `name(value)` starts a CGAL 6 style chain.
template <class Tag>
struct Dual_keyword
{
  template <class T>
  decltype(auto) operator=(const T& value) const
  {
    return boost::parameter::keyword<Tag>::instance = value;
  }
  template <class T>
  auto operator()(const T& value) const
  {
    return Optimization_parameters<>().with(Tag(), value);
  }
};

} // namespace internal
} // namespace BODT_3

namespace parameters {

inline constexpr BODT_3::internal::Dual_keyword<tag::time_limit_> time_limit{};
inline constexpr BODT_3::internal::Dual_keyword<tag::max_iteration_number_> max_iteration_number{};
inline constexpr BODT_3::internal::Dual_keyword<tag::convergence_> convergence{};
inline constexpr BODT_3::internal::Dual_keyword<BODT_3::internal::tag::moving_vertices_> moving_vertices{};
inline constexpr BODT_3::internal::Dual_keyword<BODT_3::internal::tag::smoothing_method_> smoothing_method{};
inline constexpr BODT_3::internal::Dual_keyword<BODT_3::internal::tag::preserve_features_> preserve_features{};
inline constexpr BODT_3::internal::Dual_keyword<BODT_3::internal::tag::quality_guard_> quality_guard{};
inline constexpr BODT_3::internal::Dual_keyword<BODT_3::internal::tag::topology_optimization_> topology_optimization{};
inline constexpr BODT_3::internal::Dual_keyword<BODT_3::internal::tag::vertex_insertion_> vertex_insertion{};
inline constexpr BODT_3::internal::Dual_keyword<BODT_3::internal::tag::max_vertex_insertions_> max_vertex_insertions{};
inline constexpr BODT_3::internal::Dual_keyword<BODT_3::internal::tag::edge_contraction_> edge_contraction{};
inline constexpr BODT_3::internal::Dual_keyword<BODT_3::internal::tag::worst_cell_phase_> worst_cell_phase{};
inline constexpr BODT_3::internal::Dual_keyword<BODT_3::internal::tag::ear_splits_> ear_splits{};
inline constexpr BODT_3::internal::Dual_keyword<BODT_3::internal::tag::cavity_insertion_> cavity_insertion{};
inline constexpr BODT_3::internal::Dual_keyword<BODT_3::internal::tag::max_vertex_removals_> max_vertex_removals{};
inline constexpr BODT_3::internal::Dual_keyword<BODT_3::internal::tag::max_min_threshold_> max_min_threshold{};
inline constexpr BODT_3::internal::Dual_keyword<BODT_3::internal::tag::largest_angle_phase_> largest_angle_phase{};
inline constexpr BODT_3::internal::Dual_keyword<BODT_3::internal::tag::largest_angle_threshold_> largest_angle_threshold{};
inline constexpr BODT_3::internal::Dual_keyword<BODT_3::internal::tag::number_of_threads_> number_of_threads{};
inline constexpr BODT_3::internal::Dual_keyword<BODT_3::internal::tag::feature_edge_ratio_> feature_edge_ratio{};
inline constexpr BODT_3::internal::Dual_keyword<BODT_3::internal::tag::feature_corner_ratio_> feature_corner_ratio{};
inline constexpr BODT_3::internal::Dual_keyword<BODT_3::internal::tag::max_boundary_distance_> max_boundary_distance{};
inline constexpr BODT_3::internal::Dual_keyword<BODT_3::internal::tag::progress_visitor_> progress_visitor{};

} // namespace parameters
} // namespace CGAL

#endif // CGAL_BODT_3_OPTIMIZATION_PARAMETERS_H
