#pragma once
// A partition of an energy's free cells into blocks, and how the blocks are coupled: two blocks
// are neighbours when one term holds a free cell of each (fixed cells couple nothing, their
// label never changes), so a change in one block may make its neighbours' solves stale.

#include "engine/core/csr.h"
#include "engine/core/strong_id.h"
#include "solver/energy/energy_input.h"

#include <cstdint>
#include <span>
#include <vector>

namespace linesurf::solver {

struct CellBlocks {
  /// Free cells of each block, in increasing id order (blocks without a free cell are empty).
  Csr<BlockId, CellId> cells;
  /// Neighbouring blocks of each block, in increasing id order.
  Csr<BlockId, BlockId> neighbours;
  /// Terms whose free cells lie in more than one block.
  std::size_t crossing_terms = 0;

  [[nodiscard]] std::size_t NumBlocks() const { return cells.NumRows(); }
};

/// `block_of_cell` holds one block id per cell of `energy` (ignored for fixed cells); block ids
/// must be < energy.NumCells() (blocks are numbered 0 .. max id). Throws kInvalidInput on a size
/// mismatch or an id out of range. O(terms log terms).
[[nodiscard]] CellBlocks MakeCellBlocks(const EnergyInput& energy,
                                        std::span<const std::uint32_t> block_of_cell);

}  // namespace linesurf::solver
