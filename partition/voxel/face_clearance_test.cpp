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

}  // namespace
}  // namespace linesurf::partition
