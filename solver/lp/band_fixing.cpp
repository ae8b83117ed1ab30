#include "solver/lp/band_fixing.h"

#include "solver/energy/build_lp.h"
#include "solver/energy/term_incidence.h"
#include "solver/lp/backends/maxflow/maxflow_backend.h"

namespace linesurf::solver {

std::vector<std::uint8_t> PairwiseLabels(const EnergyInput& energy, const RunContext& ctx) {
  EnergyInput pairwise;
  pairwise.cost_if_empty = energy.cost_if_empty;
  pairwise.cost_if_full = energy.cost_if_full;
  pairwise.fixed = energy.fixed;
  pairwise.pairs = energy.pairs;
  const ReducedEnergy reduced = ReduceEnergy(pairwise);
  const LpSolution solution = SolveWithMaxflow(reduced, ctx);
  const std::vector<double> values = ExpandToCells(pairwise, reduced, solution.columns);
  std::vector<std::uint8_t> labels(values.size());
  for (std::size_t c = 0; c < values.size(); ++c) labels[c] = values[c] > 0.5 ? 1 : 0;
  return labels;
}

double HigherOrderEnergy(const EnergyInput& energy, const std::vector<std::uint8_t>& labels) {
  double total = 0.0;
  for (std::size_t g = 0; g < energy.NumStructuralGroups(); ++g) {
    total += TermEnergy(energy, {TermKind::kStructural, static_cast<std::uint32_t>(g)}, labels);
  }
  for (std::size_t g = 0; g < energy.NumParityGroups(); ++g) {
    total += TermEnergy(energy, {TermKind::kParity, static_cast<std::uint32_t>(g)}, labels);
  }
  return total;
}

EnergyInput FixCellsOutsideBand(const EnergyInput& energy,
                                const std::vector<std::uint8_t>& labels, int rings) {
  std::vector<std::uint8_t> in_band(labels.size(), 0);
  for (const PairTerm& p : energy.pairs) {
    if (labels[p.a.index()] != labels[p.b.index()]) in_band[p.a.index()] = in_band[p.b.index()] = 1;
  }
  const auto mark_group = [&](std::span<const CellId> cells) {
    for (const CellId c : cells) in_band[c.index()] = 1;
  };
  for (std::size_t g = 0; g < energy.NumParityGroups(); ++g) {
    const auto cells = energy.ParityGroup(g);
    bool mixed = false;
    for (const CellId c : cells) mixed = mixed || labels[c.index()] != labels[cells[0].index()];
    if (mixed) mark_group(cells);
  }
  for (std::size_t g = 0; g < energy.NumStructuralGroups(); ++g) {
    const auto cells = energy.StructuralGroup(g);
    bool any_full = false;
    for (const CellId c : cells) any_full = any_full || labels[c.index()] == 1;
    if (!any_full) mark_group(cells);
  }
  for (int ring = 0; ring < rings; ++ring) {
    std::vector<std::uint8_t> grown = in_band;
    for (std::size_t g = 0; g < energy.NumParityGroups(); ++g) {
      const auto cells = energy.ParityGroup(g);
      bool touches = false;
      for (const CellId c : cells) touches = touches || in_band[c.index()] != 0;
      if (!touches) continue;
      for (const CellId c : cells) grown[c.index()] = 1;
    }
    in_band.swap(grown);
  }
  EnergyInput banded = energy;
  for (std::size_t c = 0; c < labels.size(); ++c) {
    const CellId id(c);
    if (banded.fixed[id] != CellFix::kFree || in_band[c] != 0) continue;
    banded.fixed[id] = labels[c] != 0 ? CellFix::kFull : CellFix::kEmpty;
  }
  return banded;
}

}  // namespace linesurf::solver
