#include "solver/lp/dual_ascent.h"

#include "solver/lp/lp_backend.h"
#include "tests/support/random_energy.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>

namespace linesurf::solver {
namespace {

constexpr double kBoundTolerance = 1e-7;

double LpOptimum(const EnergyInput& e) {
  LabelingOptions options;
  options.backend = SolverBackend::kClp;
  const auto r = SolveLabeling(e, options, RunContext{});
  EXPECT_TRUE(r) << r.error().ToString();
  return r ? r->relaxed_objective : 0.0;
}

// The bound at zero multipliers: the constant and the negative unary costs.
double TrivialBound(const ReducedEnergy& r) {
  double bound = r.constant;
  for (double u : r.unary) bound += std::min(0.0, u);
  return bound;
}

TEST(DualAscent, BoundsTheLpOptimumOfRandomEnergies) {
  for (std::uint64_t seed = 1; seed <= 30; ++seed) {
    const EnergyInput e = testing::SmallRandomEnergy(seed);
    const ReducedEnergy reduced = ReduceEnergy(e);
    const DualAscentResult ascent = DualAscentBound(reduced, 50, 0.0);
    EXPECT_LE(ascent.bound, LpOptimum(e) + kBoundTolerance) << "seed " << seed;
    EXPECT_GE(ascent.bound, TrivialBound(reduced) - kBoundTolerance) << "seed " << seed;
  }
}

TEST(DualAscent, NeverLowersTheBoundAndComesCloseOnAGridEnergy) {
  testing::GridEnergySpec spec;
  spec.nx = spec.ny = spec.nz = 10;
  const EnergyInput e = testing::GridEnergy(spec);
  const ReducedEnergy reduced = ReduceEnergy(e);
  const double optimum = LpOptimum(e);
  double previous = TrivialBound(reduced);
  for (int passes : {1, 5, 20, 100}) {
    const DualAscentResult ascent = DualAscentBound(reduced, passes, 0.0);
    EXPECT_GE(ascent.bound, previous - kBoundTolerance) << passes;
    EXPECT_LE(ascent.bound, optimum + kBoundTolerance) << passes;
    previous = ascent.bound;
    std::printf("grid 10^3: %d passes: bound %.6f, LP optimum %.6f (%.2f %%)\n",
                passes,
                ascent.bound,
                optimum,
                100.0 * ascent.bound / optimum);
  }
}

}  // namespace
}  // namespace linesurf::solver
