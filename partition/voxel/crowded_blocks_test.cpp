#include "partition/voxel/crowded_blocks.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace linesurf::partition {
namespace {

BlockGrid UnitGrid() {
  return std::move(BlockGrid::Create(Box3{Vec3::Zero(), Vec3::Constant(3.0)}, 1.0)).value();
}

/// `count` planes reaching each block of `crowded`, and one plane reaching every block.
PlaneSupportRegions Regions(const BlockGrid& grid,
                            const std::vector<Eigen::Vector3i>& crowded,
                            int count) {
  std::vector<std::vector<std::int64_t>> plane_blocks(static_cast<std::size_t>(count) + 1);
  for (std::int64_t b = 0; b < grid.NumBaseBlocks(); ++b) plane_blocks[0].push_back(b);
  for (int p = 1; p <= count; ++p) {
    for (const Eigen::Vector3i& base : crowded) {
      plane_blocks[static_cast<std::size_t>(p)].push_back(grid.LinearIndex(base));
    }
    std::sort(plane_blocks[static_cast<std::size_t>(p)].begin(),
              plane_blocks[static_cast<std::size_t>(p)].end());
  }
  return RegionsFromBlockLists(std::move(plane_blocks));
}

const Box3 kBox{Vec3::Zero(), Vec3::Constant(3.0)};

TEST(CrowdedBlocks, ACrowdedBlockIsCutInTwoAlongEachAxis) {
  const BlockGrid grid = UnitGrid();
  const PlaneSupportRegions regions = Regions(grid, {Eigen::Vector3i(1, 1, 1)}, 30);
  const SplitFaceChooser chooser(kBox, 1.0, {}, {}, {});
  EXPECT_EQ(CountCrowdedBlocks(regions, 24), 1u);
  const auto faces = FacesSplittingCrowdedBlocks(grid, regions, 24, 0.5, chooser);
  for (int a = 0; a < 3; ++a) EXPECT_EQ(faces[a], std::vector<double>{1.5}) << a;
}

TEST(CrowdedBlocks, BlocksAtTheLimitOrIntervalsTooShortAreLeft) {
  const BlockGrid grid = UnitGrid();
  const PlaneSupportRegions regions = Regions(grid, {Eigen::Vector3i(1, 1, 1)}, 30);
  const SplitFaceChooser chooser(kBox, 1.0, {}, {}, {});
  // 31 planes reach the block (the one reaching every block too).
  EXPECT_EQ(CountCrowdedBlocks(regions, 31), 0u);
  for (const auto& axis : FacesSplittingCrowdedBlocks(grid, regions, 31, 0.5, chooser)) {
    EXPECT_TRUE(axis.empty());
  }
  for (const auto& axis : FacesSplittingCrowdedBlocks(grid, regions, 24, 1.01, chooser)) {
    EXPECT_TRUE(axis.empty());
  }
}

TEST(CrowdedBlocks, OneFacePerCrowdedIntervalOfEachAxis) {
  const BlockGrid grid = UnitGrid();
  const PlaneSupportRegions regions =
      Regions(grid, {Eigen::Vector3i(2, 0, 1), Eigen::Vector3i(2, 1, 1)}, 30);
  const SplitFaceChooser chooser(kBox, 1.0, {}, {}, {});
  EXPECT_EQ(CountCrowdedBlocks(regions, 24), 2u);
  const auto faces = FacesSplittingCrowdedBlocks(grid, regions, 24, 0.5, chooser);
  EXPECT_EQ(faces[0], std::vector<double>{2.5});
  EXPECT_EQ(faces[1], (std::vector<double>{0.5, 1.5}));
  EXPECT_EQ(faces[2], std::vector<double>{1.5});
}

}  // namespace
}  // namespace linesurf::partition
