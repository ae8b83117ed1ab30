#pragma once
// The labelling of a large energy block by block ("blocks" method of SolveLabeling), given a
// partition of its cells into blocks (any partition is valid; blocks of a few thousand cells
// that follow the geometry work best: docs/design/lp_backend.md, "Per-block solve").
//
//  1. Start: the exact max-flow minimum of the unary and pairwise terms (band_fixing.h).
//  2. Sweeps of block solves: every block with a halo of BlocksOptions::halo term hops of its
//     neighbours' free cells is solved on its sub-energy (sub_energy.h: every other cell held at
//     its current label), all blocks from the same labels, in parallel, by SolveLabeling with the
//     inner backend (BlocksOptions::backend; "auto": maxflow, clp or pdhg-energy by the block's
//     size; its local search and group moves, no exact windows: those run once, in step 3),
//     after an exact shortcut: when the max-flow labels of the sub-energy's unary and pairwise
//     terms leave no structural or parity energy, they are its integral optimum and no LP is
//     solved. Then, in block order, each block's new labels (halo included) are taken when, given
//     the labels as they are by then, they lower the energy. A block is solved again when its
//     cells or a neighbour's changed; stops when none did or after BlocksOptions::sweeps sweeps.
//     The halo lets the surface move across a seam, which a block with its seams fixed cannot do.
//  3. Local search, group moves and exact windows (round_labels.h, group_moves.h,
//     window_polish.h, seeded by the blocks' relaxed values) on the whole energy.
// Every step lowers the energy, so the labels are never worse than the max-flow start
// (LabelingResult::rounded_objective holds its energy). The lower bound is the largest of: the
// pairwise optimum (the max-flow value: the other terms are >= 0); with BlocksOptions::
// bound_passes > 0 the Lagrangian dual of the global LP raised by coordinate ascent
// (dual_ascent.h); with split_bound the Lagrangian split of sub_energy.h (the blocks' interior
// energies solved: the sum of their bounds plus the energy of the terms and cells without a free
// cell, the terms across blocks counted 0; tight when few terms cross blocks, loose when many
// do).
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
/// Reads options.blocks, options.improve (the final passes on the whole energy) and the time
/// limit; `options.backend` is ignored: the blocks are solved by SolveLabeling with
/// options.blocks.backend and the rest of `options` (no exact windows). Throws like
/// SolveLabeling's backends.
[[nodiscard]] LabelingResult SolveInBlocks(const EnergyInput& energy,
                                           const ReducedEnergy& reduced,
                                           std::span<const std::uint32_t> block_of_cell,
                                           const LabelingOptions& options,
                                           const RunContext& ctx);

}  // namespace linesurf::solver
