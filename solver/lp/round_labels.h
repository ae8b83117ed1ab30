#pragma once
// Rounding of relaxed cell values to 0/1 labels (rule in lp_backend.h).

#include <cstdint>
#include <span>
#include <vector>

#include "solver/energy/energy_input.h"

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

}  // namespace linesurf::solver
