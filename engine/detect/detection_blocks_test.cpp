#include "engine/detect/detection_blocks.h"

#include "engine/core/rng.h"
#include "engine/detect/detect_planes.h"
#include "partition/voxel/active_blocks.h"
#include "partition/voxel/plane_support.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace linesurf::detect {
namespace {

using partition::BlockGrid;

// Random short segments: a dense cluster in [0, 2]^3 and a sparse spread over [0, 20]^3.
std::vector<Segment3> ClusteredSegments() {
  Rng rng(7);
  std::vector<Segment3> segments;
  for (int i = 0; i < 600; ++i) {
    const double extent = i < 400 ? 2.0 : 20.0;
    const Vec3 a(rng.Uniform(0, extent), rng.Uniform(0, extent), rng.Uniform(0, extent));
    segments.push_back({a, a + Vec3(rng.Uniform(-0.3, 0.3), rng.Uniform(-0.3, 0.3), 0.1)});
  }
  return segments;
}

BlockGrid GridOf(std::span<const Segment3> segments, double size) {
  return std::move(BlockGrid::Create(MidpointBox(segments), size)).value();
}

bool Inside(const Vec3& p, const Box3& box, double margin) {
  return (p.array() >= box.min.array() - margin).all() &&
         (p.array() <= box.max.array() + margin).all();
}

/// Home test of the grid: half-open boxes, closed at the grid box's maximum.
bool IsHome(const Vec3& m, const Box3& block, const Box3& grid_box) {
  for (int a = 0; a < 3; ++a) {
    if (m[a] < block.min[a]) return false;
    if (m[a] >= block.max[a] && !(block.max[a] == grid_box.max[a] && m[a] == block.max[a])) {
      return false;
    }
  }
  return true;
}

TEST(AssignDetectionBlocks, CrowdedBlocksAreSplitAndEveryBlockSeesItsHalo) {
  const std::vector<Segment3> segments = ClusteredSegments();
  const BlockGrid grid = GridOf(segments, 5.0);
  BlockLayout layout;
  layout.halo = 0.1;
  layout.max_home_segments = 60;
  const std::vector<DetectionBlock> blocks = AssignDetectionBlocks(segments, grid, layout);
  ASSERT_FALSE(blocks.empty());
  std::vector<int> homes(segments.size(), 0);
  int split = 0;
  for (const DetectionBlock& block : blocks) {
    split += block.key.level > 0 ? 1 : 0;
    EXPECT_EQ(block.box.min, grid.BlockBox(block.key).min);  // the grid's blocks, exactly
    EXPECT_EQ(block.box.max, grid.BlockBox(block.key).max);
    const double halo = layout.halo * std::ldexp(grid.block_size(), -block.key.level);
    EXPECT_TRUE(std::is_sorted(block.segments.begin(), block.segments.end()));
    std::size_t home_count = 0;
    for (std::size_t i = 0; i < segments.size(); ++i) {
      const Vec3 m = segments[i].Midpoint();
      const bool listed =
          std::binary_search(block.segments.begin(), block.segments.end(), SegmentId(i));
      // Everything within the halo is listed; nothing beyond it is (1e-9 for rounding).
      EXPECT_TRUE(!Inside(m, block.box, halo - 1e-9) || listed) << i;
      EXPECT_TRUE(!listed || Inside(m, block.box, halo + 1e-9)) << i;
      const bool home = IsHome(m, block.box, grid.box());
      homes[i] += home ? 1 : 0;
      home_count += home ? 1 : 0;
      EXPECT_EQ(
          home,
          std::binary_search(block.home_segments.begin(), block.home_segments.end(), SegmentId(i)))
          << i;
    }
    EXPECT_LE(home_count, layout.max_home_segments);
    EXPECT_EQ(block.home_segments.size(), home_count);
  }
  EXPECT_GT(split, 8);  // the cluster's block was split (at least once)
  for (std::size_t i = 0; i < segments.size(); ++i) EXPECT_EQ(homes[i], 1) << i;
}

TEST(SplitDetectionBlock, ChildrenShareTheParentsHomeSegmentsAndSeeTheirOwnHalo) {
  const std::vector<Segment3> segments = ClusteredSegments();
  const BlockGrid grid = GridOf(segments, 5.0);
  const double halo = 0.2;
  const std::vector<DetectionBlock> blocks =
      AssignDetectionBlocks(segments, grid, BlockLayout{.halo = halo, .max_home_segments = 0});
  const auto crowded = std::max_element(
      blocks.begin(), blocks.end(), [](const DetectionBlock& a, const DetectionBlock& b) {
        return a.home_segments.size() < b.home_segments.size();
      });
  ASSERT_GT(crowded->home_segments.size(), 300u);  // the dense cluster
  const std::vector<DetectionBlock> children = SplitDetectionBlock(segments, grid, *crowded, halo);
  ASSERT_GE(children.size(), 2u);
  std::vector<SegmentId> homes;
  for (const DetectionBlock& child : children) {
    EXPECT_EQ(child.key.level, 1);
    EXPECT_EQ(child.key.index / 2, crowded->key.index);
    EXPECT_FALSE(child.home_segments.empty());
    const double child_halo = halo * grid.block_size() / 2.0;
    for (std::size_t i = 0; i < segments.size(); ++i) {
      const Vec3 m = segments[i].Midpoint();
      const bool in_parent =
          std::binary_search(crowded->segments.begin(), crowded->segments.end(), SegmentId(i));
      const bool listed =
          std::binary_search(child.segments.begin(), child.segments.end(), SegmentId(i));
      EXPECT_TRUE(!in_parent || !Inside(m, child.box, child_halo - 1e-9) || listed) << i;
      EXPECT_TRUE(!listed || Inside(m, child.box, child_halo + 1e-9)) << i;
      EXPECT_TRUE(!listed || in_parent) << i;
    }
    homes.insert(homes.end(), child.home_segments.begin(), child.home_segments.end());
  }
  std::sort(homes.begin(), homes.end());
  EXPECT_EQ(homes, crowded->home_segments);
}

TEST(AssignDetectionBlocks, WithoutALimitTheGridIsKept) {
  const std::vector<Segment3> segments = ClusteredSegments();
  const std::vector<DetectionBlock> blocks =
      AssignDetectionBlocks(segments, GridOf(segments, 5.0), BlockLayout{});
  EXPECT_GT(blocks.size(), 8u);
  for (const DetectionBlock& block : blocks) EXPECT_EQ(block.key.level, 0);
}

// A slightly tilted wall 50 long and 4 high, 600 noisy segments, in blocks of 5: detected in ten
// blocks, fused into one plane whose support region (margin 1) covers every inlier's blocks.
TEST(AssignDetectionBlocks, OneWallAcrossTenBlocksIsOnePlane) {
  Rng rng(21);
  Scene scene;
  scene.viewpoints.push_back(Vec3(20, 25, 2));
  const Vec3 normal = Vec3(1, -0.02, 0).normalized();
  const auto on_wall = [&](double y, double z) { return Vec3(1.0 + 0.02 * y, y, z); };
  for (int i = 0; i < 600; ++i) {
    const double y = rng.Uniform(0, 49), z = rng.Uniform(0, 3.5);
    const double angle = rng.Uniform(0, 3.14159);
    const double length = rng.Uniform(0.3, 0.9);
    const Vec3 a = on_wall(y, z);
    const Vec3 b = on_wall(y + length * std::cos(angle), z + length * std::sin(angle));
    const auto noise = [&]() -> Vec3 {
      const Vec3 unit(rng.Uniform(-1, 1), rng.Uniform(-1, 1), rng.Uniform(-1, 1));
      return 0.002 * unit;
    };
    scene.segments.push_back({a + noise(), b + noise()});
    scene.observations.AddRow(std::array<ViewpointId, 1>{ViewpointId(0u)});
  }
  PlaneDetectionOptions options;
  options.epsilon = 0.02;
  options.block_size = 5.0;
  const auto detected = DetectPlanes(scene, options, {});
  ASSERT_TRUE(detected) << detected.error().ToString();
  EXPECT_EQ(detected->stats.blocks, 10);
  ASSERT_EQ(detected->planes.size(), 1u);
  EXPECT_GT(std::abs(detected->planes[PlaneId(0u)].normal.dot(normal)), 0.9999);
  const std::vector<SegmentId>& inliers = detected->support[PlaneId(0u)].inliers;
  EXPECT_GE(inliers.size(), 590u);

  const BlockGrid grid = GridOf(scene.segments.raw(), 5.0);
  const std::vector<std::vector<SegmentId>> per_plane{inliers};
  const std::vector<Plane3> planes{detected->planes[PlaneId(0u)]};
  const auto regions =
      partition::ComputePlaneSupport(grid, scene.segments.raw(), planes, per_plane, {}, {});
  ASSERT_TRUE(regions) << regions.error().ToString();
  const auto region = regions->plane_blocks[PlaneId(0u)];
  EXPECT_EQ(region.size(), static_cast<std::size_t>(grid.NumBaseBlocks()));  // all 10 (1 x 10 x 1)
  for (const SegmentId s : inliers) {
    for (const auto& c : partition::BlocksCrossed(grid, scene.segments[s])) {
      EXPECT_TRUE(std::binary_search(region.begin(), region.end(), grid.LinearIndex(c)));
    }
  }
}

}  // namespace
}  // namespace linesurf::detect
