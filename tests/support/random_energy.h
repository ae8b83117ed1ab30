#pragma once
// Seeded random energies for the solver's tests and benchmarks (test support, not library code).

#include "solver/energy/energy_input.h"

#include <cstdint>
#include <vector>

namespace linesurf::solver::testing {

struct RandomEnergySpec {
  std::size_t num_cells = 10;
  std::size_t num_pairs = 15;
  std::size_t num_structural = 4;
  std::size_t num_parity = 4;
  /// Probability that a cell is fixed (half empty, half full).
  double fixed_fraction = 0.1;
  /// Parity groups get a constant k in {-1, 0, 1} (one more draw per group) instead of 0.
  bool parity_constants = false;
  std::uint64_t seed = 1;
};

/// Random unary costs in [0,1], weights in [0.1, 1], groups of 2-4 (structural) and 4 or 8
/// (parity) distinct cells with alternating signs.
[[nodiscard]] EnergyInput RandomEnergy(const RandomEnergySpec& spec);

/// RandomEnergy of 30 cells, 50 pairs, 8 structural and 10 parity groups (default fixed
/// fraction) for `seed`: the energy the bound and band tests compare with Clp's LP optimum.
[[nodiscard]] EnergyInput SmallRandomEnergy(std::uint64_t seed, bool parity_constants = false);

/// A grid of nx*ny*nz cells shaped like the labelling energy of a complex: full inside a few
/// balls (textural evidence near their surface), pairwise visibility terms between face
/// neighbours, structural groups of 3 cells along axes, parity groups on 2x2 cell edges; cells on
/// the grid boundary fixed empty. Deterministic from `seed`.
struct GridEnergySpec {
  int nx = 20;
  int ny = 20;
  int nz = 20;
  double visibility_weight = 0.1;
  double structural_weight = 1.0;
  double edge_weight = 0.01;
  std::uint64_t seed = 1;
};
[[nodiscard]] EnergyInput GridEnergy(const GridEnergySpec& spec);

/// The exhaustive minimum over 0/1 labellings (fixed cells held); at most 20 free cells.
[[nodiscard]] double BruteForceMinimum(const EnergyInput& e);

/// Block id per cell of GridEnergy(spec): cubes of `block_size`^3 cells, numbered x fastest.
[[nodiscard]] std::vector<std::uint32_t> GridBlocks(const GridEnergySpec& spec, int block_size);

}  // namespace linesurf::solver::testing
