#include "solver/lp/round_labels.h"

#include <gtest/gtest.h>

#include <vector>

namespace linesurf::solver {
namespace {

TEST(RoundLabels, ThresholdsAtOneHalfAndKeepsFixedCells) {
  EnergyInput e;
  e.AddCell(0.0, 0.0);
  e.AddCell(0.0, 0.0);
  e.AddCell(0.0, 0.0, CellFix::kFull);
  const std::vector<double> x = {0.7, 0.3, 1.0};
  const RoundedLabels r = RoundLabels(e, x);
  EXPECT_EQ(r.labels, (std::vector<std::uint8_t>{1, 0, 1}));
  EXPECT_EQ(r.fractional_cells, 2u);
  EXPECT_EQ(r.tie_cells, 0u);
}

TEST(RoundLabels, TiesAreBrokenInIdOrderTowardsLowerEnergy) {
  // Two free cells in a structural group, both slightly penalised when full, both at 0.5.
  // Cell 0 decides first with cell 1 counted empty: full costs 0.1, empty 1 -> full. Cell 1 then:
  // full costs 0.1, empty 0 -> empty.
  EnergyInput e;
  e.AddCell(0.0, 0.1);
  e.AddCell(0.0, 0.1);
  const CellId group[] = {CellId(0u), CellId(1u)};
  e.AddStructuralGroup(group, 1.0);
  const std::vector<double> x = {0.5, 0.5};
  const RoundedLabels r = RoundLabels(e, x);
  EXPECT_EQ(r.labels, (std::vector<std::uint8_t>{1, 0}));
  EXPECT_EQ(r.tie_cells, 2u);
}

TEST(RoundLabels, TieWithEqualEnergyIsEmpty) {
  EnergyInput e;
  e.AddCell(0.0, 0.0);
  const std::vector<double> x = {0.5};
  EXPECT_EQ(RoundLabels(e, x).labels, (std::vector<std::uint8_t>{0}));
}

}  // namespace
}  // namespace linesurf::solver

namespace linesurf::solver {
namespace {

TEST(ImproveLabels, FlipsOnlyWhenTheEnergyDrops) {
  // Chain 0-1-2 with strong pairwise terms; cell 1 rounded wrongly to empty.
  EnergyInput e;
  e.AddCell(1.0, 0.0);
  e.AddCell(0.0, 0.1);
  e.AddCell(1.0, 0.0);
  e.AddPair(CellId(0u), CellId(1u), 1.0);
  e.AddPair(CellId(1u), CellId(2u), 1.0);
  std::vector<std::uint8_t> labels = {1, 0, 1};
  const double before = e.Evaluate(std::span<const std::uint8_t>(labels));
  EXPECT_EQ(ImproveLabels(e, 5, labels), 1u);
  EXPECT_EQ(labels, (std::vector<std::uint8_t>{1, 1, 1}));
  EXPECT_LT(e.Evaluate(std::span<const std::uint8_t>(labels)), before);
  EXPECT_EQ(ImproveLabels(e, 5, labels), 0u);  // a local minimum stays
}

}  // namespace
}  // namespace linesurf::solver
