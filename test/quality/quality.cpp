// Quality measures: dihedral angles against CGAL's independent
// approximate_dihedral_angle, counts, volumes, exact inversion test, and the
// real meshes of ../shared/data when present; the measures the flips and the
// guards use (tet_quality.h) against a brute-force computation, and the bounds
// on the extreme angles.
#include "delaunay_cells.h"
#include "report/json_report.h"

#include <CGAL/BODT_3/IO/medit.h>
#include <CGAL/BODT_3/boundary_distance.h>
#include <CGAL/BODT_3/mesh_quality.h>
#include <CGAL/BODT_3/internal/Quality/dihedral_angles.h>
#include <CGAL/BODT_3/internal/Quality/tet_quality.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Kernel/global_functions.h>
#include <CGAL/Random.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <map>
#include <random>
#include <sstream>
#include <vector>

namespace BODT = CGAL::BODT_3;
using CGAL::BODT_3::Tet_mesh;
using Point = Tet_mesh::Point;
using bodt_test::Delaunay_cells;

namespace {

constexpr double kPi = 3.14159265358979323846;

// The minimum sine of the six dihedral angles, from the angles themselves.
double brute_min_sine(const Point& a, const Point& b, const Point& c, const Point& d)
{
  double q = 2;
  for(double deg : BODT::internal::dihedral_angles(a, b, c, d)) q = std::min(q, std::sin(deg * kPi / 180));
  return q;
}

// Dihedral angle at edge (a, b) of tetrahedron (a, b, c, d), from CGAL.
double cgal_angle(const Point& a, const Point& b, const Point& c, const Point& d)
{
  return std::abs(CGAL::approximate_dihedral_angle(a, b, c, d));
}

std::pair<double, double> independent_min_max(const Point& p0, const Point& p1, const Point& p2, const Point& p3)
{
  const Point* p[4] = {&p0, &p1, &p2, &p3};
  double lo = 180, hi = 0;
  for(int i = 0; i < 4; ++i)
    for(int j = i + 1; j < 4; ++j)
    {
      int k = 0;
      while(k == i || k == j) ++k;
      int l = 6 - i - j - k;
      const double a = cgal_angle(*p[i], *p[j], *p[k], *p[l]);
      lo = std::min(lo, a);
      hi = std::max(hi, a);
    }
  return {lo, hi};
}

Tet_mesh one_tet(const Point& a, const Point& b, const Point& c, const Point& d, int label = 1)
{
  Tet_mesh m;
  m.points = {a, b, c, d};
  m.vertex_refs = {0, 0, 0, 0};
  m.tets = {{0, 1, 2, 3}};
  m.tet_labels = {label};
  return m;
}

} // namespace

TEST(DihedralAngles, RegularTetrahedron)
{
  const auto a = CGAL::BODT_3::internal::dihedral_angles(Point(1, 1, 1), Point(1, -1, -1), Point(-1, 1, -1), Point(-1, -1, 1));
  const double expected = std::acos(1.0 / 3.0) * 180.0 / CGAL_PI;   // 70.5288 degrees
  for(double x : a) EXPECT_NEAR(x, expected, 1e-12);
  EXPECT_NEAR(CGAL::BODT_3::internal::radius_ratio(Point(1, 1, 1), Point(1, -1, -1), Point(-1, 1, -1), Point(-1, -1, 1)), 1.0,
              1e-12);
}

TEST(DihedralAngles, AgreeWithCGALOnRandomTetrahedra)
{
  CGAL::Random rng(7);
  for(int n = 0; n < 2000; ++n)
  {
    Point p[4];
    for(auto& q : p) q = Point(rng.get_double(-1, 1), rng.get_double(-1, 1), rng.get_double(-1, 1));
    if(CGAL::orientation(p[0], p[1], p[2], p[3]) == CGAL::COPLANAR) continue;
    const auto mine = CGAL::BODT_3::internal::min_max_dihedral_angle(p[0], p[1], p[2], p[3]);
    const auto ref = independent_min_max(p[0], p[1], p[2], p[3]);
    EXPECT_NEAR(mine.first, ref.first, 1e-7);
    EXPECT_NEAR(mine.second, ref.second, 1e-7);
  }
}

TEST(DihedralAngles, RightCornerTetrahedron)
{
  // Three right angles at the edges through the origin, and arccos(1/sqrt(3)) on the others.
  const auto a = CGAL::BODT_3::internal::dihedral_angles(Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0), Point(0, 0, 1));
  EXPECT_NEAR(a[0], 90, 1e-12);
  EXPECT_NEAR(a[1], 90, 1e-12);
  EXPECT_NEAR(a[2], 90, 1e-12);
  const double other = std::acos(1.0 / std::sqrt(3.0)) * 180 / CGAL_PI;
  EXPECT_NEAR(a[3], other, 1e-12);
  EXPECT_NEAR(a[4], other, 1e-12);
  EXPECT_NEAR(a[5], other, 1e-12);
}

TEST(MeshQuality, CountsVolumeHistogramAndInversion)
{
  Tet_mesh m;
  m.points = {Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0), Point(0, 0, 1), Point(1, 1, 1), Point(0.5, 0.5, 1e-3)};
  m.vertex_refs.assign(6, 0);
  m.tets = {{0, 1, 2, 3}, {1, 2, 3, 4}, {0, 2, 1, 5}};
  m.tet_labels = {1, 2, 2};
  const auto r = CGAL::BODT_3::mesh_quality(m);
  EXPECT_EQ(r.num_tets, 3u);
  EXPECT_EQ(r.num_vertices, 6u);
  EXPECT_NEAR(r.volume_per_subdomain.at(1), 1.0 / 6.0, 1e-15);
  // Signed volumes: the third tetrahedron counts negatively.
  EXPECT_NEAR(r.volume_per_subdomain.at(2), 1.0 / 3.0 - 0.5 * 1e-3 / 3.0, 1e-15);
  std::size_t total = 0;
  for(auto c : r.histogram) total += c;
  EXPECT_EQ(total, 18u);
  // (0, 2, 1, 5) is negatively oriented (5 lies above the z = 0 face seen from its other side).
  EXPECT_EQ(CGAL::orientation(m.points[0], m.points[2], m.points[1], m.points[5]), CGAL::NEGATIVE);
  EXPECT_EQ(r.inverted_tets, 1u);
  EXPECT_EQ(r.tets_below_small, 1u);   // the flat-ish third tetrahedron
  EXPECT_NEAR(r.volume, CGAL::volume(m.points[0], m.points[1], m.points[2], m.points[3]) +
                            CGAL::volume(m.points[1], m.points[2], m.points[3], m.points[4]) +
                            CGAL::volume(m.points[0], m.points[2], m.points[1], m.points[5]),
              1e-15);
}

// A tetrahedron with one vertex 4e10 away (found by fuzzing): computed from that
// vertex, a determinant's error is ~1e-16 times the product of the three edge lengths
// (1e15 against a volume of 4e10). Every ordering of the vertices gives the exact
// volume to 1e-12 with its orientation's sign.
TEST(MeshQuality, VolumeOfATetrahedronWithAFarVertexIsAccurate)
{
  using EK = CGAL::Exact_predicates_exact_constructions_kernel;
  const Point p[4] = {Point(36776269782.557625, -5344627546.645686, -8031025811.945719),
                      Point(1.868308083149307, 0.5024785025102955, 0.43432769349863964), Point(1, -2, 11.001),
                      Point(2.033333333133333, 0.99, 1.002)};
  auto exact = [&](int a, int b, int c, int d) {
    auto e = [&](int i) { return EK::Point_3(p[i].x(), p[i].y(), p[i].z()); };
    return CGAL::to_double(CGAL::volume(e(a), e(b), e(c), e(d)));
  };
  int order[4] = {0, 1, 2, 3};
  do
  {
    const double want = exact(order[0], order[1], order[2], order[3]);
    const double got = CGAL::BODT_3::internal::tet_volume(p[order[0]], p[order[1]], p[order[2]], p[order[3]]);
    EXPECT_NEAR(got, want, 1e-12 * std::abs(want)) << order[0] << order[1] << order[2] << order[3];
  } while(std::next_permutation(order, order + 4));

  // The quality measure of every decision uses that volume: it must not depend on
  // which vertex comes first (it did, and flips then chose by a wrong measure).
  const double sine = CGAL::BODT_3::internal::min_dihedral_sine(p[0], p[1], p[2], p[3]);
  for(const auto& o : {std::array<int, 4>{1, 0, 3, 2}, std::array<int, 4>{2, 3, 0, 1}, std::array<int, 4>{3, 2, 1, 0}})
    EXPECT_NEAR(CGAL::BODT_3::internal::min_dihedral_sine(p[o[0]], p[o[1]], p[o[2]], p[o[3]]), sine, 1e-9 * sine);
}

TEST(MeshQuality, FlatTetrahedronIsCountedAsInverted)
{
  const auto m = one_tet(Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0), Point(1, 1, 0));
  const auto r = CGAL::BODT_3::mesh_quality(m);
  EXPECT_EQ(r.inverted_tets, 1u);
  EXPECT_EQ(r.min_dihedral_deg, 0.0);
  EXPECT_EQ(r.max_dihedral_deg, 180.0);
}

TEST(MeshQuality, LabelZeroIsOutsideUnlessAllAreZero)
{
  Tet_mesh m = one_tet(Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0), Point(0, 0, 1), 0);
  EXPECT_EQ(CGAL::BODT_3::mesh_quality(m).num_tets, 1u);
  m.points.push_back(Point(1, 1, 1));
  m.vertex_refs.push_back(0);
  m.tets.push_back({1, 2, 3, 4});
  m.tet_labels.push_back(3);
  const auto r = CGAL::BODT_3::mesh_quality(m);
  EXPECT_EQ(r.num_tets, 1u);
  EXPECT_EQ(r.num_vertices, 4u);
  EXPECT_EQ(r.volume_per_subdomain.count(0), 0u);
  EXPECT_NEAR(r.volume, 1.0 / 3.0, 1e-15);
}

TEST(MeshQuality, JsonHasTheDocumentedKeys)
{
  const auto r = CGAL::BODT_3::mesh_quality(one_tet(Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0), Point(0, 0, 1)));
  const nlohmann::json j = nlohmann::json::parse(CGAL::BODT_3::to_json(r));
  EXPECT_EQ(j.at("num_vertices"), 4);
  EXPECT_EQ(j.at("num_tets"), 1);
  EXPECT_EQ(j.at("tets_below_10deg"), 0);
  EXPECT_EQ(j.at("tets_above_170deg"), 0);
  EXPECT_EQ(j.at("inverted_tets"), 0);
  EXPECT_EQ(j.at("bad_tets").at("interior"), 0);
  EXPECT_DOUBLE_EQ(j.at("min_dihedral_deg").get<double>(), r.min_dihedral_deg);
  EXPECT_DOUBLE_EQ(j.at("volume").get<double>(), r.volume);
  EXPECT_DOUBLE_EQ(j.at("min_boundary_triangle_angle_deg").get<double>(), 45);
  EXPECT_EQ(j.at("histogram").at("counts").size(), r.histogram.size());
}

// The smallest angle of the boundary and interface triangles, against the law of
// cosines on the faces known to be there: a tetrahedron's four faces; two
// tetrahedra sharing a thin face, which counts only between different labels;
// the convex hull of a Delaunay triangulation, measured as a triangulation and as
// a Tet_mesh of one label.
TEST(MeshQuality, SmallestBoundaryTriangleAngle)
{
  auto by_cosines = [](const Point& a, const Point& b, const Point& c) {
    const double x = std::sqrt(CGAL::squared_distance(b, c)), y = std::sqrt(CGAL::squared_distance(c, a)),
                 z = std::sqrt(CGAL::squared_distance(a, b));
    const double A = std::acos((y * y + z * z - x * x) / (2 * y * z));
    const double B = std::acos((z * z + x * x - y * y) / (2 * z * x));
    return std::min({A, B, kPi - A - B}) * 180 / kPi;
  };
  const auto single = BODT::mesh_quality(one_tet(Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0), Point(0, 0, 1)));
  EXPECT_NEAR(single.min_boundary_triangle_angle_deg, 45, 1e-12);

  Tet_mesh m;
  m.points = {Point(0, 0, 0), Point(1, 0, 0), Point(0.5, 0.05, 0), Point(0.4, 0.3, 1), Point(0.6, 0.2, -1)};
  m.vertex_refs.assign(5, 0);
  m.tets = {{0, 1, 2, 3}, {0, 2, 1, 4}};
  const std::array<std::array<int, 3>, 6> outer = {{{1, 2, 3}, {0, 2, 3}, {0, 1, 3}, {2, 1, 4}, {0, 1, 4}, {0, 2, 4}}};
  double expected = 180;
  for(const auto& f : outer) expected = std::min(expected, by_cosines(m.points[f[0]], m.points[f[1]], m.points[f[2]]));
  const double thin = by_cosines(m.points[0], m.points[1], m.points[2]);
  ASSERT_LT(thin, expected);
  m.tet_labels = {1, 1};
  EXPECT_NEAR(BODT::mesh_quality(m).min_boundary_triangle_angle_deg, expected, 1e-9);
  m.tet_labels = {1, 2};
  EXPECT_NEAR(BODT::mesh_quality(m).min_boundary_triangle_angle_deg, thin, 1e-9);

  const Delaunay_cells d(300);
  const CGAL::Delaunay_triangulation_3<CGAL::Epick> dt(d.points.begin(), d.points.end());
  double hull = 180;
  for(auto c = dt.all_cells_begin(); c != dt.all_cells_end(); ++c)
  {
    if(!dt.is_infinite(c)) continue;
    const int i = c->index(dt.infinite_vertex());
    hull = std::min(hull, by_cosines(c->vertex((i + 1) % 4)->point(), c->vertex((i + 2) % 4)->point(),
                                     c->vertex((i + 3) % 4)->point()));
  }
  EXPECT_NEAR(BODT::mesh_quality(dt).min_boundary_triangle_angle_deg, hull, 1e-9);
  Tet_mesh cells;
  cells.points = d.points;
  cells.vertex_refs.assign(d.points.size(), 0);
  cells.tets = d.cells;
  cells.tet_labels.assign(d.cells.size(), 1);
  EXPECT_NEAR(BODT::mesh_quality(cells).min_boundary_triangle_angle_deg, hull, 1e-9);
}

// A value that is not finite is written as null, so the text stays JSON.
TEST(MeshQuality, JsonWritesNullForValuesThatAreNotFinite)
{
  auto r = CGAL::BODT_3::mesh_quality(one_tet(Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0), Point(0, 0, 1)));
  r.min_dihedral_deg = std::nan("");
  r.volume = HUGE_VAL;
  const std::string text = CGAL::BODT_3::to_json(r);
  const nlohmann::json j = nlohmann::json::parse(text);
  EXPECT_TRUE(j.at("min_dihedral_deg").is_null()) << text;
  EXPECT_TRUE(j.at("volume").is_null()) << text;
  EXPECT_EQ(text.find("nan"), std::string::npos);
  EXPECT_EQ(text.find("inf"), std::string::npos);
}

// Every real mesh: our min/max dihedral angles agree with CGAL's independent
// per-edge computation to 0.01 degree, and no tetrahedron is inverted.
TEST(MeshQuality, RealMeshesAgreeWithIndependentComputation)
{
  const std::filesystem::path dir(BODT_SHARED_DATA);
  if(!std::filesystem::exists(dir)) GTEST_SKIP() << "no " << dir;
  int checked = 0;
  for(const auto& entry : std::filesystem::directory_iterator(dir))
  {
    if(entry.path().extension() != ".mesh") continue;
    std::ostringstream warnings;
    const Tet_mesh m = CGAL::BODT_3::IO::read_medit(entry.path().string(), warnings);
    const auto r = CGAL::BODT_3::mesh_quality(m);
    const bool all_zero = m.all_labels_zero();
    double lo = 180, hi = 0;
    for(std::size_t t = 0; t < m.tets.size(); ++t)
    {
      if(!m.in_mesh(t, all_zero)) continue;
      const auto& c = m.tets[t];
      const auto mm = independent_min_max(m.points[c[0]], m.points[c[1]], m.points[c[2]], m.points[c[3]]);
      lo = std::min(lo, mm.first);
      hi = std::max(hi, mm.second);
    }
    EXPECT_NEAR(r.min_dihedral_deg, lo, 0.01) << entry.path();
    EXPECT_NEAR(r.max_dihedral_deg, hi, 0.01) << entry.path();
    EXPECT_EQ(r.inverted_tets, 0u) << entry.path();
    ++checked;
  }
  EXPECT_GE(checked, 1);
}

// The quality of a Tet_mesh is measured in blocks merged in order: the same report,
// bit for bit, on any number of threads, and the two subdomains' volumes add up.
TEST(MeshQuality, SameReportOnAnyNumberOfThreads)
{
  const Delaunay_cells d(20000);
  Tet_mesh mesh;
  mesh.points = d.points;
  mesh.vertex_refs.assign(d.points.size(), 0);
  mesh.tets = d.cells;
  for(const auto& c : d.cells)
  {
    std::array<Point, 4> p = {d.points[c[0]], d.points[c[1]], d.points[c[2]], d.points[c[3]]};
    mesh.tet_labels.push_back(CGAL::centroid(p[0], p[1], p[2], p[3]).x() < 0.5 ? 1 : 2);
  }
  ASSERT_GT(mesh.tets.size(), 4u * (1u << 14));   // several blocks
  CGAL::BODT_3::Quality_options opt;
  opt.threads = 1;
  const auto one = CGAL::BODT_3::mesh_quality(mesh, opt);
  for(int threads : {2, 4})
  {
    opt.threads = threads;
    const auto many = CGAL::BODT_3::mesh_quality(mesh, opt);
    EXPECT_EQ(nlohmann::json(many).dump(), nlohmann::json(one).dump()) << threads << " threads";
    EXPECT_EQ(many.volume, one.volume);
  }
  EXPECT_NEAR(one.volume_per_subdomain.at(1) + one.volume_per_subdomain.at(2), one.volume, 1e-12);
  EXPECT_GT(one.bad_tets_interior + one.bad_tets_touching_boundary, 0u);   // random points: bad tets everywhere
}

// The boundary distance against values known in closed form: one direction
// alone, the other alone, both, a mesh's boundary against itself moved, and the
// same value on any number of threads (the two directions are prepared side by side).
TEST(BoundaryDistance, HausdorffOfKnownSurfaces)
{
  using Triangle = CGAL::BODT_3::Boundary_triangles::value_type;
  using CGAL::BODT_3::hausdorff_distance;
  const CGAL::BODT_3::Boundary_triangles small = {Triangle(Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0))};
  const CGAL::BODT_3::Boundary_triangles large = {Triangle(Point(0, 0, 0), Point(2, 0, 0), Point(0, 2, 0))};
  // Every point of the small triangle lies on the large one; the large one's
  // corner (2, 0, 0) is 1 from the small one (its corner (1, 0, 0)), the farthest.
  for(int threads : {1, 2, 4})
  {
    EXPECT_DOUBLE_EQ(hausdorff_distance(small, large, 2, threads), 1.0) << threads;
    EXPECT_DOUBLE_EQ(hausdorff_distance(large, small, 2, threads), 1.0) << threads;
    EXPECT_EQ(hausdorff_distance(small, small, 2, threads), 0.0) << threads;
    EXPECT_EQ(hausdorff_distance(small, {}, 2, threads), 0.0) << threads;
  }

  // A random Delaunay mesh's hull, against the same hull lifted by 0.01.
  const Delaunay_cells d(2000);
  Tet_mesh mesh;
  mesh.points = d.points;
  mesh.vertex_refs.assign(d.points.size(), 0);
  mesh.tets = d.cells;
  mesh.tet_labels.assign(d.cells.size(), 1);
  const auto hull = CGAL::BODT_3::boundary_triangles(mesh);
  ASSERT_GT(hull.size(), 100u);
  CGAL::BODT_3::Boundary_triangles lifted;
  const CGAL::Epick::Vector_3 up(0, 0, 0.01);
  for(const auto& t : hull) lifted.emplace_back(t[0] + up, t[1] + up, t[2] + up);
  const double one = hausdorff_distance(hull, lifted, 6, 1);
  EXPECT_GT(one, 0.0);
  EXPECT_LE(one, 0.01 * (1 + 1e-12));   // the lift moves every point by 0.01
  for(int threads : {2, 4}) EXPECT_EQ(hausdorff_distance(hull, lifted, 6, threads), one) << threads;
  EXPECT_EQ(hausdorff_distance(lifted, hull, 6, 1), one);
}

TEST(QualityMeasure, MatchesTheSinesOfTheDihedralAngles)
{
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1, 1);
  int checked = 0;
  for(int i = 0; i < 2000; ++i)
  {
    Point p[4];
    for(auto& x : p) x = Point(u(rng), u(rng), u(rng));
    if(CGAL::orientation(p[0], p[1], p[2], p[3]) != CGAL::POSITIVE) std::swap(p[2], p[3]);
    if(CGAL::orientation(p[0], p[1], p[2], p[3]) != CGAL::POSITIVE) continue;
    EXPECT_NEAR(BODT::internal::min_dihedral_sine(p[0], p[1], p[2], p[3]), brute_min_sine(p[0], p[1], p[2], p[3]), 1e-9);
    // Negatively oriented: -1, whatever the shape.
    EXPECT_EQ(BODT::internal::min_dihedral_sine(p[0], p[1], p[3], p[2]), -1);
    ++checked;
  }
  EXPECT_GT(checked, 1900);
  Point r[4] = {Point(1, 1, 1), Point(1, -1, -1), Point(-1, 1, -1), Point(-1, -1, 1)};
  if(CGAL::orientation(r[0], r[1], r[2], r[3]) != CGAL::POSITIVE) std::swap(r[2], r[3]);
  EXPECT_NEAR(BODT::internal::min_dihedral_sine(r[0], r[1], r[2], r[3]), std::sqrt(8.0) / 3, 1e-15);
  // A flat tetrahedron has quality 0 or is refused.
  EXPECT_LE(BODT::internal::min_dihedral_sine(Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0), Point(1, 1, 0)), 0);
}

TEST(QualityMeasure, BoundsAgreeWithTheAngles)
{
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1, 1);
  BODT::internal::Dihedral_bounds bounds = BODT::internal::Dihedral_bounds::empty();
  // Bounds from a few tets, then every tet is inside iff its angles are.
  std::vector<std::array<Point, 4>> tets;
  while(tets.size() < 300)
  {
    std::array<Point, 4> p;
    for(auto& x : p) x = Point(u(rng), u(rng), u(rng));
    if(CGAL::orientation(p[0], p[1], p[2], p[3]) != CGAL::POSITIVE) std::swap(p[2], p[3]);
    if(CGAL::orientation(p[0], p[1], p[2], p[3]) == CGAL::POSITIVE) tets.push_back(p);
  }
  double lo = 180, hi = 0;
  for(std::size_t i = 0; i < 20; ++i)
  {
    bounds.include(tets[i][0], tets[i][1], tets[i][2], tets[i][3]);
    const auto mm = BODT::internal::min_max_dihedral_angle(tets[i][0], tets[i][1], tets[i][2], tets[i][3]);
    lo = std::min(lo, mm.first);
    hi = std::max(hi, mm.second);
  }
  int inside = 0;
  for(const auto& t : tets)
  {
    const auto mm = BODT::internal::min_max_dihedral_angle(t[0], t[1], t[2], t[3]);
    const bool expected = mm.first >= lo - 1e-9 && mm.second <= hi + 1e-9;
    const bool clearly = mm.first >= lo + 1e-9 && mm.second <= hi - 1e-9;
    const bool got = bounds.contains(t[0], t[1], t[2], t[3], BODT::internal::min_dihedral_sine(t[0], t[1], t[2], t[3]));
    if(clearly)
    {
      EXPECT_TRUE(got);
    }
    if(!expected)
    {
      EXPECT_FALSE(got);
    }
    inside += got ? 1 : 0;
  }
  EXPECT_GT(inside, 20);
  EXPECT_LT(inside, 300);
}

TEST(QualityMeasure, WorstFirstComparison)
{
  std::vector<double> a = {0.5, 0.1, 0.9}, b = {0.2, 0.1};
  EXPECT_EQ(BODT::internal::compare_worst_first(a, b), 1);   // 0.1 ties, then 0.5 > 0.2
  std::vector<double> c = {0.3}, d = {0.4, 0.9};
  EXPECT_EQ(BODT::internal::compare_worst_first(c, d), -1);
  std::vector<double> e = {0.3, 0.8}, f = {0.3};
  EXPECT_EQ(BODT::internal::compare_worst_first(e, f), 0);
}

// The largest-angle measure is 1 + the cosine of the largest dihedral angle: it
// orders tetrahedra by their largest angle, is 0 for a flat one with an angle of
// 180 degrees, and -1 for a negatively oriented one.
TEST(QualityMeasure, LargestAngleMeasureOrdersByTheLargestAngle)
{
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<std::pair<double, double>> measured;   // (largest angle, measure)
  while(measured.size() < 1000)
  {
    Point p[4];
    for(auto& x : p) x = Point(u(rng), u(rng), u(rng));
    if(CGAL::orientation(p[0], p[1], p[2], p[3]) != CGAL::POSITIVE) std::swap(p[2], p[3]);
    if(CGAL::orientation(p[0], p[1], p[2], p[3]) != CGAL::POSITIVE) continue;
    const double q = BODT::internal::tet_quality(BODT::Quality_measure::largest_dihedral_angle, p[0], p[1], p[2], p[3]);
    const double largest = BODT::internal::min_max_dihedral_angle(p[0], p[1], p[2], p[3]).second;
    EXPECT_NEAR(q, 1 + std::cos(largest * 3.14159265358979323846 / 180), 1e-9);
    EXPECT_EQ(BODT::internal::tet_quality(BODT::Quality_measure::largest_dihedral_angle, p[0], p[1], p[3], p[2]), -1);
    measured.emplace_back(largest, q);
  }
  std::sort(measured.begin(), measured.end());
  for(std::size_t i = 1; i < measured.size(); ++i)
  {
    if(measured[i].first > measured[i - 1].first + 1e-6)
    {
      EXPECT_LT(measured[i].second, measured[i - 1].second);
    }
  }
  // A flat tetrahedron, its fourth vertex just above the opposite face: angles near 180 degrees.
  const double flat = BODT::internal::tet_quality(BODT::Quality_measure::largest_dihedral_angle, Point(0, 0, 0), Point(2, 0, 0),
                                        Point(0, 2, 0), Point(0.5, 0.5, 1e-9));
  EXPECT_GE(flat, 0);
  EXPECT_LT(flat, 1e-6);
}
