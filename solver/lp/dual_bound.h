#pragma once
// A lower bound on an LP's optimum from any row multipliers (Lagrangian duality), so an
// approximate dual point (pdhg's) still proves a bound. The multipliers are first projected on
// their sign constraints; a column with an infinite bound whose reduced cost has the wrong sign
// would make the bound -infinity, so the positive contributions of its rows are scaled down
// until its reduced cost vanishes. Valid for any multipliers, tight at an optimal dual.

#include "solver/lp/lp_model.h"

#include <span>

namespace linesurf::solver {

/// min over the box of c.x - y.(A x - bound) for the repaired y; -infinity when no repair
/// helps. `row_duals` has one entry per row.
[[nodiscard]] double LagrangianBound(const LpModel& lp, std::span<const double> row_duals);

}  // namespace linesurf::solver
