#pragma once
// COIN-OR Clp on an LpModel: dual simplex with presolve (the reference backend), or Clp's
// barrier (its own Cholesky; measured in docs/design/lp_backend.md, not exposed by "auto").

#include "engine/core/run_context.h"
#include "solver/lp/labeling_options.h"
#include "solver/lp/lp_model.h"
#include "solver/lp/lp_solution.h"

namespace linesurf::solver {

enum class ClpAlgorithm { kDualSimplex, kBarrier };

/// Primal and dual tolerance options.tolerance; time_limit_seconds: 0 = none.
/// Throws kSolverFailed (status in the message) unless Clp proves optimality, or at the time
/// limit; kCancelled when ctx.ShouldStop() (polled from Clp's event handler every iteration).
[[nodiscard]] LpSolution SolveLpWithClp(const LpModel& lp,
                                        ClpAlgorithm algorithm,
                                        const ClpOptions& options,
                                        double time_limit_seconds,
                                        const RunContext& ctx);

}  // namespace linesurf::solver
