#pragma once
// Plane detection from 3D line segments: RANSAC with multiple support (textural and structural
// lines), Langlois, Boulch & Marlet, 3DV 2019, section 3; see docs/plane_detection.md.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "engine/core/geometry.h"
#include "engine/core/run_context.h"
#include "engine/core/scene.h"
#include "engine/core/strong_id.h"
#include "linesurf/error.h"
#include "linesurf/result.h"  // EpsilonEstimate

namespace linesurf {

/// How the distance of a segment to a plane (or to a crease line) is measured.
enum class SegmentDistance {
  kMeanEndpoint,  ///< mean of the two endpoint distances (the paper's code; tolerant to noise)
  kMaxEndpoint,   ///< max of the two endpoint distances (the whole segment lies in the slab)
};

/// Parameters of DetectPlanes. Lengths are in scene units (metres for metric scenes).
struct PlaneDetectionOptions {
  /// Inlier tolerance eps (scene units, > 0). Unset (default, `--epsilon auto`): estimated from
  /// the data (estimate_epsilon.h), so metric scenes, SfM units and noisier clouds need no flag.
  /// Paper: 2 cm on metric scenes.
  std::optional<double> epsilon;
  /// eps auto: eps = epsilon_over_noise x the robust noise scale of the endpoint-to-plane
  /// residuals ((0, 20]). 2.5: the mean of two endpoint distances of a Gaussian N(0, s^2) segment
  /// stays under 2.5 s with probability 99.9 %, its distance to a crease line with 99.2 %.
  double epsilon_over_noise = 2.5;
  /// If set, eps = relative_epsilon x (scene bounding-box diagonal) instead of `epsilon`. Range
  /// (0, 0.5).
  std::optional<double> relative_epsilon;
  /// Fusion thickness eps_fus as a multiple of eps (paper: 3).
  double epsilon_fusion_factor = 3.0;
  /// Fusion: planes closer than this angle may merge (degrees, (0, 90); paper: 10).
  double theta_fusion_deg = 10.0;
  /// Fusion: minimum shared support, as a fraction of the smaller plane's inlier count ([0, 1];
  /// paper: 0.2).
  double p_fusion = 0.2;
  /// Maximum number of candidate pairs per plane N_iter (>= 1; paper: 50000). The adaptive stop
  /// (`confidence`) usually ends the search much earlier.
  std::int64_t iterations = 50000;
  /// Candidates always evaluated per plane before the adaptive stop may end the search (>= 1).
  std::int64_t min_iterations = 512;
  /// Adaptive stop: end the search for a plane once the probability of having missed a plane
  /// better than the current best is below 1 - confidence ((0, 1); 0.999). Its trials are the
  /// valid candidates and the draws of lines more than 2 eps apart (docs/plane_detection.md).
  double confidence = 0.999;
  /// Maximum number of planes N_max (>= 1; paper: 160).
  std::int32_t max_planes = 160;
  /// A plane needs at least this many inlier segments (>= 2; the reference code uses 3).
  std::int32_t min_support = 3;
  /// One plane, one piece: when a plane's inliers fall into pieces more than this many median
  /// line lengths apart and a piece fitted on its own disagrees with the plane (by more than
  /// eps / 2 at one of its endpoints), the plane keeps only its largest piece (refitted) and the
  /// others stay free. Stops a plane tilted across two parallel roofs or walls of different
  /// buildings a few eps apart, which has more inliers than either. [0, 1000]; 0 = off (the
  /// paper's method). Not in the paper.
  double support_gap = 8.0;
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
  /// Segments on one infinite line (every endpoint within collinear_tolerance x eps of the
  /// other's line), such as the per-camera parts of one 3D line in the reference's residual
  /// inputs, are detected as one line (the span of its parts) and all get its planes: one
  /// physical line counts once, as in the reference RANSAC, which ran before the split. [0, 0.5];
  /// 0 = every segment on its own.
  double collinear_tolerance = 1e-3;
  /// Per-block detection (DESIGN section 3): when > 0, the scene is cut into cubes of this side
  /// (scene units); RANSAC runs per cube on the segments whose midpoint lies in the cube dilated
  /// by the halo, cubes in parallel, then a global fusion merges the pieces of one plane found
  /// in neighbouring cubes and re-applies the at-most-2 rule. Work grows about linearly with the
  /// scene; `max_planes` then bounds each block's RANSAC, not the total (a city has thousands),
  /// and a block whose RANSAC reaches it is split into 8 (docs/plane_detection.md).
  /// 0 = the whole scene is one block (the monolithic method). A scene that fits in one cube
  /// gives exactly the monolithic result.
  double block_size = 0.0;
  /// A block (of a grid, block_size > 0) whose RANSAC reaches max_planes is split into its 8
  /// half-size cubes, detected in its place (docs/plane_detection.md). Off for the eps probes,
  /// which want only each block's largest planes.
  bool split_blocks_at_cap = true;
  /// Halo of a block, as a fraction of its side ([0, 0.5)).
  double block_halo = 0.1;
  /// A block whose midpoints number more than this is split into 8 halves, recursively, so that
  /// crowded places do not make one block's RANSAC the bottleneck (>= 0; 0 = never split). The
  /// count is of distinct lines (collinear parts merged). 2,000: a synthetic city has about one
  /// plane per 15 lines, so a block of 2,400 lines or more reaches max_planes' 160 and runs again
  /// as its children, its RANSAC lost (docs/plane_detection.md).
  std::int64_t block_max_segments = 2000;
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

/// Detects planes in `scene.segments` (given planes and memberships are ignored).
/// Deterministic: the result depends on the input, options and seed, not on the thread count
/// (`ctx.num_threads`). Cancellable through `ctx`.
[[nodiscard]] Expected<PlaneDetectionResult> DetectPlanes(const Scene& scene,
                                                          const PlaneDetectionOptions& options,
                                                          const RunContext& ctx) noexcept;

}  // namespace linesurf
