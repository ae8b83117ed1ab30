#include "solver/lp/backends/pdhg_energy/pdhg_energy_backend.h"

#include <gtest/gtest.h>

namespace linesurf::solver {
namespace {

// The multipliers are kept in single precision: a weight that is not a float (0.1 rounds up to
// 0.100000001) must not widen its multiplier's box, or the proved bound would pass the optimum.
// Cell a wants full, b empty, one pair of weight 0.1 between them: the optimum pays the pair, and
// D(y) = y, so the bound is the multiplier's upper bound itself.
TEST(PdhgEnergy, BoundStaysBelowAWeightThatIsNotAFloat) {
  EnergyInput e;
  const CellId a = e.AddCell(1.0, 0.0);
  const CellId b = e.AddCell(0.0, 1.0);
  e.AddPair(a, b, 0.1);
  const LpSolution s = SolveEnergyWithPdhg(ReduceEnergy(e), LabelingOptions{}, RunContext{});
  EXPECT_NEAR(s.objective, 0.1, 1e-12);
  EXPECT_LE(s.lower_bound, 0.1);  // exactly: no tolerance
  EXPECT_GT(s.lower_bound, 0.1 - 1e-6);
}

}  // namespace
}  // namespace linesurf::solver
