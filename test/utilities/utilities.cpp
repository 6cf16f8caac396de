// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The utilities the stages share (internal/Utilities/): the flat view's handle
// index, the flip pass's tuple map and candidate queue, the parallel grouping,
// arrays first touched on all threads, face matching, the flip and insertion
// passes' history of failed attempts, and the in-place index shift of the flat
// view's re-reads.
#include "delaunay_cells.h"

#include <CGAL/BODT_3/internal/Utilities/Attempt_history.h>
#include <CGAL/BODT_3/internal/Utilities/Candidate_queue.h>
#include <CGAL/BODT_3/internal/Utilities/Convex_polygon_2.h>
#include <CGAL/BODT_3/internal/Utilities/Handle_index_map.h>
#include <CGAL/BODT_3/internal/Utilities/Id_tuple_map.h>
#include <CGAL/BODT_3/internal/Utilities/Index_shift.h>
#include <CGAL/BODT_3/internal/Utilities/Thread_workers.h>
#include <CGAL/BODT_3/internal/Utilities/first_touch.h>
#include <CGAL/BODT_3/internal/Utilities/group_by_key.h>
#include <CGAL/BODT_3/internal/Utilities/tet_face_matching.h>
#include <CGAL/Random.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <map>
#include <queue>
#include <vector>

namespace BODT = CGAL::BODT_3;
using bodt_test::Delaunay_cells;

// The flat view's handle index: every inserted handle found with its index, the
// others not, duplicates refused, through several rehashes.
TEST(HandleIndexMap, FindsWhatWasInsertedThroughGrowth)
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

// Arrays whose pages are first written on several threads: above the size where
// the pages are touched (4 MB), the elements are still what `assign` and `resize`
// make; a vector that has room keeps its storage (and its elements up to the size).
// Clipping a triangle: by a half-plane and by a triangle, against areas worked
// out by hand; the interpolating function takes the corners' values and is
// affine; a polygon out of the half-plane is empty.
TEST(ConvexPolygon2, ClipsToTheAreasOfTheIntersections)
{
  using P2 = CGAL::BODT_3::internal::Point_2d;
  namespace I = CGAL::BODT_3::internal;
  const P2 a{0, 0}, b{2, 0}, c{0, 2};
  I::Convex_polygon_2 t(a, b, c);
  EXPECT_DOUBLE_EQ(t.area(), 2);
  // x <= 1 keeps the triangle but its tip beyond x = 1: 2 - 1/2.
  I::Convex_polygon_2 left = t;
  left.clip(I::Affine_2d{-1, 0, 1});
  EXPECT_EQ(left.size(), 4);
  EXPECT_DOUBLE_EQ(left.area(), 1.5);
  // The triangle mirrored through x + y = 2 meets it on its hypotenuse only.
  I::Convex_polygon_2 touching = t;
  touching.clip(P2{2, 2}, P2{0, 2}, P2{2, 0});
  EXPECT_NEAR(touching.area(), 0, 1e-15);
  // The same shifted by (-1, -1) overlaps it in the square [0, 1]^2.
  I::Convex_polygon_2 square = t;
  square.clip(P2{1, 1}, P2{-1, 1}, P2{1, -1});
  EXPECT_DOUBLE_EQ(square.area(), 1);
  I::Convex_polygon_2 gone = t;
  gone.clip(I::Affine_2d{1, 1, -5});
  EXPECT_TRUE(gone.empty());
  EXPECT_EQ(gone.area(), 0);

  const std::array<P2, 3> s = {P2{0.3, -1}, P2{2, 0.5}, P2{-0.5, 1.7}};
  const I::Affine_2d f = I::interpolating(s, {1.5, -2, 0.25});
  EXPECT_NEAR(f(s[0]), 1.5, 1e-14);
  EXPECT_NEAR(f(s[1]), -2, 1e-14);
  EXPECT_NEAR(f(s[2]), 0.25, 1e-14);
  const P2 m{(s[0][0] + s[1][0] + s[2][0]) / 3, (s[0][1] + s[1][1] + s[2][1]) / 3};
  EXPECT_NEAR(f(m), (1.5 - 2 + 0.25) / 3, 1e-14);
}

TEST(FirstTouch, FreshArraysHoldTheirValuesOnAnyNumberOfThreads)
{
  namespace I = CGAL::BODT_3::internal;
  const std::size_t n = (std::size_t(6) << 20) / sizeof(int) + 123;
  for(int threads : {1, 2, 4})
  {
    std::vector<int> a{5, 6};
    I::assign_fresh(a, n, -7, threads);
    ASSERT_EQ(a.size(), n);
    EXPECT_EQ(std::count(a.begin(), a.end(), -7), static_cast<std::ptrdiff_t>(n));

    std::vector<std::array<int, 4>> r(3, std::array<int, 4>{1, 2, 3, 4});
    I::resize_for_overwrite(r, n / 4, threads);
    ASSERT_EQ(r.size(), n / 4);
    EXPECT_EQ(std::count(r.begin(), r.end(), std::array<int, 4>{0, 0, 0, 0}), static_cast<std::ptrdiff_t>(n / 4));

    const int* storage = a.data();
    I::resize_for_overwrite(a, n / 2, threads);
    EXPECT_EQ(a.data(), storage);
    EXPECT_EQ(a[n / 2 - 1], -7);

    std::vector<char> c;
    I::reserve_fresh(c, n, threads);
    EXPECT_TRUE(c.empty());
    EXPECT_GE(c.capacity(), n);
  }
}

// The flip pass's map from vertex-id tuples: the same answers as std::map over
// random inserts and updates (keys that differ only in order are different),
// through several rehashes, and after clear.
TEST(IdTupleMap, AgreesWithStdMapThroughGrowth)
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
  // Room made for more keys keeps every entry (megabytes of it, made resident on
  // two threads); room for fewer changes nothing.
  map.reserve(20 * reference.size(), 2);
  map.reserve(10);
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
  // A map reserved for no key or one still grows for more.
  for(std::size_t n : {0, 1})
  {
    CGAL::BODT_3::internal::Id_tuple_map<4, int> small;
    small.reserve(n);
    for(int i = 0; i < 100; ++i) small.assign({i, i + 1, i + 2, i + 3}, i);
    ASSERT_EQ(small.size(), 100u);
    for(int i = 0; i < 100; ++i) ASSERT_EQ(*small.find({i, i + 1, i + 2, i + 3}), i);
  }
}

// The indices a predicate keeps, found in parallel blocks, are the serial filter's,
// in order, on any number of threads (several blocks, empty ones among them).
TEST(ThreadWorkers, IndicesWhereIsTheSerialFilter)
{
  const std::size_t n = 5 * CGAL::BODT_3::internal::scan_block + 17;
  auto keep = [n](std::size_t i) { return i % 7 == 3 || (i > n / 2 && i < n / 2 + 100); };
  std::vector<std::size_t> serial;
  for(std::size_t i = 0; i < n; ++i)
    if(keep(i)) serial.push_back(i);
  auto sparse = [](std::size_t i) { return i == 5 || i == 3 * CGAL::BODT_3::internal::scan_block + 1; };
  for(int threads : {1, 2, 4})
  {
    CGAL::BODT_3::internal::Thread_workers<char> workers(threads);
    EXPECT_EQ(workers.indices_where(n, keep), serial) << threads;
    EXPECT_EQ(workers.indices_where(n, sparse),
              (std::vector<std::size_t>{5, 3 * CGAL::BODT_3::internal::scan_block + 1})) << threads;
    EXPECT_TRUE(workers.indices_where(0, keep).empty());
  }
}

// The flip and contraction passes' queue gives the order of one heap of all the
// cells: starting cells and cells pushed while popping (some better than every
// starting cell left, some worse), with many equal qualities, so that the ids
// decide, and a cell pushed again after it was popped.
TEST(CandidateQueue, PopsInTheOrderOfOneHeap)
{
  struct Entry
  {
    double quality;
    int id;
    bool operator<(const Entry& o) const   // "tried after": the worse quality first, then the lower id
    {
      if(quality != o.quality) return quality > o.quality;
      return id > o.id;
    }
    bool operator==(const Entry& o) const { return quality == o.quality && id == o.id; }
  };
  CGAL::Random random(5);
  int next_id = 0;
  auto entry = [&] { return Entry{random.get_int(0, 50) / 10.0, next_id++}; };
  std::vector<Entry> start;
  for(int i = 0; i < 3000; ++i) start.push_back(entry());
  std::priority_queue<Entry> heap(start.begin(), start.end());
  CGAL::BODT_3::internal::Candidate_queue<Entry> queue{std::vector<Entry>(start)};
  std::size_t popped = 0, pushed = 0;
  while(!heap.empty())
  {
    ASSERT_FALSE(queue.empty());
    const Entry expected = heap.top();
    heap.pop();
    const Entry got = queue.pop();
    ASSERT_EQ(got, expected) << "pop " << popped;
    ++popped;
    if(random.get_int(0, 4) == 0 && pushed < 2000)
    {
      const Entry e = random.get_int(0, 3) == 0 ? got : entry();
      heap.push(e);
      queue.push(e);
      ++pushed;
    }
  }
  EXPECT_TRUE(queue.empty());
  EXPECT_EQ(popped, start.size() + pushed);
  EXPECT_GT(pushed, 300u);
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

// Face matching without hashing finds exactly the triangulation's adjacency, the
// matched face has the same three vertices, and the result does not depend on the
// number of threads.
TEST(TetFaceMatching, FindsTheTriangulationsAdjacencyOnAnyNumberOfThreads)
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
TEST(TetFaceMatching, ReportsACrowdedFaceAndSurvivesABrokenCell)
{
  const std::vector<std::array<int, 4>> cells = {{0, 1, 2, 3}, {5, 6, 7, 8}, {1, 0, 2, 4}, {0, 1, 2, 5}, {6, 6, 7, 8}};
  const CGAL::BODT_3::internal::Tet_face_matching faces(cells, 9);
  EXPECT_EQ(faces.crowded_face, 3);   // cell 0, face opposite vertex 3: (0 1 2)
  EXPECT_EQ(faces.match[3], -1);
  EXPECT_EQ(faces.match[4 * 2 + 3], -1);
  EXPECT_EQ(faces.match[4 * 3 + 3], -1);
}

// When a cell whose flips failed is tried again: not before its wait (1, 2, 4, 8
// passes after 1, 2, 3, 4 failures), and only once something within one edge of it
// changed since the failure; after `retries_after_moves` failures, only a new
// connectivity counts, moves alone do not.
TEST(AttemptHistory, FailedCellsAreRetriedAfterTheirWaitAndAChange)
{
  BODT::internal::Attempt_history h;
  h.retries_after_moves = 1;
  h.region_stamp.assign(10, 0);
  h.topology_stamp.assign(10, 0);
  const std::array<int, 4> cell{1, 2, 3, 4};
  EXPECT_TRUE(h.worth_trying(cell));   // never tried
  h.pass = 1;
  h.clock = 5;
  h.record_failure(cell);
  h.pass = 2;
  EXPECT_FALSE(h.worth_trying(cell));   // nothing changed
  h.region_stamp[7] = 6;                // a vertex that is not the cell's
  EXPECT_FALSE(h.worth_trying(cell));
  h.region_stamp[3] = 6;                // a vertex within one edge moved
  EXPECT_TRUE(h.worth_trying(cell));
  h.clock = 7;
  h.record_failure(cell);               // second failure, at pass 2: wait 2
  h.region_stamp[2] = 8;
  h.topology_stamp[2] = 8;
  h.pass = 3;
  EXPECT_FALSE(h.worth_trying(cell));   // within the wait
  h.pass = 4;
  h.topology_stamp[2] = 0;
  EXPECT_FALSE(h.worth_trying(cell));   // moves alone no longer count
  h.star_changed(4);                    // a flip gave vertex 4 a new star, at clock 7
  EXPECT_FALSE(h.worth_trying(cell));   // not after the failure
  h.clock = 9;
  h.star_changed(4);
  EXPECT_TRUE(h.worth_trying(cell));
  EXPECT_EQ(h.region_stamp[4], 9u);
}

// A failure is kept in 8 bytes: its fields hold what a run reaches and saturate
// beyond, where a saturated value only lets the cell be tried sooner.
TEST(AttemptHistory, FailureFieldsRoundTripAndSaturate)
{
  using Failure = BODT::internal::Attempt_history::Failure;
  static_assert(sizeof(Failure) == 8);
  const Failure f(123456789012ull, 4321, 7);
  EXPECT_EQ(f.clock(), 123456789012ull);
  EXPECT_EQ(f.pass(), 4321u);
  EXPECT_EQ(f.count(), 7u);
  const Failure g(std::size_t(1) << 41, 70000, 300);
  EXPECT_EQ(g.clock(), (std::size_t(1) << 40) - 1);
  EXPECT_EQ(g.pass(), 65535u);
  EXPECT_EQ(g.count(), 255u);

  BODT::internal::Attempt_history h;
  h.region_stamp.assign(5, 0);
  h.topology_stamp.assign(5, 0);
  const std::array<int, 4> cell{0, 1, 2, 3};
  h.clock = std::size_t(1) << 41;
  h.pass = 70000;
  h.record_failure(cell);
  h.pass = 70001;
  EXPECT_FALSE(h.worth_trying(cell));   // nothing changed since
  h.region_stamp[1] = (std::size_t(1) << 40);   // after the saturated clock, not after the real one
  EXPECT_TRUE(h.worth_trying(cell));
}

// The index shift of a re-read (elements gone, new ones in before given old
// indices), on random changes of arrays of 1 to 5,000 elements: `relocate` gives
// what building the array anew in its order gives, `now` the index there of
// every kept element, `is_gone` exactly the gone ones; one and four entries
// per element, growing and shrinking.
TEST(IndexShift, RelocatesInPlaceAsARebuildWould)
{
  CGAL::Random random(7);
  for(int round = 0; round < 200; ++round)
  {
    const std::size_t n = 1 + static_cast<std::size_t>(random.get_int(0, round % 4 == 0 ? 5000 : 300));
    BODT::internal::Index_shift shift;
    for(std::size_t j = 0; j < n; ++j)
      if(random.get_double() < 0.02 * (round % 5)) shift.gone.push_back(static_cast<int>(j));
    std::vector<std::size_t> before;
    const int added = random.get_int(0, round % 3 == 0 ? 200 : 20);
    for(int f = 0; f < added; ++f) before.push_back(static_cast<std::size_t>(random.get_int(0, static_cast<int>(n) + 1)));
    std::sort(before.begin(), before.end());
    shift.prepare(before, n);

    // The array rebuilt: the kept elements and the new ones (-1 - f) in order.
    std::vector<int> expected;
    std::size_t f = 0;
    for(std::size_t j = 0; j <= n; ++j)
    {
      for(; f < before.size() && before[f] == j; ++f) expected.push_back(-1 - static_cast<int>(f));
      if(j < n && !std::binary_search(shift.gone.begin(), shift.gone.end(), static_cast<int>(j)))
        expected.push_back(static_cast<int>(j));
    }
    std::vector<std::size_t> kept_before;
    for(std::size_t b : before) kept_before.push_back(b - shift.gone_before(b));
    for(std::size_t width : {std::size_t(1), std::size_t(4)})
    {
      std::vector<int> a(width * n);
      for(std::size_t j = 0; j < width * n; ++j) a[j] = static_cast<int>(j / width);
      shift.relocate(a, width, kept_before, expected.size());
      ASSERT_EQ(a.size(), width * expected.size());
      for(std::size_t k = 0; k < expected.size(); ++k)
        for(std::size_t w = 0; w < width; ++w)
          if(expected[k] >= 0)
          {
            ASSERT_EQ(a[width * k + w], expected[k]) << "round " << round << ", element " << k;
          }
    }
    for(std::size_t k = 0; k < expected.size(); ++k)
      if(expected[k] >= 0)
      {
        ASSERT_FALSE(shift.is_gone(expected[k])) << "round " << round;
        ASSERT_EQ(shift.now(expected[k]), static_cast<int>(k)) << "round " << round;
      }
    for(int g : shift.gone) ASSERT_TRUE(shift.is_gone(g)) << "round " << round;
  }
}
