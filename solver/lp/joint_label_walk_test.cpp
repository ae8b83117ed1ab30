#include "solver/lp/joint_label_walk.h"

#include "solver/lp/round_labels.h"
#include "tests/support/random_energy.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace linesurf::solver {
namespace {

// The lowest energy over the 2^k labellings of `cells`, the others as in `labels`.
double BruteForceMinimum(const EnergyInput& e,
                         const std::vector<CellId>& cells,
                         std::vector<std::uint8_t> labels) {
  double best = e.Evaluate(std::span<const std::uint8_t>(labels));
  for (std::uint32_t code = 0; code < (1u << cells.size()); ++code) {
    for (std::size_t j = 0; j < cells.size(); ++j) labels[cells[j].index()] = (code >> j) & 1u;
    best = std::min(best, e.Evaluate(std::span<const std::uint8_t>(labels)));
  }
  return best;
}

TEST(JointLabelWalk, FindsTheBestJointLabellingOfUpToEightCells) {
  std::size_t improved = 0, kept = 0;
  for (std::uint64_t seed = 1; seed <= 40; ++seed) {
    // Parity groups with constants (as the crease terms) in every other energy.
    const EnergyInput e = testing::SmallRandomEnergy(seed, seed % 2 == 0);
    const std::vector<CellId> free = e.FreeCells();
    const TermIncidence incidence(e, free);
    JointLabelWalk walk(e, free, incidence);
    std::vector<std::uint8_t> labels(e.NumCells());
    for (std::size_t c = 0; c < labels.size(); ++c) {
      const CellFix f = e.fixed[CellId(c)];
      labels[c] = f == CellFix::kFull ? 1 : (f == CellFix::kEmpty ? 0 : (c * 5 + seed) % 3 == 0);
    }
    // Windows of 1 to 8 consecutive free cells: they share terms, so the walk's kept sums matter.
    for (std::size_t k = 1; k <= kMaxJointCells && k <= free.size(); ++k) {
      const std::size_t first = (seed * 7) % (free.size() - k + 1);
      std::vector<std::uint32_t> slots;
      std::vector<CellId> cells;
      for (std::size_t j = first; j < first + k; ++j) {
        slots.push_back(static_cast<std::uint32_t>(j));
        cells.push_back(free[j]);
      }
      const std::vector<std::uint8_t> before = labels;
      const std::uint32_t flips = walk.BestFlips(slots, labels);
      EXPECT_EQ(labels, before) << "the walk leaves the labels as they were";
      std::vector<std::uint8_t> after = labels;
      for (std::size_t j = 0; j < k; ++j) after[cells[j].index()] ^= (flips >> j) & 1u;
      const double start = e.Evaluate(std::span<const std::uint8_t>(labels));
      const double best = BruteForceMinimum(e, cells, labels);
      const double reached = e.Evaluate(std::span<const std::uint8_t>(after));
      EXPECT_NEAR(reached, best, 1e-9) << "seed " << seed << ", " << k << " cells";
      if (flips == 0) {
        EXPECT_GE(best, start - 1e-9) << "seed " << seed << ", " << k << " cells";
        ++kept;
      } else {
        EXPECT_LT(reached, start) << "seed " << seed << ", " << k << " cells";
        ++improved;
      }
    }
  }
  // Both outcomes were exercised.
  EXPECT_GT(improved, 20u);
  EXPECT_GT(kept, 20u);
}

}  // namespace
}  // namespace linesurf::solver
