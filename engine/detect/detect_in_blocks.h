#pragma once
// Per-block plane detection: the lines split into the blocks of one grid, a RANSAC run in each
// block (blocks in parallel, each deterministic), a block that reached max_planes replaced by
// its children (internal to engine/detect).

#include <optional>
#include <span>
#include <vector>

#include "engine/core/geometry.h"
#include "engine/core/run_context.h"
#include "engine/detect/detect_planes.h"
#include "engine/detect/detection_blocks.h"
#include "engine/detect/detection_run.h"
#include "engine/detect/plane_fusion.h"
#include "partition/voxel/block_grid.h"

namespace linesurf::detect {

/// The blocks of per-block detection and their grid; one block holding every line and no grid
/// when block_size is 0.
struct DetectionLayout {
  std::optional<partition::BlockGrid> grid;
  std::vector<DetectionBlock> blocks;
};

DetectionLayout SplitIntoBlocks(std::span<const Segment3> lines,
                                const PlaneDetectionOptions& options);

/// Runs the RANSAC of every block (blocks in parallel, each deterministic) and returns their
/// planes in block order, inliers as scene segment ids. A block that reached max_planes is
/// replaced by its children (SplitAtCap), run in the next round; they take its place in the
/// order. A single block keeps options.seed, so it reproduces the monolithic method exactly; the
/// run r of several (blocks first, then children in order of creation) draws from its own stream.
/// The rounds run in this process, or through `runner` when given (same planes).
std::vector<SupportedPlane> DetectInBlocks(std::span<const Segment3> lines,
                                           const DetectionLayout& layout,
                                           const PlaneDetectionOptions& options,
                                           double epsilon,
                                           const RunContext& ctx,
                                           PlaneDetectionStats& stats,
                                           DetectionRunner* runner = nullptr);

}  // namespace linesurf::detect
