#include "engine/pipeline/scene_box.h"

#include <gtest/gtest.h>

namespace linesurf::pipeline {
namespace {

/// One segment from `lo` to `hi` seen from `viewpoint`.
Scene OneSegment(const Vec3& lo, const Vec3& hi, const Vec3& viewpoint) {
  Scene scene;
  scene.segments.push_back({lo, hi});
  scene.viewpoints.push_back(viewpoint);
  return scene;
}

void ExpectBox(const Box3& box, const Vec3& min, const Vec3& max) {
  for (int a = 0; a < 3; ++a) {
    EXPECT_DOUBLE_EQ(box.min[a], min[a]) << "axis " << a;
    EXPECT_DOUBLE_EQ(box.max[a], max[a]) << "axis " << a;
  }
}

TEST(SceneBox, GrowsEachAxisByTheMarginOfItsOwnExtent) {
  // Segments and viewpoint span 100 x 40 x 20: 5 % of each extent on each side.
  const Scene scene = OneSegment({0, 0, 0}, {100, 40, 10}, {50, 20, 20});
  ExpectBox(SceneBox(scene, 0.05), {-5, -2, -1}, {105, 42, 21});
}

TEST(SceneBox, AWiderCityGetsNoMoreAirAboveIt) {
  // A city 30 m tall (viewpoints included) grows by 1.5 m up and down, 300 m or 3 km wide.
  for (const double width : {300.0, 3000.0}) {
    const Scene scene = OneSegment({0, 0, 0}, {width, width, 30}, {0, 0, 30});
    const Box3 box = SceneBox(scene, 0.05);
    EXPECT_DOUBLE_EQ(box.min.z(), -1.5) << width;
    EXPECT_DOUBLE_EQ(box.max.z(), 31.5) << width;
  }
}

TEST(SceneBox, AFlatSceneStillGetsRoom) {
  // Everything at z = 2: the thin axis grows by 5 % of 1 % of the largest extent.
  const Scene scene = OneSegment({0, 0, 2}, {200, 100, 2}, {100, 50, 2});
  ExpectBox(SceneBox(scene, 0.05), {-10, -5, 1.9}, {210, 105, 2.1});
}

TEST(SceneBox, CoincidentPointsGetABoxOfNoSizeAndNoPointsAnEmptyBox) {
  const Vec3 p(3, -2, 7);
  const Box3 point = SceneBox(OneSegment(p, p, p), 0.05);
  EXPECT_FALSE(point.IsEmpty());
  ExpectBox(point, p, p);
  EXPECT_TRUE(SceneBox(Scene{}, 0.05).IsEmpty());
}

}  // namespace
}  // namespace linesurf::pipeline
