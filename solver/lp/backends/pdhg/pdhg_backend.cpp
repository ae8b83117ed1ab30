#include "solver/lp/backends/pdhg/pdhg_backend.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <vector>

#include "engine/core/exception.h"
#include "engine/core/parallel.h"
#include "solver/lp/backends/fixed_chunks.h"
#include "solver/lp/backends/pdlp_restarts.h"
#include "solver/lp/backends/transpose_rows.h"

namespace linesurf::solver {
namespace {

constexpr const char* kPdhgBackendStage = "solve_labeling";
// Ruiz equilibration passes before the Pock-Chambolle scaling.
constexpr int kRuizPasses = 10;
// Step size factor: after Pock-Chambolle scaling (alpha = 1) ||A|| <= 1 (Schur test), so any
// eta < 1 is a valid PDHG step; 0.95 keeps a margin for rounding.
constexpr double kStepSize = 0.95;

struct SparseMatrix {
  std::size_t num_rows = 0;
  std::size_t num_cols = 0;
  std::vector<std::uint32_t> offsets;
  std::vector<std::uint32_t> columns;
  std::vector<double> values;

  // out = this * x (each entry a serial sum: deterministic); sum += out when given.
  void Multiply(const std::vector<double>& x, std::vector<double>& out,
                std::vector<double>* sum = nullptr) const {
    ForChunks(num_rows, [&](std::size_t begin, std::size_t end) {
      for (std::size_t r = begin; r < end; ++r) {
        double s = 0.0;
        for (std::uint32_t k = offsets[r]; k < offsets[r + 1]; ++k) s += values[k] * x[columns[k]];
        out[r] = s;
        if (sum != nullptr) (*sum)[r] += s;
      }
    });
  }
};

SparseMatrix Transpose(const SparseMatrix& a) {
  CompressedRows<double> columns =
      TransposeRows<double>(a.offsets, a.columns, a.values, a.num_cols);
  SparseMatrix t;
  t.num_rows = a.num_cols;
  t.num_cols = a.num_rows;
  t.offsets = std::move(columns.offsets);
  t.columns = std::move(columns.index);
  t.values = std::move(columns.value);
  return t;
}

// The LP in scaled form: A~ = diag(row_scale) A diag(col_scale), x = col_scale * x~,
// y = row_scale * y~.
struct ScaledLp {
  SparseMatrix a;
  SparseMatrix at;
  std::vector<double> row_scale;
  std::vector<double> col_scale;
  std::vector<double> cost;
  std::vector<double> col_lower;
  std::vector<double> col_upper;
  std::vector<double> row_lower;
  std::vector<double> row_upper;
};

// Multiplies row r of `a` by rs[r] and column j by cs[j] in place.
void ScaleMatrix(SparseMatrix& a, const std::vector<double>& rs, const std::vector<double>& cs) {
  ForChunks(a.num_rows, [&](std::size_t begin, std::size_t end) {
    for (std::size_t r = begin; r < end; ++r) {
      for (std::uint32_t k = a.offsets[r]; k < a.offsets[r + 1]; ++k) {
        a.values[k] *= rs[r] * cs[a.columns[k]];
      }
    }
  });
}

ScaledLp Scale(const LpModel& lp) {
  ScaledLp s;
  s.a.num_rows = lp.NumRows();
  s.a.num_cols = lp.NumColumns();
  s.a.offsets = lp.row_offsets;
  s.a.columns = lp.row_columns;
  s.a.values = lp.row_values;
  s.row_scale.assign(lp.NumRows(), 1.0);
  s.col_scale.assign(lp.NumColumns(), 1.0);
  std::vector<double> rs(lp.NumRows()), cs(lp.NumColumns());
  // Per-row and per-column norms of the current matrix: max (Ruiz) or sum (Pock-Chambolle).
  auto norms = [&](bool use_max) {
    std::fill(cs.begin(), cs.end(), 0.0);
    for (std::size_t r = 0; r < s.a.num_rows; ++r) {
      double row = 0.0;
      for (std::uint32_t k = s.a.offsets[r]; k < s.a.offsets[r + 1]; ++k) {
        const double v = std::abs(s.a.values[k]);
        double& col = cs[s.a.columns[k]];
        if (use_max) {
          row = std::max(row, v);
          col = std::max(col, v);
        } else {
          row += v;
          col += v;
        }
      }
      rs[r] = row;
    }
    for (double& v : rs) v = v > 0.0 ? 1.0 / std::sqrt(v) : 1.0;
    for (double& v : cs) v = v > 0.0 ? 1.0 / std::sqrt(v) : 1.0;
    ScaleMatrix(s.a, rs, cs);
    for (std::size_t r = 0; r < rs.size(); ++r) s.row_scale[r] *= rs[r];
    for (std::size_t j = 0; j < cs.size(); ++j) s.col_scale[j] *= cs[j];
  };
  for (int pass = 0; pass < kRuizPasses; ++pass) norms(true);
  norms(false);
  s.at = Transpose(s.a);
  const std::size_t n = lp.NumColumns();
  s.cost.resize(n);
  s.col_lower.resize(n);
  s.col_upper.resize(n);
  for (std::size_t j = 0; j < n; ++j) {
    s.cost[j] = lp.objective[j] * s.col_scale[j];
    s.col_lower[j] = lp.col_lower[j] / s.col_scale[j];
    s.col_upper[j] = lp.col_upper[j] / s.col_scale[j];
  }
  s.row_lower.resize(lp.NumRows());
  s.row_upper.resize(lp.NumRows());
  for (std::size_t r = 0; r < lp.NumRows(); ++r) {
    s.row_lower[r] = lp.row_lower[r] * s.row_scale[r];
    s.row_upper[r] = lp.row_upper[r] * s.row_scale[r];
  }
  return s;
}

double Norm2(const std::vector<double>& v) {
  return std::sqrt(SumChunks(v.size(), [&](std::size_t b, std::size_t e) {
    double s = 0.0;
    for (std::size_t i = b; i < e; ++i) s += v[i] * v[i];
    return s;
  }));
}

// Norm of the finite bounds (the "b" of the relative tolerances).
double BoundNorm(const std::vector<double>& lower, const std::vector<double>& upper) {
  double s = 0.0;
  for (std::size_t i = 0; i < lower.size(); ++i) {
    const double b = std::isfinite(lower[i]) ? lower[i] : (std::isfinite(upper[i]) ? upper[i] : 0.0);
    s += b * b;
  }
  return std::sqrt(s);
}

// Errors of a primal-dual point in the ORIGINAL (unscaled) space.
struct KktErrors {
  double primal_residual = 0.0;  // ||A x - proj_[l,u](A x)||
  double dual_residual = 0.0;    // ||c - A^T y - lambda||
  double primal_objective = 0.0;
  double dual_objective = 0.0;
  [[nodiscard]] double Gap() const { return std::abs(primal_objective - dual_objective); }
};

// x~, y~ with A~ x~ and A~^T y~ given; everything mapped back through the scales.
KktErrors ComputeErrors(const LpModel& lp, const ScaledLp& s, const std::vector<double>& x,
                        const std::vector<double>& y, const std::vector<double>& ax,
                        const std::vector<double>& aty) {
  KktErrors e;
  const std::size_t m = lp.NumRows(), n = lp.NumColumns();
  struct Partial {
    double res2 = 0.0, obj = 0.0;
  };
  // Rows: (A x)_r = ax~_r / row_scale_r; y_r = y~_r * row_scale_r.
  const double row_res2 = SumChunks(m, [&](std::size_t b, std::size_t end) {
    double acc = 0.0;
    for (std::size_t r = b; r < end; ++r) {
      const double v = ax[r] / s.row_scale[r];
      const double p = std::clamp(v, lp.row_lower[r], lp.row_upper[r]);
      acc += (v - p) * (v - p);
    }
    return acc;
  });
  const double row_dual = SumChunks(m, [&](std::size_t b, std::size_t end) {
    double acc = 0.0;
    for (std::size_t r = b; r < end; ++r) {
      const double yr = y[r] * s.row_scale[r];
      if (yr > 0.0 && std::isfinite(lp.row_lower[r])) acc += yr * lp.row_lower[r];
      if (yr < 0.0 && std::isfinite(lp.row_upper[r])) acc += yr * lp.row_upper[r];
    }
    return acc;
  });
  // Columns: reduced cost rc = c - A^T y = c - aty~ / col_scale; x = x~ * col_scale.
  double col_res2 = 0.0, col_dual = 0.0, primal = 0.0;
  {
    const std::size_t num_chunks = (n + kFixedChunk - 1) / kFixedChunk;
    std::vector<Partial> res(num_chunks), dual(num_chunks);
    ForChunks(n, [&](std::size_t b, std::size_t end) {
      Partial pr, du;
      for (std::size_t j = b; j < end; ++j) {
        const double xj = x[j] * s.col_scale[j];
        pr.obj += lp.objective[j] * xj;
        const double rc = lp.objective[j] - aty[j] / s.col_scale[j];
        const bool lower_finite = std::isfinite(lp.col_lower[j]);
        const bool upper_finite = std::isfinite(lp.col_upper[j]);
        double residual = rc;
        if (rc > 0.0 && lower_finite) {
          du.obj += rc * lp.col_lower[j];
          residual = 0.0;
        } else if (rc < 0.0 && upper_finite) {
          du.obj += rc * lp.col_upper[j];
          residual = 0.0;
        }
        pr.res2 += residual * residual;
      }
      res[b / kFixedChunk] = pr;
      dual[b / kFixedChunk] = du;
    });
    for (std::size_t c = 0; c < num_chunks; ++c) {
      col_res2 += res[c].res2;
      primal += res[c].obj;
      col_dual += dual[c].obj;
    }
  }
  e.primal_residual = std::sqrt(row_res2);
  e.dual_residual = std::sqrt(col_res2);
  e.primal_objective = primal + lp.objective_offset;
  e.dual_objective = row_dual + col_dual + lp.objective_offset;
  return e;
}

// The PDLP restart merit: KKT error weighted by the primal weight.
double Merit(const KktErrors& e, double omega) {
  return std::sqrt(omega * omega * e.primal_residual * e.primal_residual +
                   e.dual_residual * e.dual_residual / (omega * omega) + e.Gap() * e.Gap());
}


class Pdhg {
 public:
  Pdhg(const LpModel& lp, const PdhgOptions& options, const RunContext& ctx)
      : lp_(lp), options_(options), ctx_(ctx), s_(Scale(lp)) {}

  /// time_limit_seconds: 0 = none.
  LpSolution Run(double time_limit_seconds) {
    const auto start = std::chrono::steady_clock::now();
    Iterates v = Initial();
    const double cost_norm = Norm2(s_.cost);
    const double bound_norm = BoundNorm(s_.row_lower, s_.row_upper);
    double omega = cost_norm > 0.0 && bound_norm > 0.0 ? cost_norm / bound_norm : 1.0;
    const double c_norm = Norm2(lp_.objective);
    const double b_norm = BoundNorm(lp_.row_lower, lp_.row_upper);
    const double eps = options_.tolerance;

    std::int64_t since_restart = 0;
    double merit_at_restart = -1.0;
    double last_candidate_merit = std::numeric_limits<double>::infinity();
    for (std::int64_t it = 1; it <= options_.max_iterations; ++it) {
      Step(kStepSize / omega, kStepSize * omega, v);
      ++since_restart;
      // Cancellation is polled every iteration (one iteration of a large LP takes 50-150 ms).
      LINESURF_THROW_IF(
          ctx_.ShouldStop(), kCancelled, kPdhgBackendStage, "pdhg cancelled by the host");
      if (it % kRestartCheckPeriod != 0 && it != options_.max_iterations) continue;

      const double elapsed =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      LINESURF_THROW_IF(time_limit_seconds > 0.0 && elapsed > time_limit_seconds,
                        kSolverFailed,
                        kPdhgBackendStage,
                        "pdhg stopped at the time limit of " << time_limit_seconds << " s after "
                                                             << it << " iterations");
      Average(since_restart, v);
      const KktErrors current = ComputeErrors(lp_, s_, v.x, v.y, v.ax, v.aty);
      const KktErrors average = ComputeErrors(lp_, s_, v.x_avg, v.y_avg, v.ax_avg, v.aty_avg);
      for (const auto* candidate : {&current, &average}) {
        if (Converged(*candidate, eps, b_norm, c_norm)) {
          const bool is_avg = candidate == &average;
          return Finish(is_avg ? v.x_avg : v.x, is_avg ? v.y_avg : v.y, it);
        }
      }
      const double merit_current = Merit(current, omega);
      const double merit_average = Merit(average, omega);
      const bool use_average = merit_average < merit_current;
      const double candidate_merit = std::min(merit_current, merit_average);
      if (merit_at_restart < 0.0) merit_at_restart = candidate_merit;
      const bool restart =
          ShouldRestart(candidate_merit, merit_at_restart, last_candidate_merit, since_restart, it);
      last_candidate_merit = candidate_merit;
      if (!restart) continue;
      omega = Restart(use_average, omega, v);
      merit_at_restart = Merit(use_average ? average : current, omega);
      last_candidate_merit = std::numeric_limits<double>::infinity();
      since_restart = 0;
    }
    ThrowError(ErrorCode::kSolverFailed,
               kPdhgBackendStage,
               "pdhg reached the iteration limit of " + std::to_string(options_.max_iterations) +
                   " without meeting tolerance " + std::to_string(eps));
  }

 private:
  /// The scaled iterates (with A x and A^T y), their sums and averages since the last restart,
  /// and the point of the last restart.
  struct Iterates {
    std::vector<double> x, y, ax, aty;
    std::vector<double> x_next, y_next, ax_next;
    std::vector<double> x_sum, y_sum, ax_sum, aty_sum;
    std::vector<double> x_avg, y_avg, ax_avg, aty_avg;
    std::vector<double> x_restart, y_restart;
  };

  /// x at the bound nearest 0, y = 0.
  [[nodiscard]] Iterates Initial() const {
    const std::size_t m = lp_.NumRows(), n = lp_.NumColumns();
    Iterates v;
    v.x.resize(n);
    v.y.assign(m, 0.0);
    v.ax.resize(m);
    v.aty.assign(n, 0.0);
    for (std::size_t j = 0; j < n; ++j) v.x[j] = std::clamp(0.0, s_.col_lower[j], s_.col_upper[j]);
    s_.a.Multiply(v.x, v.ax);
    v.x_next.resize(n);
    v.y_next.resize(m);
    v.ax_next.resize(m);
    v.x_sum.assign(n, 0.0);
    v.y_sum.assign(m, 0.0);
    v.ax_sum.assign(m, 0.0);
    v.aty_sum.assign(n, 0.0);
    v.x_avg.resize(n);
    v.y_avg.resize(m);
    v.ax_avg.resize(m);
    v.aty_avg.resize(n);
    v.x_restart = v.x;
    v.y_restart = v.y;
    return v;
  }

  /// One PDHG iteration with primal step tau and dual step sigma, added to the sums.
  void Step(double tau, double sigma, Iterates& v) const {
    const std::size_t m = lp_.NumRows(), n = lp_.NumColumns();
    // Primal step: x+ = proj(x - tau (c - A^T y)).
    ForChunks(n, [&](std::size_t b, std::size_t e) {
      for (std::size_t j = b; j < e; ++j) {
        v.x_next[j] =
            std::clamp(v.x[j] - tau * (s_.cost[j] - v.aty[j]), s_.col_lower[j], s_.col_upper[j]);
        v.x_sum[j] += v.x_next[j];
      }
    });
    s_.a.Multiply(v.x_next, v.ax_next, &v.ax_sum);
    // Dual step on the extrapolated point: v = y - sigma A(2x+ - x),
    // y+ = v + sigma proj_[l,u](-v / sigma).
    ForChunks(m, [&](std::size_t b, std::size_t e) {
      for (std::size_t r = b; r < e; ++r) {
        const double w = v.y[r] - sigma * (2.0 * v.ax_next[r] - v.ax[r]);
        v.y_next[r] = w + sigma * std::clamp(-w / sigma, s_.row_lower[r], s_.row_upper[r]);
        v.y_sum[r] += v.y_next[r];
      }
    });
    v.x.swap(v.x_next);
    v.y.swap(v.y_next);
    v.ax.swap(v.ax_next);
    s_.at.Multiply(v.y, v.aty, &v.aty_sum);
  }

  /// The averages of the `count` iterates since the last restart.
  void Average(std::int64_t count, Iterates& v) const {
    const std::size_t m = lp_.NumRows(), n = lp_.NumColumns();
    const double inv = 1.0 / static_cast<double>(count);
    ForChunks(n, [&](std::size_t b, std::size_t e) {
      for (std::size_t j = b; j < e; ++j) {
        v.x_avg[j] = v.x_sum[j] * inv;
        v.aty_avg[j] = v.aty_sum[j] * inv;
      }
    });
    ForChunks(m, [&](std::size_t b, std::size_t e) {
      for (std::size_t r = b; r < e; ++r) {
        v.y_avg[r] = v.y_sum[r] * inv;
        v.ax_avg[r] = v.ax_sum[r] * inv;
      }
    });
  }

  /// Restarts from the average (`use_average`) or the current point; returns the primal weight
  /// that balances the primal and dual movement since the last restart.
  static double Restart(bool use_average, double omega, Iterates& v) {
    if (use_average) {
      v.x.swap(v.x_avg);
      v.y.swap(v.y_avg);
      v.ax.swap(v.ax_avg);
      v.aty.swap(v.aty_avg);
    }
    const double weight = SmoothedPrimalWeight(
        omega, ChunkedDistance(v.x, v.x_restart), ChunkedDistance(v.y, v.y_restart));
    v.x_restart = v.x;
    v.y_restart = v.y;
    std::fill(v.x_sum.begin(), v.x_sum.end(), 0.0);
    std::fill(v.y_sum.begin(), v.y_sum.end(), 0.0);
    std::fill(v.ax_sum.begin(), v.ax_sum.end(), 0.0);
    std::fill(v.aty_sum.begin(), v.aty_sum.end(), 0.0);
    return weight;
  }

  static bool Converged(const KktErrors& e, double eps, double b_norm, double c_norm) {
    return e.primal_residual <= eps * (1.0 + b_norm) && e.dual_residual <= eps * (1.0 + c_norm) &&
           e.Gap() <= eps * (1.0 + std::abs(e.primal_objective) + std::abs(e.dual_objective));
  }

  LpSolution Finish(const std::vector<double>& x_scaled, const std::vector<double>& y_scaled,
                    std::int64_t iterations) const {
    LpSolution solution;
    solution.columns.resize(x_scaled.size());
    for (std::size_t j = 0; j < x_scaled.size(); ++j) {
      solution.columns[j] = std::clamp(x_scaled[j] * s_.col_scale[j], lp_.col_lower[j], lp_.col_upper[j]);
    }
    solution.row_duals.resize(y_scaled.size());
    for (std::size_t r = 0; r < y_scaled.size(); ++r) {
      solution.row_duals[r] = y_scaled[r] * s_.row_scale[r];
    }
    solution.objective = lp_.Evaluate(solution.columns);
    solution.status = "optimal (tolerance " + std::to_string(options_.tolerance) + ")";
    solution.iterations = iterations;
    return solution;
  }

  const LpModel& lp_;
  const PdhgOptions& options_;
  const RunContext& ctx_;
  ScaledLp s_;
};

}  // namespace

LpSolution SolveLpWithPdhg(const LpModel& lp,
                           const PdhgOptions& options,
                           double time_limit_seconds,
                           const RunContext& ctx) {
  if (lp.NumColumns() == 0) {
    LpSolution solution;
    solution.objective = lp.objective_offset;
    solution.status = "optimal";
    return solution;
  }
  return RunInArena(ctx, [&] { return Pdhg(lp, options, ctx).Run(time_limit_seconds); });
}

}  // namespace linesurf::solver
