#pragma once
// The "band" strategy for large complexes: most cells lie far from any plausible surface, yet
// the regularisation puts a parity group on every edge and vertex, so the full LP of a real scene
// (Andalusian: 3e5 cells) has millions of columns. We first label the cells with the exact
// max-flow of the unary and pairwise terms only, then keep free only the cells near that
// surface (and near structural evidence it leaves unsatisfied) and fix every other cell at its
// max-flow label. The LP of the band is then small. It is a heuristic: the band's optimum is an
// upper bound of the full LP's, equal to it when the full optimum differs from the max-flow
// labelling only inside the band.

#include <cstdint>
#include <vector>

#include "engine/core/run_context.h"
#include "solver/energy/energy_input.h"

namespace linesurf::solver {

/// Labels (0/1 per cell) minimising the unary and pairwise terms of `energy` exactly
/// (structural and parity groups ignored), by max-flow.
[[nodiscard]] std::vector<std::uint8_t> PairwiseLabels(const EnergyInput& energy,
                                                       const RunContext& ctx);

/// The structural and parity energy of 0/1 `labels` (the terms PairwiseLabels leaves out).
/// When it is 0 for PairwiseLabels' labels, those labels are an integral optimum of `energy`
/// (its other terms are >= 0).
[[nodiscard]] double HigherOrderEnergy(const EnergyInput& energy,
                                       const std::vector<std::uint8_t>& labels);

/// A copy of `energy` in which every free cell outside the band is fixed at `labels`. The band:
/// cells of pair terms and parity groups whose cells have different labels (cells touching the
/// surface of `labels`), cells of structural groups that `labels` leaves all empty, then
/// `rings` times every cell sharing a parity group with a band cell.
[[nodiscard]] EnergyInput FixCellsOutsideBand(const EnergyInput& energy,
                                              const std::vector<std::uint8_t>& labels, int rings);

}  // namespace linesurf::solver
