#include "engine/detect/detect_planes.h"

#include "linesurf/option_schema.h"

#include "engine/core/exception.h"
#include "engine/core/parallel.h"
#include "engine/detect/collinear_groups.h"
#include "engine/detect/detect_in_blocks.h"
#include "engine/detect/detect_stage.h"
#include "engine/detect/estimate_epsilon.h"
#include "engine/detect/plane_fusion.h"
#include "engine/detect/segment_geometry.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <sstream>

namespace linesurf {

namespace {
using detect::kDetectPlanesStage;

Status Invalid(const std::string& field, const std::string& range) {
  return Error{ErrorCode::kInvalidOptions,
               kDetectPlanesStage,
               "PlaneDetectionOptions." + field + " must be " + range};
}
}  // namespace

Status PlaneDetectionOptions::Validate() const {
  if (Status s = ValidateOptionValues(static_cast<const DetectionParameters&>(*this)); !s) {
    return s;
  }
  if (min_iterations < 1) return Invalid("min_iterations", ">= 1");
  if (!(confidence > 0.0 && confidence < 1.0)) return Invalid("confidence", "in (0, 1)");
  if (max_failed_draws < 1) return Invalid("max_failed_draws", ">= 1");
  if (max_draws_per_candidate < 1) return Invalid("max_draws_per_candidate", ">= 1");
  if (!(min_pair_angle_deg > 0.0 && min_pair_angle_deg < 90.0)) {
    return Invalid("min_pair_angle_deg", "in (0, 90)");
  }
  if (!(min_crease_angle_deg > 0.0 && min_crease_angle_deg < 90.0)) {
    return Invalid("min_crease_angle_deg", "in (0, 90)");
  }
  if (exhaustive_pairs_max_segments < 0 || exhaustive_pairs_max_segments > 4096) {
    return Invalid("exhaustive_pairs_max_segments", "in [0, 4096]");
  }
  if (near_window < 1) return Invalid("near_window", ">= 1");
  if (!(near_fraction >= 0.0 && near_fraction <= 1.0)) return Invalid("near_fraction", "in [0, 1]");
  if (max_refit_iterations < 0) return Invalid("max_refit_iterations", ">= 0");
  return {};
}

namespace detect {
namespace {

/// Flips `plane` toward the majority of the viewpoints that observe its inliers (canonical sign
/// first: largest normal component positive, which also breaks ties).
void OrientPlane(const Scene& scene, const std::vector<SegmentId>& inliers, Plane3& plane) {
  int axis = 0;
  plane.normal.cwiseAbs().maxCoeff(&axis);
  if (plane.normal[axis] < 0.0) plane.normal = -plane.normal;
  if (scene.observations.NumRows() != scene.segments.size()) return;
  std::int64_t votes = 0;
  for (const SegmentId s : inliers) {
    for (const ViewpointId v : scene.observations[s]) {
      const double side = plane.SignedDistance(scene.viewpoints[v]);
      votes += side > 0.0 ? 1 : (side < 0.0 ? -1 : 0);
    }
  }
  if (votes < 0) plane.normal = -plane.normal;
}

/// The lines to detect on: collinear duplicates merged, or every segment on its own.
CollinearGroups LinesToDetect(const Scene& scene, const PlaneDetectionOptions& options,
                              double epsilon) {
  if (options.collinear_tolerance > 0.0) {
    return GroupCollinearSegments(scene.segments.raw(), options.collinear_tolerance * epsilon);
  }
  CollinearGroups groups;
  groups.lines = scene.segments.raw();
  for (std::size_t i = 0; i < scene.segments.size(); ++i) {
    groups.members.AddRow(std::array<SegmentId, 1>{SegmentId(i)});
  }
  return groups;
}

/// Replaces every plane's inlier lines by their member segments (ascending).
void ExpandToSegments(const CollinearGroups& groups, std::vector<SupportedPlane>& planes) {
  for (SupportedPlane& plane : planes) {
    std::vector<SegmentId> segments;
    for (const SegmentId line : plane.inliers) {
      const auto members = groups.members[line];
      segments.insert(segments.end(), members.begin(), members.end());
    }
    std::sort(segments.begin(), segments.end());
    plane.inliers = std::move(segments);
  }
}

/// Merges near-duplicate planes (pieces of one plane from neighbouring blocks only, when there
/// are several blocks) and, with several blocks, re-applies the at-most-2 rule.
void FuseDetectedPlanes(std::span<const Segment3> lines,
                        const PlaneDetectionOptions& options,
                        double epsilon,
                        std::vector<SupportedPlane>& planes,
                        PlaneDetectionStats& stats) {
  FusionParameters fusion;
  fusion.epsilon = epsilon;
  fusion.epsilon_fusion = options.epsilon_fusion_factor * epsilon;
  fusion.max_angle_rad = DegToRad(options.theta_fusion_deg);
  fusion.min_shared_fraction = options.p_fusion;
  fusion.distance = options.distance;
  const bool several_blocks = stats.blocks > 1;
  if (several_blocks) fusion.max_gap = options.block_halo * options.block_size;
  stats.merges = FusePlanes(lines, fusion, planes);
  if (several_blocks) {
    stats.memberships_dropped = LimitMemberships(lines.size(), options.min_support, planes);
  }
}

/// Moves the detected planes (inliers as scene segments) into `result`: each keeps its normal,
/// its point moves to the projection of the inliers' centroid, and it is oriented
/// (OrientPlane); the memberships and their L0/L1/L2 counts follow.
void AddPlanes(const Scene& scene,
               std::vector<SupportedPlane>& planes,
               PlaneDetectionResult& result) {
  result.memberships = IdVector<SegmentId, PlaneMembership>(scene.segments.size());
  for (SupportedPlane& sp : planes) {
    const PlaneId id = result.planes.NextId();
    const Plane3 fit = FitPlane(scene.segments.raw(), sp.inliers, sp.plane.normal);
    Plane3 plane = sp.plane;
    plane.point = fit.point - plane.SignedDistance(fit.point) * plane.normal;
    OrientPlane(scene, sp.inliers, plane);
    PlaneSupport support;
    support.inlier_count = static_cast<std::uint32_t>(sp.inliers.size());
    for (const SegmentId s : sp.inliers) {
      support.inlier_length += scene.segments[s].Length();
      LINESURF_ASSERT(result.memberships[s].Add(id));
    }
    support.inliers = std::move(sp.inliers);
    result.planes.push_back(plane);
    result.support.push_back(std::move(support));
  }
  for (const PlaneMembership& m : result.memberships) {
    (m.count == 0 ? result.stats.num_l0 : m.count == 1 ? result.stats.num_l1 : result.stats.num_l2)++;
  }
}

}  // namespace
}  // namespace detect

std::string PlaneCapWarning(const PlaneDetectionStats& stats, std::int32_t max_planes) {
  if (stats.capped_blocks == 0) return "";
  std::ostringstream os;
  os << "plane detection stopped at max_planes (" << max_planes << ") in " << stats.capped_blocks
     << " block(s): planes may be missing; raise max_planes or detect per block (block_size)";
  return os.str();
}

Expected<PlaneDetectionResult> DetectPlanes(const Scene& scene,
                                            const PlaneDetectionOptions& options,
                                            const RunContext& ctx,
                                            detect::DetectionRunner* runner) noexcept {
  if (Status valid = options.Validate(); !valid) return valid.error();
  return CatchAll(kDetectPlanesStage, [&]() -> PlaneDetectionResult {
    const auto start = std::chrono::steady_clock::now();
    for (std::size_t i = 0; i < scene.segments.size(); ++i) {
      const Segment3& s = scene.segments.raw()[i];
      LINESURF_THROW_IF(!s.p1.allFinite() || !s.p2.allFinite(),
                        kInvalidInput,
                        kDetectPlanesStage,
                        "segment " << i << " has a non-finite endpoint");
    }
    PlaneDetectionResult result;
    Expected<EpsilonEstimate> resolved = ResolveEpsilon(scene, options, ctx);
    if (!resolved) throw LinesurfException(resolved.error());
    const double epsilon = resolved->epsilon;
    result.stats.epsilon = epsilon;
    result.stats.epsilon_estimate = std::move(*resolved);
    const detect::CollinearGroups groups = detect::LinesToDetect(scene, options, epsilon);
    const std::span<const Segment3> lines = groups.lines;
    result.stats.lines = static_cast<std::int64_t>(lines.size());
    const detect::DetectionLayout layout = detect::SplitIntoBlocks(lines, options);
    std::vector<detect::SupportedPlane> planes;
    RunInArena(ctx, [&] {
      planes = detect::DetectInBlocks(lines, layout, options, epsilon, ctx, result.stats, runner);
    });
    result.stats.planes_before_fusion = static_cast<std::int32_t>(planes.size());
    const auto fusion_start = std::chrono::steady_clock::now();
    detect::FuseDetectedPlanes(lines, options, epsilon, planes, result.stats);
    detect::ExpandToSegments(groups, planes);
    result.stats.seconds_fusion =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - fusion_start).count();
    result.stats.planes_after_fusion = static_cast<std::int32_t>(planes.size());
    detect::AddPlanes(scene, planes, result);
    result.stats.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return result;
  });
}

}  // namespace linesurf
