#include "partition/voxel/plane_support.h"

#include "engine/core/rng.h"
#include "partition/voxel/active_blocks.h"
#include "partition/voxel/polygon_blocks.h"
#include "tests/support/thread_count.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <limits>

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
  std::vector<Plane3> planes{{Vec3(5, 0, 0), Vec3::UnitX()},
                             {Vec3(0, 0, 17.5), Vec3::UnitZ()},
                             {Vec3(0, 0, 3), Vec3::UnitY()}};
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
    const auto regions = ComputePlaneSupport(grid, f.segments, f.planes, f.inliers, options, {});
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
      for (const std::int64_t b :
           BlocksMetByConvexPolygon(grid, InlierHull(f.planes[p], f.segments, f.inliers[p]))) {
        touched.push_back(b);
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

// Chebyshev distance from p to the box (0 inside).
double ChebyshevDistance(const Vec3& p, const Box3& box) {
  const Vec3 below = box.min - p;
  const Vec3 above = p - box.max;
  return below.cwiseMax(above).cwiseMax(Vec3::Zero()).maxCoeff();
}

// A fractional margin f adds exactly the neighbouring blocks some inlier comes within f blocks
// of (checked against points sampled along the inliers), between margins 0 and 1.
TEST(PlaneSupport, AFractionalMarginReachesTheBlocksWithinThatShareOfABlock) {
  const Fixture f;
  const BlockGrid grid = Grid(Vec3(20, 20, 20), 2.0);
  const auto with = [&](double margin) {
    PlaneSupportOptions options;
    options.margin_blocks = margin;
    return std::move(ComputePlaneSupport(grid, f.segments, f.planes, f.inliers, options, {}))
        .value();
  };
  const PlaneSupportRegions none = with(0.0);
  const PlaneSupportRegions one = with(1.0);
  for (const double fraction : {0.25, 0.4, 0.6}) {
    const PlaneSupportRegions some = with(fraction);
    const double reach = fraction * grid.block_size();
    for (std::size_t p = 0; p < 2; ++p) {
      const auto region = some.plane_blocks[PlaneId(p)];
      EXPECT_TRUE(std::includes(region.begin(),
                                region.end(),
                                none.plane_blocks[PlaneId(p)].begin(),
                                none.plane_blocks[PlaneId(p)].end()));
      for (const std::int64_t b : one.plane_blocks[PlaneId(p)]) {
        const Box3 box = grid.BlockBox({0, grid.BaseFromLinear(b)});
        double nearest = std::numeric_limits<double>::infinity();
        double step = 0.0;
        for (const SegmentId s : f.inliers[p]) {
          const Segment3& segment = f.segments[s.index()];
          step = std::max(step, (segment.p2 - segment.p1).norm() / 200.0);
          for (int i = 0; i <= 200; ++i) {
            const Vec3 q = segment.p1 + (i / 200.0) * (segment.p2 - segment.p1);
            nearest = std::min(nearest, ChebyshevDistance(q, box));
          }
        }
        if (nearest <= reach * (1.0 - 1e-9)) {
          EXPECT_TRUE(Has(region, b)) << fraction << " plane " << p << " block " << b;
        } else if (nearest > reach + step) {
          EXPECT_FALSE(Has(region, b)) << fraction << " plane " << p << " block " << b;
        }
      }
    }
    // The wall x = 5 sits 1 from the faces x = 4 and 6 of its column of blocks.
    EXPECT_EQ(some.plane_blocks[PlaneId(0u)].size(), fraction < 0.5 ? 100u : 300u);
    EXPECT_TRUE(some.plane_blocks[PlaneId(2u)].empty());
  }
}

TEST(PlaneSupport, SameRegionsForAnyThreadCount) {
  const testing::RealThreadCounts real_threads;
  const Fixture f;
  const BlockGrid grid = Grid(Vec3(20, 20, 20), 1.5);
  RunContext one;
  one.num_threads = 1;
  const auto a = ComputePlaneSupport(grid, f.segments, f.planes, f.inliers, {}, one);
  ASSERT_TRUE(a);
  for (const int threads : testing::kThreadCounts) {
    SCOPED_TRACE(threads);
    RunContext ctx;
    ctx.num_threads = threads;
    const auto b = ComputePlaneSupport(grid, f.segments, f.planes, f.inliers, {}, ctx);
    ASSERT_TRUE(b);
    EXPECT_EQ(a->plane_blocks.items(), b->plane_blocks.items());
    EXPECT_EQ(a->plane_blocks.offsets(), b->plane_blocks.offsets());
    EXPECT_EQ(a->blocks, b->blocks);
  }
}

TEST(PlaneSupport, RejectsBadMarginsAndInliers) {
  const Fixture f;
  const BlockGrid grid = Grid(Vec3(20, 20, 20), 2.0);
  PlaneSupportOptions bad;
  for (const double margin : {-1.0, 64.5, std::numeric_limits<double>::quiet_NaN()}) {
    bad.margin_blocks = margin;
    const auto r = ComputePlaneSupport(grid, f.segments, f.planes, f.inliers, bad, {});
    ASSERT_FALSE(r) << margin;
    EXPECT_EQ(r.error().code, ErrorCode::kInvalidOptions);
  }
  std::vector<std::vector<SegmentId>> wrong{{SegmentId(9999u)}};
  const auto w = ComputePlaneSupport(grid, f.segments, std::span(f.planes).first(1), wrong, {}, {});
  ASSERT_FALSE(w);
  EXPECT_EQ(w.error().code, ErrorCode::kInvalidInput);
  EXPECT_NE(w.error().message.find("9999"), std::string::npos);
  const auto n =
      ComputePlaneSupport(grid, f.segments, std::span(f.planes).first(2), f.inliers, {}, {});
  ASSERT_FALSE(n);
  EXPECT_EQ(n.error().code, ErrorCode::kInvalidInput);
}

// A flat roof of 10 x 10 seen only by its four eaves: at margin 0 its region is still the 5 x 5
// blocks under the roof, not only the ring its lines cross.
TEST(PlaneSupport, ARoofSeenByItsEavesCoversTheBlocksBetweenThem) {
  const BlockGrid grid = Grid(Vec3(20, 20, 20), 2.0);
  const double z = 9.0;
  const std::vector<Segment3> eaves{{Vec3(5, 5, z), Vec3(15, 5, z)},
                                    {Vec3(15, 5, z), Vec3(15, 15, z)},
                                    {Vec3(15, 15, z), Vec3(5, 15, z)},
                                    {Vec3(5, 15, z), Vec3(5, 5, z)}};
  const std::vector<Plane3> roof{{Vec3(0, 0, z), Vec3::UnitZ()}};
  const std::vector<std::vector<SegmentId>> inliers{
      {SegmentId(0u), SegmentId(1u), SegmentId(2u), SegmentId(3u)}};
  PlaneSupportOptions options;
  options.margin_blocks = 0.0;
  const auto regions = ComputePlaneSupport(grid, eaves, roof, inliers, options, {});
  ASSERT_TRUE(regions) << regions.error().ToString();
  const auto region = regions->plane_blocks[PlaneId(0u)];
  std::vector<std::int64_t> expected;
  for (int y = 2; y <= 7; ++y) {
    for (int x = 2; x <= 7; ++x) expected.push_back(grid.LinearIndex(Eigen::Vector3i(x, y, 4)));
  }
  std::sort(expected.begin(), expected.end());
  EXPECT_EQ(std::vector<std::int64_t>(region.begin(), region.end()), expected);
}

}  // namespace
}  // namespace linesurf::partition
