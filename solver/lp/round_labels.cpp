#include "solver/lp/round_labels.h"

#include "engine/core/exception.h"
#include "solver/energy/term_incidence.h"
#include "solver/lp/lp_backend.h"

#include <algorithm>
#include <cmath>

namespace linesurf::solver {

RoundedLabels RoundLabels(const EnergyInput& energy, std::span<const double> relaxed) {
  LINESURF_ASSERT(relaxed.size() == energy.NumCells());
  RoundedLabels out;
  out.labels.assign(relaxed.size(), 0);
  std::vector<CellId> ties;
  for (std::size_t c = 0; c < relaxed.size(); ++c) {
    const CellId id(c);
    const double x = relaxed[c];
    if (energy.fixed[id] != CellFix::kFree) {
      out.labels[c] = energy.fixed[id] == CellFix::kFull ? 1 : 0;
      continue;
    }
    if (std::abs(x - std::round(x)) > kTieTolerance) ++out.fractional_cells;
    if (std::abs(x - 0.5) <= kTieTolerance) {
      ties.push_back(id);
    } else {
      out.labels[c] = x > 0.5 ? 1 : 0;
    }
  }
  out.tie_cells = ties.size();
  if (ties.empty()) return out;

  const TermIncidence incidence(energy, ties);
  for (std::size_t i = 0; i < ties.size(); ++i) {
    const CellId c = ties[i];
    out.labels[c.index()] = 1;
    const double full = LocalEnergy(energy, incidence.Terms(i), c, out.labels);
    out.labels[c.index()] = 0;
    const double empty = LocalEnergy(energy, incidence.Terms(i), c, out.labels);
    out.labels[c.index()] = full < empty ? 1 : 0;
  }
  return out;
}

std::size_t ImproveLabels(const EnergyInput& energy,
                          int max_passes,
                          std::vector<std::uint8_t>& labels) {
  LINESURF_ASSERT(labels.size() == energy.NumCells());
  const std::vector<CellId> free = energy.FreeCells();
  if (free.empty() || max_passes <= 0) return 0;
  return ImproveLabels(energy, free, TermIncidence(energy, free), max_passes, labels);
}

std::size_t ImproveLabels(const EnergyInput& energy,
                          std::span<const CellId> free,
                          const TermIncidence& incidence,
                          int max_passes,
                          std::vector<std::uint8_t>& labels) {
  LINESURF_ASSERT(labels.size() == energy.NumCells());
  LINESURF_ASSERT(free.empty() || incidence.Slot(free.back()) == free.size() - 1);
  std::size_t flips = 0;
  for (int pass = 0; pass < max_passes; ++pass) {
    std::size_t pass_flips = 0;
    for (std::size_t i = 0; i < free.size(); ++i) {
      const CellId c = free[i];
      const std::uint8_t current = labels[c.index()];
      const double keep = LocalEnergy(energy, incidence.Terms(i), c, labels);
      labels[c.index()] = current ^ 1u;
      const double flip = LocalEnergy(energy, incidence.Terms(i), c, labels);
      // Flip only on a decrease beyond rounding noise, so passes terminate.
      if (flip < keep - kImproveTolerance * (1.0 + std::abs(keep))) {
        ++pass_flips;
      } else {
        labels[c.index()] = current;
      }
    }
    flips += pass_flips;
    if (pass_flips == 0) break;
  }
  return flips;
}

}  // namespace linesurf::solver
