#include "engine/pipeline/judge_result.h"

#include "engine/detect/detect_planes.h"

#include <gtest/gtest.h>

#include <string>

namespace linesurf::pipeline {
namespace {

bool Mentions(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

/// A healthy exterior run: closed, manifold, positive volume, strong decision.
ResultFacts GoodExterior() {
  ResultFacts f;
  f.decision.observing_viewpoints = 28;
  f.planes = 10;
  f.planes_in_complex = 10;
  f.cells = 90;
  f.full_cells = 12;
  f.observing_viewpoints = 28;
  f.sigma = 1.0;
  f.scene_diagonal = 70.0;
  f.detection_epsilon = 0.02;
  f.samples = 1000;
  f.topology.paired = true;
  f.topology.signed_volume = 600.0;
  f.mesh_faces = 19;
  return f;
}

TEST(JudgeResult, HealthyRunHasNoWarning) {
  const ResultJudgement j = JudgeResult(GoodExterior());
  EXPECT_FALSE(j.error);
  EXPECT_TRUE(j.warnings.empty());
}

TEST(JudgeResult, EmptySurfaceIsAnErrorNamingTheCause) {
  ResultFacts f = GoodExterior();
  f.mesh_faces = 0;
  f.planes = f.planes_in_complex = 1;
  ResultJudgement j = JudgeResult(f);
  ASSERT_TRUE(j.error);
  EXPECT_EQ(j.error->code, ErrorCode::kDegenerate);
  EXPECT_TRUE(Mentions(j.error->message, "empty")) << j.error->message;
  EXPECT_TRUE(Mentions(j.error->message, "only 1 plane")) << j.error->message;

  f = GoodExterior();
  f.mesh_faces = 0;
  f.has_data_weight = false;
  j = JudgeResult(f);
  ASSERT_TRUE(j.error);
  EXPECT_TRUE(Mentions(j.error->message, "every data weight")) << j.error->message;

  f = GoodExterior();
  f.mesh_faces = 0;
  f.sigma = 1e300;
  j = JudgeResult(f);
  ASSERT_TRUE(j.error);
  EXPECT_TRUE(Mentions(j.error->message, "sigma")) << j.error->message;

  f = GoodExterior();
  f.mesh_faces = 0;
  f.grazing_samples = f.samples;
  j = JudgeResult(f);
  ASSERT_TRUE(j.error);
  EXPECT_TRUE(Mentions(j.error->message, "viewpoint lies in the segment's plane"));

  f = GoodExterior();
  f.mesh_faces = 0;
  f.auto_mode = false;
  f.interior = true;
  f.viewpoints_in_full_cells = f.observing_viewpoints;
  j = JudgeResult(f);
  ASSERT_TRUE(j.error);
  EXPECT_TRUE(Mentions(j.error->message, "is it an exterior scene")) << j.error->message;
  EXPECT_TRUE(Mentions(j.error->message, "scene mode interior was requested"));
}

TEST(JudgeResult, InvertedSurfaceIsAnError) {
  ResultFacts f = GoodExterior();
  f.topology.signed_volume = -5.0;
  ResultJudgement j = JudgeResult(f);
  ASSERT_TRUE(j.error);
  EXPECT_TRUE(Mentions(j.error->message, "inverted")) << j.error->message;
  f.interior = true;  // interior surfaces enclose empty space: negative is right
  f.decision.enclosed_viewpoints = f.decision.observing_viewpoints;
  j = JudgeResult(f);
  EXPECT_FALSE(j.error);
}

TEST(JudgeResult, CapWeakDecisionAndViewpointsInsideAreWarned) {
  ResultFacts f = GoodExterior();
  PlaneDetectionStats detection;
  detection.capped_blocks = 1;
  f.plane_cap_warning = PlaneCapWarning(detection, 160);
  f.decision.enclosed_viewpoints = 13;
  f.decision.weak = true;
  f.viewpoints_in_full_cells = 2;
  f.detection_epsilon = 20.0;
  const ResultJudgement j = JudgeResult(f);
  EXPECT_FALSE(j.error);
  ASSERT_EQ(j.warnings.size(), 4u);
  EXPECT_TRUE(Mentions(j.warnings[0], "weak evidence")) << j.warnings[0];
  EXPECT_TRUE(Mentions(j.warnings[1], "max_planes (160)")) << j.warnings[1];
  EXPECT_TRUE(Mentions(j.warnings[2], "eps")) << j.warnings[2];
  EXPECT_TRUE(Mentions(j.warnings[3], "2 of 28")) << j.warnings[3];
}

TEST(JudgeResult, GivenModeAgainstTheEvidenceIsWarned) {
  ResultFacts f = GoodExterior();
  f.auto_mode = false;
  f.decision.enclosed_viewpoints = 28;
  const ResultJudgement j = JudgeResult(f);
  ASSERT_EQ(j.warnings.size(), 1u);
  EXPECT_TRUE(Mentions(j.warnings[0], "looks like an interior")) << j.warnings[0];
  EXPECT_TRUE(Mentions(j.warnings[0], "28 of 28 observing viewpoints")) << j.warnings[0];
}

TEST(JudgeResult, ASampledDecisionSaysSoInItsWarning) {
  ResultFacts f = GoodExterior();
  f.decision.observing_viewpoints = 1000;
  f.decision.sampled_from = 6402;
  f.decision.enclosed_viewpoints = 500;
  f.decision.weak = true;
  const ResultJudgement j = JudgeResult(f);
  ASSERT_FALSE(j.warnings.empty());
  EXPECT_TRUE(Mentions(j.warnings[0], "500 of 1000 viewpoints (an even sample of 6402 observing)"))
      << j.warnings[0];
}

}  // namespace
}  // namespace linesurf::pipeline
