#include "partition/voxel/polygon_blocks.h"

#include "engine/core/rng.h"

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <algorithm>

namespace linesurf::partition {
namespace {

BlockGrid CubeGrid(double size) {
  Box3 box;
  box.Extend(Vec3::Zero());
  box.Extend(Vec3(20, 20, 20));
  return std::move(BlockGrid::Create(box, size)).value();
}

TEST(InlierHull, IsTheHullOfTheEndpointsInThePlane) {
  // Segments of the plane z = 2 (one endpoint 0.01 off it) whose hull is the square [0, 4]^2.
  const std::vector<Segment3> segments{{Vec3(0, 0, 2), Vec3(4, 0, 2)},
                                       {Vec3(4, 4, 2.01), Vec3(1, 1, 2)},
                                       {Vec3(0, 4, 2), Vec3(2, 2, 2)}};
  const Plane3 plane{Vec3(7, 7, 2), Vec3::UnitZ()};
  const std::vector<SegmentId> all{SegmentId(0u), SegmentId(1u), SegmentId(2u)};
  const std::vector<Vec3> hull = InlierHull(plane, segments, all);
  ASSERT_EQ(hull.size(), 4u);
  for (const Vec3& corner : {Vec3(0, 0, 2), Vec3(4, 0, 2), Vec3(4, 4, 2), Vec3(0, 4, 2)}) {
    EXPECT_TRUE(std::any_of(hull.begin(), hull.end(), [&](const Vec3& p) {
      return (p - corner).norm() < 1e-12;
    })) << corner.transpose();
  }
  // Counter-clockwise about the normal.
  Vec3 normal = Vec3::Zero();
  for (std::size_t i = 0; i < hull.size(); ++i) {
    normal += (hull[i] - hull[0]).cross(hull[(i + 1) % hull.size()] - hull[i]);
  }
  EXPECT_GT(normal.dot(plane.normal), 0.0);
  // One segment alone has a degenerate hull.
  EXPECT_LT(InlierHull(plane, segments, std::span(all).first(1)).size(), 3u);
}

// Every block holding a point of the polygon is listed; every listed block comes within the
// sampling step of a sampled point of it.
TEST(BlocksMetByConvexPolygon, AgreesWithSampledPointsOfRandomTriangles) {
  const BlockGrid grid = CubeGrid(1.5);
  Rng rng(11);
  for (int trial = 0; trial < 30; ++trial) {
    std::vector<Vec3> triangle;
    for (int i = 0; i < 3; ++i) {
      triangle.emplace_back(rng.Uniform(1, 19), rng.Uniform(1, 19), rng.Uniform(1, 19));
    }
    const std::vector<std::int64_t> met = BlocksMetByConvexPolygon(grid, triangle);
    ASSERT_TRUE(std::is_sorted(met.begin(), met.end()));
    constexpr int kSteps = 150;
    const double step = 2.0 * 19.0 * std::sqrt(3.0) / kSteps;
    std::vector<Vec3> samples;
    for (int i = 0; i <= kSteps; ++i) {
      for (int j = 0; i + j <= kSteps; ++j) {
        const double a = double(i) / kSteps;
        const double b = double(j) / kSteps;
        samples.push_back(triangle[0] + a * (triangle[1] - triangle[0]) +
                          b * (triangle[2] - triangle[0]));
      }
    }
    for (const Vec3& s : samples) {
      EXPECT_TRUE(std::binary_search(met.begin(), met.end(), grid.LinearIndex(grid.Locate(s))))
          << "trial " << trial;
    }
    for (const std::int64_t b : met) {
      const Box3 box = grid.BlockBox({0, grid.BaseFromLinear(b)});
      const bool near = std::any_of(samples.begin(), samples.end(), [&](const Vec3& s) {
        return (s.array() >= box.min.array() - step).all() &&
               (s.array() <= box.max.array() + step).all();
      });
      EXPECT_TRUE(near) << "trial " << trial << " block " << b;
    }
  }
}

// A square lying on the block face z = 4 touches the blocks on both sides of it.
TEST(BlocksMetByConvexPolygon, APolygonOnABlockFaceMeetsBothSides) {
  const BlockGrid grid = CubeGrid(2.0);
  const std::vector<Vec3> square{Vec3(1, 1, 4), Vec3(3, 1, 4), Vec3(3, 3, 4), Vec3(1, 3, 4)};
  std::vector<std::int64_t> expected;
  for (int z = 1; z <= 2; ++z) {
    for (int y = 0; y <= 1; ++y) {
      for (int x = 0; x <= 1; ++x) expected.push_back(grid.LinearIndex(Eigen::Vector3i(x, y, z)));
    }
  }
  std::sort(expected.begin(), expected.end());
  EXPECT_EQ(BlocksMetByConvexPolygon(grid, square), expected);
  EXPECT_TRUE(BlocksMetByConvexPolygon(grid, std::span(square).first(2)).empty());
}

}  // namespace
}  // namespace linesurf::partition
