#include "solver/lp/backends/pdhg_energy/pdhg_energy_backend.h"

#include "engine/core/exception.h"
#include "engine/core/parallel.h"
#include "solver/lp/backends/fixed_chunks.h"
#include "solver/lp/backends/pdlp_restarts.h"

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
// entry is +-1, so only the signs are stored. b and the multiplier box [lower, upper] per row.
struct SaddleProblem {
  std::size_t num_rows = 0;
  std::size_t num_cols = 0;
  std::vector<std::uint32_t> row_offsets{0};
  std::vector<std::uint32_t> row_columns;
  std::vector<std::int8_t> row_signs;
  std::vector<std::uint32_t> col_offsets;
  std::vector<std::uint32_t> col_rows;
  std::vector<std::int8_t> col_signs;
  std::vector<double> b;
  std::vector<double> lower;
  std::vector<double> upper;
  std::vector<double> unary;
  double constant = 0.0;

  // Closes the row whose entries were just appended.
  void AddRow(double offset, double lo, double hi) {
    row_offsets.push_back(static_cast<std::uint32_t>(row_columns.size()));
    b.push_back(offset);
    lower.push_back(lo);
    upper.push_back(hi);
  }
};

SaddleProblem BuildSaddle(const ReducedEnergy& e) {
  SaddleProblem p;
  p.num_cols = e.NumFree();
  p.unary = e.unary;
  p.constant = e.constant;
  for (const ReducedEnergy::Pair& pair : e.pairs) {
    p.row_columns.insert(p.row_columns.end(), {pair.a, pair.b});
    p.row_signs.insert(p.row_signs.end(), {std::int8_t{1}, std::int8_t{-1}});
    p.AddRow(0.0, -pair.weight, pair.weight);
  }
  for (std::size_t g = 0; g < e.structural_weights.size(); ++g) {
    for (std::uint32_t k = e.structural_offsets[g]; k < e.structural_offsets[g + 1]; ++k) {
      p.row_columns.push_back(e.structural_columns[k]);
      p.row_signs.push_back(-1);
    }
    p.AddRow(1.0, 0.0, e.structural_weights[g]);
  }
  for (std::size_t g = 0; g < e.parity_weights.size(); ++g) {
    for (std::uint32_t k = e.parity_offsets[g]; k < e.parity_offsets[g + 1]; ++k) {
      p.row_columns.push_back(e.parity_columns[k]);
      p.row_signs.push_back(e.parity_signs[k]);
    }
    p.AddRow(e.parity_constants[g], -e.parity_weights[g], e.parity_weights[g]);
  }
  p.num_rows = p.b.size();
  // Transpose by counting sort.
  p.col_offsets.assign(p.num_cols + 1, 0);
  for (std::uint32_t c : p.row_columns) ++p.col_offsets[c + 1];
  for (std::size_t j = 0; j < p.num_cols; ++j) p.col_offsets[j + 1] += p.col_offsets[j];
  p.col_rows.resize(p.row_columns.size());
  p.col_signs.resize(p.row_columns.size());
  std::vector<std::uint32_t> next(p.col_offsets.begin(), p.col_offsets.end() - 1);
  for (std::size_t r = 0; r < p.num_rows; ++r) {
    for (std::uint32_t k = p.row_offsets[r]; k < p.row_offsets[r + 1]; ++k) {
      const std::uint32_t pos = next[p.row_columns[k]]++;
      p.col_rows[pos] = static_cast<std::uint32_t>(r);
      p.col_signs[pos] = p.row_signs[k];
    }
  }
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
    sigma_.assign(m, 0.0);
    for (std::size_t j = 0; j < n; ++j) {
      const std::uint32_t count = p_.col_offsets[j + 1] - p_.col_offsets[j];
      tau_[j] = count == 0 ? 0.0 : kStepFactor / count;
    }
    for (std::size_t r = 0; r < m; ++r) {
      sigma_[r] = kStepFactor / (p_.row_offsets[r + 1] - p_.row_offsets[r]);
    }
    // A column in no term: its optimum is read off its unary coefficient.
    Point current{std::vector<double>(n, 0.0), std::vector<double>(m, 0.0)};
    for (std::size_t j = 0; j < n; ++j) {
      if (tau_[j] == 0.0) current.x[j] = energy_.unary[j] < 0.0 ? 1.0 : 0.0;
    }
    Point sum{std::vector<double>(n, 0.0), std::vector<double>(m, 0.0)};
    Point next = current;
    std::vector<double> extrapolated(n, 0.0);
    Point last_restart = current;
    double weight = 1.0;
    double restart_gap = -1.0;  // set at the first check
    double previous_candidate_gap = std::numeric_limits<double>::infinity();
    std::int64_t since_restart = 0;
    best_primal_ = std::numeric_limits<double>::infinity();
    best_dual_ = -std::numeric_limits<double>::infinity();
    best_x_ = current.x;

    for (std::int64_t it = 1; it <= options_.pdhg_max_iterations; ++it) {
      Step(current, weight, next, extrapolated, sum);
      std::swap(current, next);
      ++since_restart;
      LINESURF_THROW_IF(
          ctx_.ShouldStop(), kCancelled, kPdhgEnergyStage, "pdhg-energy cancelled by the host");
      if (it % kRestartCheckPeriod != 0) continue;

      const double elapsed =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      LINESURF_THROW_IF(options_.time_limit_seconds > 0.0 && elapsed > options_.time_limit_seconds,
                        kSolverFailed,
                        kPdhgEnergyStage,
                        "pdhg-energy stopped at the time limit of "
                            << options_.time_limit_seconds << " s after " << it << " iterations");
      const Point average = Average(sum, since_restart);
      const double current_gap = Gap(current);
      const double average_gap = Gap(average);
      if (Converged()) return Solution(it);

      // Restart to the better of the current and the average point; the gap is the merit (both
      // sets are bounded, so it is finite).
      const bool take_average = average_gap < current_gap;
      const double candidate_gap = take_average ? average_gap : current_gap;
      if (restart_gap < 0.0) restart_gap = candidate_gap;
      const bool restart =
          ShouldRestart(candidate_gap, restart_gap, previous_candidate_gap, since_restart, it);
      previous_candidate_gap = candidate_gap;
      if (!restart) continue;
      if (take_average) current = average;
      weight = SmoothedPrimalWeight(weight,
                                    ChunkedDistance(current.x, last_restart.x),
                                    ChunkedDistance(current.y, last_restart.y));
      last_restart = current;
      restart_gap = candidate_gap;
      previous_candidate_gap = std::numeric_limits<double>::infinity();
      since_restart = 0;
      ++restarts_;
      std::fill(sum.x.begin(), sum.x.end(), 0.0);
      std::fill(sum.y.begin(), sum.y.end(), 0.0);
    }
    ThrowError(ErrorCode::kSolverFailed,
               kPdhgEnergyStage,
               "pdhg-energy reached its iteration limit of " +
                   std::to_string(options_.pdhg_max_iterations) + " with the gap " +
                   std::to_string(best_primal_ - best_dual_) + " above tolerance " +
                   std::to_string(options_.pdhg_tolerance));
  }

 private:
  // One iteration: x+ = clip(x - tau/w (u + K^T y)), y+ = clip(y + w sigma (K (2x+ - x) + b)).
  void Step(const Point& at,
            double weight,
            Point& out,
            std::vector<double>& extrapolated,
            Point& sum) const {
    ForChunks(p_.num_cols, [&](std::size_t begin, std::size_t end) {
      for (std::size_t j = begin; j < end; ++j) {
        if (tau_[j] == 0.0) {
          out.x[j] = at.x[j];
        } else {
          double g = p_.unary[j];
          for (std::uint32_t k = p_.col_offsets[j]; k < p_.col_offsets[j + 1]; ++k) {
            g += p_.col_signs[k] * at.y[p_.col_rows[k]];
          }
          out.x[j] = std::clamp(at.x[j] - tau_[j] / weight * g, 0.0, 1.0);
        }
        extrapolated[j] = 2.0 * out.x[j] - at.x[j];
        sum.x[j] += out.x[j];
      }
    });
    ForChunks(p_.num_rows, [&](std::size_t begin, std::size_t end) {
      for (std::size_t r = begin; r < end; ++r) {
        double kx = p_.b[r];
        for (std::uint32_t k = p_.row_offsets[r]; k < p_.row_offsets[r + 1]; ++k) {
          kx += p_.row_signs[k] * extrapolated[p_.row_columns[k]];
        }
        out.y[r] = std::clamp(at.y[r] + weight * sigma_[r] * kx, p_.lower[r], p_.upper[r]);
        sum.y[r] += out.y[r];
      }
    });
  }

  static Point Average(const Point& sum, std::int64_t count) {
    Point a = sum;
    const double inv = 1.0 / static_cast<double>(count);
    ForChunks(a.x.size(), [&](std::size_t b, std::size_t e) {
      for (std::size_t j = b; j < e; ++j) a.x[j] *= inv;
    });
    ForChunks(a.y.size(), [&](std::size_t b, std::size_t e) {
      for (std::size_t r = b; r < e; ++r) a.y[r] *= inv;
    });
    return a;
  }

  // D(y) = constant + b.y + sum_j min(0, u_j + (K^T y)_j): a lower bound for any y in the box.
  double DualValue(const std::vector<double>& y) const {
    const double by = SumChunks(p_.num_rows, [&](std::size_t begin, std::size_t end) {
      double s = 0.0;
      for (std::size_t r = begin; r < end; ++r) s += p_.b[r] * y[r];
      return s;
    });
    const double reduced = SumChunks(p_.num_cols, [&](std::size_t begin, std::size_t end) {
      double s = 0.0;
      for (std::size_t j = begin; j < end; ++j) {
        double g = p_.unary[j];
        for (std::uint32_t k = p_.col_offsets[j]; k < p_.col_offsets[j + 1]; ++k) {
          g += p_.col_signs[k] * y[p_.col_rows[k]];
        }
        s += std::min(0.0, g);
      }
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
           options_.pdhg_tolerance * std::max(1.0, std::abs(best_primal_));
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
    s.status = "optimal (tolerance " + std::to_string(options_.pdhg_tolerance) + ")";
    return s;
  }

  const ReducedEnergy& energy_;
  const LabelingOptions& options_;
  const RunContext& ctx_;
  SaddleProblem p_;
  std::vector<double> tau_;
  std::vector<double> sigma_;
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
