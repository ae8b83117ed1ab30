#include "engine/detect/collinear_groups.h"

#include <gtest/gtest.h>

#include <array>

#include <Eigen/Geometry>

#include "engine/detect/detect_planes.h"

namespace linesurf::detect {
namespace {

std::vector<SegmentId> Ids(std::initializer_list<std::uint32_t> ids) {
  std::vector<SegmentId> out;
  for (const std::uint32_t i : ids) out.emplace_back(i);
  return out;
}

std::vector<SegmentId> Row(const CollinearGroups& g, std::uint32_t row) {
  const auto r = g.members[SegmentId(row)];
  return {r.begin(), r.end()};
}

TEST(GroupCollinearSegments, PartsOfOneLineFormOneGroupSpanningThem) {
  const Vec3 o(3.0, -2.0, 1.0);
  const Vec3 u = Vec3(1.0, 2.0, 0.5).normalized();
  const Vec3 off = 1e-3 * u.cross(Vec3::UnitZ()).normalized();  // 1 mm aside: another line
  const std::vector<Segment3> segments = {
      {o + 0.0 * u, o + 1.0 * u},
      {o + 2.0 * u + off, o + 3.0 * u + off},  // parallel, 1 mm away
      {o + 2.5 * u, o + 1.5 * u},              // reversed part of the first line
      {o + 4.0 * u, o + 5.0 * u + Vec3(0, 0, 1e-9)},  // numerical noise only
      {o, o + Vec3::UnitZ()},                  // crosses the first line at o
      {o, o},                                  // degenerate: on its own
  };
  const CollinearGroups g = GroupCollinearSegments(segments, 2e-5);
  ASSERT_EQ(g.members.NumRows(), 4u);
  EXPECT_EQ(Row(g, 0), Ids({0, 2, 3}));
  EXPECT_EQ(Row(g, 1), Ids({1}));
  EXPECT_EQ(Row(g, 2), Ids({4}));
  EXPECT_EQ(Row(g, 3), Ids({5}));
  // The first group's line spans t in [0, 5] along u.
  const Segment3& line = g.lines[0];
  EXPECT_NEAR((line.p1 - o).norm(), 0.0, 1e-8);
  EXPECT_NEAR((line.p2 - (o + 5.0 * u)).norm(), 0.0, 1e-8);
  EXPECT_EQ(g.lines[1].p1, segments[1].p1);
}

TEST(GroupCollinearSegments, CubeEdgesCutIntoPartsAreDetectedAsWholeEdges) {
  // The 12 edges of the cube [-1, 1]^3, each cut into 3 parts (like per-camera sub-segments).
  Scene scene;
  scene.viewpoints.push_back(Vec3(5, 4, 3));
  for (int axis = 0; axis < 3; ++axis) {
    for (int a = -1; a <= 1; a += 2) {
      for (int b = -1; b <= 1; b += 2) {
        Vec3 p;
        Vec3 q;
        p[axis] = -1;
        q[axis] = 1;
        p[(axis + 1) % 3] = q[(axis + 1) % 3] = a;
        p[(axis + 2) % 3] = q[(axis + 2) % 3] = b;
        for (int part = 0; part < 3; ++part) {
          scene.segments.push_back({p + (q - p) * (part / 3.0), p + (q - p) * ((part + 0.9) / 3.0)});
          scene.observations.AddRow(std::array<ViewpointId, 1>{ViewpointId(0u)});
        }
      }
    }
  }
  PlaneDetectionOptions options;
  options.epsilon = 0.06;
  RunContext ctx;
  const Expected<PlaneDetectionResult> r = DetectPlanes(scene, options, ctx);
  ASSERT_TRUE(r.has_value());
  EXPECT_EQ(r->stats.lines, 12);
  EXPECT_EQ(r->planes.size(), 6u);
  EXPECT_EQ(r->stats.num_l2, 36);
  for (std::size_t s = 0; s < 36; s += 3) {  // the parts of one edge share its two planes
    EXPECT_EQ(r->memberships[SegmentId(s)].planes, r->memberships[SegmentId(s + 1)].planes);
    EXPECT_EQ(r->memberships[SegmentId(s)].planes, r->memberships[SegmentId(s + 2)].planes);
  }
  for (const PlaneSupport& support : r->support) EXPECT_EQ(support.inlier_count, 12u);
}

}  // namespace
}  // namespace linesurf::detect
