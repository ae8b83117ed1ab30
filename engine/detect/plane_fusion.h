#pragma once
// Fusion of near-duplicate planes after RANSAC extraction (internal to engine/detect).

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
};

/// Greedily merges pairs of planes closer than theta_fus in angle that share at least p_fus of
/// the smaller support (segments within eps of both), smallest angle first, if every inlier of
/// the union lies within eps_fus of the refitted plane. A merged plane takes the place of the
/// earlier of its two parents. Returns the number of merges; deterministic (serial).
int FusePlanes(std::span<const Segment3> segments, const FusionParameters& params,
               std::vector<SupportedPlane>& planes);

}  // namespace linesurf::detect
