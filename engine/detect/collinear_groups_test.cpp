#include "engine/detect/collinear_groups.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "engine/detect/detect_planes.h"
#include "tools/eval/evaluate_planes.h"
#include "tools/gen/synthesize.h"

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
  // The 12 edges of the noise-free synthetic cube, each cut into 1..4 collinear parts (like
  // per-camera sub-segments).
  synth::SynthSpec spec;
  spec.family = "cube";
  spec.seed = 5;
  spec.max_pieces = 4;
  const Expected<synth::SyntheticScene> cube = synth::Synthesize(spec);
  ASSERT_TRUE(cube.has_value());
  const Scene& scene = cube->scene;
  const std::size_t n = scene.segments.size();
  ASSERT_GT(n, 24u);  // most edges are cut
  PlaneDetectionOptions options;
  options.epsilon = 0.06;
  RunContext ctx;
  const Expected<PlaneDetectionResult> r = DetectPlanes(scene, options, ctx);
  ASSERT_TRUE(r.has_value());
  EXPECT_EQ(r->stats.lines, 12);
  EXPECT_EQ(r->planes.size(), 6u);
  EXPECT_EQ(r->stats.num_l2, static_cast<std::int64_t>(n));
  // Each face holds all the parts of its 4 edges, and nothing else.
  EXPECT_EQ(eval::CountTruePlanesHeld(scene, r->memberships), 6);
  std::size_t memberships = 0;
  for (const PlaneSupport& support : r->support) memberships += support.inlier_count;
  EXPECT_EQ(memberships, 2 * n);
  // The parts of one edge (same true planes) share its two detected planes.
  const auto& truth = scene.memberships;
  const auto& found = r->memberships;
  for (std::size_t a = 0; a < n; ++a) {
    for (std::size_t b = a + 1; b < n; ++b) {
      if (truth[SegmentId(a)].planes != truth[SegmentId(b)].planes) continue;
      EXPECT_EQ(found[SegmentId(a)].planes, found[SegmentId(b)].planes) << a << " " << b;
    }
  }
}

}  // namespace
}  // namespace linesurf::detect
