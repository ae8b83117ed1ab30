#include "partition/voxel/active_blocks.h"

#include "engine/core/rng.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace linesurf::partition {
namespace {

BlockGrid UnitGrid(int n) {
  Box3 box;
  box.Extend(Vec3(0, 0, 0));
  box.Extend(Vec3(n, n, n));
  return std::move(BlockGrid::Create(box, 1.0)).value();
}

TEST(BlocksCrossed, DiagonalSegmentCrossesExpectedBlocks) {
  const BlockGrid grid = UnitGrid(4);
  const auto blocks = BlocksCrossed(grid, {Vec3(0.5, 0.5, 0.5), Vec3(3.5, 0.5, 0.5)});
  ASSERT_EQ(blocks.size(), 4u);
  for (int i = 0; i < 4; ++i) EXPECT_EQ(blocks[i], Eigen::Vector3i(i, 0, 0));
  const auto diagonal = BlocksCrossed(grid, {Vec3(0.2, 0.1, 0.5), Vec3(2.7, 1.9, 0.5)});
  // Crosses x = 1 (t 0.32), y = 1 (t 0.5), x = 2 (t 0.72).
  const std::vector<Eigen::Vector3i> expected{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {2, 1, 0}};
  EXPECT_EQ(diagonal, expected);
}

// Brute force: a block is crossed when some of 2,000 samples along the segment lies in it; the
// DDA must list every such block, ends in the endpoint blocks and moves one face at a time.
TEST(BlocksCrossed, ListsEveryBlockASampledSegmentVisits) {
  const BlockGrid grid = UnitGrid(6);
  Rng rng(11);
  for (int trial = 0; trial < 200; ++trial) {
    const Segment3 s{Vec3(rng.Uniform(0, 6), rng.Uniform(0, 6), rng.Uniform(0, 6)),
                     Vec3(rng.Uniform(0, 6), rng.Uniform(0, 6), rng.Uniform(0, 6))};
    const auto blocks = BlocksCrossed(grid, s);
    EXPECT_EQ(blocks.front(), grid.Locate(s.p1));
    EXPECT_EQ(blocks.back(), grid.Locate(s.p2));
    for (std::size_t i = 1; i < blocks.size(); ++i) {
      EXPECT_EQ((blocks[i] - blocks[i - 1]).cwiseAbs().sum(), 1);
    }
    for (int k = 0; k <= 2000; ++k) {
      const Vec3 p = s.p1 + (k / 2000.0) * (s.p2 - s.p1);
      const Eigen::Vector3i b = grid.Locate(p);
      EXPECT_NE(std::find(blocks.begin(), blocks.end(), b), blocks.end()) << trial << " " << k;
    }
  }
}

TEST(RasteriseSegments, ListsBlocksInLinearOrderWithTheirSegments) {
  const BlockGrid grid = UnitGrid(4);
  const std::vector<Segment3> segments = {{Vec3(0.5, 0.5, 0.5), Vec3(3.5, 0.5, 0.5)},
                                          {Vec3(0.5, 3.5, 3.5), Vec3(0.5, 3.5, 3.7)},
                                          {Vec3(0.5, 0.5, 0.5), Vec3(0.5, 0.5, 0.7)}};
  const ActiveBlocks active = RasteriseSegments(grid, segments);
  ASSERT_EQ(active.blocks.size(), 5u);
  EXPECT_TRUE(std::is_sorted(active.blocks.begin(), active.blocks.end()));
  EXPECT_EQ(active.blocks.front(), 0);
  EXPECT_EQ(active.segments[BlockId(0u)].size(), 2u);
  EXPECT_EQ(active.blocks.back(), grid.LinearIndex({0, 3, 3}));
  EXPECT_EQ(active.segments[BlockId(4u)][0], SegmentId(1u));
}

TEST(DilateBlocks, GrowsByTheMarginInTheChebyshevNorm) {
  const BlockGrid grid = UnitGrid(9);
  const std::vector<std::int64_t> seed{grid.LinearIndex({4, 4, 4}), grid.LinearIndex({0, 0, 0})};
  for (int margin = 0; margin <= 3; ++margin) {
    const std::vector<std::int64_t> grown = DilateBlocks(grid, seed, margin);
    EXPECT_TRUE(std::is_sorted(grown.begin(), grown.end()));
    std::vector<std::int64_t> expected;
    for (std::int64_t b = 0; b < grid.NumBaseBlocks(); ++b) {
      const Eigen::Vector3i c = grid.BaseFromLinear(b);
      const int d0 = (c - Eigen::Vector3i(4, 4, 4)).cwiseAbs().maxCoeff();
      const int d1 = c.cwiseAbs().maxCoeff();
      if (std::min(d0, d1) <= margin) expected.push_back(b);
    }
    EXPECT_EQ(grown, expected) << margin;
  }
}

}  // namespace
}  // namespace linesurf::partition
