#pragma once
// Plane support regions (DESIGN section 3, step 1; docs/design/block_engine.md section 2): the
// base blocks a plane may split are those its inlier segments cross and the hull of its inliers
// meets, dilated by a margin that
// may be a fraction of a block (a wall whose lines stop short of the corner still meets its
// neighbour across a block face).

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
  /// Dilation of each region in base blocks, [0, 64]. The fraction f reaches the 26-neighbours of
  /// crossed blocks that lie within f block sizes of an inlier (each axis, Chebyshev); the whole
  /// part then dilates by that many blocks (26-neighbourhood). 0 keeps the crossed blocks only.
  double margin_blocks = 0.0;

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

/// Regions of `planes`, whose inliers are `inliers[p]` (ids into `segments`): the blocks the
/// inliers cross and those the convex hull of their endpoints in the plane meets (InlierHull),
/// grown by the margin. Planes in parallel inside an arena from ctx.num_threads; the result does
/// not depend on the thread count. Errors: kInvalidOptions, kInvalidInput (an inlier id out of
/// range, planes and inlier lists of different counts), kCancelled.
[[nodiscard]] Expected<PlaneSupportRegions> ComputePlaneSupport(
    const BlockGrid& grid,
    std::span<const Segment3> segments,
    std::span<const Plane3> planes,
    std::span<const std::vector<SegmentId>> inliers,
    const PlaneSupportOptions& options,
    const RunContext& ctx) noexcept;

}  // namespace linesurf::partition
