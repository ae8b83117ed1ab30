#pragma once
// A partition of the cells of one complex into blocks of nearby cells, for the per-block solve
// of the labelling (solver "blocks", block_labeling.h) on a monolithic complex: the cells'
// centroids are split recursively at the median of the longest side of their bounding box (a
// k-d tree), until no block holds more than `max_cells` cells. Blocks then hold about the same
// number of cells wherever the planes crowd, unlike a uniform grid of the box. The block
// engine's complexes carry their own blocks; this is for one global complex.

#include "engine/core/cell_complex.h"

#include <cstdint>
#include <vector>

namespace linesurf::pipeline {

/// One block id per cell, blocks numbered in depth-first order of the splits (the lower half
/// first); ties in a coordinate are broken by cell id, so the result depends only on the complex.
/// `max_cells` >= 1.
[[nodiscard]] std::vector<std::uint32_t> CentroidBlocks(const CellComplex& complex,
                                                        std::size_t max_cells);

}  // namespace linesurf::pipeline
