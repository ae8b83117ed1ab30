#pragma once
// Plane detection from 3D line segments: RANSAC with multiple support (textural and structural
// lines), Langlois, Boulch & Marlet, 3DV 2019, section 3; see docs/design/plane_detection.md.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "engine/core/geometry.h"
#include "engine/core/run_context.h"
#include "engine/core/scene.h"
#include "engine/core/strong_id.h"
#include "linesurf/error.h"
#include "linesurf/options.h"
#include "linesurf/result.h"  // EpsilonEstimate

namespace linesurf {

/// How the distance of a segment to a plane (or to a crease line) is measured.
enum class SegmentDistance {
  kMeanEndpoint,  ///< mean of the two endpoint distances (the paper's code; tolerant to noise)
  kMaxEndpoint,   ///< max of the two endpoint distances (the whole segment lies in the slab)
};

/// Parameters of DetectPlanes. Lengths are in scene units (metres for metric scenes). The
/// options a user sets are the facade's DetectionParameters (linesurf/options.h: defaults and
/// rationale; ranges in linesurf/option_schema.h); the fields here are the engine's own knobs.
struct PlaneDetectionOptions : DetectionParameters {
  /// Candidates always evaluated per plane before the adaptive stop may end the search (>= 1).
  std::int64_t min_iterations = 512;
  /// Adaptive stop: end the search for a plane once the probability of having missed a plane
  /// better than the current best is below 1 - confidence ((0, 1); 0.999). Its trials are the
  /// valid candidates and the draws of lines more than 2 eps apart (docs/design/plane_detection.md).
  double confidence = 0.999;
  /// Bound on failed pair draws (invalid pairs) while searching one plane (>= 1). Replaces the
  /// reference's N_iter x 1e5 draws of its final, failing extraction.
  std::int64_t max_failed_draws = 200000;
  /// Draw attempts per candidate before the candidate counts as failed (>= 1).
  std::int32_t max_draws_per_candidate = 64;
  /// Pairs whose directions are closer than this angle are rejected (degrees, (0, 90)).
  double min_pair_angle_deg = 3.0;
  /// A segment on plane P' joins candidate P as a structural (crease) segment only if P and P'
  /// make at least this angle (degrees, (0, 90)); below it the crease line is ill-defined.
  double min_crease_angle_deg = 10.0;
  /// Distance measure of segments to planes and crease lines.
  SegmentDistance distance = SegmentDistance::kMeanEndpoint;
  /// When the sampling pool holds at most this many segments, every pair is a candidate
  /// (exhaustive search, N_iter ignored); 0 disables it.
  std::int32_t exhaustive_pairs_max_segments = 64;
  /// The second segment of a pair is drawn among the `near_window` segments before and after the
  /// first in a spatial (BVH leaf) order, with probability `near_fraction`; otherwise uniformly.
  std::int32_t near_window = 128;
  double near_fraction = 0.9;
  /// Rank candidates by the truncated quadratic score sum(1 - (d / eps)^2) over inliers (MSAC)
  /// instead of the inlier count: prefers planes whose inliers are tight, which keeps slightly
  /// tilted hybrids of nearby parallel planes from winning.
  bool score_by_residual = false;
  /// Refit / re-collect rounds per plane (>= 0).
  std::int32_t max_refit_iterations = 10;
  /// Ablation: a segment supports at most one plane (no structural lines).
  bool single_support = false;
  /// Ablation: segments already on a plane are tested by their plane distance instead of their
  /// distance to the crease line P ∩ P'.
  bool no_structural_condition = false;
  /// A block (of a grid, block_size > 0) whose RANSAC reaches max_planes is split into its 8
  /// half-size cubes, detected in its place (docs/design/plane_detection.md). Off for the eps probes,
  /// which want only each block's largest planes.
  bool split_blocks_at_cap = true;
  /// Seed of all random streams; same input + options + seed => same output, any thread count.
  std::uint64_t seed = 0;

  /// Names the first out-of-range field.
  [[nodiscard]] Status Validate() const;
};

/// Support of one detected plane.
struct PlaneSupport {
  std::uint32_t inlier_count = 0;
  double inlier_length = 0.0;  ///< total length of the inlier segments
  std::vector<SegmentId> inliers;  ///< ascending
};

struct PlaneDetectionStats {
  std::int32_t planes_before_fusion = 0;
  std::int32_t planes_after_fusion = 0;
  std::int32_t merges = 0;
  /// Segments on 0, 1, 2 planes after fusion.
  std::int64_t num_l0 = 0;
  std::int64_t num_l1 = 0;
  std::int64_t num_l2 = 0;
  std::int64_t candidates_evaluated = 0;
  std::int64_t failed_draws = 0;
  /// Distinct lines detected on (segments after merging collinear duplicates).
  std::int64_t lines = 0;
  /// Blocks detected (1 without per-block detection; a block split at the cap counts as its
  /// children) and memberships dropped by the at-most-2 rule after merging the blocks' planes.
  std::int64_t blocks = 0;
  std::int64_t memberships_dropped = 0;
  /// Blocks whose RANSAC stopped because it reached max_planes and that could not be split
  /// (planes may be missing there).
  std::int64_t capped_blocks = 0;
  double epsilon = 0.0;  ///< the eps actually used (scene units)
  EpsilonEstimate epsilon_estimate;  ///< how it was chosen
  double seconds = 0.0;
  double seconds_fusion = 0.0;
};

struct PlaneDetectionResult {
  /// Point = length-weighted centroid of the inliers' endpoints; unit normal oriented toward the
  /// majority of the viewpoints observing the inliers.
  IdVector<PlaneId, Plane3> planes;
  IdVector<PlaneId, PlaneSupport> support;
  /// One entry per input segment, plane ids ascending, at most 2.
  IdVector<SegmentId, PlaneMembership> memberships;
  PlaneDetectionStats stats;
};

/// The warning for a detection that stopped at max_planes in `stats.capped_blocks` blocks ("" when
/// none did): planes may be missing.
[[nodiscard]] std::string PlaneCapWarning(const PlaneDetectionStats& stats, std::int32_t max_planes);

namespace detect {
class DetectionRunner;
}

/// Detects planes in `scene.segments` (given planes and memberships are ignored).
/// Deterministic: the result depends on the input, options and seed, not on the thread count
/// (`ctx.num_threads`). Cancellable through `ctx`. The per-block RANSAC runs in this process, or
/// through `runner` when given (detect/detection_run.h: the same planes).
[[nodiscard]] Expected<PlaneDetectionResult> DetectPlanes(
    const Scene& scene,
    const PlaneDetectionOptions& options,
    const RunContext& ctx,
    detect::DetectionRunner* runner = nullptr) noexcept;

}  // namespace linesurf
