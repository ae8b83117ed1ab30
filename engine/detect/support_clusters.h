#pragma once
// The spatially separate pieces of a plane's support, and whether one plane stands for several
// offset faces (internal to engine/detect; docs/design/plane_detection.md, "One plane, one piece").

#include "engine/core/geometry.h"
#include "engine/core/strong_id.h"

#include <span>
#include <vector>

namespace linesurf::detect {

/// Distance between the closest points of two segments.
[[nodiscard]] double SegmentSegmentDistance(const Segment3& a, const Segment3& b);

/// The connected pieces of `inliers` (sorted ids), two segments linked when they come within
/// `gap` of each other; every piece sorted by id, pieces by decreasing size, then by first id.
[[nodiscard]] std::vector<std::vector<SegmentId>> SupportClusters(
    std::span<const Segment3> segments, std::span<const SegmentId> inliers, double gap);

/// True when some piece of at least `min_lines` segments whose endpoints spread at least
/// `min_width` across their main direction (so that its own tilt is determined), fitted on its
/// own (FitPlane), lies more than `tolerance` from `plane` at one of its endpoints: the plane is
/// a compromise between faces offset or tilted against each other (two roofs at different
/// heights), not one face seen in several places (the footprints of buildings on one ground).
[[nodiscard]] bool PiecesDisagree(std::span<const Segment3> segments,
                                  const std::vector<std::vector<SegmentId>>& pieces,
                                  const Plane3& plane,
                                  std::size_t min_lines,
                                  double min_width,
                                  double tolerance);

}  // namespace linesurf::detect
