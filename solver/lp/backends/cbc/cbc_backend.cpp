#include "solver/lp/backends/cbc/cbc_backend.h"

#include "engine/core/exception.h"
#include "solver/lp/backends/coin/coin_problem.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <CbcEventHandler.hpp>
#include <CbcModel.hpp>
#include <CbcStrategy.hpp>
#include <OsiClpSolverInterface.hpp>

namespace linesurf::solver {
namespace {

constexpr const char* kCbcBackendStage = "solve_labeling";

// Stops Cbc at the next node once the host cancels.
class CancelHandler : public CbcEventHandler {
 public:
  CancelHandler(const RunContext* ctx, bool* cancelled) : ctx_(ctx), cancelled_(cancelled) {}
  CbcAction event(CbcEvent which_event) override {
    if (which_event == node && ctx_->ShouldStop()) {
      *cancelled_ = true;
      return stop;
    }
    return noAction;
  }
  CbcEventHandler* clone() const override { return new CancelHandler(*this); }

 private:
  const RunContext* ctx_;
  bool* cancelled_;
};

double Objective(const LpModel& lp, std::span<const double> x) {
  double value = lp.objective_offset;
  for (std::size_t j = 0; j < x.size(); ++j) value += lp.objective[j] * x[j];
  return value;
}

// Values of all columns from the integral ones: each slack takes the least value its rows allow
// (every row is "slack + sum a x >= lower" with the slack first).
std::vector<double> CompleteSlacks(const LpModel& lp,
                                   std::size_t num_integer,
                                   std::span<const double> start) {
  std::vector<double> x(lp.NumColumns(), 0.0);
  std::copy(start.begin(), start.end(), x.begin());
  for (std::size_t r = 0; r < lp.NumRows(); ++r) {
    const std::uint32_t first = lp.row_offsets[r];
    const std::uint32_t slack = lp.row_columns[first];
    LINESURF_ASSERT(slack >= num_integer && lp.row_values[first] == 1.0);
    double rest = 0.0;
    for (std::uint32_t k = first + 1; k < lp.row_offsets[r + 1]; ++k) {
      rest += lp.row_values[k] * x[lp.row_columns[k]];
    }
    x[slack] = std::max(x[slack], lp.row_lower[r] - rest);
  }
  return x;
}

}  // namespace

bool CbcAvailable() noexcept { return true; }

LpSolution SolveIlpWithCbc(const LpModel& lp,
                           std::size_t num_integer_columns,
                           std::span<const double> start,
                           const IlpLimits& limits,
                           const RunContext& ctx) {
  LINESURF_ASSERT(num_integer_columns <= lp.NumColumns());
  LINESURF_ASSERT(start.empty() || start.size() == num_integer_columns);
  LpSolution solution;
  solution.status = "optimal";
  if (lp.NumColumns() == 0) {
    solution.objective = solution.lower_bound = lp.objective_offset;
    return solution;
  }
  const CoinProblem coin = ToCoinProblem(lp);
  OsiClpSolverInterface osi;
  osi.messageHandler()->setLogLevel(0);
  osi.loadProblem(coin.matrix,
                  coin.col_lower.data(),
                  coin.col_upper.data(),
                  lp.objective.data(),
                  coin.row_lower.data(),
                  coin.row_upper.data());
  for (std::size_t j = 0; j < num_integer_columns; ++j) osi.setInteger(static_cast<int>(j));

  CbcModel model(osi);
  model.setLogLevel(0);
  model.messageHandler()->setLogLevel(0);
  model.solver()->messageHandler()->setLogLevel(0);
  model.setNumberThreads(0);
  if (limits.max_nodes > 0) model.setMaximumNodes(static_cast<int>(limits.max_nodes));
  if (limits.time_limit_seconds > 0.0) {
    model.setUseElapsedTime(true);  // wall time, as every other limit of ours
    model.setMaximumSeconds(limits.time_limit_seconds);
  }
  CbcStrategyDefault strategy(1, 5, 5);
  model.setStrategy(strategy);
  bool cancelled = false;
  CancelHandler handler(&ctx, &cancelled);
  model.passInEventHandler(&handler);
  if (!start.empty()) {
    const std::vector<double> x = CompleteSlacks(lp, num_integer_columns, start);
    model.setBestSolution(
        x.data(), static_cast<int>(x.size()), Objective(lp, x) - lp.objective_offset, true);
  }
  model.branchAndBound();

  LINESURF_THROW_IF(cancelled, kCancelled, kCbcBackendStage, "Cbc solve cancelled by the host");
  const double* best = model.bestSolution();
  LINESURF_THROW_IF(best == nullptr,
                    kSolverFailed,
                    kCbcBackendStage,
                    "Cbc found no integral solution (status " << model.status() << ", secondary "
                                                              << model.secondaryStatus() << ")");
  solution.columns.assign(best, best + lp.NumColumns());
  for (std::size_t j = 0; j < num_integer_columns; ++j) {
    solution.columns[j] = std::round(solution.columns[j]);
  }
  // Slacks recomputed at the rounded cells, so the objective is exactly the energy.
  solution.columns =
      CompleteSlacks(lp,
                     num_integer_columns,
                     std::span<const double>(solution.columns.data(), num_integer_columns));
  solution.objective = Objective(lp, solution.columns);
  solution.iterations = model.getNodeCount();
  if (model.isProvenOptimal()) {
    solution.lower_bound =
        std::min(solution.objective, model.getBestPossibleObjValue() + lp.objective_offset);
  } else {
    solution.status = model.maximumSecondsReached() ? "time limit" : "node limit";
    solution.lower_bound = model.getBestPossibleObjValue() + lp.objective_offset;
  }
  return solution;
}

}  // namespace linesurf::solver
