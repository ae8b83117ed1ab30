#include "engine/pipeline/evaluate_mesh.h"

#include "tests/support/box_mesh.h"

#include <gtest/gtest.h>

#include <array>
#include <vector>

namespace linesurf::pipeline {
namespace {

using linesurf::testing::Append;
using linesurf::testing::Box;
using linesurf::testing::Cube;

// Built once and copied: GCC 12 warns of a dangling pointer (a false positive) when the
// defaults' initializer list is inlined into every test.
EvaluationOptions SmallOptions() {
  static const EvaluationOptions small = [] {
    EvaluationOptions options;
    options.samples_per_mesh = 20000;
    return options;
  }();
  return small;
}

TEST(EvaluateMesh, GroundTruthAgainstItselfIsPerfect) {
  EvaluationOptions options = SmallOptions();
  options.thresholds = {0.001, 0.05};
  const auto result = EvaluateMesh(Cube(1.0), Cube(1.0), options);
  ASSERT_TRUE(result) << result.error().ToString();
  EXPECT_DOUBLE_EQ(result->precision[0], 1.0);
  EXPECT_DOUBLE_EQ(result->completeness[0], 1.0);
  EXPECT_LT(result->result_to_gt.max, 1e-9);
  EXPECT_LT(result->gt_to_result.max, 1e-9);
  EXPECT_NEAR(result->result_area, 24.0, 1e-9);
  EXPECT_EQ(result->num_visible_gt_samples, options.samples_per_mesh);
  const MeshValidity& topo = result->topology;
  EXPECT_TRUE(topo.closed);
  EXPECT_TRUE(topo.two_manifold);
  EXPECT_TRUE(topo.oriented);
  EXPECT_TRUE(topo.outward);
  EXPECT_FALSE(topo.self_intersecting);
  EXPECT_EQ(topo.num_components, 1U);
  EXPECT_NEAR(topo.signed_volume, 8.0, 1e-9);
}

TEST(EvaluateMesh, VerticesMovedByFiveCentimetresIsClearlyWorse) {
  const auto result = EvaluateMesh(Cube(1.05), Cube(1.0), SmallOptions());
  ASSERT_TRUE(result) << result.error().ToString();
  // Thresholds 2, 5, 10 cm: every face is 5 cm away from the ground truth.
  EXPECT_EQ(result->precision[0], 0.0);
  EXPECT_EQ(result->completeness[0], 0.0);
  EXPECT_EQ(result->precision[2], 1.0);
  EXPECT_GT(result->result_to_gt.mean, 0.049);
  EXPECT_GT(result->gt_to_result.median, 0.049);
  EXPECT_LT(result->result_to_gt.max, 0.05 * std::sqrt(3.0) + 1e-9);
}

TEST(EvaluateMesh, RandomVertexJitterLowersPrecision) {
  PolygonMesh moved = Cube(1.0);
  for (std::size_t v = 0; v < moved.vertices.size(); ++v) {
    moved.vertices[v] += 0.05 * Vec3((v & 1) ? 1 : -1, (v & 2) ? -1 : 1, 1).normalized();
  }
  const auto perfect = EvaluateMesh(Cube(1.0), Cube(1.0), SmallOptions());
  const auto worse = EvaluateMesh(moved, Cube(1.0), SmallOptions());
  ASSERT_TRUE(perfect && worse);
  EXPECT_LT(worse->precision[0], 0.9 * perfect->precision[0]);
  EXPECT_LT(worse->completeness[0], 0.9 * perfect->completeness[0]);
}

TEST(EvaluateMesh, MissingFaceIsNotClosed) {
  PolygonMesh open;
  const PolygonMesh cube = Cube(1.0);
  open.vertices = cube.vertices;
  for (std::size_t f = 1; f < cube.NumFaces(); ++f) open.AddFace(cube.Face(f));
  const auto result = EvaluateMesh(open, cube, SmallOptions());
  ASSERT_TRUE(result) << result.error().ToString();
  EXPECT_FALSE(result->topology.closed);
  EXPECT_FALSE(result->topology.outward);
  EXPECT_TRUE(result->topology.two_manifold);
  EXPECT_TRUE(result->topology.oriented);
  EXPECT_EQ(result->topology.num_boundary_edges, 4U);
  EXPECT_DOUBLE_EQ(result->precision[0], 1.0);
  EXPECT_LT(result->completeness[0], 0.9);  // a sixth of the ground truth is missing
  EXPECT_GT(result->completeness[0], 0.75);
}

TEST(EvaluateMesh, VisibilityIgnoresHiddenGroundTruth) {
  // The ground truth holds a small box hidden inside the big one; the result is the big box.
  const PolygonMesh gt = Append(Cube(1.0), Cube(0.3));
  const auto all = EvaluateMesh(Cube(1.0), gt, SmallOptions());
  const std::vector<Vec3> views{Vec3(5, -4, 3), Vec3(-5, 4, 2), Vec3(0, 0, -6)};
  const auto seen = EvaluateMesh(Cube(1.0), gt, SmallOptions(), views);
  ASSERT_TRUE(all && seen);
  EXPECT_LT(all->completeness[2], 0.97);  // the inner box is 0.36 / 24.36 of the area
  EXPECT_DOUBLE_EQ(seen->completeness[0], 1.0);
  EXPECT_LT(seen->num_visible_gt_samples, seen->num_gt_samples);
  // Three generic viewpoints outside see at most 3 x 3 faces... all six here (one each axis side).
  EXPECT_GT(seen->num_visible_gt_samples, seen->num_gt_samples / 2);
}

TEST(EvaluateMesh, IdenticalForAnyThreadCount) {
  PolygonMesh moved = Cube(1.0);
  moved.vertices[3] += Vec3(0.1, -0.07, 0.02);
  RunContext serial;
  serial.num_threads = 1;
  RunContext parallel;
  parallel.num_threads = 2;
  const auto a = EvaluateMesh(moved, Cube(1.0), SmallOptions(), std::nullopt, &serial);
  const auto b = EvaluateMesh(moved, Cube(1.0), SmallOptions(), std::nullopt, &parallel);
  ASSERT_TRUE(a && b);
  EXPECT_EQ(a->precision, b->precision);
  EXPECT_EQ(a->completeness, b->completeness);
  EXPECT_EQ(a->result_to_gt.mean, b->result_to_gt.mean);
  EXPECT_EQ(a->gt_to_result.p95, b->gt_to_result.p95);
}

TEST(EvaluateMesh, RejectsBadOptionsAndEmptyMeshes) {
  EvaluationOptions options;
  options.thresholds = {0.05, 0.02};
  const auto bad = EvaluateMesh(Cube(1.0), Cube(1.0), options);
  ASSERT_FALSE(bad);
  EXPECT_EQ(bad.error().code, ErrorCode::kInvalidOptions);
  const auto empty = EvaluateMesh(PolygonMesh{}, Cube(1.0), SmallOptions());
  ASSERT_FALSE(empty);
  EXPECT_EQ(empty.error().code, ErrorCode::kInvalidInput);
}

}  // namespace
}  // namespace linesurf::pipeline
