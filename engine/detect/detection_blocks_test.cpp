#include "engine/detect/detection_blocks.h"

#include "engine/core/rng.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace linesurf::detect {
namespace {

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

bool Inside(const Vec3& p, const Box3& box, double margin) {
  return (p.array() >= box.min.array() - margin).all() &&
         (p.array() <= box.max.array() + margin).all();
}

TEST(AssignDetectionBlocks, CrowdedBlocksAreSplitAndEveryBlockSeesItsHalo) {
  const std::vector<Segment3> segments = ClusteredSegments();
  BlockLayout layout;
  layout.block_size = 5.0;
  layout.halo = 0.1;
  layout.max_home_segments = 60;
  const std::vector<DetectionBlock> blocks = AssignDetectionBlocks(segments, layout);
  ASSERT_FALSE(blocks.empty());
  std::vector<int> homes(segments.size(), 0);
  int split = 0;
  for (const DetectionBlock& block : blocks) {
    split += block.depth > 0 ? 1 : 0;
    const double side = block.box.Extent().x();
    const double halo = layout.halo * side;
    EXPECT_TRUE(std::is_sorted(block.segments.begin(), block.segments.end()));
    std::size_t home_count = 0;
    for (std::size_t i = 0; i < segments.size(); ++i) {
      const Vec3 m = segments[i].Midpoint();
      const bool listed =
          std::binary_search(block.segments.begin(), block.segments.end(), SegmentId(i));
      // Everything within the halo is listed; nothing beyond it is (1e-9 for rounding).
      EXPECT_TRUE(!Inside(m, block.box, halo - 1e-9) || listed) << i;
      EXPECT_TRUE(!listed || Inside(m, block.box, halo + 1e-9)) << i;
      const bool home =
          (m.array() >= block.box.min.array()).all() && (m.array() < block.box.max.array()).all();
      homes[i] += home ? 1 : 0;
      home_count += home ? 1 : 0;
    }
    EXPECT_LE(home_count, layout.max_home_segments);
  }
  EXPECT_GT(split, 8);  // the cluster's block was split (at least once)
  for (std::size_t i = 0; i < segments.size(); ++i) EXPECT_EQ(homes[i], 1) << i;
}

TEST(AssignDetectionBlocks, WithoutALimitTheGridIsKept) {
  BlockLayout layout;
  layout.block_size = 5.0;
  const std::vector<DetectionBlock> blocks = AssignDetectionBlocks(ClusteredSegments(), layout);
  for (const DetectionBlock& block : blocks) EXPECT_EQ(block.depth, 0);
}

}  // namespace
}  // namespace linesurf::detect
