// CGAL::bodt_optimize_mesh_3's parameters: both of CGAL's styles reach the same
// options and give the same mesh, the domain of odt_optimize_mesh_3's signature is
// accepted, CGAL's own optimizers still take the keywords this package redeclares,
// the return code prints by name, and max_iteration_number = 0 terminates.
// (Parameters that must not compile are checked by the parameters_refused_* tests.)
#include <CGAL/BODT_3/Return_code.h>
#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Labeled_mesh_domain_3.h>
#include <CGAL/bodt_optimize_mesh_3.h>
#include <CGAL/point_generators_3.h>

#include <gtest/gtest.h>

#include <iterator>
#include <sstream>
#include <type_traits>
#include <vector>

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Delaunay = CGAL::Delaunay_triangulation_3<K>;
namespace BODT = CGAL::BODT_3;
namespace params = CGAL::parameters;

namespace {

// The paper's random sphere, smaller: a Delaunay triangulation of random points.
Delaunay random_ball(int n = 300)
{
  CGAL::Random random(3);
  CGAL::Random_points_in_sphere_3<K::Point_3> generator(1.0, random);
  std::vector<K::Point_3> points;
  std::copy_n(generator, n, std::back_inserter(points));
  return Delaunay(points.begin(), points.end());
}

std::vector<K::Point_3> points_of(const Delaunay& tr)
{
  std::vector<K::Point_3> p;
  for(auto v = tr.finite_vertices_begin(); v != tr.finite_vertices_end(); ++v) p.push_back(v->point());
  return p;
}

struct Counting_visitor
{
  int* classifications;
  int* iterations;
  void after_classification(const BODT::Smoothing_result&) { ++*classifications; }
  void after_iteration(const BODT::Iteration_stats&) { ++*iterations; }
};

} // namespace

// The chain's members and the keywords set the fields they name.
TEST(Parameters, ChainSetsEveryOption)
{
  const auto p = params::max_iteration_number(7)
                     .time_limit(3.5)
                     .convergence(0.01)
                     .freeze_bound(0.002)
                     .max_boundary_distance(0.004)
                     .moving_vertices(BODT::Moving_vertices::NONE)
                     .preserve_features(false)
                     .quality_guard(false)
                     .topology_optimization(false)
                     .vertex_insertion(false)
                     .max_vertex_insertions(12)
                     .edge_contraction(true)
                     .max_vertex_removals(9)
                     .worst_cell_phase(false)
                     .max_min_threshold(0.25)
                     .smoothing_method(BODT::Smoothing_method::NODT)
                     .feature_edge_ratio(0.2)
                     .feature_corner_ratio(0.3);
  const BODT::Smoothing_options& o = p.options();
  EXPECT_EQ(o.max_iteration_number, 7u);
  EXPECT_EQ(o.time_limit, 3.5);
  EXPECT_EQ(o.convergence, 0.01);
  EXPECT_EQ(o.freeze_bound, 0.002);
  EXPECT_EQ(o.max_boundary_distance, 0.004);
  EXPECT_EQ(o.moving_vertices, BODT::Moving_vertices::NONE);
  EXPECT_FALSE(o.preserve_features);
  EXPECT_FALSE(o.quality_guard);
  EXPECT_FALSE(o.topology_optimization);
  EXPECT_FALSE(o.vertex_insertion);
  EXPECT_EQ(o.max_vertex_insertions, 12);
  EXPECT_TRUE(o.edge_contraction);
  EXPECT_EQ(o.max_vertex_removals, 9);
  EXPECT_FALSE(o.worst_cell_phase);
  EXPECT_EQ(o.max_min_threshold, 0.25);
  EXPECT_EQ(o.smoothing_method, BODT::Smoothing_method::NODT);
  EXPECT_EQ(o.tensor_voting.edge_ratio, 0.2);
  EXPECT_EQ(o.tensor_voting.corner_ratio, 0.3);

  const BODT::Smoothing_options defaults;
  const BODT::Smoothing_options d = params::time_limit(1).options();
  EXPECT_TRUE(d.topology_optimization);
  EXPECT_TRUE(d.vertex_insertion);
  EXPECT_EQ(d.max_vertex_insertions, -1);
  EXPECT_FALSE(d.edge_contraction);
  EXPECT_EQ(d.max_vertex_removals, -1);
  EXPECT_TRUE(d.worst_cell_phase);
  EXPECT_TRUE(d.cavity_insertion);
  EXPECT_EQ(d.max_min_threshold, defaults.max_min_threshold);
  EXPECT_EQ(d.smoothing_method, BODT::Smoothing_method::BODT);
  EXPECT_EQ(d.max_iteration_number, defaults.max_iteration_number);
}

// The keywords this package declares in CGAL::parameters give, when assigned,
// exactly the Boost.Parameter argument CGAL's own keywords give, so that CGAL's
// optimizers (odt_optimize_mesh_3, ...) take them as before.
TEST(Parameters, AssignedKeywordsAreCgalsBoostArguments)
{
  using Ours = decltype(params::time_limit = 10.0);
  using Cgals = decltype(boost::parameter::keyword<params::tag::time_limit_>::instance = 10.0);
  EXPECT_TRUE((std::is_same<Ours, Cgals>::value));
  using Ours_n = decltype(params::max_iteration_number = 5);
  using Cgals_n = decltype(boost::parameter::keyword<params::tag::max_iteration_number_>::instance = 5);
  EXPECT_TRUE((std::is_same<Ours_n, Cgals_n>::value));
  const double limit = 10;
  EXPECT_EQ((params::time_limit = limit).get_value(), 10.0);
}

TEST(Parameters, BothStylesGiveTheSameMesh)
{
  Delaunay a = random_ball(), b = random_ball(), c = random_ball();
  const auto code_a = CGAL::bodt_optimize_mesh_3(a, params::max_iteration_number = 4, params::quality_guard = false);
  const auto code_b = CGAL::bodt_optimize_mesh_3(b, params::max_iteration_number(4).quality_guard(false));
  CGAL::bodt_optimize_mesh_3(c, params::max_iteration_number = 4);
  EXPECT_EQ(code_a, CGAL::MAX_ITERATION_NUMBER_REACHED);
  EXPECT_EQ(code_b, code_a);
  EXPECT_EQ(points_of(a), points_of(b));
  EXPECT_NE(points_of(a), points_of(c)) << "quality_guard did not reach the smoother";
}

// freeze_bound keeps every vertex whose move is shorter than that fraction of its
// local size where it is: with a bound no move reaches, the sweeps move nothing;
// with 0, they move vertices; both styles set it.
TEST(Parameters, FreezeBoundKeepsShortMovesOut)
{
  const Delaunay input = random_ball();
  auto sweeps_only = [](double freeze) {
    return params::max_iteration_number(3)
        .freeze_bound(freeze)
        .topology_optimization(false)
        .vertex_insertion(false)
        .max_min_threshold(0)
        .largest_angle_phase(false);
  };
  Delaunay frozen = input, free = input, keyword = input;
  const auto code = CGAL::bodt_optimize_mesh_3(frozen, sweeps_only(1e9));
  CGAL::bodt_optimize_mesh_3(free, sweeps_only(0));
  EXPECT_EQ(code, CGAL::CANT_IMPROVE_ANYMORE);
  EXPECT_EQ(points_of(frozen), points_of(input));
  EXPECT_NE(points_of(free), points_of(input));
  CGAL::bodt_optimize_mesh_3(keyword, params::max_iteration_number = 3, params::freeze_bound = 1e9,
                             params::topology_optimization = false, params::vertex_insertion = false,
                             params::max_min_threshold = 0, params::largest_angle_phase = false);
  EXPECT_EQ(points_of(keyword), points_of(input));
}

TEST(Parameters, VisitorIsCalledInBothStyles)
{
  int classifications = 0, iterations = 0;
  Delaunay a = random_ball();
  // The main phase alone: with the largest-angle phases, up to three times as many
  // (pipeline/smoothing.cpp, Pipeline.LargestAnglePhaseLowersTheLargestAngle).
  CGAL::bodt_optimize_mesh_3(a, params::max_iteration_number = 3, params::largest_angle_phase = false,
                             params::progress_visitor = Counting_visitor{&classifications, &iterations});
  EXPECT_EQ(classifications, 1);
  EXPECT_EQ(iterations, 3);
  Delaunay b = random_ball();
  CGAL::bodt_optimize_mesh_3(b, params::progress_visitor(Counting_visitor{&classifications, &iterations})
                                    .max_iteration_number(2)
                                    .largest_angle_phase(false));
  EXPECT_EQ(classifications, 2);
  EXPECT_EQ(iterations, 5);
}

// odt_optimize_mesh_3(c3t3, domain, parameters...) callers can change the name
// alone: the domain is taken (and not used), and the parameters still count.
TEST(Parameters, DomainOfOdtSignatureIsAccepted)
{
  using Domain = CGAL::Labeled_mesh_domain_3<K>;
  const Domain domain = Domain::create_implicit_mesh_domain(
      [](const K::Point_3& p) { return p.x() * p.x() + p.y() * p.y() + p.z() * p.z() - 1; },
      K::Sphere_3(CGAL::ORIGIN, 4.));
  Delaunay a = random_ball(), b = random_ball();
  CGAL::bodt_optimize_mesh_3(a, domain, params::max_iteration_number = 3);
  CGAL::bodt_optimize_mesh_3(b, params::max_iteration_number = 3);
  EXPECT_EQ(points_of(a), points_of(b));
  Delaunay c = random_ball();
  int classifications = 0, iterations = 0;
  CGAL::bodt_optimize_mesh_3(c, domain, params::max_iteration_number(2).largest_angle_phase(false).progress_visitor(
                                             Counting_visitor{&classifications, &iterations}));
  EXPECT_EQ(iterations, 2);
  // CGAL 6's way of saying "no parameter".
  Delaunay d = random_ball(), e = random_ball();
  CGAL::bodt_optimize_mesh_3(d, domain, params::default_values());
  CGAL::bodt_optimize_mesh_3(e);
  EXPECT_EQ(points_of(d), points_of(e));
}

TEST(Parameters, ReturnCodePrintsByName)
{
  std::ostringstream out;
  out << CGAL::MAX_ITERATION_NUMBER_REACHED << " " << CGAL::CANT_IMPROVE_ANYMORE << " " << CGAL::TIME_LIMIT_REACHED
      << " " << CGAL::CONVERGENCE_REACHED;
  EXPECT_EQ(out.str(), "MAX_ITERATION_NUMBER_REACHED CANT_IMPROVE_ANYMORE TIME_LIMIT_REACHED CONVERGENCE_REACHED");
  EXPECT_STREQ(BODT::to_string(CGAL::MESH_OPTIMIZATION_UNKNOWN_ERROR), "MESH_OPTIMIZATION_UNKNOWN_ERROR");
}

// 0 iterations means "until nothing changes", with CGAL's cap of 1000 sweeps.
// Unguarded ODT keeps moving the vertices of a random ball by tiny amounts, which
// used to loop forever; it now stops at the cap. Guarded, it stops when a sweep
// moves nothing.
TEST(Parameters, ZeroIterationsTerminates)
{
  Delaunay unguarded = random_ball(200), guarded = random_ball(200);
  int classifications = 0, iterations = 0;
  // A convergence no run reaches, and no vertex frozen: the cap ends it.
  const auto code = CGAL::bodt_optimize_mesh_3(
      unguarded, params::max_iteration_number(0).convergence(1e-300).freeze_bound(0).quality_guard(false)
                     .largest_angle_phase(false).progress_visitor(Counting_visitor{&classifications, &iterations}));
  EXPECT_EQ(iterations, 1000);
  EXPECT_EQ(code, CGAL::MAX_ITERATION_NUMBER_REACHED);
  iterations = 0;
  // No convergence given: CGAL's default one ends it long before the cap.
  const auto guarded_code = CGAL::bodt_optimize_mesh_3(
      guarded, params::max_iteration_number(0).progress_visitor(Counting_visitor{&classifications, &iterations}));
  EXPECT_LT(iterations, 1000);
  EXPECT_TRUE(guarded_code == CGAL::CONVERGENCE_REACHED || guarded_code == CGAL::CANT_IMPROVE_ANYMORE);
}
