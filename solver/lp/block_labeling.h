#pragma once
// The labelling of a large energy block by block ("blocks" method of SolveLabeling), given a
// partition of its cells into blocks (any partition is valid; blocks of a few thousand cells
// that follow the geometry work best: docs/design/lp_backend.md, "Per-block solve").
//
//  1. Interior solves, every block at once: the block's interior energy (sub_energy.h: its
//     cells and the terms that reach no free cell of another block) is minimised by
//     SolveLabeling with the inner backend ("auto": maxflow, clp or pdhg by size), after an exact
//     shortcut: when the max-flow labels of its unary and pairwise terms leave no structural or
//     parity energy, they are its integral optimum and no LP is solved. Each block's LP bound
//     (or integer optimum) is kept.
//  2. Coordination sweeps (alternating seam fixing): the blocks of one colour of cell_blocks.h
//     at a time, in parallel, each re-solved (same shortcut, same inner solve) on its sub-energy
//     with every other cell held at its current label; its new labels are taken when they lower
//     the energy. A block is re-solved only when a neighbour's labels changed since its last
//     solve. Stops when no block is left to re-solve or after `block_sweeps` sweeps.
//  3. Local search and group moves (round_labels.h, group_moves.h) on the whole energy, for the
//     seams.
// Every accepted step lowers the energy of the labels, so the result is never worse than the
// labels of step 1. The lower bound is the Lagrangian split of sub_energy.h (InteriorEnergy):
// the sum of the blocks' interior bounds plus the energy of the terms and cells without a free
// cell, the terms across blocks counted 0. It is valid but looser than the global LP's by about
// the LP value of the terms across blocks.
// Deterministic for any thread count: blocks are solved serially inside (one thread each),
// their results are stored per block and applied in block order.

#include "engine/core/run_context.h"
#include "solver/energy/energy_input.h"
#include "solver/lp/lp_backend.h"

#include <cstdint>
#include <span>

namespace linesurf::solver {

/// `block_of_cell`: one block id per cell (see MakeCellBlocks). `options.backend` is ignored;
/// the blocks use `options.block_backend`. Throws like SolveLabeling's backends.
[[nodiscard]] LabelingResult SolveInBlocks(const EnergyInput& energy,
                                           std::span<const std::uint32_t> block_of_cell,
                                           const LabelingOptions& options,
                                           const RunContext& ctx);

}  // namespace linesurf::solver
