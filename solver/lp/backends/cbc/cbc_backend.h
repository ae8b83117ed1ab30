#pragma once
// COIN-OR Cbc (branch and cut) on an LpModel whose first columns are required integral: the
// exact integer program of the labelling (cells 0/1, slacks continuous; at integral cells the
// optimal slacks are integral too). For measurements of the rounding gap, tests, and exact
// solves of small windows. Built only when Cbc is found (target linesurf_lp_cbc, option
// LINESURF_WITH_CBC); without it CbcAvailable() is false and SolveIlpWithCbc throws
// kInvalidOptions. Single-threaded and limited by nodes, not time, so results are deterministic.

#include "engine/core/run_context.h"
#include "solver/lp/lp_model.h"
#include "solver/lp/lp_solution.h"

#include <cstdint>
#include <span>

namespace linesurf::solver {

struct IlpLimits {
  /// Branch-and-bound nodes; 0 = no limit. Reaching it returns the best labelling found with
  /// status "node limit" (deterministic, unlike a time limit).
  std::int64_t max_nodes = 0;
  /// Wall seconds; 0 = none. Reaching it returns the best labelling with status "time limit".
  double time_limit_seconds = 0.0;
};

/// True when this build has the Cbc backend.
[[nodiscard]] bool CbcAvailable() noexcept;

/// Minimises `lp` with columns [0, num_integer_columns) integral (they must be boxed in [0, 1])
/// and the others continuous. Every row must hold its slack column first with coefficient 1
/// (build_lp.h's layout), so that `start` (optional: values of the integral columns) can be
/// completed with its optimal slacks and handed to Cbc as the first incumbent.
/// Returns the best solution found, LpSolution::lower_bound = Cbc's best bound (the optimum when
/// status is "optimal"); iterations = nodes. Throws kSolverFailed when no integral solution is
/// found, kCancelled when ctx.ShouldStop() (polled at every node), kInvalidOptions without Cbc.
[[nodiscard]] LpSolution SolveIlpWithCbc(const LpModel& lp,
                                         std::size_t num_integer_columns,
                                         std::span<const double> start,
                                         const IlpLimits& limits,
                                         const RunContext& ctx);

}  // namespace linesurf::solver
