#pragma once
// What an LP backend returns: the column values of the LpModel it solved.

#include <cstdint>
#include <string>
#include <vector>

namespace linesurf::solver {

struct LpSolution {
  /// One value per LpModel column.
  std::vector<double> columns;
  /// LpModel::Evaluate(columns) as the backend computed it (objective_offset included).
  double objective = 0.0;
  /// "optimal" or the backend's word for a successful stop.
  std::string status;
  std::int64_t iterations = 0;
};

}  // namespace linesurf::solver
