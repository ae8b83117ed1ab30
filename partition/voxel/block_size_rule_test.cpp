#include "partition/voxel/block_size_rule.h"

#include "engine/core/rng.h"

#include <gtest/gtest.h>

namespace linesurf::partition {
namespace {

std::vector<Segment3> RandomSegments(int n, double extent, double length, std::uint64_t seed) {
  Rng rng(seed);
  std::vector<Segment3> out;
  for (int i = 0; i < n; ++i) {
    const Vec3 a(rng.Uniform(0, extent), rng.Uniform(0, extent), rng.Uniform(0, extent));
    out.push_back({a, a + Vec3(length, 0, 0)});
  }
  return out;
}

Box3 Cube(double extent) {
  Box3 box;
  box.Extend(Vec3::Zero());
  box.Extend(Vec3::Constant(extent));
  return box;
}

TEST(ChooseBlockSize, ASparseSceneIsOneBlock) {
  const auto choice = ChooseBlockSize(RandomSegments(500, 10, 0.5, 1), Cube(10), {});
  ASSERT_TRUE(choice) << choice.error().ToString();
  EXPECT_EQ(choice->halvings, 0);
  EXPECT_EQ(choice->block_size, 10.0);
}

TEST(ChooseBlockSize, DenseScenesAreHalvedUntilTheMeanFitsTheTarget) {
  BlockSizeRule rule;
  rule.target_segments_per_block = 100;
  rule.min_block_lengths = 1;
  const auto segments = RandomSegments(20000, 64, 0.5, 2);
  const auto choice = ChooseBlockSize(segments, Cube(64), rule);
  ASSERT_TRUE(choice) << choice.error().ToString();
  // Uniform density: 20,000 / 8^k <= 100 first at k = 3 (39 per block), with all 512 occupied.
  EXPECT_EQ(choice->halvings, 3);
  EXPECT_EQ(choice->block_size, 8.0);
  EXPECT_EQ(choice->occupied_blocks, 512u);
  EXPECT_LE(choice->mean_segments_per_block, 100.0);
  EXPECT_FALSE(choice->limited_by_length);
}

TEST(ChooseBlockSize, BlocksStayLongerThanTheSegments) {
  BlockSizeRule rule;
  rule.target_segments_per_block = 1;  // unreachable
  rule.min_block_lengths = 4;
  const auto choice = ChooseBlockSize(RandomSegments(5000, 64, 2.0, 3), Cube(64), rule);
  ASSERT_TRUE(choice) << choice.error().ToString();
  EXPECT_EQ(choice->block_size, 8.0);  // 4 is below 4 * 2
  EXPECT_TRUE(choice->limited_by_length);
}

// Few segments, but each of 64 cells of a 4 x 4 x 4 lattice holds segments of its own 8 planes:
// the segment target is met by one block, the plane target only by blocks of a lattice cell.
TEST(ChooseBlockSize, ManyPlanesPerBlockAreHalvedUntilTheMeanFitsTheTarget) {
  std::vector<Segment3> segments;
  std::vector<PlaneMembership> memberships;
  Rng rng(5);
  for (int cell = 0; cell < 64; ++cell) {
    const Vec3 corner(16.0 * (cell % 4), 16.0 * ((cell / 4) % 4), 16.0 * (cell / 16));
    for (int p = 0; p < 8; ++p) {
      const Vec3 a = corner + Vec3(rng.Uniform(1, 14), rng.Uniform(1, 14), rng.Uniform(1, 14));
      segments.push_back({a, a + Vec3(0.5, 0, 0)});
      PlaneMembership m;
      m.Add(PlaneId(static_cast<std::size_t>(cell * 8 + p)));
      memberships.push_back(m);
    }
  }
  BlockSizeRule rule;
  rule.min_block_lengths = 1;
  rule.target_planes_per_block = 8;
  const auto by_segments = ChooseBlockSize(segments, Cube(64), rule);
  ASSERT_TRUE(by_segments);
  EXPECT_EQ(by_segments->halvings, 0);
  const auto choice = ChooseBlockSize(segments, Cube(64), rule, memberships);
  ASSERT_TRUE(choice) << choice.error().ToString();
  EXPECT_EQ(choice->block_size, 16.0);
  EXPECT_EQ(choice->occupied_blocks, 64u);
  EXPECT_EQ(choice->mean_planes_per_block, 8.0);
  EXPECT_FALSE(ChooseBlockSize(segments, Cube(64), rule, std::span(memberships).first(3)));
}

TEST(ChooseBlockSize, RejectsBadRules) {
  BlockSizeRule rule;
  rule.target_segments_per_block = 0;
  EXPECT_FALSE(ChooseBlockSize({}, Cube(1), rule));
  rule = {};
  rule.min_block_lengths = -1;
  EXPECT_FALSE(ChooseBlockSize({}, Cube(1), rule));
}

}  // namespace
}  // namespace linesurf::partition
