#include "solver/lp/window_polish.h"

#include "solver/lp/backends/cbc/cbc_backend.h"
#include "tests/support/random_energy.h"
#include "tests/support/thread_count.h"

#include <gtest/gtest.h>

#include <vector>

namespace linesurf::solver {
namespace {

double EnergyOfLabels(const EnergyInput& e, const std::vector<std::uint8_t>& labels) {
  return e.Evaluate(std::span<const std::uint8_t>(labels));
}

// Fixed cells at their label, free cells in a seeded pattern; the relaxed values put every
// third free cell at 1/2, so those cells seed windows.
struct Start {
  std::vector<std::uint8_t> labels;
  std::vector<double> relaxed;
};

Start StartOf(const EnergyInput& e, std::uint64_t seed) {
  Start s;
  for (std::size_t c = 0; c < e.NumCells(); ++c) {
    const CellFix f = e.fixed[CellId(c)];
    const std::uint8_t label =
        f == CellFix::kFull ? 1 : (f == CellFix::kEmpty ? 0 : (c * 7 + seed) % 3 == 0);
    s.labels.push_back(label);
    s.relaxed.push_back(f == CellFix::kFree && c % 3 == seed % 3 ? 0.5 : label);
  }
  return s;
}

testing::RandomEnergySpec Spec(std::size_t cells, std::uint64_t seed) {
  testing::RandomEnergySpec spec;
  spec.num_cells = cells;
  spec.num_pairs = 2 * cells;
  spec.num_structural = cells / 5;
  spec.num_parity = cells / 3;
  spec.fixed_fraction = 0.1;
  spec.seed = seed;
  return spec;
}

WindowPolishOptions Windows(std::size_t cells, std::int64_t max_nodes, std::size_t max_windows) {
  WindowPolishOptions options;
  options.window_cells = cells;
  options.max_nodes = max_nodes;
  options.max_windows = max_windows;
  return options;
}

TEST(WindowPolish, OneWindowOverAllFreeCellsFindsTheIntegralOptimum) {
  if (!CbcAvailable()) GTEST_SKIP() << "this build has no Cbc backend";
  for (std::uint64_t seed = 1; seed <= 10; ++seed) {
    const EnergyInput e = testing::RandomEnergy(Spec(14, seed));
    Start start = StartOf(e, seed);
    const WindowPolishOptions options = Windows(64, 100000, 10);
    const WindowPolishStats stats =
        PolishInWindows(e, start.relaxed, options, RunContext{}, start.labels);
    EXPECT_EQ(stats.windows, 1u) << seed;
    EXPECT_TRUE(stats.whole_energy_proven) << seed;
    EXPECT_NEAR(EnergyOfLabels(e, start.labels), testing::BruteForceMinimum(e), 1e-9) << seed;
  }
}

TEST(WindowPolish, NeverRaisesTheEnergyAndKeepsFixedCells) {
  if (!CbcAvailable()) GTEST_SKIP() << "this build has no Cbc backend";
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    const EnergyInput e = testing::RandomEnergy(Spec(400, seed));
    Start start = StartOf(e, seed);
    const double before = EnergyOfLabels(e, start.labels);
    const WindowPolishOptions options = Windows(12, 50, 1000);
    const WindowPolishStats stats =
        PolishInWindows(e, start.relaxed, options, RunContext{}, start.labels);
    EXPECT_GT(stats.improved_windows, 0u) << seed;
    EXPECT_LT(EnergyOfLabels(e, start.labels), before) << seed;
    for (std::size_t c = 0; c < start.labels.size(); ++c) {
      const CellFix f = e.fixed[CellId(c)];
      if (f != CellFix::kFree) {
        EXPECT_EQ(start.labels[c], f == CellFix::kFull ? 1 : 0);
      }
    }
  }
}

TEST(WindowPolish, SameLabelsForAnyThreadCount) {
  if (!CbcAvailable()) GTEST_SKIP() << "this build has no Cbc backend";
  // Terms between random cells: the windows of a batch overlap, so many parallel solves are made
  // stale by an earlier window and must be solved again.
  const linesurf::testing::RealThreadCounts real_threads;
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    testing::RandomEnergySpec spec = Spec(300, seed);
    spec.num_pairs = 1500;
    spec.num_parity = 300;
    const EnergyInput e = testing::RandomEnergy(spec);
    const Start start = StartOf(e, seed);
    const WindowPolishOptions options = Windows(4, 50, 1000);
    RunContext serial;
    serial.num_threads = 1;
    std::vector<std::uint8_t> expected = start.labels;
    const WindowPolishStats reference =
        PolishInWindows(e, start.relaxed, options, serial, expected);
    EXPECT_GT(reference.improved_windows, 10u) << seed;
    for (const int threads : linesurf::testing::kThreadCounts) {
      RunContext ctx;
      ctx.num_threads = threads;
      std::vector<std::uint8_t> labels = start.labels;
      const WindowPolishStats stats = PolishInWindows(e, start.relaxed, options, ctx, labels);
      EXPECT_EQ(labels, expected) << seed << ", " << threads << " threads";
      EXPECT_EQ(stats.windows, reference.windows) << seed << ", " << threads;
      EXPECT_EQ(stats.improved_windows, reference.improved_windows) << seed << ", " << threads;
      EXPECT_EQ(stats.changed_cells, reference.changed_cells) << seed << ", " << threads;
    }
  }
}

}  // namespace
}  // namespace linesurf::solver
