#include "solver/lp/backends/pdhg_energy/pdhg_energy_backend.h"

#include "engine/core/exception.h"
#include "engine/core/parallel.h"
#include "solver/lp/backends/fixed_chunks.h"
#include "solver/lp/backends/pdlp_restarts.h"
#include "solver/lp/backends/transpose_rows.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace linesurf::solver {
namespace {

constexpr const char* kPdhgEnergyStage = "solve_labeling";
// Step factor below the bound 1 of the preconditioned steps, a margin for rounding.
constexpr double kStepFactor = 0.95;

// K (rows: pairs, structural groups, parity groups, in that order) with its transpose; every
// entry is +-1, so only the signs are stored. Per row only the multiplier bound `upper` (the
// weight) is stored: the offset b (0 for a pair, 1 for a structural group, the constant of a
// parity group) and the lower bound (-upper, 0 for a structural group) follow from the row's
// kind, which keeps the memory an iteration streams through small.
struct SaddleProblem {
  std::size_t num_rows = 0;
  std::size_t num_cols = 0;
  std::size_t first_structural_row = 0;
  std::size_t first_parity_row = 0;
  std::vector<std::uint32_t> row_offsets{0};
  std::vector<std::uint32_t> row_columns;
  std::vector<std::int8_t> row_signs;
  std::vector<std::uint32_t> col_offsets;
  std::vector<std::uint32_t> col_rows;
  std::vector<std::int8_t> col_signs;
  std::vector<double> upper;
  std::vector<std::int32_t> parity_constants;
  std::vector<double> unary;
  double constant = 0.0;

  // Closes the row whose entries were just appended.
  void AddRow(double weight) {
    row_offsets.push_back(static_cast<std::uint32_t>(row_columns.size()));
    upper.push_back(weight);
  }

  // b of row r.
  [[nodiscard]] double Offset(std::size_t r) const {
    if (r < first_structural_row) return 0.0;
    if (r < first_parity_row) return 1.0;
    return static_cast<double>(parity_constants[r - first_parity_row]);
  }

  // The lower multiplier bound of row r.
  [[nodiscard]] double Lower(std::size_t r) const {
    return r >= first_structural_row && r < first_parity_row ? 0.0 : -upper[r];
  }
};

SaddleProblem BuildSaddle(const ReducedEnergy& e) {
  const std::size_t entries =
      2 * e.pairs.size() + e.structural_columns.size() + e.parity_columns.size();
  LINESURF_THROW_IF(entries >= std::numeric_limits<std::uint32_t>::max(),
                    kResourceExhausted,
                    kPdhgEnergyStage,
                    "energy too large for 32-bit indices: " << entries << " term entries");
  SaddleProblem p;
  p.num_cols = e.NumFree();
  p.unary = e.unary;
  p.constant = e.constant;
  for (const ReducedEnergy::Pair& pair : e.pairs) {
    p.row_columns.insert(p.row_columns.end(), {pair.a, pair.b});
    p.row_signs.insert(p.row_signs.end(), {std::int8_t{1}, std::int8_t{-1}});
    p.AddRow(pair.weight);
  }
  p.first_structural_row = p.upper.size();
  for (std::size_t g = 0; g < e.structural_weights.size(); ++g) {
    for (std::uint32_t k = e.structural_offsets[g]; k < e.structural_offsets[g + 1]; ++k) {
      p.row_columns.push_back(e.structural_columns[k]);
      p.row_signs.push_back(-1);
    }
    p.AddRow(e.structural_weights[g]);
  }
  p.first_parity_row = p.upper.size();
  for (std::size_t g = 0; g < e.parity_weights.size(); ++g) {
    for (std::uint32_t k = e.parity_offsets[g]; k < e.parity_offsets[g + 1]; ++k) {
      p.row_columns.push_back(e.parity_columns[k]);
      p.row_signs.push_back(e.parity_signs[k]);
    }
    p.AddRow(e.parity_weights[g]);
  }
  p.parity_constants = e.parity_constants;
  p.num_rows = p.upper.size();
  CompressedRows<std::int8_t> columns =
      TransposeRows<std::int8_t>(p.row_offsets, p.row_columns, p.row_signs, p.num_cols);
  p.col_offsets = std::move(columns.offsets);
  p.col_rows = std::move(columns.index);
  p.col_signs = std::move(columns.value);
  return p;
}

// A primal-dual point.
struct Point {
  std::vector<double> x;
  std::vector<double> y;
};

class EnergyPdhg {
 public:
  EnergyPdhg(const ReducedEnergy& energy, const LabelingOptions& options, const RunContext& ctx)
      : energy_(energy), options_(options), ctx_(ctx), p_(BuildSaddle(energy)) {}

  LpSolution Run() {
    const auto start = std::chrono::steady_clock::now();
    const std::size_t n = p_.num_cols, m = p_.num_rows;
    // Preconditioned steps (Pock & Chambolle 2011, alpha = 1, |K_ij| = 1): 1 / entries.
    tau_.assign(n, 0.0);
    for (std::size_t j = 0; j < n; ++j) {
      const std::uint32_t count = p_.col_offsets[j + 1] - p_.col_offsets[j];
      tau_[j] = count == 0 ? 0.0 : kStepFactor / count;
    }
    // A row's dual step depends only on its entry count: one value per count.
    std::uint32_t max_count = 0;
    for (std::size_t r = 0; r < m; ++r) {
      max_count = std::max(max_count, p_.row_offsets[r + 1] - p_.row_offsets[r]);
    }
    sigma_by_count_.assign(max_count + 1, 0.0);
    for (std::uint32_t count = 1; count <= max_count; ++count) {
      sigma_by_count_[count] = kStepFactor / count;
    }
    // A column in no term: its optimum is read off its unary coefficient.
    Point current{std::vector<double>(n, 0.0), std::vector<double>(m, 0.0)};
    for (std::size_t j = 0; j < n; ++j) {
      if (tau_[j] == 0.0) current.x[j] = energy_.unary[j] < 0.0 ? 1.0 : 0.0;
    }
    Point step = current;  // T(current): the PDHG step, a feasible point
    Point anchor = current;
    std::vector<double> extrapolated(n, 0.0);
    double weight = 1.0;
    double restart_gap = -1.0;  // set at the first check
    double previous_gap = std::numeric_limits<double>::infinity();
    std::int64_t since_restart = 0;
    best_primal_ = std::numeric_limits<double>::infinity();
    best_dual_ = -std::numeric_limits<double>::infinity();
    best_x_ = current.x;

    for (std::int64_t it = 1; it <= options_.pdhg_max_iterations; ++it) {
      // T's point is read only at the checks: between them it is not stored.
      const bool check = it % kRestartCheckPeriod == 0 || it == options_.pdhg_max_iterations;
      Iterate(current, anchor, since_restart, weight, check, step, extrapolated);
      ++since_restart;
      LINESURF_THROW_IF(
          ctx_.ShouldStop(), kCancelled, kPdhgEnergyStage, "pdhg-energy cancelled by the host");
      if (!check) continue;

      const double elapsed =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      LINESURF_THROW_IF(options_.time_limit_seconds > 0.0 && elapsed > options_.time_limit_seconds,
                        kSolverFailed,
                        kPdhgEnergyStage,
                        "pdhg-energy stopped at the time limit of "
                            << options_.time_limit_seconds << " s after " << it << " iterations");
      // The merit is the duality gap at the step's point (feasible; both sets are bounded, so the
      // gap is finite).
      const double gap = Gap(step);
      if (Converged()) return Solution(it);
      if (restart_gap < 0.0) restart_gap = gap;
      const bool restart = ShouldRestart(gap, restart_gap, previous_gap, since_restart, it);
      previous_gap = gap;
      if (!restart) continue;
      // Restart the Halpern sequence at the step's point, with a rebalanced primal weight.
      weight = SmoothedPrimalWeight(
          weight, ChunkedDistance(step.x, anchor.x), ChunkedDistance(step.y, anchor.y));
      anchor = step;
      current = step;
      restart_gap = gap;
      previous_gap = std::numeric_limits<double>::infinity();
      since_restart = 0;
      ++restarts_;
    }
    ThrowError(ErrorCode::kSolverFailed,
               kPdhgEnergyStage,
               "pdhg-energy reached its iteration limit of " +
                   std::to_string(options_.pdhg_max_iterations) + " with the gap " +
                   std::to_string(best_primal_ - best_dual_) + " above tolerance " +
                   std::to_string(options_.pdhg_energy_tolerance));
  }

 private:
  // One iteration: the PDHG operator T, x+ = clip(x - tau/w (u + K^T y)), then
  // y+ = clip(y + w sigma (K (2 x+ - x) + b)), written to `step`; and the reflected Halpern
  // iteration (Lu & Yang 2024, "Restarted Halpern PDHG for linear programming") in place,
  // z <- (k+1)/(k+2) (2 T(z) - z) + 1/(k+2) z_0, k the iterations since the restart and z_0 the
  // restart point. A column's z is replaced once T no longer needs it (the rows read only the
  // extrapolated x), a row's right after its own update. T(z) itself is written to `step` only
  // when `keep_step` (the iterations that check the gap). On the block engine's Andalusian energy
  // 12,864 iterations where PDLP's restarts to the average took 16,128
  // (docs/design/lp_backend.md, "Energy pdhg").
  void Iterate(Point& z,
               const Point& anchor,
               std::int64_t k,
               double weight,
               bool keep_step,
               Point& step,
               std::vector<double>& extrapolated) const {
    const double lambda = (static_cast<double>(k) + 1.0) / (static_cast<double>(k) + 2.0);
    ForChunks(p_.num_cols, [&](std::size_t begin, std::size_t end) {
      for (std::size_t j = begin; j < end; ++j) {
        const double x = tau_[j] == 0.0
                             ? z.x[j]
                             : std::clamp(z.x[j] - tau_[j] / weight * ReducedCost(j, z.y), 0.0, 1.0);
        if (keep_step) step.x[j] = x;
        extrapolated[j] = 2.0 * x - z.x[j];
      }
    }, kElementwiseChunk);
    ForChunks(p_.num_rows, [&](std::size_t begin, std::size_t end) {
      for (std::size_t r = begin; r < end; ++r) {
        const std::uint32_t first = p_.row_offsets[r], last = p_.row_offsets[r + 1];
        double kx = p_.Offset(r);
        for (std::uint32_t i = first; i < last; ++i) {
          kx += p_.row_signs[i] * extrapolated[p_.row_columns[i]];
        }
        const double y = std::clamp(
            z.y[r] + weight * sigma_by_count_[last - first] * kx, p_.Lower(r), p_.upper[r]);
        if (keep_step) step.y[r] = y;
        z.y[r] = lambda * (2.0 * y - z.y[r]) + (1.0 - lambda) * anchor.y[r];
      }
    }, kElementwiseChunk);
    // extrapolated = 2 T(x) - x: the reflection of x already.
    ForChunks(p_.num_cols, [&](std::size_t begin, std::size_t end) {
      for (std::size_t j = begin; j < end; ++j) {
        z.x[j] = lambda * extrapolated[j] + (1.0 - lambda) * anchor.x[j];
      }
    }, kElementwiseChunk);
  }

  // (u + K^T y)_j: the primal gradient of column j, the reduced cost in the dual.
  double ReducedCost(std::size_t j, const std::vector<double>& y) const {
    double g = p_.unary[j];
    for (std::uint32_t k = p_.col_offsets[j]; k < p_.col_offsets[j + 1]; ++k) {
      g += p_.col_signs[k] * y[p_.col_rows[k]];
    }
    return g;
  }

  // D(y) = constant + b.y + sum_j min(0, u_j + (K^T y)_j): a lower bound for any y in the box.
  double DualValue(const std::vector<double>& y) const {
    const double by = SumChunks(p_.num_rows, [&](std::size_t begin, std::size_t end) {
      double s = 0.0;
      for (std::size_t r = begin; r < end; ++r) s += p_.Offset(r) * y[r];
      return s;
    });
    const double reduced = SumChunks(p_.num_cols, [&](std::size_t begin, std::size_t end) {
      double s = 0.0;
      for (std::size_t j = begin; j < end; ++j) s += std::min(0.0, ReducedCost(j, y));
      return s;
    });
    return p_.constant + by + reduced;
  }

  // The gap of a point; records the best primal point and the best bound seen.
  double Gap(const Point& point) {
    const double primal = energy_.Evaluate(std::span<const double>(point.x));
    const double dual = DualValue(point.y);
    if (primal < best_primal_) {
      best_primal_ = primal;
      best_x_ = point.x;
    }
    best_dual_ = std::max(best_dual_, dual);
    return primal - dual;
  }

  [[nodiscard]] bool Converged() const {
    return best_primal_ - best_dual_ <=
           options_.pdhg_energy_tolerance * std::max(1.0, std::abs(best_primal_));
  }

  LpSolution Solution(std::int64_t iterations) const {
    ctx_.Log(LogLevel::kInfo,
             kPdhgEnergyStage,
             "pdhg-energy: " + std::to_string(iterations) + " iterations, " +
                 std::to_string(restarts_) + " restarts, energy " + std::to_string(best_primal_) +
                 ", bound " + std::to_string(best_dual_));
    LpSolution s;
    s.columns = best_x_;
    s.objective = best_primal_;
    s.lower_bound = best_dual_;
    s.iterations = iterations;
    s.status = "optimal (tolerance " + std::to_string(options_.pdhg_energy_tolerance) + ")";
    return s;
  }

  const ReducedEnergy& energy_;
  const LabelingOptions& options_;
  const RunContext& ctx_;
  SaddleProblem p_;
  std::vector<double> tau_;
  std::vector<double> sigma_by_count_;
  double best_primal_ = 0.0;
  double best_dual_ = 0.0;
  std::vector<double> best_x_;
  std::int64_t restarts_ = 0;
};

}  // namespace

LpSolution SolveEnergyWithPdhg(const ReducedEnergy& energy,
                               const LabelingOptions& options,
                               const RunContext& ctx) {
  return RunInArena(ctx, [&] { return EnergyPdhg(energy, options, ctx).Run(); });
}

}  // namespace linesurf::solver
