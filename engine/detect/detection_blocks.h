#pragma once
// The blocks of per-block plane detection (DESIGN section 3, step 2; internal to engine/detect),
// on the block engine's one grid (partition/voxel/block_grid.h): every segment has one home
// block (the leaf block holding its midpoint) and is also given to the leaf blocks whose box,
// dilated by the halo, holds its midpoint. A block with too many home segments is replaced by its
// 8 children, recursively (an octree over the crowded places); so is a block whose RANSAC
// reached max_planes (SplitDetectionBlock, called by the detection).

#include "engine/core/geometry.h"
#include "engine/core/strong_id.h"
#include "partition/voxel/block_grid.h"

#include <cstdint>
#include <span>
#include <vector>

namespace linesurf::detect {

struct DetectionBlock {
  partition::BlockKey key;  ///< the block in the grid; key.level is its depth
  Box3 box;                 ///< grid.BlockBox(key) (without halo)
  /// Segments whose midpoint lies in the block dilated by its halo (ascending). Includes every
  /// segment whose home block this is.
  std::vector<SegmentId> segments;
  /// The segments whose home block this is (ascending; a subset of `segments`).
  std::vector<SegmentId> home_segments;
};

struct BlockLayout {
  double halo = 0.1;                  ///< halo as a fraction of a block's nominal side, [0, 0.5)
  std::size_t max_home_segments = 0;  ///< split a block with more home segments (0 = never)
};

/// The box of per-block detection when no grid is given: the box of the segments' midpoints.
Box3 MidpointBox(std::span<const Segment3> segments);

/// The occupied blocks of `grid`, base blocks in increasing (z, y, x), a split block replaced by
/// its children in the same order. A block's nominal side at level L is block_size / 2^L.
std::vector<DetectionBlock> AssignDetectionBlocks(std::span<const Segment3> segments,
                                                  const partition::BlockGrid& grid,
                                                  const BlockLayout& layout);

/// The children of `block` (one level down) that are home to some of its home segments, in the
/// order of AssignDetectionBlocks, each with a halo of `halo` x its own side; not split further.
std::vector<DetectionBlock> SplitDetectionBlock(std::span<const Segment3> segments,
                                                const partition::BlockGrid& grid,
                                                const DetectionBlock& block,
                                                double halo);

}  // namespace linesurf::detect
