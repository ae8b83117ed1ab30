#pragma once
/// @file sub_energy.h
/// @brief The energy of a subset of cells with every other cell held at a given label: what an
/// exact solve of a window (window_polish.h) or of one block of a larger scene works on.
///
/// The sub-energy's cells are the chosen cells first (in the order given, free unless fixed in
/// the full energy), then every other cell that shares a term with them, fixed at its label.
/// It holds only the terms that touch a chosen cell, so its size is that of the neighbourhood,
/// not of the whole energy. For labels that agree outside the chosen cells, the full energy
/// minus the sub-energy is the same constant: minimising the sub-energy minimises the full
/// energy over the chosen cells.

#include "solver/energy/energy_input.h"
#include "solver/energy/term_incidence.h"

#include <cstdint>
#include <span>
#include <vector>

namespace linesurf::solver {

struct SubEnergy {
  EnergyInput energy;
  /// Cell of the full energy for each cell of `energy`; the chosen cells come first.
  std::vector<CellId> cells;
};

/// `incidence` must list the terms of `energy` for (at least) every chosen cell; `labels` holds
/// one 0/1 label per cell of `energy` (fixed cells at their label). Chosen cells must be distinct.
[[nodiscard]] SubEnergy RestrictEnergy(const EnergyInput& energy,
                                       const TermIncidence& incidence,
                                       std::span<const CellId> chosen,
                                       const std::vector<std::uint8_t>& labels);

}  // namespace linesurf::solver
