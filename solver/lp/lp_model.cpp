#include "solver/lp/lp_model.h"

#include <algorithm>

#include "engine/core/exception.h"

namespace linesurf::solver {

std::uint32_t LpModel::AddColumn(double cost, double lower, double upper) {
  objective.push_back(cost);
  col_lower.push_back(lower);
  col_upper.push_back(upper);
  return static_cast<std::uint32_t>(objective.size() - 1);
}

void LpModel::AddRow(std::span<const std::uint32_t> columns, std::span<const double> values,
                     double lower, double upper) {
  LINESURF_ASSERT(columns.size() == values.size());
  row_columns.insert(row_columns.end(), columns.begin(), columns.end());
  row_values.insert(row_values.end(), values.begin(), values.end());
  row_offsets.push_back(static_cast<std::uint32_t>(row_columns.size()));
  row_lower.push_back(lower);
  row_upper.push_back(upper);
}

double LpModel::Evaluate(std::span<const double> x) const {
  double value = objective_offset;
  for (std::size_t j = 0; j < objective.size(); ++j) value += objective[j] * x[j];
  return value;
}

double LpModel::MaxViolation(std::span<const double> x) const {
  double worst = 0.0;
  for (std::size_t j = 0; j < objective.size(); ++j) {
    worst = std::max({worst, col_lower[j] - x[j], x[j] - col_upper[j]});
  }
  for (std::size_t r = 0; r < row_lower.size(); ++r) {
    double ax = 0.0;
    for (std::uint32_t k = row_offsets[r]; k < row_offsets[r + 1]; ++k) {
      ax += row_values[k] * x[row_columns[k]];
    }
    worst = std::max({worst, row_lower[r] - ax, ax - row_upper[r]});
  }
  return worst;
}

}  // namespace linesurf::solver
