#include "partition/voxel/plane_support.h"

#include "engine/core/rng.h"
#include "partition/voxel/active_blocks.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace linesurf::partition {
namespace {

BlockGrid Grid(const Vec3& extent, double size) {
  Box3 box;
  box.Extend(Vec3::Zero());
  box.Extend(extent);
  return std::move(BlockGrid::Create(box, size)).value();
}

bool Has(std::span<const std::int64_t> sorted, std::int64_t b) {
  return std::binary_search(sorted.begin(), sorted.end(), b);
}

// Three planes: a wall x = 5 of random segments over y, z in [0, 20], a small patch, and a plane
// without inliers.
struct Fixture {
  std::vector<Segment3> segments;
  std::vector<std::vector<SegmentId>> inliers{3};
  Fixture() {
    Rng rng(5);
    for (int i = 0; i < 1000; ++i) {
      const Vec3 a(5.0, rng.Uniform(0, 20), rng.Uniform(0, 20));
      const Vec3 b(5.0, rng.Uniform(0, 20), rng.Uniform(0, 20));
      inliers[0].emplace_back(segments.size());
      segments.push_back({a, a + 0.2 * (b - a)});
    }
    for (int i = 0; i < 20; ++i) {
      const Vec3 a(rng.Uniform(12, 13), rng.Uniform(12, 13), 17.5);
      inliers[1].emplace_back(segments.size());
      segments.push_back({a, a + Vec3(0.3, 0.2, 0)});
    }
  }
};

TEST(PlaneSupport, RegionsCoverEveryInlierAndGrowByTheMargin) {
  const Fixture f;
  const BlockGrid grid = Grid(Vec3(20, 20, 20), 2.0);
  for (int margin = 0; margin <= 2; ++margin) {
    PlaneSupportOptions options;
    options.margin_blocks = margin;
    const auto regions = ComputePlaneSupport(grid, f.segments, f.inliers, options, {});
    ASSERT_TRUE(regions) << regions.error().ToString();
    ASSERT_EQ(regions->plane_blocks.NumRows(), 3u);
    for (std::size_t p = 0; p < 3; ++p) {
      const auto region = regions->plane_blocks[PlaneId(p)];
      EXPECT_TRUE(std::is_sorted(region.begin(), region.end()));
      std::vector<std::int64_t> touched;
      for (const SegmentId s : f.inliers[p]) {
        for (const auto& c : BlocksCrossed(grid, f.segments[s.index()])) {
          EXPECT_TRUE(Has(region, grid.LinearIndex(c))) << p << " " << s.index();
          touched.push_back(grid.LinearIndex(c));
        }
      }
      std::sort(touched.begin(), touched.end());
      touched.erase(std::unique(touched.begin(), touched.end()), touched.end());
      EXPECT_EQ(std::vector<std::int64_t>(region.begin(), region.end()),
                DilateBlocks(grid, touched, margin));
    }
    // The wall x = 5 lies in the column of blocks x = 2; with margin m it reaches x = 2 +- m.
    const auto wall = regions->plane_blocks[PlaneId(0u)];
    for (const std::int64_t b : wall) {
      EXPECT_LE(std::abs(grid.BaseFromLinear(b).x() - 2), margin);
    }
    EXPECT_EQ(wall.size(), static_cast<std::size_t>((1 + 2 * margin) * 100));
    EXPECT_TRUE(regions->plane_blocks[PlaneId(2u)].empty());
    // The inverse lists agree with the regions.
    std::size_t pairs = 0;
    for (std::size_t i = 0; i < regions->blocks.size(); ++i) {
      for (const PlaneId p : regions->block_planes[BlockId(i)]) {
        EXPECT_TRUE(Has(regions->plane_blocks[p], regions->blocks[i]));
        ++pairs;
      }
    }
    EXPECT_EQ(pairs, regions->plane_blocks.NumItems());
  }
}

TEST(PlaneSupport, SameRegionsForAnyThreadCount) {
  const Fixture f;
  const BlockGrid grid = Grid(Vec3(20, 20, 20), 1.5);
  RunContext one;
  one.num_threads = 1;
  RunContext two;
  two.num_threads = 2;
  const auto a = ComputePlaneSupport(grid, f.segments, f.inliers, {}, one);
  const auto b = ComputePlaneSupport(grid, f.segments, f.inliers, {}, two);
  ASSERT_TRUE(a && b);
  EXPECT_EQ(a->plane_blocks.items(), b->plane_blocks.items());
  EXPECT_EQ(a->plane_blocks.offsets(), b->plane_blocks.offsets());
  EXPECT_EQ(a->blocks, b->blocks);
}

TEST(PlaneSupport, RejectsBadMarginsAndInliers) {
  const Fixture f;
  const BlockGrid grid = Grid(Vec3(20, 20, 20), 2.0);
  PlaneSupportOptions bad;
  bad.margin_blocks = -1;
  const auto r = ComputePlaneSupport(grid, f.segments, f.inliers, bad, {});
  ASSERT_FALSE(r);
  EXPECT_EQ(r.error().code, ErrorCode::kInvalidOptions);
  std::vector<std::vector<SegmentId>> wrong{{SegmentId(9999u)}};
  const auto w = ComputePlaneSupport(grid, f.segments, wrong, {}, {});
  ASSERT_FALSE(w);
  EXPECT_EQ(w.error().code, ErrorCode::kInvalidInput);
  EXPECT_NE(w.error().message.find("9999"), std::string::npos);
}

}  // namespace
}  // namespace linesurf::partition
