#pragma once
// Which base blocks of a BlockGrid segments cross (DESIGN section 3, step 1), and dilation of
// block sets. OpenVDB holds the sparse sets (an index-space grid whose voxels are base blocks);
// its types stay in active_blocks.cpp.

#include "engine/core/csr.h"
#include "engine/core/geometry.h"
#include "engine/core/strong_id.h"
#include "partition/voxel/block_grid.h"

#include <Eigen/Core>

#include <cstdint>
#include <span>
#include <vector>

namespace linesurf::partition {

/// Base blocks crossed by a segment, in walking order from p1 to p2: a 3D DDA on the grid's face
/// tables. The blocks of both endpoints (Locate) are always included; where the segment passes
/// through a block edge or corner, the DDA steps one axis at a time and lists a neighbour too
/// (conservative).
std::vector<Eigen::Vector3i> BlocksCrossed(const BlockGrid& grid, const Segment3& segment);

struct ActiveBlocks {
  /// Base blocks crossed by at least one segment, as increasing linear indices.
  std::vector<std::int64_t> blocks;
  /// Segments crossing each listed block (row i belongs to blocks[i]), in increasing SegmentId.
  Csr<BlockId, SegmentId> segments;
};

/// The base blocks `segments` cross, each with its segments.
ActiveBlocks RasteriseSegments(const BlockGrid& grid, std::span<const Segment3> segments);

/// The base blocks within `margin` blocks (26-neighbourhood, Chebyshev distance) of `blocks`
/// (linear indices), clipped to the grid, increasing. margin 0 returns the sorted unique input.
std::vector<std::int64_t> DilateBlocks(const BlockGrid& grid,
                                       std::span<const std::int64_t> blocks,
                                       int margin);

}  // namespace linesurf::partition
