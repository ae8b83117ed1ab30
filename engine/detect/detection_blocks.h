#pragma once
// The coarse blocks of per-block plane detection (DESIGN section 3, step 2; internal to
// engine/detect): every segment has one home block (the block holding its midpoint) and is also
// given to the blocks whose box, dilated by the halo, holds its midpoint.

#include "engine/core/geometry.h"
#include "engine/core/strong_id.h"

#include <cstdint>
#include <span>
#include <vector>

namespace linesurf::detect {

struct DetectionBlock {
  /// Position in the grid of cubes of side block_size anchored at the segments' bounding-box
  /// minimum; blocks are listed in increasing (z, y, x).
  std::int64_t x = 0, y = 0, z = 0;
  /// Segments whose midpoint lies in the block dilated by the halo (ascending). Includes every
  /// segment whose home block this is.
  std::vector<SegmentId> segments;
};

/// The occupied blocks of side `block_size` (> 0) with halo `halo` (in [0, block_size / 2)).
/// Throws kInvalidOptions when the grid would need more than 2^20 blocks along one axis.
std::vector<DetectionBlock> AssignDetectionBlocks(std::span<const Segment3> segments,
                                                  double block_size,
                                                  double halo);

}  // namespace linesurf::detect
