#include "solver/lp/band_fixing.h"

#include <gtest/gtest.h>

#include "solver/lp/lp_backend.h"
#include "solver/testing/random_energy.h"

namespace linesurf::solver {
namespace {

constexpr double kObjectiveTolerance = 1e-6;

LabelingResult MustSolve(const EnergyInput& e, const std::string& backend) {
  LabelingOptions options;
  options.backend = backend;
  RunContext ctx;
  ctx.num_threads = 1;
  auto result = SolveLabeling(e, options, ctx);
  EXPECT_TRUE(result) << (result ? "" : result.error().ToString());
  if (!result) return {};
  return std::move(result).value();
}

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

TEST(BandFixing, BandSolveIsAnUpperBoundOfTheFullLpAndKeepsFixes) {
  for (std::uint64_t seed = 1; seed <= 10; ++seed) {
    testing::RandomEnergySpec spec;
    spec.num_cells = 30;
    spec.num_pairs = 50;
    spec.num_structural = 8;
    spec.num_parity = 10;
    spec.seed = seed;
    const EnergyInput e = testing::RandomEnergy(spec);
    const LabelingResult clp = MustSolve(e, "clp");
    const LabelingResult band = MustSolve(e, "band");
    EXPECT_EQ(band.backend.rfind("band+", 0), 0u) << band.backend;
    EXPECT_GE(band.relaxed_objective, clp.relaxed_objective - kObjectiveTolerance) << seed;
    EXPECT_NEAR(band.labels_objective, e.Evaluate(std::span<const std::uint8_t>(band.labels)),
                kObjectiveTolerance);
    for (std::size_t c = 0; c < e.NumCells(); ++c) {
      const CellFix f = e.fixed[CellId(c)];
      if (f != CellFix::kFree) {
        EXPECT_EQ(band.labels[c], f == CellFix::kFull ? 1 : 0);
      }
    }
  }
}

TEST(BandFixing, GridEnergyBandIsCloseToTheFullLp) {
  testing::GridEnergySpec spec;
  spec.nx = spec.ny = spec.nz = 10;
  const EnergyInput e = testing::GridEnergy(spec);
  const LabelingResult clp = MustSolve(e, "clp");
  const LabelingResult band = MustSolve(e, "band");
  EXPECT_LT(band.band_lp_columns, clp.lp_columns);
  EXPECT_GE(band.relaxed_objective, clp.relaxed_objective - kObjectiveTolerance);
  // The labels of the band are within 5 % of the energy of the full LP's labels.
  EXPECT_LE(band.labels_objective, 1.05 * clp.labels_objective);
}

}  // namespace
}  // namespace linesurf::solver
