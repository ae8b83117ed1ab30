#pragma once
/// @file pdhg_energy_backend.h
/// @brief First-order primal-dual solve of the energy's relaxation in its saddle-point form
/// (backend "pdhg-energy"), without the LP's slack columns.
///
/// Every term of the reduced energy is a maximum over a bounded multiplier:
///   w |x_a - x_b|          = max_{y in [-w, w]} y (x_a - x_b)
///   w max(0, 1 - sum x)    = max_{y in [0, w]}  y (1 - sum x)
///   w |sum nu x + k|       = max_{y in [-w, w]} y (sum nu x + k)
/// so the relaxation is min_{x in [0,1]^n} max_{y in Y} u.x + y.(K x + b) with one multiplier per
/// term and K of +-1 entries. Chambolle-Pock steps with the diagonal preconditioning of Pock &
/// Chambolle (2011, alpha = 1) for the multipliers scaled to their boxes (y_r / w_r: a column's
/// step is 1 / the sum of its terms' weights, a row's w_r / entries) in reflected Halpern
/// iterations with restarts and a primal weight (Lu & Yang 2024; PDLP's restart rules). Both
/// sets are boxes, so every step's point is feasible: the primal value is the energy of x, and
/// every y proves the lower bound
///   D(y) = constant + b.y + sum_j min(0, u_j + (K^T y)_j)
/// of the relaxation (and so of the integral optimum). Stops when the best primal value and the
/// best bound are within PdhgEnergyOptions::tolerance (relative).
///
/// Against "pdhg" on the LP (build_lp.h), the same relaxation has one variable per free cell
/// instead of one per cell and term, and one multiplier per term instead of two rows.
/// Parallel over fixed chunks (fixed_chunks.h): the same result for any number of threads.

#include "engine/core/run_context.h"
#include "solver/energy/build_lp.h"
#include "solver/lp/labeling_options.h"
#include "solver/lp/lp_solution.h"

namespace linesurf::solver {

/// @return columns = the free cells' values (the best primal point found), objective = its
/// energy, lower_bound = the best D(y), status "optimal (tolerance T)".
/// Throws kSolverFailed at options.max_iterations or at time_limit_seconds (0 = none),
/// kCancelled when ctx.ShouldStop() (polled every iteration).
[[nodiscard]] LpSolution SolveEnergyWithPdhg(const ReducedEnergy& energy,
                                             const PdhgEnergyOptions& options,
                                             double time_limit_seconds,
                                             const RunContext& ctx);

}  // namespace linesurf::solver
