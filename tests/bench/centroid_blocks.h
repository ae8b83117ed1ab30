#pragma once
// A partition of the cells of one complex into blocks of nearby cells, for the study of the
// per-block solve (solver "blocks", block_labeling.h) on one global complex
// (block_labelling_study.cpp; the pipeline solves on its partition's own blocks): the cells'
// centroids are split recursively at the median of the longest side of their bounding box (a
// k-d tree), until no block holds more than `max_cells` cells. Blocks then hold about the same
// number of cells wherever the planes crowd, unlike a uniform grid of the box.

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
