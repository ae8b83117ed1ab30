#pragma once
/// @file sub_energy.h
/// @brief The energy of a subset of cells with every other cell held at a given label: what an
/// exact solve of a window (window_polish.h) or of one block of a larger scene works on; and the
/// interior energy of a subset, the piece of a Lagrangian split of the energy by blocks.
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

/// The interior energy of the chosen cells (all free in `energy`, distinct): their unary costs
/// and the terms that touch a chosen cell and no free cell outside them; the other cells of
/// those terms are fixed cells of `energy`, kept fixed. Terms that reach a free cell outside the
/// chosen ones are left out. For a partition of the free cells into blocks every term with a free
/// cell lies in exactly one interior energy or is left out by all; since every term is >= 0, the
/// sum over blocks of the interiors' minima, plus the energy of the terms and cells without a free
/// cell, is a lower bound of the minimum of `energy` (a Lagrangian split with zero multipliers).
[[nodiscard]] SubEnergy InteriorEnergy(const EnergyInput& energy,
                                       const TermIncidence& incidence,
                                       std::span<const CellId> chosen);

}  // namespace linesurf::solver
