#pragma once
// Boykov-Kolmogorov max-flow (libmaxflow) on a reduced energy with only unary and pairwise
// terms: an exact minimum, integral, hence also an optimum of the LP relaxation.

#include "engine/core/run_context.h"
#include "solver/energy/build_lp.h"
#include "solver/lp/lp_solution.h"

namespace linesurf::solver {

/// Returns the 0/1 value per free column (LpSolution::columns has NumFree() entries, no slacks)
/// and the energy. Throws kInvalidOptions when `reduced` has structural or parity groups.
/// Cells left in the source set (free to go either way at equal cost) are empty.
[[nodiscard]] LpSolution SolveWithMaxflow(const ReducedEnergy& reduced, const RunContext& ctx);

}  // namespace linesurf::solver
