#include "solver/lp/lp_model.h"

#include <gtest/gtest.h>

namespace linesurf::solver {
namespace {

TEST(LpModel, EvaluatesObjectiveAndViolation) {
  LpModel lp;
  const auto x = lp.AddColumn(1.0, 0.0, 1.0);
  const auto y = lp.AddColumn(2.0, 0.0, 1.0);
  const std::uint32_t cols[] = {x, y};
  const double vals[] = {1.0, 1.0};
  lp.AddRow(cols, vals, 1.0, kLpInfinity);
  const double feasible[] = {1.0, 0.0};
  const double infeasible[] = {0.25, 0.25};
  EXPECT_DOUBLE_EQ(lp.Evaluate(feasible), 1.0);
  EXPECT_DOUBLE_EQ(lp.MaxViolation(feasible), 0.0);
  EXPECT_DOUBLE_EQ(lp.MaxViolation(infeasible), 0.5);
}

}  // namespace
}  // namespace linesurf::solver
