#pragma once
// Plane support regions (DESIGN section 3, step 1; docs/design/block_engine.md section 2): the
// base blocks a plane may split are those its inlier segments cross, dilated by a margin.

#include "linesurf/error.h"

#include "engine/core/csr.h"
#include "engine/core/geometry.h"
#include "engine/core/run_context.h"
#include "engine/core/strong_id.h"
#include "partition/voxel/block_grid.h"

#include <cstdint>
#include <span>
#include <vector>

namespace linesurf::partition {

struct PlaneSupportOptions {
  /// Dilation of each region, in base blocks (26-neighbourhood), [0, 64].
  int margin_blocks = 1;

  [[nodiscard]] Status Validate() const;
};

struct PlaneSupportRegions {
  /// Base blocks (increasing linear indices) of each plane's region. A plane without inliers has
  /// an empty region.
  Csr<PlaneId, std::int64_t> plane_blocks;
  /// Base blocks reached by at least one region, increasing.
  std::vector<std::int64_t> blocks;
  /// Planes whose region holds blocks[i] (row i), increasing.
  Csr<BlockId, PlaneId> block_planes;
};

/// Regions from explicit block lists (increasing linear indices per plane), with the inverse
/// lists: what ComputePlaneSupport returns for regions it computed.
PlaneSupportRegions RegionsFromBlockLists(std::vector<std::vector<std::int64_t>> plane_blocks);

/// Regions of the planes whose inliers are `inliers[p]` (ids into `segments`), planes in
/// parallel inside an arena from ctx.num_threads; the result does not depend on the thread
/// count. Errors: kInvalidOptions, kInvalidInput (an inlier id out of range), kCancelled.
[[nodiscard]] Expected<PlaneSupportRegions> ComputePlaneSupport(
    const BlockGrid& grid,
    std::span<const Segment3> segments,
    std::span<const std::vector<SegmentId>> inliers,
    const PlaneSupportOptions& options,
    const RunContext& ctx) noexcept;

}  // namespace linesurf::partition
