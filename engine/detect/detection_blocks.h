#pragma once
// The coarse blocks of per-block plane detection (DESIGN section 3, step 2; internal to
// engine/detect): every segment has one home block (the block holding its midpoint) and is also
// given to the blocks whose box, dilated by the halo, holds its midpoint. A block with too many
// home segments is split into 8 children, recursively (an octree over the crowded places).

#include "engine/core/geometry.h"
#include "engine/core/strong_id.h"

#include <cstdint>
#include <span>
#include <vector>

namespace linesurf::detect {

struct DetectionBlock {
  Box3 box;       ///< the block's cube (without halo)
  int depth = 0;  ///< 0 for a grid block, +1 per split
  /// Segments whose midpoint lies in the block dilated by its halo (ascending). Includes every
  /// segment whose home block this is.
  std::vector<SegmentId> segments;
};

struct BlockLayout {
  double block_size = 0.0;  ///< side of the grid blocks anchored at the midpoints' minimum (> 0)
  double halo = 0.1;        ///< halo as a fraction of a block's side, [0, 0.5)
  std::size_t max_home_segments = 0;  ///< split a block with more home segments (0 = never)
};

/// The occupied blocks, grid blocks in increasing (z, y, x), a split block replaced by its
/// children in the same order. Throws kInvalidOptions when the grid would need more than 2^20
/// blocks along one axis.
std::vector<DetectionBlock> AssignDetectionBlocks(std::span<const Segment3> segments,
                                                  const BlockLayout& layout);

}  // namespace linesurf::detect
