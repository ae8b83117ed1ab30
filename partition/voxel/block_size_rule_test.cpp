#include "partition/voxel/block_size_rule.h"

#include "engine/core/rng.h"

#include <gtest/gtest.h>

#include <cmath>

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

TEST(ChooseBlockSize, ASparseSceneIsOneBlockOnEitherLadder) {
  for (const BlockSizeLadder ladder :
       {BlockSizeLadder::kHalvingsOfTheExtent, BlockSizeLadder::kQuarterOctavesFromTheFloor}) {
    const auto choice =
        ChooseBlockSize(RandomSegments(500, 10, 0.5, 1), Cube(10), {.ladder = ladder});
    ASSERT_TRUE(choice) << choice.error().ToString();
    EXPECT_TRUE(choice->whole_scene);
    EXPECT_EQ(choice->block_size, 10.0);
    EXPECT_FALSE(choice->limited_by_length);
  }
}

TEST(ChooseBlockSize, DenseScenesAreHalvedUntilTheMeanFitsTheTarget) {
  BlockSizeRule rule;
  rule.ladder = BlockSizeLadder::kHalvingsOfTheExtent;
  rule.target_segments_per_block = 100;
  rule.min_block_lengths = 1;
  const auto segments = RandomSegments(20000, 64, 0.5, 2);
  const auto choice = ChooseBlockSize(segments, Cube(64), rule);
  ASSERT_TRUE(choice) << choice.error().ToString();
  // Uniform density: 20,000 / 8^k <= 100 first at k = 3 (39 per block), with all 512 occupied.
  EXPECT_EQ(choice->steps, 3);
  EXPECT_EQ(choice->block_size, 8.0);
  EXPECT_EQ(choice->occupied_blocks, 512u);
  EXPECT_LE(choice->mean_segments_per_block, 100.0);
  EXPECT_FALSE(choice->limited_by_length);
}

// Uniform density: the mean is 20,000 * (s / 64)^3 where all blocks are occupied, so the climb
// from the floor (0.5) stops below the 100 the halvings reach at 8: at 0.5 * 2^(18/4) = 11.3
// (6 blocks a side, the last clipped: 92.6 per block); 13.5 (5 a side) holds 160.
TEST(ChooseBlockSize, DenseScenesClimbFromTheFloorUntilAMeanMissesTheTarget) {
  BlockSizeRule rule;
  rule.target_segments_per_block = 100;
  rule.min_block_lengths = 1;
  const auto choice = ChooseBlockSize(RandomSegments(20000, 64, 0.5, 2), Cube(64), rule);
  ASSERT_TRUE(choice) << choice.error().ToString();
  EXPECT_EQ(choice->steps, 18);
  EXPECT_DOUBLE_EQ(choice->block_size, 0.5 * std::exp2(4.5));
  EXPECT_EQ(choice->occupied_blocks, 216u);
  EXPECT_LE(choice->mean_segments_per_block, 100.0);
  EXPECT_FALSE(choice->whole_scene);
  EXPECT_FALSE(choice->limited_by_length);
}

TEST(ChooseBlockSize, BlocksStayLongerThanTheSegments) {
  for (const BlockSizeLadder ladder :
       {BlockSizeLadder::kHalvingsOfTheExtent, BlockSizeLadder::kQuarterOctavesFromTheFloor}) {
    BlockSizeRule rule;
    rule.ladder = ladder;
    rule.target_segments_per_block = 1;  // unreachable
    rule.min_block_lengths = 4;
    const auto choice = ChooseBlockSize(RandomSegments(5000, 64, 2.0, 3), Cube(64), rule);
    ASSERT_TRUE(choice) << choice.error().ToString();
    // Halvings: 64 / 8, as 4 is below 4 * 2. The climb: the floor itself.
    EXPECT_EQ(choice->block_size, 8.0);
    EXPECT_TRUE(choice->limited_by_length);
  }
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
  rule.ladder = BlockSizeLadder::kHalvingsOfTheExtent;
  rule.min_block_lengths = 1;
  rule.target_planes_per_block = 8;
  const auto by_segments = ChooseBlockSize(segments, Cube(64), rule);
  ASSERT_TRUE(by_segments);
  EXPECT_TRUE(by_segments->whole_scene);
  const auto choice = ChooseBlockSize(segments, Cube(64), rule, memberships);
  ASSERT_TRUE(choice) << choice.error().ToString();
  EXPECT_EQ(choice->block_size, 16.0);
  EXPECT_EQ(choice->occupied_blocks, 64u);
  EXPECT_EQ(choice->mean_planes_per_block, 8.0);
  EXPECT_FALSE(ChooseBlockSize(segments, Cube(64), rule, std::span(memberships).first(3)));
}

// Buildings of 8 planes each on a 16 m lattice (within [1, 15] of their cell). A city of 4 x 4
// and one of 12 x 12 buildings have the same density, so the climb gives both the same blocks;
// halvings of the extent give 64 / 2^k and 192 / 2^k, never the same (the city of 1,000
// buildings got 13.3x the cells of the city of 100 that way).
TEST(ChooseBlockSize, TheClimbGivesTheSameBlocksToCitiesOfOneDensity) {
  const auto city = [](int n, BlockSizeLadder ladder) {
    std::vector<Segment3> segments;
    std::vector<PlaneMembership> memberships;
    Rng rng(7);
    for (int cell = 0; cell < n * n; ++cell) {
      const Vec3 corner(16.0 * (cell % n), 16.0 * (cell / n), 0.0);
      for (int p = 0; p < 8; ++p) {
        for (int k = 0; k < 10; ++k) {
          const Vec3 a =
              corner + Vec3(rng.Uniform(1, 14.5), rng.Uniform(1, 15), rng.Uniform(1, 15));
          segments.push_back({a, a + Vec3(0.5, 0, 0)});
          PlaneMembership m;
          m.Add(PlaneId(static_cast<std::size_t>(cell * 8 + p)));
          memberships.push_back(m);
        }
      }
    }
    Box3 box;
    box.Extend(Vec3::Zero());
    box.Extend(Vec3(16.0 * n, 16.0 * n, 16.0));
    BlockSizeRule rule;
    rule.ladder = ladder;
    rule.min_block_lengths = 1;
    rule.target_planes_per_block = 8;
    const auto choice = ChooseBlockSize(segments, box, rule, memberships);
    EXPECT_TRUE(choice) << choice.error().ToString();
    return choice ? choice->block_size : 0.0;
  };
  const double small = city(4, BlockSizeLadder::kQuarterOctavesFromTheFloor);
  EXPECT_GT(small, 0.5);
  EXPECT_LT(small, 64.0);
  EXPECT_EQ(city(12, BlockSizeLadder::kQuarterOctavesFromTheFloor), small);
  EXPECT_NE(city(12, BlockSizeLadder::kHalvingsOfTheExtent),
            city(4, BlockSizeLadder::kHalvingsOfTheExtent));
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
