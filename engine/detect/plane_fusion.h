#pragma once
// Fusion of near-duplicate planes after RANSAC extraction (internal to engine/detect).

#include <limits>
#include <cstdint>
#include <span>
#include <vector>

#include "engine/core/geometry.h"
#include "engine/core/strong_id.h"
#include "engine/detect/detect_planes.h"

namespace linesurf::detect {

/// A plane with its inlier segments (ascending ids).
struct SupportedPlane {
  Plane3 plane;
  std::vector<SegmentId> inliers;
};

struct FusionParameters {
  double epsilon = 0.0;         ///< shared-support tolerance (scene units)
  double epsilon_fusion = 0.0;  ///< every inlier of a merged plane lies within this
  double max_angle_rad = 0.0;   ///< theta_fus
  double min_shared_fraction = 0.0;  ///< p_fus, of the smaller plane's support
  SegmentDistance distance = SegmentDistance::kMeanEndpoint;
  /// Pairs whose inliers' bounding boxes are farther apart than this (along some axis) are not
  /// considered; infinite for one-block detection, the halo for per-block detection (only
  /// pieces of one plane found in neighbouring blocks merge, which keeps fusion local).
  double max_gap = std::numeric_limits<double>::infinity();
};

/// Greedily merges pairs of planes closer than theta_fus in angle that share at least p_fus of
/// the smaller support (segments within eps of both), smallest angle first, if every inlier of
/// the union lies within eps_fus of the refitted plane. A merged plane takes the place of the
/// earlier of its two parents. Returns the number of merges; deterministic (serial).
int FusePlanes(std::span<const Segment3> segments, const FusionParameters& params,
               std::vector<SupportedPlane>& planes);

/// Re-applies the at-most-2 rule after per-block detection and fusion (a segment may have been
/// collected by planes of several blocks): planes are visited by decreasing support (ties: lower
/// index) and a segment stays an inlier of the first two that hold it. Planes left with fewer
/// than `min_support` inliers are removed (order of the others kept). Returns the number of
/// memberships removed.
std::int64_t LimitMemberships(std::size_t num_segments, std::int32_t min_support,
                              std::vector<SupportedPlane>& planes);

}  // namespace linesurf::detect
