#include "partition/voxel/crowded_blocks.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace linesurf::partition {
namespace {

BlockGrid GridOf(const Box3& box, double size) {
  return std::move(BlockGrid::Create(box, size)).value();
}

/// `count` planes reaching each block that holds a point of `crowded`, and one plane reaching
/// every block.
PlaneSupportRegions Regions(const BlockGrid& grid, const std::vector<Vec3>& crowded, int count) {
  std::vector<std::vector<std::int64_t>> plane_blocks(static_cast<std::size_t>(count) + 1);
  for (std::int64_t b = 0; b < grid.NumBaseBlocks(); ++b) plane_blocks[0].push_back(b);
  std::vector<std::int64_t> reached;
  for (const Vec3& p : crowded) reached.push_back(grid.LinearIndex(grid.Locate(p)));
  std::sort(reached.begin(), reached.end());
  reached.erase(std::unique(reached.begin(), reached.end()), reached.end());
  for (int p = 1; p <= count; ++p) plane_blocks[static_cast<std::size_t>(p)] = reached;
  return RegionsFromBlockLists(std::move(plane_blocks));
}

/// Cuts rounds until nothing more is cut; returns the faces added.
std::size_t CutUntilDone(const std::vector<Vec3>& crowded,
                         std::int32_t max_depth,
                         std::int64_t max_blocks,
                         const SplitFaceChooser& chooser,
                         BlockGrid& grid) {
  CutDepths depths = UncutDepths(grid);
  std::size_t total = 0;
  for (;;) {
    const Expected<std::size_t> added = CutCrowdedBlocks(
        Regions(grid, crowded, 30), 24, max_depth, max_blocks, chooser, grid, depths);
    EXPECT_TRUE(added) << added.error().ToString();
    if (!added || *added == 0) return total;
    total += *added;
  }
}

const Box3 kUnitBox{Vec3::Zero(), Vec3::Constant(3.0)};

TEST(CrowdedBlocks, ACrowdedBlockIsCutInTwoAlongEachAxis) {
  BlockGrid grid = GridOf(kUnitBox, 1.0);
  const SplitFaceChooser chooser(kUnitBox, 1.0, {}, {}, {});
  const PlaneSupportRegions regions = Regions(grid, {Vec3(1.5, 1.5, 1.5)}, 30);
  EXPECT_EQ(CountCrowdedBlocks(regions, 24), 1u);
  EXPECT_EQ(CountCrowdedBlocks(regions, 31), 0u);  // 31 planes reach it
  CutDepths depths = UncutDepths(grid);
  ASSERT_EQ(*CutCrowdedBlocks(regions, 24, 2, 1 << 20, chooser, grid, depths), 3u);
  for (int a = 0; a < 3; ++a) {
    EXPECT_EQ(grid.FaceTable(a), (std::vector<double>{0, 1, 1.5, 2, 3})) << a;
    EXPECT_EQ(depths[a], (std::vector<std::int32_t>{0, 1, 1, 0})) << a;
  }
}

TEST(CrowdedBlocks, BlocksAtTheLimitAreLeft) {
  BlockGrid grid = GridOf(kUnitBox, 1.0);
  const SplitFaceChooser chooser(kUnitBox, 1.0, {}, {}, {});
  CutDepths depths = UncutDepths(grid);
  const PlaneSupportRegions regions = Regions(grid, {Vec3(1.5, 1.5, 1.5)}, 30);
  EXPECT_EQ(*CutCrowdedBlocks(regions, 31, 2, 1 << 20, chooser, grid, depths), 0u);
  EXPECT_EQ(grid.dims(), Eigen::Vector3i(3, 3, 3));
}

TEST(CrowdedBlocks, OneFacePerCrowdedIntervalOfEachAxis) {
  BlockGrid grid = GridOf(kUnitBox, 1.0);
  const SplitFaceChooser chooser(kUnitBox, 1.0, {}, {}, {});
  CutDepths depths = UncutDepths(grid);
  const PlaneSupportRegions regions = Regions(grid, {Vec3(2.5, 0.5, 1.5), Vec3(2.5, 1.5, 1.5)}, 30);
  EXPECT_EQ(CountCrowdedBlocks(regions, 24), 2u);
  ASSERT_EQ(*CutCrowdedBlocks(regions, 24, 2, 1 << 20, chooser, grid, depths), 4u);
  EXPECT_EQ(grid.FaceTable(0), (std::vector<double>{0, 1, 2, 2.5, 3}));
  EXPECT_EQ(grid.FaceTable(1), (std::vector<double>{0, 0.5, 1, 1.5, 2, 3}));
  EXPECT_EQ(grid.FaceTable(2), (std::vector<double>{0, 1, 1.5, 2, 3}));
}

// The depth, not the length, decides: on a box and size whose halves come out a rounding error
// short of half the size, and with a wall that moves the first cut off the middle, a block that
// stays crowded is cut exactly `max_depth` times along every axis.
TEST(CrowdedBlocks, AStillCrowdedBlockIsCutToTheDepthWhateverTheLengths) {
  const Box3 box{Vec3(-0.1, 0.3, 1.0 / 3.0), Vec3(2.9, 3.3, 3.0 + 1.0 / 3.0)};
  const std::vector<Plane3> wall{{Vec3(1.4, 0, 0), Vec3::UnitX()}};
  const SplitFaceChooser chooser(box, 1.0, wall, {}, {});
  const Vec3 crowded = Vec3(1.37, 1.77, 1.81);  // stays in a crowded block at every depth
  for (const std::int32_t depth : {1, 2, 3}) {
    SCOPED_TRACE(depth);
    BlockGrid grid = GridOf(box, 1.0);
    EXPECT_EQ(CutUntilDone({crowded}, depth, 1 << 20, chooser, grid), 3u * depth);
    EXPECT_EQ(grid.dims(), Eigen::Vector3i::Constant(3 + depth));
    const Box3 holding = grid.BlockBox(BlockKey{0, grid.Locate(crowded)});
    for (int a = 0; a < 3; ++a) {
      EXPECT_LE(holding.Extent()[a], std::ldexp(1.0, -depth) * 1.5 + 1e-12) << a;
    }
  }
}

// A round that would grow the grid past `max_blocks` cuts nothing.
TEST(CrowdedBlocks, ARoundPastTheBlockBudgetCutsNothing) {
  const SplitFaceChooser chooser(kUnitBox, 1.0, {}, {}, {});
  BlockGrid grid = GridOf(kUnitBox, 1.0);
  EXPECT_EQ(CutUntilDone({Vec3(1.5, 1.5, 1.5)}, 2, 63, chooser, grid), 0u);
  EXPECT_EQ(grid.dims(), Eigen::Vector3i(3, 3, 3));
  EXPECT_EQ(CutUntilDone({Vec3(1.5, 1.5, 1.5)}, 2, 64, chooser, grid), 3u);
}

}  // namespace
}  // namespace linesurf::partition
