#include "solver/lp/backends/pdhg_energy/pdhg_energy_backend.h"

#include "engine/core/exception.h"
#include "engine/core/parallel.h"
#include "solver/lp/backends/fixed_chunks.h"
#include "solver/lp/backends/pdlp_restarts.h"
#include "solver/lp/backends/transpose_rows.h"

#include <algorithm>
#include <bit>
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

// An entry of K is +-1: it is stored as the index of its column (in a row) or row (in a
// column) with the sign in the top bit, one word where an index and a sign byte took five.
constexpr std::uint32_t kNegativeEntry = 0x80000000u;

[[nodiscard]] inline std::uint32_t EntryIndex(std::uint32_t entry) {
  return entry & ~kNegativeEntry;
}

// entry * v, exactly: +v or -v (the entry's sign bit moved onto v's, without a branch on
// signs that follow no pattern).
[[nodiscard]] inline double EntryTimes(std::uint32_t entry, double v) {
  const std::uint64_t sign = static_cast<std::uint64_t>(entry & kNegativeEntry) << 32;
  return std::bit_cast<double>(std::bit_cast<std::uint64_t>(v) ^ sign);
}

// Multipliers, their bounds and the reflected columns 2 T(x) - x are stored in single precision
// and computed in double: they are most of what an iteration streams and gathers (22 % less time
// on Andalusian), the relaxation is only needed to pdhg_energy_tolerance, and every stored
// multiplier stays inside its box, so each D(y) is still a lower bound.
using Stored = float;

// The largest float not above a weight (>= 0): a multiplier box that is never wider than the
// term's.
[[nodiscard]] inline Stored BoundNotAbove(double weight) {
  const Stored w = static_cast<Stored>(weight);
  return static_cast<double>(w) > weight ? std::nextafter(w, Stored{0}) : w;
}

// K (rows: pairs, structural groups, parity groups, in that order) with its transpose, in signed
// entries. Per row only the multiplier bound `upper` (the weight) is stored: the offset b (0 for
// a pair, 1 for a structural group, the constant of a parity group) and the lower bound (-upper,
// 0 for a structural group) follow from the row's kind, which keeps the memory an iteration
// streams through small.
struct SaddleProblem {
  std::size_t num_rows = 0;
  std::size_t num_cols = 0;
  std::size_t first_structural_row = 0;
  std::size_t first_parity_row = 0;
  std::vector<std::uint32_t> row_offsets{0};
  std::vector<std::uint32_t> row_entries;
  std::vector<std::uint32_t> col_offsets;
  std::vector<std::uint32_t> col_entries;
  std::vector<Stored> upper;
  std::vector<std::int32_t> parity_constants;
  std::vector<double> unary;
  double constant = 0.0;

  void AddEntry(std::uint32_t column, int sign) {
    row_entries.push_back(sign < 0 ? column | kNegativeEntry : column);
  }

  // Closes the row whose entries were just appended.
  void AddRow(double weight) {
    row_offsets.push_back(static_cast<std::uint32_t>(row_entries.size()));
    upper.push_back(BoundNotAbove(weight));
  }

  // Entries of column j.
  [[nodiscard]] std::uint32_t ColumnCount(std::size_t j) const {
    return col_offsets[j + 1] - col_offsets[j];
  }

  // b of row r.
  [[nodiscard]] double Offset(std::size_t r) const {
    if (r < first_structural_row) return 0.0;
    if (r < first_parity_row) return 1.0;
    return static_cast<double>(parity_constants[r - first_parity_row]);
  }

  // The lower multiplier bound of row r.
  [[nodiscard]] double Lower(std::size_t r) const {
    return r >= first_structural_row && r < first_parity_row ? 0.0 : -static_cast<double>(upper[r]);
  }
};

SaddleProblem BuildSaddle(const ReducedEnergy& e) {
  const std::size_t entries =
      2 * e.pairs.size() + e.structural_columns.size() + e.parity_columns.size();
  const std::size_t rows = e.pairs.size() + e.structural_weights.size() + e.parity_weights.size();
  LINESURF_THROW_IF(
      std::max({entries, rows, e.NumFree()}) >= kNegativeEntry,
      kResourceExhausted,
      kPdhgEnergyStage,
      "energy too large for 31-bit indices: " << entries << " term entries, " << rows << " terms");
  SaddleProblem p;
  p.num_cols = e.NumFree();
  p.unary = e.unary;
  p.constant = e.constant;
  for (const ReducedEnergy::Pair& pair : e.pairs) {
    p.AddEntry(pair.a, 1);
    p.AddEntry(pair.b, -1);
    p.AddRow(pair.weight);
  }
  p.first_structural_row = p.upper.size();
  for (std::size_t g = 0; g < e.structural_weights.size(); ++g) {
    for (std::uint32_t k = e.structural_offsets[g]; k < e.structural_offsets[g + 1]; ++k) {
      p.AddEntry(e.structural_columns[k], -1);
    }
    p.AddRow(e.structural_weights[g]);
  }
  p.first_parity_row = p.upper.size();
  for (std::size_t g = 0; g < e.parity_weights.size(); ++g) {
    for (std::uint32_t k = e.parity_offsets[g]; k < e.parity_offsets[g + 1]; ++k) {
      p.AddEntry(e.parity_columns[k], e.parity_signs[k]);
    }
    p.AddRow(e.parity_weights[g]);
  }
  p.parity_constants = e.parity_constants;
  p.num_rows = p.upper.size();
  std::vector<std::uint32_t> columns(p.row_entries.size());
  std::vector<std::uint32_t> signs(p.row_entries.size());
  for (std::size_t k = 0; k < p.row_entries.size(); ++k) {
    columns[k] = EntryIndex(p.row_entries[k]);
    signs[k] = p.row_entries[k] & kNegativeEntry;
  }
  CompressedRows<std::uint32_t> transposed =
      TransposeRows<std::uint32_t>(p.row_offsets, columns, signs, p.num_cols);
  p.col_offsets = std::move(transposed.offsets);
  p.col_entries = std::move(transposed.index);
  for (std::size_t k = 0; k < p.col_entries.size(); ++k) p.col_entries[k] |= transposed.value[k];
  return p;
}

// A primal-dual point.
struct Point {
  std::vector<double> x;
  std::vector<Stored> y;
};

class EnergyPdhg {
 public:
  EnergyPdhg(const ReducedEnergy& energy, const PdhgEnergyOptions& options, const RunContext& ctx)
      : energy_(energy), options_(options), ctx_(ctx), p_(BuildSaddle(energy)) {}

  /// time_limit_seconds: 0 = none.
  LpSolution Run(double time_limit_seconds) {
    const auto start = std::chrono::steady_clock::now();
    const std::size_t n = p_.num_cols, m = p_.num_rows;
    // Preconditioned steps (Pock & Chambolle 2011, alpha = 1) for the multipliers scaled to
    // their boxes, eta_r = y_r / w_r: that saddle's matrix W K has entries +-w_r, so a column's
    // step is 1 / (sum of its terms' weights) and a row's is 1 / (w_r entries), which in y is
    // w_r / entries. Every term's multiplier then crosses its box in about as many iterations
    // whatever its weight (Andalusian: 3,072 iterations where steps of 1 / entries took 9,536).
    std::uint32_t max_count = 0;
    for (std::size_t r = 0; r < m; ++r) {
      max_count = std::max(max_count, p_.row_offsets[r + 1] - p_.row_offsets[r]);
    }
    dual_step_by_count_.assign(max_count + 1, 0.0);
    for (std::uint32_t count = 1; count <= max_count; ++count) {
      dual_step_by_count_[count] = kStepFactor / count;
    }
    primal_step_.assign(n, 0.0);
    for (std::size_t j = 0; j < n; ++j) {
      double weights = 0.0;
      for (std::uint32_t k = p_.col_offsets[j]; k < p_.col_offsets[j + 1]; ++k) {
        weights += static_cast<double>(p_.upper[EntryIndex(p_.col_entries[k])]);
      }
      // A column whose terms all weigh 0 follows its unary coefficient at a unit step.
      primal_step_[j] = kStepFactor / (weights > 0.0 ? weights : 1.0);
    }
    // The restart point z_0. A column in no term: its optimum is read off its unary coefficient.
    Point anchor{std::vector<double>(n, 0.0), std::vector<Stored>(m, Stored{0})};
    for (std::size_t j = 0; j < n; ++j) {
      if (p_.ColumnCount(j) == 0) anchor.x[j] = energy_.unary[j] < 0.0 ? 1.0 : 0.0;
    }
    Point step = anchor;  // T(z): the PDHG step, a feasible point
    // The Halpern point z: its multipliers; its x is never stored (Iterate).
    std::vector<Stored> z_y = anchor.y;
    std::vector<Stored> reflected(n, Stored{0});
    double weight = 1.0;
    double restart_gap = -1.0;  // set at the first check
    double previous_gap = std::numeric_limits<double>::infinity();
    std::int64_t since_restart = 0;
    best_primal_ = std::numeric_limits<double>::infinity();
    best_dual_ = -std::numeric_limits<double>::infinity();
    best_x_ = anchor.x;

    for (std::int64_t it = 1; it <= options_.max_iterations; ++it) {
      // T's point is read only at the checks: between them it is not stored.
      const bool check = it % kRestartCheckPeriod == 0 || it == options_.max_iterations;
      Iterate(z_y, anchor, since_restart, weight, check, step, reflected);
      ++since_restart;
      LINESURF_THROW_IF(
          ctx_.ShouldStop(), kCancelled, kPdhgEnergyStage, "pdhg-energy cancelled by the host");
      if (!check) continue;

      const double elapsed =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      LINESURF_THROW_IF(time_limit_seconds > 0.0 && elapsed > time_limit_seconds,
                        kSolverFailed,
                        kPdhgEnergyStage,
                        "pdhg-energy stopped at the time limit of "
                            << time_limit_seconds << " s after " << it << " iterations");
      // The merit is the duality gap at the step's point (feasible; both sets are bounded, so the
      // gap is finite).
      const double gap = Gap(step);
      if (Converged()) return Solution(it);
      if (restart_gap < 0.0) restart_gap = gap;
      const bool restart = ShouldRestart(gap, restart_gap, previous_gap, since_restart, it);
      previous_gap = gap;
      if (!restart) continue;
      // Restart the Halpern sequence at the step's point, with a rebalanced primal weight: the
      // multipliers' distance is taken in eta = y / w, where the steps are preconditioned.
      weight = SmoothedPrimalWeight(weight,
                                    ChunkedDistance(step.x, anchor.x),
                                    ChunkedDistance(step.y, anchor.y, [this](std::size_t r) {
                                      return static_cast<double>(p_.upper[r]);
                                    }));
      anchor = step;
      z_y = step.y;
      restart_gap = gap;
      previous_gap = std::numeric_limits<double>::infinity();
      since_restart = 0;
      ++restarts_;
    }
    ThrowError(ErrorCode::kSolverFailed,
               kPdhgEnergyStage,
               "pdhg-energy reached its iteration limit of " +
                   std::to_string(options_.max_iterations) + " with the gap " +
                   std::to_string(best_primal_ - best_dual_) + " above tolerance " +
                   std::to_string(options_.tolerance));
  }

 private:
  // One iteration: the PDHG operator T, x+ = clip(x - tau/w (u + K^T y)), then
  // y+ = clip(y + w sigma (K (2 x+ - x) + b)), written to `step`; and the reflected Halpern
  // iteration (Lu & Yang 2024, "Restarted Halpern PDHG for linear programming"),
  // z <- lambda_k (2 T(z) - z) + (1 - lambda_k) z_0, k the iterations since the restart, z_0 the
  // restart point. A row's z is updated in place right after its own step. z's x is never
  // stored: the iteration keeps 2 T(x) - x in `reflected` (the rows read it), and the next
  // iteration's column step forms its x from it and z_0 (z_0 itself right after a restart),
  // which saves a pass over the columns. T(z) itself is written to `step` only when `keep_step`
  // (the iterations that check the gap). On the block engine's Andalusian energy 12,864
  // iterations where PDLP's restarts to the average took 16,128 (docs/design/lp_backend.md,
  // "Energy pdhg").
  void Iterate(std::vector<Stored>& z_y,
               const Point& anchor,
               std::int64_t k,
               double weight,
               bool keep_step,
               Point& step,
               std::vector<Stored>& reflected) const {
    const double lambda = HalpernWeight(k);
    const double previous = k == 0 ? 0.0 : HalpernWeight(k - 1);
    ForChunks(
        p_.num_cols,
        [&](std::size_t begin, std::size_t end) {
          for (std::size_t j = begin; j < end; ++j) {
            const double z_x =
                k == 0 ? anchor.x[j] : previous * reflected[j] + (1.0 - previous) * anchor.x[j];
            const std::uint32_t count = p_.ColumnCount(j);
            const double x =
                count == 0
                    ? z_x
                    : std::clamp(z_x - primal_step_[j] / weight * ReducedCost(j, z_y), 0.0, 1.0);
            if (keep_step) step.x[j] = x;
            reflected[j] = static_cast<Stored>(2.0 * x - z_x);
          }
        },
        kElementwiseChunk);
    ForChunks(
        p_.num_rows,
        [&](std::size_t begin, std::size_t end) {
          for (std::size_t r = begin; r < end; ++r) {
            const std::uint32_t first = p_.row_offsets[r], last = p_.row_offsets[r + 1];
            double kx = p_.Offset(r);
            for (std::uint32_t i = first; i < last; ++i) {
              kx += EntryTimes(p_.row_entries[i],
                               static_cast<double>(reflected[EntryIndex(p_.row_entries[i])]));
            }
            const double y = std::clamp(z_y[r] + weight * dual_step_by_count_[last - first] *
                                                     static_cast<double>(p_.upper[r]) * kx,
                                        p_.Lower(r),
                                        static_cast<double>(p_.upper[r]));
            if (keep_step) step.y[r] = static_cast<Stored>(y);
            z_y[r] =
                static_cast<Stored>(lambda * (2.0 * y - z_y[r]) + (1.0 - lambda) * anchor.y[r]);
          }
        },
        kElementwiseChunk);
  }

  // The Halpern weight lambda_k = (k + 1) / (k + 2).
  static double HalpernWeight(std::int64_t k) {
    return (static_cast<double>(k) + 1.0) / (static_cast<double>(k) + 2.0);
  }

  // (u + K^T y)_j: the primal gradient of column j, the reduced cost in the dual.
  double ReducedCost(std::size_t j, const std::vector<Stored>& y) const {
    double g = p_.unary[j];
    for (std::uint32_t k = p_.col_offsets[j]; k < p_.col_offsets[j + 1]; ++k) {
      g += EntryTimes(p_.col_entries[k], static_cast<double>(y[EntryIndex(p_.col_entries[k])]));
    }
    return g;
  }

  // D(y) = constant + b.y + sum_j min(0, u_j + (K^T y)_j): a lower bound for any y in the box.
  double DualValue(const std::vector<Stored>& y) const {
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
    return best_primal_ - best_dual_ <= options_.tolerance * std::max(1.0, std::abs(best_primal_));
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
    s.status = "optimal (tolerance " + std::to_string(options_.tolerance) + ")";
    return s;
  }

  const ReducedEnergy& energy_;
  const PdhgEnergyOptions& options_;
  const RunContext& ctx_;
  SaddleProblem p_;
  // A row's step with that many entries, before its weight (0: none); each column's step.
  std::vector<double> dual_step_by_count_;
  std::vector<double> primal_step_;
  double best_primal_ = 0.0;
  double best_dual_ = 0.0;
  std::vector<double> best_x_;
  std::int64_t restarts_ = 0;
};

}  // namespace

LpSolution SolveEnergyWithPdhg(const ReducedEnergy& energy,
                               const PdhgEnergyOptions& options,
                               double time_limit_seconds,
                               const RunContext& ctx) {
  return RunInArena(ctx, [&] { return EnergyPdhg(energy, options, ctx).Run(time_limit_seconds); });
}

}  // namespace linesurf::solver
