#include "engine/pipeline/sanitize_scene.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace linesurf::pipeline {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

/// Adds a segment seen from `views` (raw ids, may be bad) with optional memberships.
void AddSegment(Scene& scene, const Vec3& a, const Vec3& b, std::vector<ViewpointId> views,
                PlaneMembership m = {}) {
  scene.segments.push_back(Segment3{a, b});
  scene.observations.AddRow(views);
  scene.memberships.push_back(m);
}

PlaneMembership Members(std::initializer_list<std::uint32_t> ids) {
  PlaneMembership m;
  for (const std::uint32_t id : ids) {
    m.planes[m.count++] = PlaneId(id);
  }
  return m;
}

/// A small scene on the floor z = offset.z() of a 10 m square, with two planes.
Scene FloorScene(const Vec3& offset) {
  Scene scene;
  scene.viewpoints.push_back(offset + Vec3(5, 5, 10));
  scene.viewpoints.push_back(offset + Vec3(-5, 5, 10));
  scene.planes.push_back(Plane3{offset, Vec3::UnitZ()});
  scene.planes.push_back(Plane3{offset, Vec3::UnitX()});
  for (int i = 0; i <= 10; ++i) {
    AddSegment(scene, offset + Vec3(0, i, 0), offset + Vec3(10, i, 0),
               {ViewpointId(0u), ViewpointId(1u)}, Members({0}));
  }
  return scene;
}

TEST(SanitizeScene, CleanSceneIsKeptAndRecentred) {
  const auto result = SanitizeScene(FloorScene(Vec3::Zero()), SanitizeOptions{});
  ASSERT_TRUE(result) << result.error().ToString();
  EXPECT_EQ(result->stats.kept_segments, 11u);
  EXPECT_TRUE(result->warnings.empty());
  EXPECT_EQ(result->scene.world_from_local.translation, Vec3(5, 5, 0));
  EXPECT_EQ(result->scene.segments[SegmentId(0u)].p1, Vec3(-5, -5, 0));
  EXPECT_EQ(result->scene.planes[PlaneId(0u)].point, Vec3(-5, -5, 0));
}

TEST(SanitizeScene, MillionMetreOffsetKeepsGeometry) {
  const Vec3 offset(2.5e6, -1.25e6, 1e6);
  const auto result = SanitizeScene(FloorScene(offset), SanitizeOptions{});
  ASSERT_TRUE(result) << result.error().ToString();
  const Scene& local = result->scene;
  EXPECT_EQ(local.world_from_local.translation, offset + Vec3(5, 5, 0));
  EXPECT_EQ(local.NumSegments(), 11u);
  for (const Segment3& s : local.segments) {
    EXPECT_LT(s.p1.norm(), 10.0);                 // near the origin
    EXPECT_NEAR(s.Length(), 10.0, 1e-9);          // lengths survive the shift
    EXPECT_NEAR(local.planes[PlaneId(0u)].SignedDistance(s.p1), 0.0, 1e-9);
  }
  // World coordinates come back within rounding of the input.
  const Vec3 world = local.world_from_local.Apply(local.viewpoints[ViewpointId(1u)]);
  EXPECT_NEAR((world - (offset + Vec3(-5, 5, 10))).norm(), 0.0, 1e-9);
}

TEST(SanitizeScene, DropsAndFixesEveryKindOfBadElement) {
  Scene scene = FloorScene(Vec3::Zero());
  scene.viewpoints.push_back(Vec3(kNaN, 0, 0));               // viewpoint 2: dropped
  scene.planes.push_back(Plane3{Vec3::Zero(), Vec3::Zero()});  // plane 2: zero normal
  scene.planes[PlaneId(1u)].normal = Vec3(2, 0, 0);             // renormalised
  scene.planes[PlaneId(1u)].point = Vec3(3000, 7, 1);           // far: re-anchored
  AddSegment(scene, Vec3(0, 0, kNaN), Vec3(1, 1, 1), {ViewpointId(0u)});          // non-finite
  AddSegment(scene, Vec3(1, 1, 1), Vec3(1, 1, 1), {ViewpointId(0u)});             // zero length
  AddSegment(scene, Vec3(1, 1, 0), Vec3(1, 2, 0),
             {ViewpointId(0u), ViewpointId(0u), ViewpointId(2u), ViewpointId(9u)},
             Members({0, 0}));                                                    // dup view, bad
  AddSegment(scene, Vec3(2, 1, 0), Vec3(2, 2, 0), {}, Members({2, 7}));           // no views
  AddSegment(scene, Vec3(1e300, 0, 0), Vec3(0, 0, 0), {ViewpointId(1u)});         // absurd size
  const auto result = SanitizeScene(scene, SanitizeOptions{});
  ASSERT_TRUE(result) << result.error().ToString();
  const SanitizeStats& s = result->stats;
  EXPECT_EQ(s.input_segments, 16u);
  EXPECT_EQ(s.kept_segments, 13u);
  EXPECT_EQ(s.dropped_non_finite_segments, 2u);
  EXPECT_EQ(s.dropped_short_segments, 1u);
  EXPECT_EQ(s.dropped_bad_viewpoints, 1u);
  EXPECT_EQ(s.removed_bad_observations, 2u);
  EXPECT_EQ(s.removed_duplicate_views, 1u);
  EXPECT_EQ(s.segments_without_views, 1u);
  EXPECT_EQ(s.dropped_bad_planes, 1u);
  EXPECT_EQ(s.renormalised_normals, 1u);
  EXPECT_EQ(s.reanchored_planes, 1u);
  EXPECT_EQ(s.removed_bad_memberships, 2u);
  EXPECT_EQ(s.removed_repeated_memberships, 1u);
  EXPECT_EQ(result->warnings.size(), 11u);

  const Scene& out = result->scene;
  EXPECT_EQ(out.planes.size(), 2u);
  const Plane3& wall = out.planes[PlaneId(1u)];
  EXPECT_EQ(wall.normal, Vec3::UnitX());
  // Same plane x = 3000, now anchored at its point nearest the data centre (5, 5, 0).
  EXPECT_EQ(out.world_from_local.Apply(wall.point), Vec3(3000, 5, 0));
  const auto row = out.observations[SegmentId(11u)];
  ASSERT_EQ(row.size(), 1u);
  EXPECT_EQ(row[0], ViewpointId(0u));
  EXPECT_EQ(out.memberships[SegmentId(11u)].count, 1);
  EXPECT_EQ(out.memberships[SegmentId(12u)].count, 0);
}

TEST(SanitizeScene, ResidualsFollowTheObservationsKept) {
  Scene scene;
  scene.viewpoints.push_back(Vec3(0, 0, 5));
  scene.viewpoints.push_back(Vec3(1, 0, 5));
  scene.segments.push_back(Segment3{Vec3(0, 0, 0), Vec3(1, 0, 0)});
  scene.observations.AddRow(std::vector<ViewpointId>{ViewpointId(1u), ViewpointId(1u),
                                                     ViewpointId(0u)});
  scene.residuals = {{1, 1, 1, 1}, {2, 2, 2, 2}, {3, 3, 3, 3}};
  const auto result = SanitizeScene(scene, SanitizeOptions{});
  ASSERT_TRUE(result);
  ASSERT_EQ(result->scene.residuals.size(), 2u);
  EXPECT_EQ(result->scene.residuals[1][0], 3.0);
  EXPECT_FALSE(result->scene.HasMemberships());
}

TEST(SanitizeScene, FailsOnlyWhenNothingUsableIsLeft) {
  Scene scene;
  scene.segments.push_back(Segment3{Vec3(kNaN, 0, 0), Vec3(1, 0, 0)});
  scene.segments.push_back(Segment3{Vec3(1e300, 0, 0), Vec3(-1e300, 0, 0)});
  scene.observations.AddRow(std::vector<ViewpointId>{});
  scene.observations.AddRow(std::vector<ViewpointId>{});
  const auto result = SanitizeScene(scene, SanitizeOptions{});
  ASSERT_FALSE(result);
  EXPECT_EQ(result.error().code, ErrorCode::kInvalidInput);
  EXPECT_NE(result.error().message.find("no usable segment left"), std::string::npos);
  EXPECT_NE(result.error().message.find("2 segments dropped: non-finite"), std::string::npos);

  const auto empty = SanitizeScene(Scene{}, SanitizeOptions{});
  ASSERT_FALSE(empty);
  EXPECT_NE(empty.error().message.find("no segments"), std::string::npos);
}

TEST(SanitizeScene, InconsistentArraysAreInvalidInput) {
  Scene scene = FloorScene(Vec3::Zero());
  scene.memberships.resize(3);
  const auto result = SanitizeScene(scene, SanitizeOptions{});
  ASSERT_FALSE(result);
  EXPECT_EQ(result.error().code, ErrorCode::kInvalidInput);
}

TEST(SanitizeScene, ValidateNamesTheBadField) {
  SanitizeOptions options;
  options.min_segment_length_rel = -1;
  const Status status = options.Validate();
  ASSERT_FALSE(status);
  EXPECT_EQ(status.error().code, ErrorCode::kInvalidOptions);
  EXPECT_NE(status.error().message.find("min_segment_length_rel"), std::string::npos);
  options = SanitizeOptions{};
  options.max_abs_coordinate = std::numeric_limits<double>::infinity();
  EXPECT_FALSE(options.Validate());
  EXPECT_FALSE(SanitizeScene(FloorScene(Vec3::Zero()), options));
}

TEST(SanitizeScene, WithoutRecentringCoordinatesStay) {
  SanitizeOptions options;
  options.recentre = false;
  const auto result = SanitizeScene(FloorScene(Vec3(1e6, 0, 0)), options);
  ASSERT_TRUE(result);
  EXPECT_TRUE(result->scene.world_from_local.translation.isZero());
  EXPECT_EQ(result->scene.segments[SegmentId(0u)].p1, Vec3(1e6, 0, 0));
}

}  // namespace
}  // namespace linesurf::pipeline
