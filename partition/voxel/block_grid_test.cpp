#include "partition/voxel/block_grid.h"

#include <gtest/gtest.h>

namespace linesurf::partition {
namespace {

TEST(BlockGrid, DiagonalSegmentCrossesExpectedBlocks) {
  Box3 box;
  box.Extend(Vec3(0, 0, 0));
  box.Extend(Vec3(4, 4, 4));
  std::vector<Segment3> segments = {{Vec3(0.5, 0.5, 0.5), Vec3(3.5, 0.5, 0.5)},
                                    {Vec3(0.5, 0.5, 0.5), Vec3(0.5, 0.5, 0.7)}};
  auto grid = BuildBlockGrid(segments, box, BlockGridOptions{.block_size = 1.0});
  ASSERT_TRUE(grid) << grid.error().ToString();
  EXPECT_EQ(grid->dims, Eigen::Vector3i(4, 4, 4));
  ASSERT_EQ(grid->NumBlocks(), 4u);  // x = 0..3 at y = z = 0
  EXPECT_EQ(grid->block_segments[BlockId(0u)].size(), 2u);
  EXPECT_EQ(grid->block_segments[BlockId(3u)].size(), 1u);
  EXPECT_EQ(grid->block_coords[3], Eigen::Vector3i(3, 0, 0));
}

TEST(BlockGrid, RejectsBadBlockSize) {
  Box3 box;
  box.Extend(Vec3(0, 0, 0));
  box.Extend(Vec3(1, 1, 1));
  auto grid = BuildBlockGrid({}, box, BlockGridOptions{.block_size = 0.0});
  ASSERT_FALSE(grid);
  EXPECT_EQ(grid.error().code, ErrorCode::kInvalidOptions);
}

TEST(BlockGrid, RejectsAbsurdSizes) {
  Box3 box;
  box.Extend(Vec3(0, 0, 0));
  box.Extend(Vec3(1e6, 1e6, 1e6));
  auto grid = BuildBlockGrid({}, box, BlockGridOptions{.block_size = 1.0});
  ASSERT_FALSE(grid);
  EXPECT_EQ(grid.error().code, ErrorCode::kResourceExhausted);
}

}  // namespace
}  // namespace linesurf::partition
