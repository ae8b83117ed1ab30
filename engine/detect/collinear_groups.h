#pragma once
// Collinear duplicates (internal to engine/detect): segments lying on one infinite line, such as
// the per-camera sub-segments of one 3D line in the reference's "residual" inputs, are detected
// as one line, the way the reference RANSAC saw them before the split, and share its planes.

#include <span>
#include <vector>

#include "engine/core/csr.h"
#include "engine/core/geometry.h"
#include "engine/core/strong_id.h"

namespace linesurf::detect {

struct CollinearGroups {
  /// One segment per group: the span of its members along the line of its first member.
  std::vector<Segment3> lines;
  /// Members of each group (scene segment ids, ascending); groups ordered by first member.
  Csr<SegmentId, SegmentId> members;
};

/// Groups segments whose endpoints all lie within `tolerance` of each other's infinite lines
/// (> 0, scene units). Deterministic; a group never mixes segments farther apart than that.
CollinearGroups GroupCollinearSegments(std::span<const Segment3> segments, double tolerance);

}  // namespace linesurf::detect
