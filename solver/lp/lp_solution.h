#pragma once
// What an LP backend returns: the column values of the LpModel it solved.

#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace linesurf::solver {

struct LpSolution {
  /// One value per LpModel column.
  std::vector<double> columns;
  /// LpModel::Evaluate(columns) as the backend computed it (objective_offset included).
  double objective = 0.0;
  /// A proven lower bound on the optimum of the problem the backend solved (the LP for Clp, the
  /// integer program for Cbc); -infinity when the backend proves none.
  double lower_bound = -std::numeric_limits<double>::infinity();
  /// One multiplier per LpModel row (sign: y >= 0 on a row's lower side), from backends that
  /// keep a dual point (pdhg); empty otherwise.
  std::vector<double> row_duals;
  /// "optimal" or the backend's word for a successful stop.
  std::string status;
  std::int64_t iterations = 0;
};

}  // namespace linesurf::solver
