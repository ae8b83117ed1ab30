#pragma once
// Sanitise, then detect planes: the start of every run that detects its planes (`linesurf
// detect` and Reconstruct without given planes), written once.

#include "linesurf/error.h"

#include "engine/core/run_context.h"
#include "engine/core/scene.h"
#include "engine/detect/detect_planes.h"
#include "engine/pipeline/sanitize_scene.h"
#include "engine/pipeline/stage_timer.h"
#include "partition/voxel/block_size_rule.h"

#include <cstddef>
#include <string>
#include <vector>

namespace linesurf::pipeline {

struct DetectedScene {
  /// Sanitised (local frame, see world_from_local) and holding the detected planes and one
  /// membership per segment; the input's own planes are dropped first (detection ignores them).
  Scene scene;
  /// Per segment of `scene`, its id in the input scene.
  IdVector<SegmentId, SegmentId> input_segment;
  SanitizeStats sanitize_stats;
  /// The data's frame sanitation turned the scene into (SanitizeResult::frame).
  DataFrame frame;
  /// Sanitation's warnings, one sentence each.
  std::vector<std::string> warnings;
  /// The detection's numbers and per-plane support (its planes and memberships are in `scene`).
  PlaneDetectionStats detection_stats;
  IdVector<PlaneId, PlaneSupport> support;
  /// How many planes the input carried (ignored).
  std::size_t given_planes = 0;
  /// Side of the detection blocks used (0 = the whole scene at once).
  double detection_block_size = 0.0;
};

/// @brief Drops the input's planes and memberships, sanitises, and detects planes.
/// @param timer when given, times the stages "sanitize" and "detect".
/// @param auto_blocks when given and detect.block_size is 0, detection runs on cubes of the side
/// this rule picks for the sanitised segments (by segments alone), or on the whole scene when the
/// rule picks one block (then the result is the monolithic detection's).
/// @param runner when given, runs the per-block RANSAC (DetectPlanes).
/// @return the errors of SanitizeScene and DetectPlanes (kCancelled between the two).
[[nodiscard]] Expected<DetectedScene> SanitizeAndDetectPlanes(
    Scene scene,
    const SanitizeOptions& sanitize,
    const PlaneDetectionOptions& detect,
    const RunContext& ctx,
    StageTimer* timer = nullptr,
    const partition::BlockSizeRule* auto_blocks = nullptr,
    detect::DetectionRunner* runner = nullptr) noexcept;

}  // namespace linesurf::pipeline
