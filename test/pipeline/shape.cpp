// The shape is kept whatever the labels say (issue 30): over boxes and L-shaped
// blocks labelled every way a user can label them (labelled_boxes.h), after the
// default pipeline every input vertex on a face, an interface or an embedded
// surface is still on its plane, hence every vertex on a straight edge on its line
// and every corner where it was, and every subdomain keeps its volume.
#include "labelled_boxes.h"

#include <CGAL/BODT_3/mesh_quality.h>
#include <CGAL/BODT_3/smooth.h>

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace BODT = CGAL::BODT_3;
using namespace bodt_test;

namespace {

class Shape : public ::testing::TestWithParam<Labelled_box_case>
{};

double distance(const Labelled_box& box, int plane, const BODT::Tet_mesh::Point& p)
{
  const Kept_plane& q = box.planes[static_cast<std::size_t>(plane)];
  return std::abs(q.normal * (p - CGAL::ORIGIN) - q.offset);
}

} // namespace

TEST_P(Shape, FacesEdgesCornersAndVolumesAreKept)
{
  const Labelled_box box = make_labelled_box(GetParam());
  const double tolerance = 1e-12 * box.size;
  BODT::Tet_mesh m = box.mesh;
  const BODT::Quality_report before = BODT::mesh_quality(m);
  ASSERT_EQ(before.inverted_tets, 0u);
  for(std::size_t v = 0; v < box.on.size(); ++v)
    for(int p : box.on[v]) ASSERT_LT(distance(box, p, m.points[v]), tolerance) << "input vertex " << v;

  const BODT::Smoothing_result result = BODT::smooth(m, BODT::Smoothing_options());
  EXPECT_GT(result.moved_vertices, 0u);   // else nothing below is tested
  const BODT::Quality_report after = BODT::mesh_quality(m);
  EXPECT_EQ(after.inverted_tets, 0u);
  for(std::size_t v = 0; v < box.on.size(); ++v)
  {
    for(int p : box.on[v]) EXPECT_LT(distance(box, p, m.points[v]), tolerance) << "vertex " << v << " left plane " << p;
    // On three planes: a corner, or a point where an embedded surface's rim meets an edge.
    if(box.on[v].size() >= 3)
    {
      EXPECT_LT(std::sqrt(CGAL::squared_distance(m.points[v], box.mesh.points[v])), tolerance) << "corner " << v;
    }
  }
  for(const auto& [label, volume] : before.volume_per_subdomain)
    EXPECT_NEAR(after.volume_per_subdomain.at(label), volume, 1e-11 * volume) << "subdomain " << label;
}

INSTANTIATE_TEST_SUITE_P(EveryLabelling, Shape, ::testing::ValuesIn(all_labelled_box_cases()),
                         [](const ::testing::TestParamInfo<Labelled_box_case>& info) { return info.param.name(); });
