// Quality measures: dihedral angles against CGAL's independent
// approximate_dihedral_angle, counts, volumes, exact inversion test, and the
// real meshes of ../shared/data when present.
#include "report/json_report.h"

#include <CGAL/BODT_3/internal/Utilities/Handle_index_map.h>
#include <CGAL/BODT_3/internal/Utilities/Id_tuple_map.h>
#include <CGAL/BODT_3/internal/Utilities/Thread_workers.h>
#include <CGAL/BODT_3/internal/Utilities/group_by_key.h>
#include <CGAL/BODT_3/IO/medit.h>
#include <CGAL/BODT_3/mesh_quality.h>
#include <CGAL/BODT_3/internal/Utilities/tet_face_matching.h>
#include <CGAL/BODT_3/internal/Quality/tet_quality.h>

#include <CGAL/Delaunay_triangulation_3.h>
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
#include <sstream>

using CGAL::BODT_3::Tet_mesh;
using Point = Tet_mesh::Point;

namespace {

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
  EXPECT_EQ(j.at("histogram").at("counts").size(), r.histogram.size());
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

// The flat view's handle index: every inserted handle found with its index, the
// others not, duplicates refused, through several rehashes.
TEST(Handle_index_map, FindsWhatWasInsertedThroughGrowth)
{
  std::vector<int> storage(5000), others(100);
  CGAL::BODT_3::internal::Handle_index_map<int*> map;
  map.reset(0);
  for(std::size_t i = 0; i < storage.size(); ++i) EXPECT_TRUE(map.insert(&storage[i], static_cast<int>(i)));
  EXPECT_FALSE(map.insert(&storage[7], 99));
  EXPECT_EQ(map.size(), storage.size());
  for(std::size_t i = 0; i < storage.size(); ++i) ASSERT_EQ(map.find(&storage[i]), static_cast<int>(i));
  for(int& x : others) EXPECT_EQ(map.find(&x), -1);
  map.reset(10);
  EXPECT_EQ(map.find(&storage[0]), -1);
  EXPECT_EQ(map.size(), 0u);
}

// Handles inserted from several threads at once are found with their index.
TEST(Handle_index_map, InsertAllFromThreadsFindsEveryHandle)
{
  std::vector<int> storage(50000), others(100);
  std::vector<int*> handles;
  for(int& x : storage) handles.push_back(&x);
  for(int threads : {1, 2, 4})
  {
    CGAL::BODT_3::internal::Handle_index_map<int*> map;
    map.reset(handles.size() / 4);   // grows before the threads insert
    CGAL::BODT_3::internal::Thread_workers<char> workers(threads);
    map.insert_all(handles, workers);
    EXPECT_EQ(map.size(), handles.size());
    for(std::size_t i = 0; i < handles.size(); ++i) ASSERT_EQ(map.find(handles[i]), static_cast<int>(i));
    for(int& x : others) EXPECT_EQ(map.find(&x), -1);
    EXPECT_FALSE(map.insert(handles[9], 1));
  }
}

// The flip pass's map from vertex-id tuples: the same answers as std::map over
// random inserts and updates (keys that differ only in order are different),
// through several rehashes, and after clear.
TEST(Id_tuple_map, AgreesWithStdMapThroughGrowth)
{
  CGAL::Random random(11);
  CGAL::BODT_3::internal::Id_tuple_map<4, int> map;
  std::map<std::array<int, 4>, int> reference;
  auto key = [&] {
    return std::array<int, 4>{random.get_int(0, 40), random.get_int(0, 40), random.get_int(0, 40), random.get_int(0, 40)};
  };
  EXPECT_EQ(map.find(key()), nullptr);
  for(int i = 0; i < 20000; ++i)
  {
    const auto k = key();
    if(i % 3 == 0)
    {
      map.assign(k, i);
      reference[k] = i;
    }
    else
    {
      bool inserted = false;
      int& value = map.find_or_insert(k, -i, inserted);
      const auto ins = reference.emplace(k, -i);
      ASSERT_EQ(inserted, ins.second);
      ASSERT_EQ(value, ins.first->second);
      if(!inserted) value = reference[k] = value + 1;
    }
  }
  EXPECT_EQ(map.size(), reference.size());
  for(const auto& kv : reference)
  {
    const int* found = map.find(kv.first);
    ASSERT_NE(found, nullptr);
    ASSERT_EQ(*found, kv.second);
  }
  for(int i = 0; i < 1000; ++i)
  {
    const auto k = key();
    const int* found = map.find(k);
    EXPECT_EQ(found != nullptr, reference.count(k) == 1);
  }
  map.clear();
  EXPECT_EQ(map.size(), 0u);
  EXPECT_EQ(map.find(reference.begin()->first), nullptr);
}

// The parallel counting sort groups like a sequential stable one, on any number of threads.
TEST(GroupByKey, StableGroupsOnAnyNumberOfThreads)
{
  CGAL::Random random(3);
  const std::size_t items = 100000, keys = 5000;
  std::vector<std::array<int, 3>> item_keys(items);
  for(auto& k : item_keys)
    for(int& x : k) x = random.get_int(0, static_cast<int>(keys));
  // Item i emits (k, 3 i + j) for its j-th key k.
  auto each = [&](std::size_t i, const auto& emit) {
    for(int j = 0; j < 3; ++j) emit(static_cast<std::size_t>(item_keys[i][j]), static_cast<long>(3 * i + j));
  };
  std::vector<std::vector<long>> expected(keys);
  for(std::size_t i = 0; i < items; ++i)
    for(int j = 0; j < 3; ++j) expected[item_keys[i][j]].push_back(static_cast<long>(3 * i + j));
  for(int threads : {1, 2, 4, 16})
  {
    std::vector<int> begin;
    std::vector<long> values;
    CGAL::BODT_3::internal::group_by_key<long>(items, keys, threads, each, begin, values);
    ASSERT_EQ(begin.size(), keys + 1);
    ASSERT_EQ(values.size(), 3 * items);
    for(std::size_t k = 0; k < keys; ++k)
      ASSERT_EQ(std::vector<long>(values.begin() + begin[k], values.begin() + begin[k + 1]), expected[k])
          << "key " << k << ", " << threads << " threads";
  }
}

namespace {

// The finite cells of a Delaunay triangulation of `n` random points in the unit
// cube, as index arrays, with the TDS's own adjacency to compare against.
struct Delaunay_cells
{
  std::vector<Point> points;
  std::vector<std::array<int, 4>> cells;
  std::vector<int> neighbor;   // 4 c + i: the finite cell across, or -1

  explicit Delaunay_cells(int n)
  {
    using Dt = CGAL::Delaunay_triangulation_3<CGAL::Epick>;
    CGAL::Random random(7);
    std::vector<Point> in;
    for(int i = 0; i < n; ++i) in.emplace_back(random.get_double(), random.get_double(), random.get_double());
    Dt dt(in.begin(), in.end());
    std::map<Dt::Vertex_handle, int> vid;
    for(auto v = dt.finite_vertices_begin(); v != dt.finite_vertices_end(); ++v)
    {
      vid[v] = static_cast<int>(points.size());
      points.push_back(v->point());
    }
    std::map<Dt::Cell_handle, int> cid;
    for(auto c = dt.finite_cells_begin(); c != dt.finite_cells_end(); ++c)
    {
      cid[c] = static_cast<int>(cells.size());
      cells.push_back({vid[c->vertex(0)], vid[c->vertex(1)], vid[c->vertex(2)], vid[c->vertex(3)]});
    }
    for(auto c = dt.finite_cells_begin(); c != dt.finite_cells_end(); ++c)
      for(int i = 0; i < 4; ++i)
        neighbor.push_back(dt.is_infinite(c->neighbor(i)) ? -1 : cid[c->neighbor(i)]);
  }
};

} // namespace

// Face matching without hashing finds exactly the triangulation's adjacency, the
// matched face has the same three vertices, and the result does not depend on the
// number of threads.
TEST(Tet_face_matching, FindsTheTriangulationsAdjacencyOnAnyNumberOfThreads)
{
  const Delaunay_cells d(3000);
  const CGAL::BODT_3::internal::Tet_face_matching one(d.cells, d.points.size(), 1);
  EXPECT_EQ(one.crowded_face, -1);
  ASSERT_EQ(one.match.size(), 4 * d.cells.size());
  for(std::size_t f = 0; f < one.match.size(); ++f)
  {
    const int m = one.match[f];
    ASSERT_EQ(m < 0 ? -1 : m / 4, d.neighbor[f]) << "face " << f;
    if(m < 0) continue;
    EXPECT_EQ(one.match[static_cast<std::size_t>(m)], static_cast<int>(f));
    // The far vertices differ; the three others are shared.
    const auto& a = d.cells[f / 4];
    const auto& b = d.cells[static_cast<std::size_t>(m / 4)];
    EXPECT_EQ(std::count(b.begin(), b.end(), a[f % 4]), 0);
    for(int k = 1; k < 4; ++k) EXPECT_EQ(std::count(b.begin(), b.end(), a[(f % 4 + k) % 4]), 1);
  }
  for(int threads : {2, 4})
    EXPECT_EQ(CGAL::BODT_3::internal::Tet_face_matching(d.cells, d.points.size(), threads).match, one.match);
}

// Three tetrahedra on one face: none of the three is matched, and the first face
// (by id) of the crowd is reported; a tetrahedron using a vertex twice is skipped.
TEST(Tet_face_matching, ReportsACrowdedFaceAndSurvivesABrokenCell)
{
  const std::vector<std::array<int, 4>> cells = {{0, 1, 2, 3}, {5, 6, 7, 8}, {1, 0, 2, 4}, {0, 1, 2, 5}, {6, 6, 7, 8}};
  const CGAL::BODT_3::internal::Tet_face_matching faces(cells, 9);
  EXPECT_EQ(faces.crowded_face, 3);   // cell 0, face opposite vertex 3: (0 1 2)
  EXPECT_EQ(faces.match[3], -1);
  EXPECT_EQ(faces.match[4 * 2 + 3], -1);
  EXPECT_EQ(faces.match[4 * 3 + 3], -1);
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
