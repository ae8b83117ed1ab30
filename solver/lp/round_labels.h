#pragma once
// Rounding of relaxed cell values to 0/1 labels (rule in lp_backend.h).

#include "solver/energy/energy_input.h"
#include "solver/energy/term_incidence.h"

#include <cstdint>
#include <span>
#include <vector>

namespace linesurf::solver {

struct RoundedLabels {
  std::vector<std::uint8_t> labels;
  /// Free cells with |x - round(x)| > kTieTolerance.
  std::size_t fractional_cells = 0;
  /// Cells with |x - 0.5| <= kTieTolerance, decided by the tie rule.
  std::size_t tie_cells = 0;
};

/// Thresholds `relaxed` (one value per cell, fixed cells at their label) at 0.5; ties are
/// decided in increasing CellId order by the lower energy given the labels so far (undecided
/// ties count as empty), equal energy -> empty. Deterministic, serial.
[[nodiscard]] RoundedLabels RoundLabels(const EnergyInput& energy,
                                        std::span<const double> relaxed);

/// Relative energy decrease a flip must bring in ImproveLabels.
inline constexpr double kImproveTolerance = 1e-12;

/// Local search after rounding: up to `max_passes` sweeps over the free cells in id order, each
/// cell flipped when that lowers the energy (given the current labels of all others). Never
/// raises the energy; deterministic, serial. Returns the number of flips.
std::size_t ImproveLabels(const EnergyInput& energy, int max_passes,
                          std::vector<std::uint8_t>& labels);

/// The same, with the free cells (energy.FreeCells()) and their incidence given: a caller that
/// searches again and again (group moves, pass after pass) builds them once, where each build
/// walks every term of the energy.
std::size_t ImproveLabels(const EnergyInput& energy,
                          std::span<const CellId> free,
                          const TermIncidence& incidence,
                          int max_passes,
                          std::vector<std::uint8_t>& labels);

}  // namespace linesurf::solver
