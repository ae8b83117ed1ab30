#include "partition/voxel/face_clearance.h"

#include "partition/voxel/block_grid.h"

#include <gtest/gtest.h>

#include <cmath>

namespace linesurf::partition {
namespace {

Box3 SymmetricBox() {
  Box3 box;
  box.Extend(Vec3(-5.876830850360709, -4.7768308503607084, -2.0768308503607087));
  box.Extend(Vec3(5.8768308503607081, 4.7768308503607084, 2.0768308503607087));
  return box;
}

// The distance from `x` to the nearest interior face of `grid` along `axis`.
double FaceDistance(const BlockGrid& grid, int axis, double x) {
  const std::vector<double>& faces = grid.FaceTable(axis);
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 1; i + 1 < faces.size(); ++i) best = std::min(best, std::abs(faces[i] - x));
  return best;
}

// The case of a noise-free floor plan: half the longest extent puts a face 8.9e-16 from the
// wall x = 0 on the centre line; the size moves so that the face clears it.
TEST(SizeClearOfParallelPlanes, MovesAFaceOffAWallOnTheCentreLine) {
  const Box3 box = SymmetricBox();
  const double size = box.Extent().x() / 2.0;
  const BlockGrid before = std::move(BlockGrid::Create(box, size)).value();
  ASSERT_LT(FaceDistance(before, 0, 0.0), 1e-12);
  const std::vector<Plane3> walls{{Vec3(0, 1, 0), Vec3::UnitX()}, {Vec3(0, 2, 0), -Vec3::UnitY()}};
  const double moved = SizeClearOfParallelPlanes(box, size, walls);
  EXPECT_GT(moved, size);
  EXPECT_LT(moved, size * 1.01);
  const BlockGrid after = std::move(BlockGrid::Create(box, moved)).value();
  EXPECT_GE(FaceDistance(after, 0, 0.0), 1e-6 * moved);
  EXPECT_GE(FaceDistance(after, 1, 2.0), 1e-6 * moved);
}

// Planes away from every face, and planes that cross the faces steeply, leave the size alone.
TEST(SizeClearOfParallelPlanes, KeepsTheSizeWhenNoParallelPlaneIsNearAFace) {
  const Box3 box = SymmetricBox();
  const double size = box.Extent().x() / 2.0;
  const std::vector<Plane3> planes{{Vec3(1.3, 0, 0), Vec3::UnitX()},
                                   {Vec3(0, 0, 0), Vec3(1, 0.2, 0).normalized()},
                                   {Vec3(0, 0, 0.5), Vec3::UnitZ()}};
  EXPECT_EQ(SizeClearOfParallelPlanes(box, size, planes), size);
  EXPECT_EQ(SizeClearOfParallelPlanes(box, size, {}), size);
}

// A noisy wall near y = -4, tilted enough (1e-3) that over the box it is not parallel to the
// faces, with its inliers in a 2.5 cm slab: 6 m blocks from y = -10 put a face through the slab.
// Without the inliers the size stays; with them it moves just past the slab.
TEST(SizeClearOfParallelPlanes, MovesAFaceOutOfTheSlabOfANoisyWallsInliers) {
  Box3 box;
  box.Extend(Vec3::Constant(-10.0));
  box.Extend(Vec3::Constant(14.0));
  const double size = 6.0;
  const std::vector<Plane3> wall{{Vec3(0, -4.003, 0), Vec3(0.001, 1, 0).normalized()}};
  std::vector<Segment3> segments;
  for (int i = 0; i < 8; ++i) {
    const double y = -4.003 + ((i % 3) - 1) * 0.0125;
    segments.push_back({Vec3(-3, y, 0.5 + 0.4 * i), Vec3(3, y, 0.5 + 0.4 * i)});
  }
  std::vector<std::vector<SegmentId>> inliers(1);
  for (std::size_t i = 0; i < segments.size(); ++i) inliers[0].emplace_back(i);
  EXPECT_EQ(SizeClearOfParallelPlanes(box, size, wall), size);
  const double moved = SizeClearOfParallelPlanes(box, size, wall, segments, inliers);
  EXPECT_GT(moved, size);
  EXPECT_LT(moved, size * 1.01);
  const BlockGrid after = std::move(BlockGrid::Create(box, moved)).value();
  EXPECT_GE(FaceDistance(after, 1, -4.003), 0.0125);
}

// Slabs side by side over [-4, 2.5] leave no size of the search a clear first face along y (it
// lies in [-4, 2)): the size is then the first that clears the planes alone.
TEST(SizeClearOfParallelPlanes, FallsBackToThePlanesWhenNoSizeClearsTheSlabs) {
  Box3 box;
  box.Extend(Vec3::Constant(-10.0));
  box.Extend(Vec3::Constant(14.0));
  const double size = 6.0;
  std::vector<Segment3> segments;
  std::vector<std::vector<SegmentId>> inliers;
  for (int i = 0; i < 11; ++i) {
    const double lo = -4.0 + 0.59 * i;
    segments.push_back({Vec3(-3, lo, -3), Vec3(3, lo + 0.59, 3)});
    inliers.push_back({SegmentId(static_cast<std::size_t>(i))});
  }
  // Every plane lies on y = -4, where 6 m puts the first face: the planes alone move it a step.
  const std::vector<Plane3> planes(inliers.size(), Plane3{Vec3(0, -4, 0), Vec3::UnitY()});
  const double moved = SizeClearOfParallelPlanes(box, size, planes, segments, inliers);
  EXPECT_EQ(moved, size * (1.0 + 1.0 / 1024));
}

}  // namespace
}  // namespace linesurf::partition
