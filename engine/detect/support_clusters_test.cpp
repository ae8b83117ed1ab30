#include "engine/detect/support_clusters.h"

#include <gtest/gtest.h>

#include <vector>

namespace linesurf::detect {
namespace {

Segment3 Seg(double x1, double y1, double z1, double x2, double y2, double z2) {
  return Segment3{Vec3(x1, y1, z1), Vec3(x2, y2, z2)};
}

std::vector<SegmentId> All(std::size_t n) {
  std::vector<SegmentId> ids;
  for (std::size_t i = 0; i < n; ++i) ids.emplace_back(i);
  return ids;
}

TEST(SegmentSegmentDistance, CrossingSkewParallelAndDegenerate) {
  EXPECT_NEAR(SegmentSegmentDistance(Seg(-1, 0, 0, 1, 0, 0), Seg(0, -1, 0, 0, 1, 0)), 0.0, 1e-15);
  EXPECT_NEAR(SegmentSegmentDistance(Seg(-1, 0, 0, 1, 0, 0), Seg(0, -1, 2, 0, 1, 2)), 2.0, 1e-15);
  // Parallel, overlapping and not: the gap between the ends counts.
  EXPECT_NEAR(SegmentSegmentDistance(Seg(0, 0, 0, 2, 0, 0), Seg(1, 1, 0, 3, 1, 0)), 1.0, 1e-15);
  EXPECT_NEAR(SegmentSegmentDistance(Seg(0, 0, 0, 1, 0, 0), Seg(4, 0, 0, 5, 0, 0)), 3.0, 1e-15);
  // An end of one against the inside of the other.
  EXPECT_NEAR(SegmentSegmentDistance(Seg(0, 0, 0, 4, 0, 0), Seg(2, 3, 0, 2, 1, 0)), 1.0, 1e-15);
  // Points.
  EXPECT_NEAR(SegmentSegmentDistance(Seg(0, 0, 0, 0, 0, 0), Seg(3, 4, 0, 3, 4, 0)), 5.0, 1e-15);
  EXPECT_NEAR(SegmentSegmentDistance(Seg(1, 1, 0, 1, 1, 0), Seg(0, 0, 0, 2, 0, 0)), 1.0, 1e-15);
}

TEST(SupportClusters, PiecesFartherApartThanTheGapAreSeparateLargestFirst) {
  const std::vector<Segment3> segments = {Seg(20, 0, 0, 21, 0, 0),  // B
                                          Seg(0, 0, 0, 1, 0, 0),
                                          Seg(1.5, 0, 0, 2.5, 0, 0),
                                          Seg(3, 0, 0, 3, 1, 0),        // A: a chain
                                          Seg(21, 0.5, 0, 21, 1.5, 0),  // B
                                          Seg(40, 0, 0, 40, 1, 0),      // C
                                          Seg(3.2, 1, 0, 4, 1, 0)};     // A
  const auto pieces = SupportClusters(segments, All(segments.size()), 0.6);
  ASSERT_EQ(pieces.size(), 3u);
  EXPECT_EQ(pieces[0],
            (std::vector<SegmentId>{SegmentId(1u), SegmentId(2u), SegmentId(3u), SegmentId(6u)}));
  EXPECT_EQ(pieces[1], (std::vector<SegmentId>{SegmentId(0u), SegmentId(4u)}));
  EXPECT_EQ(pieces[2], (std::vector<SegmentId>{SegmentId(5u)}));
  // A larger gap links them all; a subset is clustered on its own.
  EXPECT_EQ(SupportClusters(segments, All(segments.size()), 20.0).size(), 1u);
  const std::vector<SegmentId> two = {SegmentId(1u), SegmentId(2u)};
  EXPECT_EQ(SupportClusters(segments, two, 0.4).size(), 2u);
}

// Two square outlines, 20 apart, as the roof edges of two buildings.
std::vector<Segment3> TwoOutlines(double z_left, double z_right) {
  std::vector<Segment3> out;
  for (const auto& [x0, z] : {std::pair{0.0, z_left}, std::pair{20.0, z_right}}) {
    out.push_back(Seg(x0, 0, z, x0 + 10, 0, z));
    out.push_back(Seg(x0 + 10, 0, z, x0 + 10, 10, z));
    out.push_back(Seg(x0 + 10, 10, z, x0, 10, z));
    out.push_back(Seg(x0, 10, z, x0, 0, z));
  }
  return out;
}

TEST(PiecesDisagree, TwoRoofsAtDifferentHeightsUnderOneTiltedPlaneDisagree) {
  const std::vector<Segment3> offset = TwoOutlines(10.0, 10.2);
  const auto pieces = SupportClusters(offset, All(offset.size()), 5.0);
  ASSERT_EQ(pieces.size(), 2u);
  // The plane through both (tilted along x): 0.05 off each outline's own plane at its far corners.
  Plane3 tilted;
  tilted.normal = Vec3(-0.2 / 20.0, 0.0, 1.0).normalized();
  tilted.point = Vec3(15.0, 5.0, 10.1);
  EXPECT_TRUE(PiecesDisagree(offset, pieces, tilted, 3, 1.0, 0.02));
  EXPECT_FALSE(PiecesDisagree(offset, pieces, tilted, 3, 1.0, 0.06));
  // Too few lines or too narrow a piece: no own fit, no verdict.
  EXPECT_FALSE(PiecesDisagree(offset, pieces, tilted, 5, 1.0, 0.02));
  EXPECT_FALSE(PiecesDisagree(offset, pieces, tilted, 3, 10.0, 0.02));

  // One ground seen in two places: its pieces agree with it.
  const std::vector<Segment3> level = TwoOutlines(0.0, 0.0);
  Plane3 ground;
  ground.normal = Vec3::UnitZ();
  ground.point = Vec3::Zero();
  EXPECT_FALSE(
      PiecesDisagree(level, SupportClusters(level, All(level.size()), 5.0), ground, 3, 1.0, 0.02));
}

}  // namespace
}  // namespace linesurf::detect
