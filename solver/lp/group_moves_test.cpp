#include "solver/lp/group_moves.h"

#include "solver/lp/round_labels.h"
#include "tests/support/random_energy.h"
#include "tests/support/thread_count.h"

#include <gtest/gtest.h>

#include <vector>

namespace linesurf::solver {
namespace {

double Energy(const EnergyInput& e, const std::vector<std::uint8_t>& labels) {
  return e.Evaluate(std::span<const std::uint8_t>(labels));
}

// Fixed cells at their label, free cells in a seeded pattern.
std::vector<std::uint8_t> StartLabels(const EnergyInput& e, std::uint64_t seed) {
  std::vector<std::uint8_t> labels(e.NumCells());
  for (std::size_t c = 0; c < labels.size(); ++c) {
    const CellFix f = e.fixed[CellId(c)];
    labels[c] = f == CellFix::kFull ? 1 : (f == CellFix::kEmpty ? 0 : (c * 7 + seed) % 3 == 0);
  }
  return labels;
}

TEST(GroupMoves, FlipTogetherWhatNoSingleFlipImproves) {
  // Two empty cells that both want to be full but pay a strong pairwise term when they differ:
  // each single flip costs 1 - 0.6, the joint flip gains 1.2.
  EnergyInput e;
  e.AddCell(0.6, 0.0);
  e.AddCell(0.6, 0.0);
  e.AddPair(CellId(0u), CellId(1u), 1.0);
  std::vector<std::uint8_t> labels = {0, 0};
  EXPECT_EQ(ImproveLabels(e, 10, labels), 0u);
  EXPECT_EQ(ImproveByGroupMoves(e, 10, RunContext{}, labels), 2u);
  EXPECT_EQ(labels, (std::vector<std::uint8_t>{1, 1}));
}

TEST(GroupMoves, NeverRaiseTheEnergyAndKeepFixedCells) {
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    testing::RandomEnergySpec spec;
    spec.num_cells = 60;
    spec.num_pairs = 120;
    spec.num_structural = 20;
    spec.num_parity = 30;
    spec.fixed_fraction = 0.1;
    spec.seed = seed;
    const EnergyInput e = testing::RandomEnergy(spec);
    std::vector<std::uint8_t> labels = StartLabels(e, seed);
    ImproveLabels(e, 10, labels);
    const double before = Energy(e, labels);
    ImproveByGroupMoves(e, 10, RunContext{}, labels);
    EXPECT_LE(Energy(e, labels), before + 1e-12) << seed;
    for (std::size_t c = 0; c < labels.size(); ++c) {
      const CellFix f = e.fixed[CellId(c)];
      if (f != CellFix::kFree) {
        EXPECT_EQ(labels[c], f == CellFix::kFull ? 1 : 0);
      }
    }
  }
}

TEST(GroupMoves, SameLabelsForAnyThreadCount) {
  // Terms between random cells: the moves of a sweep overlap, so many parallel evaluations are
  // made stale by an earlier move and must be evaluated again.
  const linesurf::testing::RealThreadCounts real_threads;
  for (std::uint64_t seed = 1; seed <= 4; ++seed) {
    testing::RandomEnergySpec spec;
    spec.num_cells = 3000;
    spec.num_pairs = 6000;
    spec.num_structural = 600;
    spec.num_parity = 900;
    spec.seed = seed;
    const EnergyInput e = testing::RandomEnergy(spec);
    const std::vector<std::uint8_t> start = StartLabels(e, seed);
    RunContext serial;
    serial.num_threads = 1;
    std::vector<std::uint8_t> expected = start;
    const std::size_t changes = ImproveByGroupMoves(e, 10, serial, expected);
    EXPECT_GT(changes, 100u) << seed;
    for (const int threads : linesurf::testing::kThreadCounts) {
      RunContext ctx;
      ctx.num_threads = threads;
      std::vector<std::uint8_t> labels = start;
      EXPECT_EQ(ImproveByGroupMoves(e, 10, ctx, labels), changes) << seed << ", " << threads;
      EXPECT_EQ(labels, expected) << seed << ", " << threads << " threads";
    }
  }
}

}  // namespace
}  // namespace linesurf::solver
