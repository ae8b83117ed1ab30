#pragma once
/// @file complex_regularisation.h
/// @brief Internal to engine/pipeline: the edge and corner regularisation (Boulch et al. 2014,
/// see evidence.h) of the edges and vertices inside one complex.

#include "engine/core/cell_complex.h"
#include "engine/pipeline/evidence.h"
#include "solver/energy/energy_input.h"

#include <cstddef>

namespace linesurf::pipeline {

/// Adds a parity group for every edge (weight edge_weight * length / sigma) and every vertex
/// (corner_weight) of `complex` that does not lie on its box, so that all its cells are cells of
/// the complex, signs from the complex's 2-colouring, cells numbered from `first_cell`. Edges in
/// id order, then vertices in id order.
void AddComplexRegularisation(const CellComplex& complex,
                              const EnergyOptions& options,
                              double sigma,
                              std::size_t first_cell,
                              solver::EnergyInput& energy);

}  // namespace linesurf::pipeline
