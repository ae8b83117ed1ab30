#include "engine/core/geometry.h"

#include "engine/core/endpoint_box.h"

#include <gtest/gtest.h>

#include <vector>

namespace linesurf {
namespace {

Box3 BoxOf(const Vec3& a, const Vec3& b) {
  Box3 box;
  box.Extend(a);
  box.Extend(b);
  return box;
}

TEST(Box3, OverlapsCountsSharedBoundariesBothWays) {
  const Box3 unit = BoxOf(Vec3(0, 0, 0), Vec3(1, 1, 1));
  const Box3 face_neighbour = BoxOf(Vec3(1, 0, 0), Vec3(2, 1, 1));
  const Box3 corner_neighbour = BoxOf(Vec3(1, 1, 1), Vec3(2, 2, 2));
  const Box3 flat_inside = BoxOf(Vec3(0.5, 0.2, 0.2), Vec3(0.5, 0.8, 0.8));
  EXPECT_TRUE(unit.Overlaps(face_neighbour));
  EXPECT_TRUE(face_neighbour.Overlaps(unit));
  EXPECT_TRUE(unit.Overlaps(corner_neighbour));
  EXPECT_TRUE(flat_inside.Overlaps(unit));
  EXPECT_TRUE(unit.Overlaps(flat_inside));
}

TEST(Box3, OverlapsNeedsEveryAxisToMeet) {
  const Box3 unit = BoxOf(Vec3(0, 0, 0), Vec3(1, 1, 1));
  const Box3 apart_in_z = BoxOf(Vec3(0, 0, 1.0000001), Vec3(1, 1, 2));
  const Box3 across_in_x_only = BoxOf(Vec3(-1, 2, 2), Vec3(3, 3, 3));
  EXPECT_FALSE(unit.Overlaps(apart_in_z));
  EXPECT_FALSE(apart_in_z.Overlaps(unit));
  EXPECT_FALSE(unit.Overlaps(across_in_x_only));
}

TEST(Box3, EmptyBoxOverlapsNothing) {
  const Box3 unit = BoxOf(Vec3(0, 0, 0), Vec3(1, 1, 1));
  EXPECT_FALSE(unit.Overlaps(Box3{}));
  EXPECT_FALSE(Box3{}.Overlaps(unit));
  EXPECT_FALSE(Box3{}.Overlaps(Box3{}));
}

TEST(EndpointBox, SpansTheEndpointsOfTheChosenSegmentsOnly) {
  const std::vector<Segment3> segments = {{Vec3(0, 0, 0), Vec3(1, 2, 3)},
                                          {Vec3(-5, -5, -5), Vec3(9, 9, 9)},
                                          {Vec3(4, -1, 0.5), Vec3(2, 1, -2)}};
  const std::vector<SegmentId> chosen = {SegmentId(0u), SegmentId(2u)};
  const Box3 box = EndpointBox(segments, chosen);
  EXPECT_EQ(box.min, Vec3(0, -1, -2));
  EXPECT_EQ(box.max, Vec3(4, 2, 3));
  EXPECT_TRUE(EndpointBox(segments, {}).IsEmpty());
}

}  // namespace
}  // namespace linesurf
