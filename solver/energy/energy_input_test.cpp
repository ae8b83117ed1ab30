#include "solver/energy/energy_input.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace linesurf::solver {
namespace {

EnergyInput SmallEnergy() {
  EnergyInput e;
  e.AddCell(1.0, 0.0);
  e.AddCell(0.0, 2.0);
  e.AddCell(0.5, 0.5, CellFix::kEmpty);
  e.AddPair(CellId(0u), CellId(1u), 3.0);
  const CellId group[] = {CellId(1u), CellId(2u)};
  e.AddStructuralGroup(group, 4.0);
  const std::int8_t signs[] = {1, -1};
  e.AddParityGroup(group, signs, 5.0);
  return e;
}

TEST(EnergyInput, ValidEnergyPasses) { EXPECT_TRUE(SmallEnergy().Validate()); }

TEST(EnergyInput, EvaluatesEveryTerm) {
  const EnergyInput e = SmallEnergy();
  const std::vector<std::uint8_t> all_empty = {0, 0, 0};
  // unary 1 + 0 + 0.5, pair 0, structural 4, parity 0
  EXPECT_DOUBLE_EQ(e.Evaluate(std::span<const std::uint8_t>(all_empty)), 5.5);
  const std::vector<std::uint8_t> one_full = {0, 1, 0};
  // unary 1 + 2 + 0.5, pair 3, structural 0, parity 5
  EXPECT_DOUBLE_EQ(e.Evaluate(std::span<const std::uint8_t>(one_full)), 11.5);
  const std::vector<double> half = {0.5, 0.5, 0.0};
  // unary 0.5 + 1 + 0.5, pair 0, structural 2, parity 2.5
  EXPECT_DOUBLE_EQ(e.Evaluate(std::span<const double>(half)), 6.5);
}

TEST(EnergyInput, RejectsBadTerms) {
  {
    EnergyInput e = SmallEnergy();
    e.AddPair(CellId(0u), CellId(0u), 1.0);
    EXPECT_EQ(e.Validate().error().code, ErrorCode::kInvalidInput);
  }
  {
    EnergyInput e = SmallEnergy();
    e.AddPair(CellId(0u), CellId(7u), 1.0);
    EXPECT_FALSE(e.Validate());
  }
  {
    EnergyInput e = SmallEnergy();
    e.structural_weights[0] = -1.0;
    EXPECT_FALSE(e.Validate());
  }
  {
    EnergyInput e = SmallEnergy();
    e.parity_signs[0] = 0;
    EXPECT_FALSE(e.Validate());
  }
  {
    EnergyInput e = SmallEnergy();
    const CellId repeated[] = {CellId(0u), CellId(0u)};
    e.AddStructuralGroup(repeated, 1.0);
    EXPECT_FALSE(e.Validate());
  }
  {
    EnergyInput e = SmallEnergy();
    e.cost_if_empty[CellId(1u)] = std::nan("");
    EXPECT_FALSE(e.Validate());
  }
}

}  // namespace
}  // namespace linesurf::solver
