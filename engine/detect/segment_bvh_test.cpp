#include "engine/detect/segment_bvh.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>

#include "engine/core/rng.h"

namespace linesurf::detect {
namespace {

TEST(SegmentBvh, SlabQueryReturnsEverySegmentThatCanTouchThePlane) {
  Rng rng(7);
  std::vector<Segment3> segments;
  for (int i = 0; i < 500; ++i) {
    const Vec3 a(rng.Uniform(-5, 5), rng.Uniform(-5, 5), rng.Uniform(-5, 5));
    const Vec3 d(rng.Uniform(-1, 1), rng.Uniform(-1, 1), rng.Uniform(-1, 1));
    segments.push_back({a, a + d});
  }
  const SegmentBvh bvh(segments);
  ASSERT_EQ(bvh.Order().size(), segments.size());
  std::set<SegmentId> seen(bvh.Order().begin(), bvh.Order().end());
  EXPECT_EQ(seen.size(), segments.size());
  for (std::size_t i = 0; i < segments.size(); ++i) {
    EXPECT_EQ(bvh.Order()[bvh.PositionOf(SegmentId(i))], SegmentId(i));
  }
  Plane3 plane{Vec3(0.3, -0.2, 1.0), Vec3(1, 2, -0.5).normalized()};
  const double t = 0.1;
  std::set<SegmentId> found;
  bvh.ForEachInSlab(plane, t, [&](SegmentId s) { found.insert(s); });
  int inside = 0;
  for (std::size_t i = 0; i < segments.size(); ++i) {
    const double d1 = plane.SignedDistance(segments[i].p1);
    const double d2 = plane.SignedDistance(segments[i].p2);
    const bool touches = std::min(d1, d2) <= t && std::max(d1, d2) >= -t;
    if (touches) {
      ++inside;
      EXPECT_TRUE(found.count(SegmentId(i))) << i;
    }
  }
  EXPECT_GT(inside, 10);
  EXPECT_LT(found.size(), segments.size());  // the query prunes
}

}  // namespace
}  // namespace linesurf::detect
