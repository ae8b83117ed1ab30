#include "engine/pipeline/block_partition.h"

#include "engine/core/rng.h"
#include "partition/voxel/active_blocks.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace linesurf::pipeline {
namespace {

// The six faces of the cube [0, 2]^3, 40 short segments on each face (its inliers), seen from
// one viewpoint; the scene box is [-1, 3]^3.
Scene CubeScene() {
  Scene scene;
  Rng rng(17);
  scene.viewpoints.push_back(Vec3(2.8, 2.7, 2.9));
  for (int axis = 0; axis < 3; ++axis) {
    for (int side = 0; side < 2; ++side) {
      const PlaneId id = scene.planes.NextId();
      Plane3 plane;
      plane.point = Vec3::Zero();
      plane.point[axis] = 2.0 * side;
      plane.normal = Vec3::Zero();
      plane.normal[axis] = side == 0 ? -1.0 : 1.0;
      scene.planes.push_back(plane);
      for (int i = 0; i < 40; ++i) {
        Vec3 a(rng.Uniform(0.1, 1.9), rng.Uniform(0.1, 1.9), rng.Uniform(0.1, 1.9));
        a[axis] = 2.0 * side;
        Vec3 b = a;
        b[(axis + 1) % 3] += 0.1;
        scene.segments.push_back({a, b});
        scene.observations.AddRow(std::array<ViewpointId, 1>{ViewpointId(0u)});
        PlaneMembership m;
        m.Add(id);
        scene.memberships.push_back(m);
      }
    }
  }
  return scene;
}

Box3 SceneBox() { return Box3{Vec3::Constant(-1.0), Vec3::Constant(3.0)}; }

BlockPartition Build(const Scene& scene, const BlockPartitionOptions& options) {
  Expected<BlockPartition> p = BuildBlockPartition(scene, SceneBox(), options, {});
  EXPECT_TRUE(p) << p.error().ToString();
  return std::move(p).value();
}

TEST(BuildBlockPartition, CubeFacesOnBlockFacesAreKeptAndTheComplexesAreValid) {
  const Scene scene = CubeScene();
  BlockPartitionOptions options;
  options.block_size = 1.0;  // faces at -1, 0, 1, 2, 3: the cube's planes lie on block faces
  options.support.margin_blocks = 1.0;  // regions reach the blocks on both sides of a face
  const BlockPartition p = Build(scene, options);
  const Status ok = partition::ValidateBlockComplexes(p.complexes);
  EXPECT_TRUE(ok) << ok.error().ToString();
  EXPECT_EQ(p.stats.dims, Eigen::Vector3i(4, 4, 4));
  EXPECT_FALSE(p.stats.automatic_size);
  EXPECT_EQ(p.stats.planes_without_inliers, 0u);
  // No plane crosses a block interior, so every block is one cell; each plane lies on the faces
  // of the blocks its region reaches on both sides of it.
  EXPECT_EQ(p.complexes.stats.cells, 64u);
  EXPECT_GT(p.complexes.stats.planes_on_faces, 6u * 4u * 2u);
  // Every inlier's blocks are in its plane's region.
  for (std::size_t s = 0; s < scene.segments.size(); ++s) {
    const PlaneId plane = scene.memberships[SegmentId(s)].planes[0];
    const auto region = p.regions.plane_blocks[plane];
    for (const auto& c : partition::BlocksCrossed(p.complexes.grid, scene.segments[SegmentId(s)])) {
      EXPECT_TRUE(
          std::binary_search(region.begin(), region.end(), p.complexes.grid.LinearIndex(c)));
    }
  }
}

TEST(BuildBlockPartition, PlanesSplitOnlyTheBlocksOfTheirRegions) {
  const Scene scene = CubeScene();
  BlockPartitionOptions options;
  options.block_size = 1.5;  // faces at -1, 0.5, 2, 3: x = 2 etc. on faces, x = 0 inside blocks
  options.support.margin_blocks = 0;
  const BlockPartition p = Build(scene, options);
  const Status ok = partition::ValidateBlockComplexes(p.complexes);
  EXPECT_TRUE(ok) << ok.error().ToString();
  // The plane x = 0 reaches only the blocks with x index 0 whose y, z range meets the face.
  const auto region = p.regions.plane_blocks[PlaneId(0u)];
  for (const std::int64_t b : region) EXPECT_EQ(p.complexes.grid.BaseFromLinear(b).x(), 0);
  EXPECT_EQ(region.size(), 4u);  // y, z in blocks 0..1 (the cube spans [0.1, 1.9])
  std::size_t split = 0;
  for (const auto& block : p.complexes.blocks) split += block.complex.NumCells() > 1 ? 1 : 0;
  EXPECT_GT(split, 0u);
  EXPECT_LT(split, p.complexes.blocks.size());
}

TEST(BuildBlockPartition, AutomaticSizeOfASmallSceneIsOneBlock) {
  const Scene scene = CubeScene();
  const BlockPartition p = Build(scene, BlockPartitionOptions{});
  EXPECT_TRUE(p.stats.automatic_size);
  EXPECT_EQ(p.stats.block_size, 4.0);
  EXPECT_EQ(p.complexes.blocks.size(), 1u);
  const auto mono = partition::BuildCellComplex(SceneBox(), scene.planes.raw(), {}, {});
  ASSERT_TRUE(mono);
  EXPECT_EQ(p.complexes.blocks[0].complex.NumCells(), mono->complex.NumCells());
  EXPECT_EQ(p.complexes.blocks[0].complex.vertex_points.raw(), mono->complex.vertex_points.raw());
}

// With a limit of 2 planes the cube's one automatic block is crowded: the first round cuts
// it at the middle of the box, the second cuts the halves again, with the faces kept off the
// cube's walls that lie on those middles. A given size is taken as it is.
TEST(BuildBlockPartition, CrowdedAutomaticBlocksAreCutOffTheWalls) {
  const Scene scene = CubeScene();
  BlockPartitionOptions options;
  options.crowded_planes_per_block = 2;
  const BlockPartition p = Build(scene, options);
  const Status ok = partition::ValidateBlockComplexes(p.complexes);
  EXPECT_TRUE(ok) << ok.error().ToString();
  EXPECT_EQ(p.stats.block_size, 4.0);
  EXPECT_EQ(p.stats.crowded_split_faces, 3u + 6u);
  EXPECT_EQ(p.stats.dims, Eigen::Vector3i(4, 4, 4));
  for (int a = 0; a < 3; ++a) {
    const std::vector<double>& faces = p.complexes.grid.FaceTable(a);
    EXPECT_EQ(faces[2], 1.0);
    for (const double wall : {0.0, 2.0}) {
      EXPECT_GE(std::abs(faces[wall == 0.0 ? 1 : 3] - wall), 1e-6 * 4.0);
      EXPECT_LT(std::abs(faces[wall == 0.0 ? 1 : 3] - wall), 0.5);
    }
  }

  options.block_size = 4.0;
  const BlockPartition given = Build(scene, options);
  EXPECT_EQ(given.stats.crowded_split_faces, 0u);
  EXPECT_EQ(given.complexes.blocks.size(), 1u);
}

TEST(BuildBlockPartition, RejectsBadOptionsAndMissingInliers) {
  Scene scene = CubeScene();
  BlockPartitionOptions bad;
  bad.block_size = -1.0;
  EXPECT_FALSE(BuildBlockPartition(scene, SceneBox(), bad, {}));
  bad = {};
  bad.support.margin_blocks = 100;
  EXPECT_FALSE(BuildBlockPartition(scene, SceneBox(), bad, {}));
  bad = {};
  bad.crowded_cut_depth = -1;
  const auto rounds = BuildBlockPartition(scene, SceneBox(), bad, {});
  ASSERT_FALSE(rounds);
  EXPECT_NE(rounds.error().message.find("crowded_cut_depth"), std::string::npos);
  scene.memberships.clear();
  const auto r = BuildBlockPartition(scene, SceneBox(), {}, {});
  ASSERT_FALSE(r);
  EXPECT_EQ(r.error().code, ErrorCode::kInvalidInput);
}

}  // namespace
}  // namespace linesurf::pipeline
