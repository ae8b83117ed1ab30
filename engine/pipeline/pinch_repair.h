#pragma once
/// @file pinch_repair.h
/// @brief Labels whose surface is one valid solid: where the full region pinches (two parts
/// meeting only along an edge or at a point), ExtractBlockSurface keeps the surface a 2-manifold
/// by giving each part its own vertex at the same position. That mesh is closed and manifold,
/// but its parts touch without sharing the contact, which GIS and BIM validators (val3dity's
/// classes, ISO 19107) refuse. The repair changes labels instead: at every such position one
/// free cell next to the surface there takes the other label, the one whose change raises the
/// energy least, and the surface is extracted again, until no position is split or a round
/// changes nothing.

#include "linesurf/error.h"

#include "engine/core/run_context.h"
#include "engine/pipeline/extract_block_surface.h"
#include "partition/arrangement/block_complexes.h"
#include "solver/energy/energy_input.h"

#include <cstdint>
#include <vector>

namespace linesurf::pipeline {

/// Extractions the reconstruction's repair may add: each round relabels one cell per split
/// position, and a pinch seldom needs more than two.
inline constexpr int kPinchRepairRounds = 8;

struct PinchRepairStats {
  std::size_t rounds = 0;         ///< extractions after the first
  std::size_t flipped_cells = 0;  ///< cells whose label the repair changed
  std::size_t split_points = 0;   ///< positions still held by several vertices at the end
  double energy_increase = 0.0;   ///< energy of the final labels minus that of the given ones
};

struct PinchRepair {
  BlockExtractResult surface;  ///< the surface of the final labels
  PinchRepairStats stats;
};

/// Extracts the surface of `labels` (global cells of `complexes`) and repairs its pinches as
/// the file comment says, at most `max_rounds` times; `labels` is updated. Fixed cells of
/// `energy` keep their label. Deterministic (positions in coordinate order, ties by cell id)
/// for any ctx.num_threads. Errors: those of ExtractBlockSurface.
[[nodiscard]] Expected<PinchRepair> ExtractWithoutPinches(
    const partition::BlockComplexes& complexes,
    const solver::EnergyInput& energy,
    const ExtractOptions& options,
    int max_rounds,
    std::vector<std::uint8_t>& labels,
    const RunContext& ctx) noexcept;

}  // namespace linesurf::pipeline
