#include "solver/energy/build_lp.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "tests/support/random_energy.h"

namespace linesurf::solver {
namespace {

constexpr double kExact = 1e-9;

// All 0/1 assignments of the free cells, as full per-cell vectors.
template <typename Fn>
void ForEachLabelling(const EnergyInput& e, const ReducedEnergy& r, Fn&& fn) {
  const std::size_t n = r.NumFree();
  ASSERT_LE(n, 16u);
  for (std::uint32_t mask = 0; mask < (1u << n); ++mask) {
    std::vector<double> cols(n);
    for (std::size_t j = 0; j < n; ++j) cols[j] = (mask >> j) & 1u;
    fn(cols, ExpandToCells(e, r, cols));
  }
}

// Slack values that make `cols` feasible at least cost: the LP value of an integral labelling.
std::vector<double> WithOptimalSlacks(const LpModel& lp, std::vector<double> cols) {
  cols.resize(lp.NumColumns(), 0.0);
  for (std::size_t r = 0; r < lp.NumRows(); ++r) {
    // Every row is slack + rest >= lower with the slack first (coefficient 1).
    const std::uint32_t begin = lp.row_offsets[r];
    double rest = 0.0;
    for (std::uint32_t k = begin + 1; k < lp.row_offsets[r + 1]; ++k) {
      rest += lp.row_values[k] * cols[lp.row_columns[k]];
    }
    double& slack = cols[lp.row_columns[begin]];
    slack = std::max(slack, lp.row_lower[r] - rest);
  }
  return cols;
}

TEST(BuildLp, ReducedAndLpEnergiesEqualTheEnergyOnEveryLabelling) {
  for (std::uint64_t seed = 1; seed <= 40; ++seed) {
    testing::RandomEnergySpec spec;
    spec.num_cells = 12;
    spec.fixed_fraction = 0.3;
    spec.parity_constants = seed > 20;  // groups |k + sum nu x| with k != 0 from seed 21
    spec.seed = seed;
    const EnergyInput e = testing::RandomEnergy(spec);
    ASSERT_TRUE(e.Validate());
    const ReducedEnergy r = ReduceEnergy(e);
    const LpModel lp = BuildLpModel(r);
    ForEachLabelling(e, r, [&](const std::vector<double>& cols, const std::vector<double>& x) {
      const double expected = e.Evaluate(std::span<const double>(x));
      EXPECT_NEAR(r.Evaluate(cols), expected, kExact) << "seed " << seed;
      const std::vector<double> full = WithOptimalSlacks(lp, cols);
      EXPECT_LE(lp.MaxViolation(full), kExact);
      EXPECT_NEAR(lp.Evaluate(full), expected, kExact) << "seed " << seed;
    });
  }
}

TEST(BuildLp, FixedCellsAreSubstitutedNotColumns) {
  EnergyInput e;
  const CellId a = e.AddCell(1.0, 0.0);
  const CellId empty = e.AddCell(0.0, 0.0, CellFix::kEmpty);
  const CellId full = e.AddCell(0.0, 0.0, CellFix::kFull);
  e.AddPair(a, empty, 2.0);  // -> 2 x_a
  e.AddPair(a, full, 3.0);   // -> 3 - 3 x_a
  const CellId g1[] = {a, empty};
  e.AddStructuralGroup(g1, 5.0);  // -> 5 - 5 x_a
  const CellId g2[] = {a, full};
  e.AddStructuralGroup(g2, 7.0);  // -> 0
  const CellId g3[] = {a, full, empty};
  const std::int8_t s3[] = {1, 1, -1};
  e.AddParityGroup(g3, s3, 11.0);  // |x + 1| -> 11 + 11 x_a
  e.AddPair(empty, full, 13.0);    // constant 13
  const ReducedEnergy r = ReduceEnergy(e);
  ASSERT_EQ(r.NumFree(), 1u);
  EXPECT_FALSE(r.HasHigherOrderTerms());
  EXPECT_TRUE(r.pairs.empty());
  // unary: (0 - 1) + 2 - 3 - 5 + 11 = 4; constant 1 + 3 + 5 + 11 + 13 = 33
  EXPECT_NEAR(r.unary[0], 4.0, kExact);
  EXPECT_NEAR(r.constant, 33.0, kExact);
  const LpModel lp = BuildLpModel(r);
  EXPECT_EQ(lp.NumColumns(), 1u);
  EXPECT_EQ(lp.NumRows(), 0u);
  EXPECT_NEAR(lp.objective_offset, 33.0, kExact);
}

TEST(BuildLp, CanonicalOrderAndZeroWeightsDropped) {
  EnergyInput e;
  for (int i = 0; i < 4; ++i) e.AddCell(0.0, 0.0);
  e.AddPair(CellId(0u), CellId(1u), 1.0);
  e.AddPair(CellId(1u), CellId(2u), 0.0);  // dropped
  const CellId g[] = {CellId(1u), CellId(2u), CellId(3u)};
  e.AddStructuralGroup(g, 1.0);
  const std::int8_t s[] = {1, -1, 1};
  e.AddParityGroup(g, s, 1.0);
  const LpModel lp = BuildLpModel(ReduceEnergy(e));
  // 4 cells, then pair slack 4, structural slack 5, parity slack 6.
  ASSERT_EQ(lp.NumColumns(), 7u);
  ASSERT_EQ(lp.NumRows(), 5u);
  EXPECT_EQ(lp.row_columns[lp.row_offsets[0]], 4u);
  EXPECT_EQ(lp.row_columns[lp.row_offsets[2]], 5u);
  EXPECT_EQ(lp.row_columns[lp.row_offsets[3]], 6u);
  EXPECT_EQ(lp.row_columns[lp.row_offsets[4]], 6u);
  EXPECT_EQ(lp.NumNonzeros(), 6u + 4u + 8u);
}

}  // namespace
}  // namespace linesurf::solver
