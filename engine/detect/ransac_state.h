#pragma once
// What the parts of one multi-support RANSAC run share: its input and the state the run grows
// (internal to engine/detect).

#include <span>
#include <vector>

#include "engine/core/geometry.h"
#include "engine/core/scene.h"
#include "engine/detect/detect_planes.h"
#include "engine/detect/plane_fusion.h"
#include "engine/detect/segment_bvh.h"

namespace linesurf::detect {

/// The lines of one run, its options and its inlier tolerance eps (scene units).
struct RansacInput {
  std::span<const Segment3> segments;
  const PlaneDetectionOptions& options;
  double epsilon;
};

/// The run's index over the lines and what it has extracted so far (owned by RansacDetector;
/// read by the inlier test and the candidate search as it is when they are called).
struct RansacState {
  const SegmentBvh& bvh;
  const std::vector<PlaneMembership>& memberships;  ///< per line: the planes holding it
  const std::vector<SupportedPlane>& planes;        ///< extracted so far, in order
};

}  // namespace linesurf::detect
