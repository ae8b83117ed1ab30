#include "engine/pipeline/data_frame.h"

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

namespace linesurf::pipeline {
namespace {

/// A box-like building in the frame `turn` (its z up): edges along the three axes, more along
/// x than y, a few lines in no axis, and cameras on a ring at eye height around it.
Scene Building(const Eigen::Matrix3d& turn, bool with_views = true) {
  Scene scene;
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  auto add = [&](const Vec3& a, const Vec3& b) {
    scene.segments.push_back(Segment3{turn * a, turn * b});
  };
  for (int i = 0; i < 40; ++i) {
    const double x = 10.0 * u(rng), y = 4.0 * u(rng), z = 3.0 + 3.0 * u(rng);
    add({x - 2.0, y, z}, {x + 2.0, y, z});              // along x
    if (i % 2 == 0) add({x, y - 1.5, z}, {x, y + 1.5, z});  // along y, fewer
    add({x, y, z - 1.0}, {x, y, z + 1.0});              // vertical
    add({x, y, z}, {x + 0.5 * u(rng), y + 0.5 * u(rng), z + 0.5 * u(rng)});  // in no axis
  }
  const std::size_t n = scene.NumSegments();
  if (with_views) {
    for (int k = 0; k < 16; ++k) {
      const double a = 2.0 * EIGEN_PI * k / 16.0;
      scene.viewpoints.push_back(turn * Vec3(25.0 * std::cos(a), 15.0 * std::sin(a), 1.6));
    }
  }
  for (std::size_t s = 0; s < n; ++s) {
    const std::vector<ViewpointId> row =
        with_views ? std::vector<ViewpointId>{ViewpointId(s % 16), ViewpointId((s + 5) % 16)}
                   : std::vector<ViewpointId>{};
    scene.observations.AddRow(row);
  }
  return scene;
}

Eigen::Matrix3d Turn(double degrees, const Vec3& axis) {
  return Eigen::AngleAxisd(degrees * EIGEN_PI / 180.0, axis.normalized()).toRotationMatrix();
}

TEST(DataFrame, FindsTheBuildingsAxesAndItsUp) {
  const Eigen::Matrix3d turn = Turn(70.0, {1.0, 2.0, 3.0});
  const DataFrame frame = EstimateDataFrame(Building(turn));
  ASSERT_TRUE(frame.found);
  EXPECT_EQ(frame.up_evidence, UpEvidence::kViewpointSpread);
  EXPECT_GT(frame.up.dot(turn * Vec3::UnitZ()), 1.0 - 1e-9);
  EXPECT_GT(frame.axes.col(2).dot(frame.up), 1.0 - 1e-12);
  // x is the axis more line length follows: the building's x, either way.
  EXPECT_GT(std::abs(frame.axes.col(0).dot(turn * Vec3::UnitX())), 1.0 - 1e-9);
  EXPECT_NEAR(frame.axes.determinant(), 1.0, 1e-12);
  // By length: the lines in no axis are short (at most 0.87 of the 300 in the axes).
  EXPECT_GT(frame.axis_share, 0.9);
  EXPECT_LT(frame.axis_share, 1.0);
}

TEST(DataFrame, TurnsWithTheScene) {
  const Scene scene = Building(Turn(20.0, {0.0, 0.0, 1.0}));
  const DataFrame frame = EstimateDataFrame(scene);
  const Eigen::Matrix3d move = Turn(70.0, {1.0, 2.0, 3.0});
  Scene moved = scene;
  for (Segment3& s : moved.segments) s = Segment3{move * s.p1, move * s.p2};
  for (Vec3& v : moved.viewpoints) v = move * v;
  const DataFrame moved_frame = EstimateDataFrame(moved);
  ASSERT_TRUE(frame.found && moved_frame.found);
  EXPECT_LT((moved_frame.axes - move * frame.axes).norm(), 1e-9);
}

TEST(DataFrame, WithoutViewpointsUpIsTheAxisNearestTheInputsZ) {
  const DataFrame frame = EstimateDataFrame(Building(Turn(10.0, {1.0, 0.0, 0.0}), false));
  ASSERT_TRUE(frame.found);
  EXPECT_EQ(frame.up_evidence, UpEvidence::kInputZ);
  EXPECT_GT(std::abs(frame.up.dot(Turn(10.0, {1.0, 0.0, 0.0}) * Vec3::UnitZ())), 1.0 - 1e-9);
}

TEST(DataFrame, ParallelLinesHaveNoFrame) {
  Scene scene;
  for (int i = 0; i < 10; ++i) {
    scene.segments.push_back(Segment3{Vec3(i, 0, 0), Vec3(i, 0, 0) + Vec3(1, 1, 1)});
  }
  for (std::size_t s = 0; s < scene.NumSegments(); ++s) {
    scene.observations.AddRow(std::vector<ViewpointId>{});
  }
  const DataFrame frame = EstimateDataFrame(scene);
  EXPECT_FALSE(frame.found);
  EXPECT_EQ(frame.up_evidence, UpEvidence::kNone);
  EXPECT_TRUE(frame.axes.isIdentity());
  EXPECT_EQ(EstimateDataFrame(Scene{}).found, false);
}

}  // namespace
}  // namespace linesurf::pipeline
