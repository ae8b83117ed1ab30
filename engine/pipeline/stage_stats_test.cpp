#include "engine/pipeline/stage_stats.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace linesurf::pipeline {
namespace {

// Four segments: on no plane, on plane 0, on planes 0 and 1, on plane 1; two viewpoints, three
// observations.
Scene FourSegments() {
  Scene scene;
  for (int i = 0; i < 4; ++i) {
    scene.segments.push_back({Vec3(i, 0.0, 0.0), Vec3(i, 1.0, 0.0)});
  }
  scene.viewpoints.push_back(Vec3(0.0, 0.0, 5.0));
  scene.viewpoints.push_back(Vec3(1.0, 0.0, 5.0));
  scene.observations.AddRow(std::array<ViewpointId, 2>{ViewpointId(0u), ViewpointId(1u)});
  scene.observations.AddRow(std::array<ViewpointId, 1>{ViewpointId(1u)});
  scene.observations.AddRow(std::array<ViewpointId, 0>{});
  scene.observations.AddRow(std::array<ViewpointId, 0>{});
  scene.planes.push_back(Plane3{Vec3::Zero(), Vec3::UnitZ()});
  scene.planes.push_back(Plane3{Vec3::Zero(), Vec3::UnitX()});
  scene.memberships.resize(4);
  scene.memberships[SegmentId(1u)].Add(PlaneId(0u));
  scene.memberships[SegmentId(2u)].Add(PlaneId(0u));
  scene.memberships[SegmentId(2u)].Add(PlaneId(1u));
  scene.memberships[SegmentId(3u)].Add(PlaneId(1u));
  return scene;
}

TEST(StageStats, InputsAreTheSanitisedScenesAndTheSegmentsRead) {
  SanitizeStats sanitation;
  sanitation.input_segments = 9;
  const InputStats s = MakeInputStats(sanitation, FourSegments());
  EXPECT_EQ(s.input_segments, 9u);
  EXPECT_EQ(s.segments, 4u);
  EXPECT_EQ(s.viewpoints, 2u);
  EXPECT_EQ(s.observations, 3u);
}

TEST(StageStats, GivenPlanesCountTheMembershipsAndHaveNoDetectionBlocks) {
  EpsilonEstimate eps;
  eps.epsilon = 0.25;
  eps.source = "planes";
  const DetectionStats s = MakeDetectionStats(FourSegments(), eps);
  EXPECT_EQ(s.planes, 2u);
  EXPECT_EQ(s.capped_blocks, 0u);
  EXPECT_EQ(s.detection_block_size, 0.0);
  EXPECT_EQ(s.segments_with_planes, (std::array<std::size_t, 3>{1, 2, 1}));
  EXPECT_EQ(s.epsilon.epsilon, 0.25);
  EXPECT_EQ(s.epsilon.source, "planes");
}

TEST(StageStats, DetectedPlanesTakeTheDetectionsBlocksAndEpsilon) {
  DetectedScene detected;
  detected.scene = FourSegments();
  detected.detection_stats.capped_blocks = 3;
  detected.detection_stats.epsilon_estimate.epsilon = 0.5;
  detected.detection_stats.epsilon_estimate.source = "probe";
  detected.detection_block_size = 12.0;
  const DetectionStats s = MakeDetectionStats(detected);
  EXPECT_EQ(s.planes, 2u);
  EXPECT_EQ(s.capped_blocks, 3u);
  EXPECT_EQ(s.detection_block_size, 12.0);
  EXPECT_EQ(s.segments_with_planes, (std::array<std::size_t, 3>{1, 2, 1}));
  EXPECT_EQ(s.epsilon.source, "probe");
}

TEST(StageStats, SceneWithoutMembershipsHasEverySegmentOnNoPlane) {
  Scene scene = FourSegments();
  scene.memberships.clear();
  EXPECT_EQ(MakeDetectionStats(scene, {}).segments_with_planes,
            (std::array<std::size_t, 3>{4, 0, 0}));
}

TEST(StageStats, SceneModeReasonOnlyWhenTheModeWasAutomatic) {
  ResultFacts facts;
  facts.interior = true;
  facts.decision.reason = "auto: 3 of 3 viewpoints enclosed -> interior";
  facts.auto_mode = true;
  SceneModeStats s = MakeSceneModeStats(facts);
  EXPECT_EQ(s.scene_mode, "interior");
  EXPECT_EQ(s.scene_mode_reason, facts.decision.reason);
  facts.auto_mode = false;
  facts.interior = false;
  s = MakeSceneModeStats(facts);
  EXPECT_EQ(s.scene_mode, "exterior");
  EXPECT_EQ(s.scene_mode_reason, "");
}

TEST(StageStats, LabelingCountsTheFullCellsAndKeepsTheSolversWords) {
  solver::LabelingResult labeling;
  labeling.labels = {1, 0, 1, 1, 0};
  labeling.backend = SolverBackend::kClp;
  labeling.status = "optimal";
  labeling.method = "clp lp, rounding";
  labeling.lp_columns = 5;
  labeling.lp_rows = 7;
  labeling.lp_nonzeros = 11;
  labeling.labels_objective = 2.0;
  labeling.rounded_objective = 2.5;
  labeling.relaxed_objective = 1.5;
  labeling.lower_bound_source = "none";
  labeling.fractional_cells = 1;
  const LabelingStats s = MakeLabelingStats(labeling);
  EXPECT_EQ(s.full_cells, 3u);
  EXPECT_EQ(s.lp_variables, 5u);
  EXPECT_EQ(s.lp_constraints, 7u);
  EXPECT_EQ(s.lp_nonzeros, 11u);
  EXPECT_EQ(s.solver_backend, "clp");
  EXPECT_EQ(s.solver_status, "optimal");
  EXPECT_EQ(s.labeling_method, "clp lp, rounding");
  EXPECT_EQ(s.objective, 2.0);
  EXPECT_EQ(s.rounded_objective, 2.5);
  EXPECT_EQ(s.relaxed_objective, 1.5);
  EXPECT_TRUE(std::isinf(s.lower_bound) && s.lower_bound < 0.0);  // none known
  EXPECT_EQ(s.lower_bound_source, "none");
  EXPECT_EQ(s.fractional_cells, 1u);
}

TEST(StageStats, SurfaceIsTheMeshReturnedWithTheExtractionsSplitVertices) {
  PolygonMesh mesh;
  mesh.vertices = {Vec3::Zero(), Vec3::UnitX(), Vec3::UnitY()};
  mesh.face_offsets = {0, 3};
  mesh.face_indices = {0, 1, 2};
  MeshTopology topology;
  topology.paired = true;
  topology.num_non_manifold_vertices = 1;
  topology.signed_volume = -1.5;
  ExtractStats extraction;
  extraction.split_vertices = 4;
  const SurfaceStats s = MakeSurfaceStats(mesh, topology, extraction, {});
  EXPECT_EQ(s.mesh_vertices, 3u);
  EXPECT_EQ(s.mesh_faces, 1u);
  EXPECT_TRUE(s.mesh_closed);
  EXPECT_FALSE(s.mesh_manifold);
  EXPECT_EQ(s.mesh_volume, -1.5);
  EXPECT_EQ(s.split_vertices, 4u);
}

TEST(StageStats, FragmentsAndQuality) {
  FragmentRemoval removal;
  removal.removed_components = 2;
  removal.removed_volume = 0.75;
  removal.removed_supported_segments = 5;
  const FragmentStats f = MakeFragmentStats(removal);
  EXPECT_EQ(f.removed_fragments, 2u);
  EXPECT_EQ(f.removed_fragment_volume, 0.75);
  EXPECT_EQ(f.removed_fragment_segments, 5u);
  SurfaceQuality figures;
  figures.data_fit = 0.9;
  const QualityStats q = MakeQualityStats(figures);
  EXPECT_TRUE(q.measured);
  EXPECT_EQ(q.data_fit, 0.9);
  EXPECT_FALSE(QualityStats{}.measured);
}

TEST(StageStats, ResourcesSumTheStagesInRunOrder) {
  const ResourceStats s = MakeResourceStats({{"sanitize", 0.5}, {"detect", 1.25}, {"solve", 2.0}});
  ASSERT_EQ(s.stage_seconds.size(), 3u);
  EXPECT_EQ(s.stage_seconds[1].first, "detect");
  EXPECT_EQ(s.total_seconds, 3.75);
  EXPECT_EQ(MakeResourceStats({}).total_seconds, 0.0);
}

}  // namespace
}  // namespace linesurf::pipeline
