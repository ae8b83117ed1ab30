#pragma once
// Test helper: bit-exact comparison of two scenes (every value, every id).

#include <gtest/gtest.h>

#include <cstring>

#include "engine/core/scene.h"

namespace linesurf::io {

inline bool SameBits(double a, double b) { return std::memcmp(&a, &b, sizeof(double)) == 0; }

inline bool SameBits(const Vec3& a, const Vec3& b) {
  return SameBits(a.x(), b.x()) && SameBits(a.y(), b.y()) && SameBits(a.z(), b.z());
}

/// Every value of two scenes is bit-identical.
inline void ExpectScenesIdentical(const Scene& a, const Scene& b) {
  ASSERT_EQ(a.NumSegments(), b.NumSegments());
  ASSERT_EQ(a.viewpoints.size(), b.viewpoints.size());
  ASSERT_EQ(a.planes.size(), b.planes.size());
  ASSERT_EQ(a.memberships.size(), b.memberships.size());
  ASSERT_EQ(a.residuals.size(), b.residuals.size());
  EXPECT_EQ(a.observations.offsets(), b.observations.offsets());
  EXPECT_EQ(a.observations.items(), b.observations.items());
  EXPECT_EQ(a.extra_fields, b.extra_fields);
  for (std::size_t s = 0; s < a.NumSegments(); ++s) {
    ASSERT_TRUE(SameBits(a.segments[SegmentId(s)].p1, b.segments[SegmentId(s)].p1)) << s;
    ASSERT_TRUE(SameBits(a.segments[SegmentId(s)].p2, b.segments[SegmentId(s)].p2)) << s;
  }
  for (std::size_t v = 0; v < a.viewpoints.size(); ++v) {
    ASSERT_TRUE(SameBits(a.viewpoints[ViewpointId(v)], b.viewpoints[ViewpointId(v)])) << v;
  }
  for (std::size_t p = 0; p < a.planes.size(); ++p) {
    ASSERT_TRUE(SameBits(a.planes[PlaneId(p)].point, b.planes[PlaneId(p)].point)) << p;
    ASSERT_TRUE(SameBits(a.planes[PlaneId(p)].normal, b.planes[PlaneId(p)].normal)) << p;
  }
  for (std::size_t s = 0; s < a.memberships.size(); ++s) {
    const auto& ma = a.memberships[SegmentId(s)];
    const auto& mb = b.memberships[SegmentId(s)];
    ASSERT_EQ(ma.count, mb.count) << s;
    for (int k = 0; k < ma.count; ++k) ASSERT_EQ(ma.planes[k], mb.planes[k]) << s;
  }
  for (std::size_t r = 0; r < a.residuals.size(); ++r) {
    for (int k = 0; k < 4; ++k) ASSERT_TRUE(SameBits(a.residuals[r][k], b.residuals[r][k]));
  }
}

}  // namespace linesurf::io
