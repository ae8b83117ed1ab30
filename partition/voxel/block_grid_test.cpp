#include "partition/voxel/block_grid.h"

#include "engine/core/rng.h"

#include <gtest/gtest.h>

namespace linesurf::partition {
namespace {

BlockGrid MakeGrid(const Box3& box, double size) {
  Expected<BlockGrid> grid = BlockGrid::Create(box, size);
  EXPECT_TRUE(grid) << grid.error().ToString();
  return std::move(grid).value();
}

// Sizes and offsets where min + i * s + s and min + (i + 1) * s round differently: the old grid
// gave neighbouring blocks faces an ulp apart there.
TEST(BlockGrid, NeighboursShareTheirFacesExactly) {
  const BlockGrid grid = MakeGrid(Box3{Vec3(-0.1, -13.7, 1e3 / 3), Vec3(9.3, 2.2, 500)}, 0.7);
  EXPECT_EQ(grid.dims(), Eigen::Vector3i(14, 23, 239));
  int checked = 0;
  for (int a = 0; a < 3; ++a) {
    for (int i = 0; i + 1 < grid.dims()[a]; ++i) {
      BlockKey lo{0, Eigen::Vector3i::Zero()};
      lo.index[a] = i;
      BlockKey hi = lo;
      hi.index[a] = i + 1;
      ASSERT_EQ(grid.BlockBox(lo).max[a], grid.BlockBox(hi).min[a]) << a << " " << i;
      ++checked;
    }
  }
  EXPECT_EQ(checked, 13 + 22 + 238);
}

TEST(BlockGrid, TheBlocksCoverTheBoxExactlyAndTheLastIsClipped) {
  const Box3 box = Box3{Vec3(0.1, 0.2, 0.3), Vec3(10.1, 1.2, 0.4)};
  const BlockGrid grid = MakeGrid(box, 3.0);
  EXPECT_EQ(grid.dims(), Eigen::Vector3i(4, 1, 1));
  EXPECT_EQ(grid.BlockBox({0, {0, 0, 0}}).min, box.min);
  EXPECT_EQ(grid.BlockBox({0, {3, 0, 0}}).max, box.max);
  EXPECT_DOUBLE_EQ(grid.BlockBox({0, {3, 0, 0}}).Extent().x(), 1.0);
}

TEST(BlockGrid, OneBlockIsTheBoxItself) {
  const Box3 box = Box3{Vec3(-0.1, -0.7, 2.3), Vec3(0.3, 0.9, 2.9)};
  const BlockGrid grid = MakeGrid(box, 100.0);
  EXPECT_EQ(grid.NumBaseBlocks(), 1);
  const Box3 only = grid.BlockBox({0, {0, 0, 0}});
  EXPECT_EQ(only.min, box.min);
  EXPECT_EQ(only.max, box.max);
}

TEST(BlockGrid, WholeBlocksAreCubesFromTheOrigin) {
  const Vec3 origin(-0.3, 0.1, 7.7);
  auto grid = BlockGrid::CreateWholeBlocks(origin, 0.7, Eigen::Vector3d(3, 1, 2.9));
  ASSERT_TRUE(grid) << grid.error().ToString();
  EXPECT_EQ(grid->dims(), Eigen::Vector3i(3, 1, 2));
  for (int a = 0; a < 3; ++a) {
    for (std::size_t i = 0; i < grid->FaceTable(a).size(); ++i) {
      EXPECT_EQ(grid->FaceTable(a)[i], origin[a] + static_cast<double>(i) * 0.7);
    }
  }
  EXPECT_EQ(grid->box().max.z(), origin.z() + 2 * 0.7);
  EXPECT_FALSE(BlockGrid::CreateWholeBlocks(origin, 0.7, Eigen::Vector3d(0, 1, 1)));
}

TEST(BlockGrid, ChildrenTileTheirParentWithSharedFaces) {
  const BlockGrid grid = MakeGrid(Box3{Vec3(-0.1, -0.3, 0.7), Vec3(2.9, 3.1, 3.3)}, 0.9);
  ASSERT_EQ(grid.dims(), Eigen::Vector3i(4, 4, 3));
  const BlockKey parent{0, {1, 2, 2}};  // the last layer along z: clipped at the box
  const Box3 pb = grid.BlockBox(parent);
  double volume = 0.0;
  for (const BlockKey& child : grid.Children(parent)) {
    const Box3 cb = grid.BlockBox(child);
    volume += cb.Extent().prod();
    for (int a = 0; a < 3; ++a) {
      // A child face on the parent's boundary is the parent's face, bit for bit.
      if (child.index[a] % 2 == 0) {
        EXPECT_EQ(cb.min[a], pb.min[a]);
      } else {
        EXPECT_EQ(cb.max[a], pb.max[a]);
      }
    }
    // Grandchildren at the far corner meet the neighbour base block exactly.
    const BlockKey grand = grid.Children(child)[7];
    EXPECT_EQ(grid.BlockBox(grand).max, cb.max);
  }
  EXPECT_NEAR(volume, pb.Extent().prod(), 1e-12);
  // The two level-1 children along x meet on one face.
  EXPECT_EQ(grid.BlockBox({1, {2, 4, 4}}).max.x(), grid.BlockBox({1, {3, 4, 4}}).min.x());
}

TEST(BlockGrid, LocateAgreesWithTheBlockBoxes) {
  const BlockGrid grid = MakeGrid(Box3{Vec3(-1, -2, -3), Vec3(4, 5, 6)}, 0.37);
  Rng rng(3);
  for (int i = 0; i < 2000; ++i) {
    Vec3 p(rng.Uniform(-1, 4), rng.Uniform(-2, 5), rng.Uniform(-3, 6));
    if (i % 3 == 0) p.x() = grid.FaceTable(0)[i % grid.FaceTable(0).size()];  // on a face
    const Eigen::Vector3i b = grid.Locate(p);
    const Box3 box = grid.BlockBox({0, b});
    for (int a = 0; a < 3; ++a) {
      EXPECT_LE(box.min[a], p[a]);
      // Half-open, except the last block, which is closed at the box.
      if (b[a] + 1 < grid.dims()[a]) {
        EXPECT_LT(p[a], box.max[a]);
      }
      EXPECT_LE(p[a], box.max[a]);
    }
    const BlockKey child = grid.ChildHolding({0, b}, p);
    const Box3 cb = grid.BlockBox(child);
    EXPECT_TRUE(cb.Contains(p));
    EXPECT_EQ(grid.BaseFromLinear(grid.LinearIndex(b)), b);
  }
  EXPECT_EQ(grid.Locate(Vec3(-10, 10, 0)), Eigen::Vector3i(0, grid.dims().y() - 1, 8));
}

TEST(BlockGrid, RejectsBadSizesAndBoxes) {
  const Box3 unit = Box3{Vec3(0, 0, 0), Vec3(1, 1, 1)};
  for (const double size : {0.0, -1.0, std::nan(""), std::numeric_limits<double>::infinity()}) {
    auto grid = BlockGrid::Create(unit, size);
    ASSERT_FALSE(grid);
    EXPECT_EQ(grid.error().code, ErrorCode::kInvalidOptions);
  }
  auto flat = BlockGrid::Create(Box3{Vec3(0, 0, 0), Vec3(1, 1, 0)}, 0.5);
  ASSERT_FALSE(flat);
  EXPECT_EQ(flat.error().code, ErrorCode::kInvalidInput);
  auto huge = BlockGrid::Create(Box3{Vec3(0, 0, 0), Vec3(1e6, 1e6, 1e6)}, 1.0);
  ASSERT_FALSE(huge);
  EXPECT_EQ(huge.error().code, ErrorCode::kResourceExhausted);
}

// A face added inside a slab cuts every block of that slab: the neighbours across it share it,
// points locate on the right side, and the nominal size stays.
TEST(BlockGrid, AddedFacesCutWholeSlabsAndAreShared) {
  const BlockGrid base = MakeGrid(Box3{Vec3(0, 0, 0), Vec3(4, 3, 2)}, 1.0);
  Expected<BlockGrid> cut = base.WithFaces({std::vector<double>{1.25, 3.0, 1.25}, {}, {0.5}});
  ASSERT_TRUE(cut) << cut.error().ToString();
  EXPECT_EQ(cut->dims(), Eigen::Vector3i(5, 3, 3));  // 3.0 is a face already; 1.25 comes once
  EXPECT_EQ(cut->FaceTable(0), (std::vector<double>{0, 1, 1.25, 2, 3, 4}));
  EXPECT_EQ(cut->FaceTable(2), (std::vector<double>{0, 0.5, 1, 2}));
  EXPECT_EQ(cut->block_size(), 1.0);
  EXPECT_EQ(cut->box().min, base.box().min);
  EXPECT_EQ(cut->box().max, base.box().max);
  EXPECT_EQ(cut->Locate(Vec3(1.2, 0.5, 0.4)), Eigen::Vector3i(1, 0, 0));
  EXPECT_EQ(cut->Locate(Vec3(1.25, 0.5, 0.5)), Eigen::Vector3i(2, 0, 1));
  const BlockKey lo{0, Eigen::Vector3i(1, 2, 0)};
  const BlockKey hi{0, Eigen::Vector3i(2, 2, 0)};
  EXPECT_EQ(cut->BlockBox(lo).max.x(), 1.25);
  EXPECT_EQ(cut->BlockBox(hi).min.x(), 1.25);
}

TEST(BlockGrid, AddedFacesOutsideTheBoxAreRejected) {
  const BlockGrid base = MakeGrid(Box3{Vec3(0, 0, 0), Vec3(4, 3, 2)}, 1.0);
  for (const double x : {0.0, 2.0, -0.5, std::nan("")}) {
    Expected<BlockGrid> cut = base.WithFaces({std::vector<double>{}, {}, {x}});
    ASSERT_FALSE(cut) << x;
    EXPECT_EQ(cut.error().code, ErrorCode::kInvalidInput);
    EXPECT_NE(cut.error().message.find("axis 2"), std::string::npos) << cut.error().message;
  }
}

}  // namespace
}  // namespace linesurf::partition
