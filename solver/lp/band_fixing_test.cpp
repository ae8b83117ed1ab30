#include "solver/lp/band_fixing.h"

#include <gtest/gtest.h>

#include "tests/support/random_energy.h"

namespace linesurf::solver {
namespace {

std::size_t CountFree(const EnergyInput& e) {
  std::size_t n = 0;
  for (const CellFix f : e.fixed) n += f == CellFix::kFree ? 1 : 0;
  return n;
}

TEST(BandFixing, FixesCellsAwayFromThePairwiseSurfaceAtTheirLabel) {
  testing::GridEnergySpec spec;
  spec.nx = spec.ny = spec.nz = 14;
  const EnergyInput e = testing::GridEnergy(spec);
  RunContext ctx;
  const std::vector<std::uint8_t> labels = PairwiseLabels(e, ctx);
  ASSERT_EQ(labels.size(), e.NumCells());
  const EnergyInput banded = FixCellsOutsideBand(e, labels, 0);
  const std::size_t band = CountFree(banded);
  EXPECT_GT(band, 0u);
  EXPECT_LT(band, CountFree(e));
  EXPECT_GT(CountFree(FixCellsOutsideBand(e, labels, 2)), band);
  for (std::size_t c = 0; c < e.NumCells(); ++c) {
    const CellId id(c);
    if (e.fixed[id] != CellFix::kFree) {
      EXPECT_EQ(banded.fixed[id], e.fixed[id]) << "boundary conditions are kept";
    } else if (banded.fixed[id] != CellFix::kFree) {
      EXPECT_EQ(banded.fixed[id] == CellFix::kFull, labels[c] == 1) << "fixed at the max-flow label";
    }
  }
}

}  // namespace
}  // namespace linesurf::solver
