#include "solver/lp/dual_bound.h"

#include "engine/core/exception.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace linesurf::solver {
namespace {

// y_r may be > 0 only where row r has a finite lower side, < 0 only with a finite upper side.
double Project(double y, double lower, double upper) {
  if (y > 0.0 && !std::isfinite(lower)) return 0.0;
  if (y < 0.0 && !std::isfinite(upper)) return 0.0;
  return y;
}

// A column whose reduced cost d would send the box minimum to -infinity.
bool Unbounded(double d, double lower, double upper) {
  return (d < 0.0 && !std::isfinite(upper)) || (d > 0.0 && !std::isfinite(lower));
}

}  // namespace

double LagrangianBound(const LpModel& lp, std::span<const double> row_duals) {
  LINESURF_ASSERT(row_duals.size() == lp.NumRows());
  const std::size_t m = lp.NumRows(), n = lp.NumColumns();
  std::vector<double> y(m);
  for (std::size_t r = 0; r < m; ++r)
    y[r] = Project(row_duals[r], lp.row_lower[r], lp.row_upper[r]);
  // Reduced costs d = c - A^T y, and the rows of each column (transpose).
  std::vector<double> d(lp.objective);
  std::vector<std::uint32_t> col_offsets(n + 1, 0), col_rows(lp.NumNonzeros());
  for (std::size_t r = 0; r < m; ++r) {
    for (std::uint32_t k = lp.row_offsets[r]; k < lp.row_offsets[r + 1]; ++k) {
      d[lp.row_columns[k]] -= lp.row_values[k] * y[r];
      ++col_offsets[lp.row_columns[k] + 1];
    }
  }
  for (std::size_t j = 0; j < n; ++j) col_offsets[j + 1] += col_offsets[j];
  std::vector<std::uint32_t> next(col_offsets.begin(), col_offsets.end() - 1);
  for (std::size_t r = 0; r < m; ++r) {
    for (std::uint32_t k = lp.row_offsets[r]; k < lp.row_offsets[r + 1]; ++k) {
      col_rows[next[lp.row_columns[k]]++] = static_cast<std::uint32_t>(r);
    }
  }
  const auto coefficient = [&](std::size_t r, std::size_t j) {
    for (std::uint32_t k = lp.row_offsets[r]; k < lp.row_offsets[r + 1]; ++k) {
      if (lp.row_columns[k] == j) return lp.row_values[k];
    }
    return 0.0;
  };
  // Repair, column by column: scale the rows pushing d_j the wrong way so that d_j = 0.
  for (std::size_t j = 0; j < n; ++j) {
    if (!Unbounded(d[j], lp.col_lower[j], lp.col_upper[j])) continue;
    const double sign = d[j] < 0.0 ? 1.0 : -1.0;  // rows with sign * a_rj y_r > 0 push d_j
    double push = 0.0;
    for (std::uint32_t k = col_offsets[j]; k < col_offsets[j + 1]; ++k) {
      const std::size_t r = col_rows[k];
      push += std::max(0.0, sign * coefficient(r, j) * y[r]);
    }
    const double excess = std::abs(d[j]);
    if (!(push >= excess)) return -kLpInfinity;
    const double keep = 1.0 - excess / push;
    for (std::uint32_t k = col_offsets[j]; k < col_offsets[j + 1]; ++k) {
      const std::size_t r = col_rows[k];
      if (!(sign * coefficient(r, j) * y[r] > 0.0)) continue;
      const double change = y[r] * (keep - 1.0);
      y[r] += change;
      for (std::uint32_t q = lp.row_offsets[r]; q < lp.row_offsets[r + 1]; ++q) {
        d[lp.row_columns[q]] -= lp.row_values[q] * change;
      }
    }
    d[j] = 0.0;  // exactly, not up to the rounding of the updates above
  }
  double bound = lp.objective_offset;
  for (std::size_t r = 0; r < m; ++r) {
    if (y[r] > 0.0) bound += y[r] * lp.row_lower[r];
    if (y[r] < 0.0) bound += y[r] * lp.row_upper[r];
  }
  for (std::size_t j = 0; j < n; ++j) {
    if (d[j] == 0.0) continue;
    if (Unbounded(d[j], lp.col_lower[j], lp.col_upper[j])) return -kLpInfinity;
    bound += d[j] > 0.0 ? d[j] * lp.col_lower[j] : d[j] * lp.col_upper[j];
  }
  return bound;
}

}  // namespace linesurf::solver
