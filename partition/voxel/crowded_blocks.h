#pragma once
// Refinement of crowded blocks (docs/design/block_engine.md, section 1): the cells of a block
// grow with the cube of the planes that split it, so a block that a few dozen planes reach (the
// middle of Andalusian: 59 planes, a fifth of all cells) is cut in two along each axis. The cut is
// a face of the grid's tables, through the whole slab, so every face stays shared by exactly two
// blocks and the complexes, seams, evidence and stitch need nothing new.

#include "partition/voxel/block_grid.h"
#include "partition/voxel/face_clearance.h"
#include "partition/voxel/plane_support.h"

#include <array>
#include <cstddef>
#include <vector>

namespace linesurf::partition {

/// Blocks of `regions` that more than `max_planes` planes reach.
[[nodiscard]] std::size_t CountCrowdedBlocks(const PlaneSupportRegions& regions,
                                             std::size_t max_planes);

/// Per axis, increasing: one face (placed by `chooser`) inside every interval of the grid's face
/// table that holds a crowded block (more than `max_planes` planes) and is at least `min_length`
/// long. Empty on every axis when no block is crowded.
[[nodiscard]] std::array<std::vector<double>, 3> FacesSplittingCrowdedBlocks(
    const BlockGrid& grid,
    const PlaneSupportRegions& regions,
    std::size_t max_planes,
    double min_length,
    const SplitFaceChooser& chooser);

}  // namespace linesurf::partition
