#pragma once
// Refinement of crowded blocks (docs/design/block_engine.md, section 1): the cells of a block
// grow with the cube of the planes that split it, so a block that a few dozen planes reach (the
// middle of Andalusian: 59 planes, a fifth of all cells) is cut in two along each axis. The cut is
// a face of the grid's tables, through the whole slab, so every face stays shared by exactly two
// blocks and the complexes, seams, evidence and stitch need nothing new.

#include "partition/voxel/block_grid.h"
#include "partition/voxel/plane_support.h"
#include "partition/voxel/split_face_chooser.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace linesurf::partition {

/// Per axis, how many cuts made each interval of the grid's face table (one entry per interval).
using CutDepths = std::array<std::vector<std::int32_t>, 3>;

/// The depths of a grid no cut has touched: all 0.
[[nodiscard]] CutDepths UncutDepths(const BlockGrid& grid);

/// Blocks of `regions` that more than `max_planes` planes reach.
[[nodiscard]] std::size_t CountCrowdedBlocks(const PlaneSupportRegions& regions,
                                             std::size_t max_planes);

/// One round of cuts: a face (placed by `chooser`) inside every interval of each axis that holds
/// a crowded block (more than `max_planes` planes) and was cut fewer than `max_depth` times, unless
/// the grid would then hold more than `max_blocks` blocks. Updates `grid` and `depths` (both halves
/// of a cut interval one deeper) and returns the faces added: 0 when nothing was cut.
/// Errors: those of BlockGrid::WithFaces.
[[nodiscard]] Expected<std::size_t> CutCrowdedBlocks(const PlaneSupportRegions& regions,
                                                     std::size_t max_planes,
                                                     std::int32_t max_depth,
                                                     std::int64_t max_blocks,
                                                     const SplitFaceChooser& chooser,
                                                     BlockGrid& grid,
                                                     CutDepths& depths) noexcept;

}  // namespace linesurf::partition
