#pragma once
// The box of some segments' endpoints (a plane's inliers): what fusion compares planes by and
// what the partition keeps block faces off.

#include "engine/core/geometry.h"
#include "engine/core/strong_id.h"

#include <span>

namespace linesurf {

/// The box of the endpoints of `segments[id]` for each id; empty when `ids` is.
[[nodiscard]] inline Box3 EndpointBox(std::span<const Segment3> segments,
                                      std::span<const SegmentId> ids) {
  Box3 box;
  for (const SegmentId id : ids) {
    box.Extend(segments[id.index()].p1);
    box.Extend(segments[id.index()].p2);
  }
  return box;
}

}  // namespace linesurf
