#include "engine/pipeline/detect_scene_planes.h"

#include <gtest/gtest.h>

namespace linesurf::pipeline {
namespace {

/// The 12 edges of the cube [0, 2]^3 (each on two faces), seen from one viewpoint, plus a
/// zero-length segment that sanitation drops and a given plane that detection must ignore.
Scene CubeEdges() {
  Scene scene;
  scene.viewpoints.push_back(Vec3(5, 6, 7));
  const ViewpointId view(0u);
  for (int axis = 0; axis < 3; ++axis) {
    for (int a = 0; a < 2; ++a) {
      for (int b = 0; b < 2; ++b) {
        Vec3 p = Vec3::Zero();
        p[(axis + 1) % 3] = 2.0 * a;
        p[(axis + 2) % 3] = 2.0 * b;
        Vec3 q = p;
        q[axis] = 2.0;
        scene.segments.push_back({p, q});
        scene.observations.AddRow(std::vector<ViewpointId>{view});
      }
    }
  }
  scene.segments.push_back({Vec3(1, 1, 1), Vec3(1, 1, 1)});
  scene.observations.AddRow(std::vector<ViewpointId>{view});
  scene.planes.push_back({Vec3(0, 0, 1), Vec3(0, 0, 1)});
  scene.memberships.resize(scene.segments.size());
  return scene;
}

TEST(SanitizeAndDetectPlanes, SanitisesIgnoresGivenPlanesAndDetects) {
  StageTimer timer;
  PlaneDetectionOptions detect;
  detect.epsilon = 0.06;
  const auto result = SanitizeAndDetectPlanes(CubeEdges(), {}, detect, RunContext{}, &timer);
  ASSERT_TRUE(result) << result.error().ToString();
  EXPECT_EQ(result->given_planes, 1u);
  EXPECT_EQ(result->scene.NumSegments(), 12u);  // the zero-length segment dropped
  EXPECT_EQ(result->sanitize_stats.input_segments, 13u);
  EXPECT_FALSE(result->warnings.empty());
  EXPECT_EQ(result->scene.planes.size(), 6u);
  EXPECT_EQ(result->support.size(), 6u);
  ASSERT_EQ(result->scene.memberships.size(), 12u);
  for (const PlaneMembership& m : result->scene.memberships) EXPECT_EQ(m.count, 2);
  EXPECT_EQ(result->detection_stats.planes_after_fusion, 6);
  timer.Stop();
  ASSERT_EQ(timer.Stages().size(), 2u);
  EXPECT_EQ(timer.Stages()[0].first, "sanitize");
  EXPECT_EQ(timer.Stages()[1].first, "detect");
}

TEST(SanitizeAndDetectPlanes, CancelledBetweenTheStages) {
  RunContext ctx;
  ctx.is_cancelled = [] { return true; };
  const auto result = SanitizeAndDetectPlanes(CubeEdges(), {}, {}, ctx);
  ASSERT_FALSE(result);
  EXPECT_EQ(result.error().code, ErrorCode::kCancelled);
}

}  // namespace
}  // namespace linesurf::pipeline
