#pragma once
// A linear program as plain data, built in canonical order (columns by element id, rows by
// constraint kind then id) so that every backend sees the same model for any thread count:
//   minimise objective . x  subject to  row_lower <= A x <= row_upper,  col_lower <= x <= col_upper.

#include <cstdint>
#include <limits>
#include <span>
#include <vector>

namespace linesurf::solver {

inline constexpr double kLpInfinity = std::numeric_limits<double>::infinity();

struct LpModel {
  /// Constant added to objective . x so that LP objective values equal the energy they model
  /// (e.g. the terms of fixed cells folded out by BuildLp).
  double objective_offset = 0.0;
  std::vector<double> objective;
  std::vector<double> col_lower;
  std::vector<double> col_upper;
  std::vector<double> row_lower;
  std::vector<double> row_upper;
  /// Row r has entries [row_offsets[r], row_offsets[r+1]) of row_columns / row_values.
  std::vector<std::uint32_t> row_offsets{0};
  std::vector<std::uint32_t> row_columns;
  std::vector<double> row_values;

  [[nodiscard]] std::size_t NumColumns() const { return objective.size(); }
  [[nodiscard]] std::size_t NumRows() const { return row_lower.size(); }
  [[nodiscard]] std::size_t NumNonzeros() const { return row_values.size(); }

  /// Adds a column and returns its index.
  std::uint32_t AddColumn(double cost, double lower, double upper);
  /// Adds the row lower <= sum values[i] * x[columns[i]] <= upper.
  void AddRow(std::span<const std::uint32_t> columns, std::span<const double> values, double lower,
              double upper);
  /// Objective value of `x` (objective_offset included).
  [[nodiscard]] double Evaluate(std::span<const double> x) const;
  /// Largest violation of any row or bound by `x` (0 when feasible).
  [[nodiscard]] double MaxViolation(std::span<const double> x) const;
};

}  // namespace linesurf::solver
