#include "partition/voxel/split_face_chooser.h"

#include <gtest/gtest.h>

#include <cmath>

namespace linesurf::partition {
namespace {

// A wall on the middle of the interval moves the split face just off it; a noisy wall's inlier
// slab there moves it out of the slab; with nothing near, the face is the exact middle.
TEST(SplitFaceChooser, KeepsTheSplitOffWallsAndSlabsNearTheMiddle) {
  const Box3 box{Vec3::Zero(), Vec3::Constant(8.0)};
  EXPECT_EQ(SplitFaceChooser(box, 4.0, {}, {}, {}).Choose(0, 2.0, 4.0), 3.0);

  const std::vector<Plane3> wall{{Vec3(3, 0, 0), Vec3::UnitX()}};
  const double off_wall = SplitFaceChooser(box, 4.0, wall, {}, {}).Choose(0, 2.0, 4.0);
  EXPECT_GE(std::abs(off_wall - 3.0), 1e-6 * 4.0);
  EXPECT_LT(std::abs(off_wall - 3.0), 1e-2);
  EXPECT_EQ(SplitFaceChooser(box, 4.0, wall, {}, {}).Choose(1, 2.0, 4.0), 3.0);

  // Inliers of a wall tilted enough not to count as parallel, spread over x in [2.99, 3.02].
  const std::vector<Plane3> tilted{{Vec3(3, 0, 0), Vec3(1, 0.01, 0).normalized()}};
  const std::vector<Segment3> segments{{Vec3(2.99, 1, 1), Vec3(3.02, 1, 2)}};
  const std::vector<std::vector<SegmentId>> inliers{{SegmentId(0u)}};
  const double off_slab = SplitFaceChooser(box, 4.0, tilted, segments, inliers).Choose(0, 2.0, 4.0);
  EXPECT_TRUE(off_slab < 2.99 || off_slab > 3.02) << off_slab;
  EXPECT_LT(std::abs(off_slab - 3.0), 0.5);
}

// A slab over the whole middle half of the interval leaves only the planes to keep off: the face
// lies in the slab, just off the wall on the middle. Walls closer together than the clearance
// over the whole middle half leave nothing: the middle itself.
TEST(SplitFaceChooser, FallsBackToThePlanesThenToTheMiddle) {
  const Box3 box{Vec3::Zero(), Vec3::Constant(8.0)};
  const std::vector<Plane3> planes{{Vec3(3, 0, 0), Vec3(1, 0.01, 0).normalized()},
                                   {Vec3(3, 0, 0), Vec3::UnitX()}};
  const std::vector<Segment3> segments{{Vec3(2.4, 1, 1), Vec3(3.6, 1, 1.01)}};
  const std::vector<std::vector<SegmentId>> inliers{{SegmentId(0u)}, {}};
  const double in_slab = SplitFaceChooser(box, 20.0, planes, segments, inliers).Choose(0, 2.0, 4.0);
  EXPECT_NE(in_slab, 3.0);
  EXPECT_LT(std::abs(in_slab - 3.0), 1e-2);

  std::vector<Plane3> walls;
  for (int k = 0; k <= 12000; ++k) walls.push_back({Vec3(2.4 + 1e-4 * k, 0, 0), Vec3::UnitX()});
  EXPECT_EQ(SplitFaceChooser(box, 4.0, walls, {}, {}, 1e-4).Choose(0, 2.0, 4.0), 3.0);
}

}  // namespace
}  // namespace linesurf::partition
