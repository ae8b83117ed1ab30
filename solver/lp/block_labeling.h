#pragma once
// The labelling of a large energy block by block ("blocks" method of SolveLabeling), given a
// partition of its cells into blocks (any partition is valid; blocks of a few thousand cells
// that follow the geometry work best: docs/design/lp_backend.md, "Per-block solve").
//
//  1. Start: the exact max-flow minimum of the unary and pairwise terms (band_fixing.h).
//  2. Sweeps of block solves (alternating seam fixing): the blocks of one colour of
//     cell_blocks.h at a time, in parallel, each solved on its sub-energy (sub_energy.h) with
//     every other cell held at its current label, by SolveLabeling with the inner backend
//     (block_backend; "auto": maxflow, clp or pdhg by the block's size) after an exact shortcut:
//     when the max-flow labels of the block's unary and pairwise terms leave no structural or
//     parity energy, they are its integral optimum and no LP is solved. The new labels are taken
//     when they lower the energy; a block is solved again only when a neighbour changed. Stops
//     when no block is left or after `block_sweeps` sweeps.
//  3. Local search and group moves (round_labels.h, group_moves.h) on the whole energy.
// Every step lowers the energy, so the labels are never worse than the max-flow start
// (LabelingResult::rounded_objective holds its energy). The lower bound is the pairwise optimum
// (the max-flow value: the other terms are >= 0); with block_bound_passes > 0 also the
// Lagrangian dual of the global LP raised by that many passes of coordinate ascent
// (dual_ascent.h); with block_split_bound also the Lagrangian
// split of sub_energy.h (the blocks' interior energies solved: the sum of their bounds plus the
// energy of the terms and cells without a free cell, terms across blocks counted 0), the larger
// of the two. The split is tight when few terms cross blocks, loose when many do.
// Deterministic for any thread count: blocks are solved serially inside (one thread each),
// their results are stored per block and applied in block order.

#include "engine/core/run_context.h"
#include "solver/energy/build_lp.h"
#include "solver/energy/energy_input.h"
#include "solver/lp/lp_backend.h"

#include <cstdint>
#include <span>

namespace linesurf::solver {

/// `block_of_cell`: one block id per cell (see MakeCellBlocks); `reduced` = ReduceEnergy(energy).
/// `options.backend` is ignored; the blocks use `options.block_backend`. Throws like
/// SolveLabeling's backends.
[[nodiscard]] LabelingResult SolveInBlocks(const EnergyInput& energy,
                                           const ReducedEnergy& reduced,
                                           std::span<const std::uint32_t> block_of_cell,
                                           const LabelingOptions& options,
                                           const RunContext& ctx);

}  // namespace linesurf::solver
