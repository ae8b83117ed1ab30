#include "solver/energy/sub_energy.h"

#include "engine/core/rng.h"
#include "tests/support/random_energy.h"

#include <gtest/gtest.h>

#include <vector>

namespace linesurf::solver {
namespace {

TEST(SubEnergy, DiffersFromTheFullEnergyByAConstantOverTheChosenCells) {
  for (std::uint64_t seed = 1; seed <= 10; ++seed) {
    testing::RandomEnergySpec spec;
    spec.num_cells = 40;
    spec.num_pairs = 60;
    spec.num_structural = 10;
    spec.num_parity = 12;
    spec.parity_constants = seed % 2 == 0;
    spec.seed = seed;
    const EnergyInput e = testing::RandomEnergy(spec);
    Rng rng(MixSeed(seed, RngStage::kSynth, 0x5b));
    std::vector<CellId> free, chosen;
    std::vector<std::uint8_t> labels(e.NumCells());
    for (std::size_t c = 0; c < e.NumCells(); ++c) {
      const CellFix f = e.fixed[CellId(c)];
      labels[c] = f == CellFix::kFull ? 1 : (f == CellFix::kEmpty ? 0 : rng.Below(2));
      if (f != CellFix::kFree) continue;
      free.push_back(CellId(c));
      if (rng.Uniform() < 0.3) chosen.push_back(CellId(c));
    }
    const TermIncidence incidence(e, free);
    const SubEnergy sub = RestrictEnergy(e, incidence, chosen, labels);
    ASSERT_TRUE(sub.energy.Validate());
    ASSERT_GE(sub.cells.size(), chosen.size());
    for (std::size_t i = 0; i < chosen.size(); ++i) EXPECT_EQ(sub.cells[i], chosen[i]);
    double constant = 0.0;
    for (int trial = 0; trial < 20; ++trial) {
      if (trial > 0) {
        for (CellId c : chosen) labels[c.index()] = rng.Below(2);
      }
      std::vector<std::uint8_t> local(sub.cells.size());
      for (std::size_t i = 0; i < sub.cells.size(); ++i) local[i] = labels[sub.cells[i].index()];
      const double difference = e.Evaluate(std::span<const std::uint8_t>(labels)) -
                                sub.energy.Evaluate(std::span<const std::uint8_t>(local));
      if (trial == 0) constant = difference;
      EXPECT_NEAR(difference, constant, 1e-9) << "seed " << seed << " trial " << trial;
    }
  }
}

}  // namespace
}  // namespace linesurf::solver
