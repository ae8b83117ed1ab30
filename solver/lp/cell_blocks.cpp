#include "solver/lp/cell_blocks.h"

#include "engine/core/exception.h"

#include <algorithm>
#include <string>
#include <utility>

namespace linesurf::solver {
namespace {

constexpr const char* kCellBlocksStage = "cell_blocks";

}  // namespace

CellBlocks MakeCellBlocks(const EnergyInput& energy, std::span<const std::uint32_t> block_of_cell) {
  const std::size_t n = energy.NumCells();
  LINESURF_THROW_IF(block_of_cell.size() != n,
                    kInvalidInput,
                    kCellBlocksStage,
                    "block of cell: " << block_of_cell.size() << " entries for " << n << " cells");
  std::uint32_t num_blocks = 0;
  for (std::size_t c = 0; c < n; ++c) {
    if (energy.fixed[CellId(c)] != CellFix::kFree) continue;
    LINESURF_THROW_IF(
        block_of_cell[c] >= n,
        kInvalidInput,
        kCellBlocksStage,
        "block of cell " << c << ": " << block_of_cell[c] << " is not below the " << n << " cells");
    num_blocks = std::max(num_blocks, block_of_cell[c] + 1);
  }
  CellBlocks blocks;
  // Cells by block: count, scan, scatter (cells stay in id order within a block).
  std::vector<std::vector<CellId>> members(num_blocks);
  for (std::size_t c = 0; c < n; ++c) {
    if (energy.fixed[CellId(c)] == CellFix::kFree) members[block_of_cell[c]].push_back(CellId(c));
  }
  for (const auto& m : members) blocks.cells.AddRow(m);

  // Block pairs joined by a term, from the distinct blocks of each term's free cells.
  std::vector<std::pair<std::uint32_t, std::uint32_t>> links;
  std::vector<std::uint32_t> touched;
  const auto add_term = [&](auto&& cells) {
    touched.clear();
    for (CellId c : cells) {
      if (energy.fixed[c] == CellFix::kFree) touched.push_back(block_of_cell[c.index()]);
    }
    std::sort(touched.begin(), touched.end());
    touched.erase(std::unique(touched.begin(), touched.end()), touched.end());
    if (touched.size() > 1) ++blocks.crossing_terms;
    for (std::size_t i = 0; i < touched.size(); ++i) {
      for (std::size_t j = 0; j < touched.size(); ++j) {
        if (i != j) links.emplace_back(touched[i], touched[j]);
      }
    }
  };
  for (const PairTerm& p : energy.pairs) add_term(std::initializer_list<CellId>{p.a, p.b});
  for (std::size_t g = 0; g < energy.NumStructuralGroups(); ++g)
    add_term(energy.StructuralGroup(g));
  for (std::size_t g = 0; g < energy.NumParityGroups(); ++g) add_term(energy.ParityGroup(g));
  std::sort(links.begin(), links.end());
  links.erase(std::unique(links.begin(), links.end()), links.end());
  std::vector<BlockId> row;
  std::size_t k = 0;
  for (std::uint32_t b = 0; b < num_blocks; ++b) {
    row.clear();
    for (; k < links.size() && links[k].first == b; ++k) row.push_back(BlockId(links[k].second));
    blocks.neighbours.AddRow(row);
  }

  return blocks;
}

}  // namespace linesurf::solver
