// Vertex classification: tensor voting (eq. 11) on known geometry, the rules for
// meshes with feature information, non-manifold points, and the
// volume-preserving choice of move at interfaces and junctions.
#include <CGAL/BODT_3/Tensor_voting.h>
#include <CGAL/BODT_3/Tet_mesh.h>
#include <CGAL/BODT_3/Vertex_classification.h>
#include <CGAL/BODT_3/Volume_preserving_move.h>
#include <CGAL/BODT_3/smooth.h>

#include <CGAL/Random.h>

#include "test_support.h"

#include <gtest/gtest.h>

#include <cmath>

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = K::Point_3;
using Vector = K::Vector_3;
namespace BODT = CGAL::BODT_3;

namespace {

BODT::Smoothing_mesh<K> smoothing_mesh(const BODT::Tet_mesh& m)
{
  BODT::Smoothing_mesh<K> s;
  s.points = m.points;
  s.cells = m.tets;
  s.in_mesh.assign(m.tets.size(), 1);
  s.subdomain = m.tet_labels;
  s.build_incidences();
  return s;
}

int count_on_box(const BODT::Tet_mesh& m, int v, int n)
{
  int c = 0;
  for(double x : {m.points[v].x(), m.points[v].y(), m.points[v].z()})
    if(x == 0 || x == n) ++c;
  return c;
}

// The boundary star of x0 = origin on the plane z = 0 (ring counterclockwise
// seen from above) bent along the x axis by `fold` degrees: a straight edge.
BODT::Vertex_star<K> folded_star(double fold_deg, int fan_left, int fan_right)
{
  BODT::Vertex_star<K> star;
  star.x0 = Point(0, 0, 0);
  const double f = fold_deg * CGAL_PI / 180;
  std::vector<Point> ring;
  // Half-plane y >= 0 stays flat, triangulated into fan_left triangles.
  for(int i = 0; i <= fan_left; ++i)
  {
    const double a = CGAL_PI * i / fan_left;
    ring.emplace_back(std::cos(a), std::sin(a), 0);
  }
  // Half-plane y <= 0 is turned about the x axis by f.
  for(int i = 1; i < fan_right; ++i)
  {
    const double a = CGAL_PI + CGAL_PI * i / fan_right;
    ring.emplace_back(std::cos(a), std::sin(a) * std::cos(f), std::sin(a) * std::sin(f));
  }
  for(std::size_t i = 0; i < ring.size(); ++i) star.boundary.push_back({ring[i], ring[(i + 1) % ring.size()]});
  return star;
}

} // namespace

TEST(TensorVoting, FlatStarIsSurface)
{
  const auto vote = BODT::tensor_vote(folded_star(0, 3, 5), BODT::Tensor_voting_options());
  EXPECT_EQ(vote.kind, BODT::Voted_kind::surface);
}

TEST(TensorVoting, SharpEdgeIsFeatureAlongTheEdge)
{
  for(double fold : {30.0, 60.0, 90.0, 120.0})
  {
    const auto vote = BODT::tensor_vote(folded_star(fold, 2, 7), BODT::Tensor_voting_options());
    EXPECT_EQ(vote.kind, BODT::Voted_kind::feature) << fold;
    EXPECT_NEAR(std::abs(vote.direction.x()), 1.0, 1e-12) << fold;
  }
}

TEST(TensorVoting, AngleWeightsMakeTheRatioDependOnTheDihedralAngleOnly)
{
  // Two triangulations of the same fold: mu_1 / mu_0 = tan^2(fold / 2) for both.
  BODT::Tensor_voting_options opt;
  for(double fold : {20.0, 40.0})
    for(auto fans : {std::make_pair(1 + 1, 9), std::make_pair(6, 3)})
    {
      const double expected = std::pow(std::tan(fold * CGAL_PI / 360), 2);
      opt.edge_ratio = expected * 0.999;
      EXPECT_EQ(BODT::tensor_vote(folded_star(fold, fans.first, fans.second), opt).kind, BODT::Voted_kind::feature);
      opt.edge_ratio = expected * 1.001;
      EXPECT_EQ(BODT::tensor_vote(folded_star(fold, fans.first, fans.second), opt).kind, BODT::Voted_kind::surface);
    }
}

TEST(Classification, BoxCornersEdgesFacesByTensorVoting)
{
  const int n = 3;
  const BODT::Tet_mesh m = bodt_test::cube_grid(n, [](int, int, int) { return 1; });
  const auto s = smoothing_mesh(m);
  const auto cls = BODT::classify_vertices(s, BODT::Feature_hints(), BODT::Classification_options());
  EXPECT_TRUE(cls.used_tensor_voting);
  for(std::size_t v = 0; v < m.points.size(); ++v)
  {
    const int on = count_on_box(m, static_cast<int>(v), n);
    const BODT::Vertex_kind expected = on == 0   ? BODT::Vertex_kind::interior
                                       : on == 1 ? BODT::Vertex_kind::surface
                                       : on == 2 ? BODT::Vertex_kind::feature
                                                 : BODT::Vertex_kind::fixed;
    EXPECT_EQ(cls.kind[v], expected) << "vertex " << v << " " << m.points[v];
  }
}

TEST(Classification, FeatureHintsWinAndInteriorOnlyFixesTheBoundary)
{
  const int n = 2;
  const BODT::Tet_mesh m = bodt_test::cube_grid(n, [](int, int, int) { return 1; });
  const auto s = smoothing_mesh(m);
  // One feature edge chain along the bottom front edge: (0,0,0)-(1,0,0)-(2,0,0).
  BODT::Feature_hints hints;
  hints.feature_edges = {{0, 1}, {1, 2}};
  const auto cls = BODT::classify_vertices(s, hints, BODT::Classification_options());
  EXPECT_FALSE(cls.used_tensor_voting);
  EXPECT_EQ(cls.kind[0], BODT::Vertex_kind::fixed);     // one feature edge: a corner
  EXPECT_EQ(cls.kind[1], BODT::Vertex_kind::feature);   // two: on the curve
  EXPECT_EQ(cls.kind[2], BODT::Vertex_kind::fixed);
  EXPECT_EQ(cls.kind[3], BODT::Vertex_kind::surface);   // a box corner the hints do not mention

  BODT::Classification_options interior_only;
  interior_only.move_boundary = false;
  const auto odt = BODT::classify_vertices(s, BODT::Feature_hints(), interior_only);
  for(std::size_t v = 0; v < m.points.size(); ++v)
    EXPECT_EQ(odt.kind[v], count_on_box(m, static_cast<int>(v), n) == 0 ? BODT::Vertex_kind::interior
                                                                        : BODT::Vertex_kind::fixed);
}

TEST(Classification, PinchedVertexIsFixed)
{
  // Two single cubes of tetrahedra sharing only the vertex (1,1,1).
  BODT::Tet_mesh m = bodt_test::cube_grid(2, [](int i, int j, int k) { return (i == j && j == k) ? 1 : 0; });
  const auto s = [&] {
    BODT::Smoothing_mesh<K> sm;
    sm.points = m.points;
    sm.cells = m.tets;
    for(int l : m.tet_labels) sm.in_mesh.push_back(l != 0);
    sm.subdomain = m.tet_labels;
    sm.build_incidences();
    return sm;
  }();
  const auto cls = BODT::classify_vertices(s, BODT::Feature_hints(), BODT::Classification_options());
  const int centre = (1 * 3 + 1) * 3 + 1;
  EXPECT_EQ(cls.kind[centre], BODT::Vertex_kind::fixed);
  EXPECT_EQ(cls.non_manifold, 1u);
}

TEST(Classification, InterfaceAndJunctionVerticesKeepEverySubdomainVolume)
{
  // A 4x4x4 box split at x = 2 into subdomains 1 and 2; interior points jittered.
  const int n = 4;
  BODT::Tet_mesh m = bodt_test::cube_grid(n, [](int i, int, int) { return i < 2 ? 1 : 2; });
  CGAL::Random rng(3);
  for(auto& p : m.points)
  {
    const bool inside = p.x() > 0 && p.x() < n && p.y() > 0 && p.y() < n && p.z() > 0 && p.z() < n;
    if(inside)
      p = Point(p.x() == 2 ? p.x() : p.x() + rng.get_double(-0.2, 0.2), p.y() + rng.get_double(-0.2, 0.2),
                p.z() + rng.get_double(-0.2, 0.2));
  }
  const auto before = BODT::mesh_quality(m);
  BODT::Smoothing_options opt;
  opt.quality_guard = false;
  const auto result = BODT::smooth(m, opt);
  const auto after = BODT::mesh_quality(m);
  EXPECT_GT(result.moved_vertices, 0u);
  EXPECT_EQ(after.inverted_tets, 0u);
  for(int label : {1, 2})
    EXPECT_NEAR(after.volume_per_subdomain.at(label), before.volume_per_subdomain.at(label), 1e-12 * 32);
  // Interface vertices stay on the plane x = 2; junction vertices (x = 2 on the box
  // boundary) stay on their line.
  for(const auto& p : m.points)
  {
    if(std::abs(p.x() - 2) < 0.5)
    {
      EXPECT_NEAR(p.x(), 2.0, 1e-12);
    }
  }
}
