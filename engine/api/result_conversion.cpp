#include "engine/api/result_conversion.h"

#include "engine/api/scene_conversion.h"

namespace linesurf::api {
namespace {

DetectStats ToPublicStats(const PlaneDetectionStats& s, const pipeline::SanitizeStats& sane) {
  DetectStats out;
  out.input_segments = sane.input_segments;
  out.segments = sane.kept_segments;
  out.lines = s.lines;
  out.epsilon = s.epsilon;
  out.epsilon_estimate = s.epsilon_estimate;
  out.blocks = s.blocks;
  out.planes_before_fusion = s.planes_before_fusion;
  out.planes = s.planes_after_fusion;
  out.merges = s.merges;
  out.memberships_dropped = s.memberships_dropped;
  out.capped_blocks = s.capped_blocks;
  out.segments_with_0_planes = s.num_l0;
  out.segments_with_1_plane = s.num_l1;
  out.segments_with_2_planes = s.num_l2;
  out.candidates_evaluated = s.candidates_evaluated;
  out.failed_draws = s.failed_draws;
  out.seconds = s.seconds;
  out.seconds_fusion = s.seconds_fusion;
  return out;
}

}  // namespace

ReconstructResult ToPublicResult(const pipeline::ReconstructResult& result) {
  ReconstructResult out;
  out.mesh = ToMesh(result.mesh);
  // The pipeline already moved the planes to world coordinates.
  out.planes = ToWorldPlanes(result.planes, Rigid3{});
  out.memberships = ToMemberships(result.memberships, result.input_segment);
  out.stats = result.stats;
  out.warnings = result.warnings;
  return out;
}

DetectResult ToPublicResult(const pipeline::DetectedScene& detected, std::int32_t max_planes) {
  DetectResult out;
  out.planes = ToWorldPlanes(detected.scene.planes, detected.scene.world_from_local);
  out.support.reserve(detected.support.size());
  for (const PlaneSupport& s : detected.support) {
    out.support.push_back(PlaneSupportInfo{s.inlier_count, s.inlier_length});
  }
  out.memberships = ToMemberships(detected.scene.memberships, detected.input_segment);
  out.stats = ToPublicStats(detected.detection_stats, detected.sanitize_stats);
  out.warnings = detected.warnings;
  if (std::string cap = PlaneCapWarning(detected.detection_stats, max_planes); !cap.empty()) {
    out.warnings.push_back(std::move(cap));
  }
  return out;
}

}  // namespace linesurf::api
