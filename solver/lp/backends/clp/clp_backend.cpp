#include "solver/lp/backends/clp/clp_backend.h"

#include <chrono>
#include <cmath>
#include <memory>
#include <vector>

#include <ClpEventHandler.hpp>
#include <ClpSimplex.hpp>
#include <ClpSolve.hpp>

#include "engine/core/exception.h"
#include "solver/lp/backends/coin/coin_problem.h"

namespace linesurf::solver {
namespace {

constexpr const char* kClpBackendStage = "solve_labeling";

// Stops Clp (status 5) when the host cancels or the wall-time limit passes. Copied by Clp into
// the presolved model, so it only holds pointers to objects that outlive the solve.
class StopHandler : public ClpEventHandler {
 public:
  StopHandler(const RunContext* ctx, std::chrono::steady_clock::time_point deadline,
              bool* cancelled, bool* timed_out)
      : ctx_(ctx), deadline_(deadline), cancelled_(cancelled), timed_out_(timed_out) {}

  int event(Event which_event) override {
    if (which_event != endOfIteration && which_event != endOfFactorization) return -1;
    if (ctx_->ShouldStop()) {
      *cancelled_ = true;
      return 0;
    }
    if (std::chrono::steady_clock::now() > deadline_) {
      *timed_out_ = true;
      return 0;
    }
    return -1;
  }
  ClpEventHandler* clone() const override { return new StopHandler(*this); }

 private:
  const RunContext* ctx_;
  std::chrono::steady_clock::time_point deadline_;
  bool* cancelled_;
  bool* timed_out_;
};

const char* ClpStatusName(int status) {
  switch (status) {
    case 0: return "optimal";
    case 1: return "primal infeasible";
    case 2: return "dual infeasible (unbounded)";
    case 3: return "stopped on iterations or time";
    case 4: return "stopped due to errors";
    case 5: return "stopped by event";
    default: return "unknown status";
  }
}

}  // namespace

LpSolution SolveLpWithClp(const LpModel& lp,
                          ClpAlgorithm algorithm,
                          const ClpOptions& options,
                          double time_limit_seconds,
                          const RunContext& ctx) {
  const int num_cols = static_cast<int>(lp.NumColumns());
  LpSolution solution;
  if (num_cols == 0) {
    solution.objective = lp.objective_offset;
    solution.status = "optimal";
    return solution;
  }
  const CoinProblem coin = ToCoinProblem(lp);

  ClpSimplex model;
  model.setLogLevel(0);
  model.messageHandler()->setLogLevel(0);
  model.loadProblem(coin.matrix, coin.col_lower.data(), coin.col_upper.data(),
                    lp.objective.data(), coin.row_lower.data(), coin.row_upper.data());
  model.setPrimalTolerance(options.tolerance);
  model.setDualTolerance(options.tolerance);
  model.setOptimizationDirection(1.0);

  bool cancelled = false;
  bool timed_out = false;
  const auto deadline = time_limit_seconds > 0.0
                            ? std::chrono::steady_clock::now() +
                                  std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                      std::chrono::duration<double>(time_limit_seconds))
                            : std::chrono::steady_clock::time_point::max();
  StopHandler handler(&ctx, deadline, &cancelled, &timed_out);
  model.passInEventHandler(&handler);

  ClpSolve solve_options;
  solve_options.setSolveType(algorithm == ClpAlgorithm::kBarrier ? ClpSolve::useBarrier
                                                                  : ClpSolve::useDual);
  solve_options.setPresolveType(ClpSolve::presolveOn);
  model.initialSolve(solve_options);

  LINESURF_THROW_IF(cancelled, kCancelled, kClpBackendStage, "Clp solve cancelled by the host");
  LINESURF_THROW_IF(timed_out,
                    kSolverFailed,
                    kClpBackendStage,
                    "Clp stopped at the time limit of " << time_limit_seconds << " s");
  LINESURF_THROW_IF(!model.isProvenOptimal(),
                    kSolverFailed,
                    kClpBackendStage,
                    "Clp failed: status " << model.status() << " (" << ClpStatusName(model.status())
                                          << "), secondary status " << model.secondaryStatus());
  const double* values = model.primalColumnSolution();
  solution.columns.assign(values, values + num_cols);
  solution.objective = lp.Evaluate(solution.columns);
  solution.status = "optimal";
  solution.iterations = model.numberIterations();
  return solution;
}

}  // namespace linesurf::solver
