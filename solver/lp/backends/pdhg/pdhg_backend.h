#pragma once
// First-order primal-dual LP solver (PDHG in the style of PDLP: Ruiz + Pock-Chambolle diagonal
// preconditioning, adaptive restarts to the average iterate, primal weight updates).
// Handles any LpModel (rows l <= A x <= u, bounds possibly infinite).
// Parallel SpMV over fixed row/column chunks with oneTBB; every output entry is a serial sum and
// every reduction sums fixed-chunk partials in order, so results do not depend on thread count.

#include "engine/core/run_context.h"
#include "solver/lp/labeling_options.h"
#include "solver/lp/lp_model.h"
#include "solver/lp/lp_solution.h"

namespace linesurf::solver {

/// Stops when relative primal residual, dual residual and duality gap are all below
/// options.tolerance; throws kSolverFailed at options.max_iterations or at time_limit_seconds
/// (0 = none), kCancelled when ctx.ShouldStop() (polled every iteration).
[[nodiscard]] LpSolution SolveLpWithPdhg(const LpModel& lp,
                                         const PdhgOptions& options,
                                         double time_limit_seconds,
                                         const RunContext& ctx);

}  // namespace linesurf::solver
