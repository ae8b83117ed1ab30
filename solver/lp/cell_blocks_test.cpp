#include "solver/lp/cell_blocks.h"

#include "engine/core/exception.h"
#include "tests/support/random_energy.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

namespace linesurf::solver {
namespace {

TEST(CellBlocks, PartitionAndNeighboursFitTheTerms) {
  testing::GridEnergySpec spec;
  spec.nx = spec.ny = spec.nz = 9;
  const EnergyInput e = testing::GridEnergy(spec);
  const std::vector<std::uint32_t> block_of_cell = testing::GridBlocks(spec, 3);
  const CellBlocks blocks = MakeCellBlocks(e, block_of_cell);
  ASSERT_EQ(blocks.NumBlocks(), 27u);
  // Every free cell in its block, once; fixed cells in none.
  std::vector<int> seen(e.NumCells(), 0);
  for (std::uint32_t b = 0; b < blocks.NumBlocks(); ++b) {
    for (CellId c : blocks.cells[BlockId(b)]) {
      ++seen[c.index()];
      EXPECT_EQ(block_of_cell[c.index()], b);
    }
  }
  for (std::size_t c = 0; c < e.NumCells(); ++c) {
    EXPECT_EQ(seen[c], e.fixed[CellId(c)] == CellFix::kFree ? 1 : 0) << "cell " << c;
  }
  // Neighbours: exactly the blocks that share a term through free cells.
  std::vector<std::vector<std::uint32_t>> expected(blocks.NumBlocks());
  std::size_t crossing = 0;
  const auto link = [&](std::vector<CellId> cells) {
    std::vector<std::uint32_t> touched;
    for (CellId c : cells) {
      if (e.fixed[c] == CellFix::kFree) touched.push_back(block_of_cell[c.index()]);
    }
    std::sort(touched.begin(), touched.end());
    touched.erase(std::unique(touched.begin(), touched.end()), touched.end());
    crossing += touched.size() > 1 ? 1 : 0;
    for (std::uint32_t a : touched) {
      for (std::uint32_t b : touched) {
        if (a != b) expected[a].push_back(b);
      }
    }
  };
  for (const PairTerm& p : e.pairs) link({p.a, p.b});
  for (std::size_t g = 0; g < e.NumStructuralGroups(); ++g) {
    const auto cells = e.StructuralGroup(g);
    link({cells.begin(), cells.end()});
  }
  for (std::size_t g = 0; g < e.NumParityGroups(); ++g) {
    const auto cells = e.ParityGroup(g);
    link({cells.begin(), cells.end()});
  }
  EXPECT_GT(crossing, 0u);
  EXPECT_EQ(blocks.crossing_terms, crossing);
  for (std::uint32_t a = 0; a < blocks.NumBlocks(); ++a) {
    std::sort(expected[a].begin(), expected[a].end());
    expected[a].erase(std::unique(expected[a].begin(), expected[a].end()), expected[a].end());
    std::vector<std::uint32_t> got;
    for (BlockId b : blocks.neighbours[BlockId(a)]) {
      got.push_back(b.value());
    }
    EXPECT_EQ(got, expected[a]) << "block " << a;
  }
}

TEST(CellBlocks, RejectsAPartitionThatDoesNotFit) {
  testing::RandomEnergySpec spec;
  const EnergyInput e = testing::RandomEnergy(spec);
  std::vector<std::uint32_t> short_partition(e.NumCells() - 1, 0);
  EXPECT_THROW((void)MakeCellBlocks(e, short_partition), LinesurfException);
  std::vector<std::uint32_t> out_of_range(e.NumCells(), 0);
  for (std::size_t c = 0; c < e.NumCells(); ++c) {
    if (e.fixed[CellId(c)] == CellFix::kFree) {
      out_of_range[c] = static_cast<std::uint32_t>(e.NumCells());
      break;
    }
  }
  EXPECT_THROW((void)MakeCellBlocks(e, out_of_range), LinesurfException);
}

}  // namespace
}  // namespace linesurf::solver
