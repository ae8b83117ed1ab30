#include "solver/lp/backends/pdhg_energy/pdhg_energy_backend.h"

#include "tests/support/random_energy.h"

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
  const LpSolution s = SolveEnergyWithPdhg(ReduceEnergy(e), PdhgEnergyOptions{}, 0.0, RunContext{});
  EXPECT_NEAR(s.objective, 0.1, 1e-12);
  EXPECT_LE(s.lower_bound, 0.1);  // exactly: no tolerance
  EXPECT_GT(s.lower_bound, 0.1 - 1e-6);
}

// The steps are preconditioned on the multipliers scaled to their boxes, so the iterates do not
// depend on the units of the weights (scene units squared for areas, for one): every cost times
// a power of two scales every iterate exactly, and the solve takes the same iterations to the
// same x. Steps of 1 / entries for y (unweighted) would make the multipliers of heavy terms
// climb slower than those of light ones, and the two solves would differ.
TEST(PdhgEnergy, IteratesDoNotDependOnTheUnitsOfTheCosts) {
  testing::GridEnergySpec spec;
  spec.nx = spec.ny = spec.nz = 8;
  const EnergyInput e = testing::GridEnergy(spec);
  constexpr double kScale = 1024.0;
  EnergyInput scaled = e;
  for (double& c : scaled.cost_if_empty) c *= kScale;
  for (double& c : scaled.cost_if_full) c *= kScale;
  for (PairTerm& pair : scaled.pairs) pair.weight *= kScale;
  for (double& w : scaled.structural_weights) w *= kScale;
  for (double& w : scaled.parity_weights) w *= kScale;

  const LpSolution s = SolveEnergyWithPdhg(ReduceEnergy(e), PdhgEnergyOptions{}, 0.0, RunContext{});
  const LpSolution t =
      SolveEnergyWithPdhg(ReduceEnergy(scaled), PdhgEnergyOptions{}, 0.0, RunContext{});
  EXPECT_GT(s.iterations, 64);  // a solve that needs its restarts, not a trivial one
  EXPECT_EQ(s.iterations, t.iterations);
  EXPECT_EQ(s.columns, t.columns);
  EXPECT_DOUBLE_EQ(s.objective * kScale, t.objective);
}

}  // namespace
}  // namespace linesurf::solver
