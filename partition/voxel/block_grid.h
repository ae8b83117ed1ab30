#pragma once
// Coarse voxel partition of the scene box into cubic blocks (DESIGN section 3, step 1): each
// segment is rasterised into the blocks it crosses. The block engine builds one cell complex per
// block from this.

#include <span>

#include <Eigen/Core>

#include "linesurf/error.h"
#include "engine/core/csr.h"
#include "engine/core/geometry.h"
#include "engine/core/strong_id.h"

namespace linesurf::partition {

struct BlockGridOptions {
  /// Edge length of a cubic block, local units (> 0).
  double block_size = 10.0;
  /// Refuse grids with more blocks than this (guards against absurd sizes).
  std::size_t max_blocks = 1u << 24;
};

struct BlockGrid {
  Box3 box;                 ///< the covered box: box.min + dims * block_size >= input box
  Eigen::Vector3i dims{0, 0, 0};
  double block_size = 0.0;
  /// Only blocks crossed by at least one segment, in increasing linear index (x fastest).
  std::vector<Eigen::Vector3i> block_coords;
  /// Segments crossing each listed block, in increasing SegmentId.
  Csr<BlockId, SegmentId> block_segments;

  [[nodiscard]] std::size_t NumBlocks() const { return block_coords.size(); }
  [[nodiscard]] Box3 BlockBox(BlockId b) const;
};

/// Rasterises `segments` (all inside `box`) into blocks with an exact 3D DDA.
Expected<BlockGrid> BuildBlockGrid(std::span<const Segment3> segments, const Box3& box,
                                   const BlockGridOptions& options) noexcept;

}  // namespace linesurf::partition
