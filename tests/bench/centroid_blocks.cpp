#include "tests/bench/centroid_blocks.h"

#include "engine/core/exception.h"
#include "partition/arrangement/cell_geometry.h"

#include <algorithm>

namespace linesurf::pipeline {
namespace {

struct Splitter {
  const std::vector<Vec3>& centroid;
  std::size_t max_cells;
  std::vector<std::uint32_t>& block_of_cell;
  std::uint32_t next_block = 0;

  // Cells [begin, end) of `order` become one block or are split in two at the median.
  void Split(std::vector<std::uint32_t>& order, std::size_t begin, std::size_t end) {
    if (end - begin <= max_cells) {
      for (std::size_t i = begin; i < end; ++i) block_of_cell[order[i]] = next_block;
      ++next_block;
      return;
    }
    Box3 box;
    for (std::size_t i = begin; i < end; ++i) box.Extend(centroid[order[i]]);
    const Vec3 extent = box.Extent();
    int axis = 0;
    for (int a = 1; a < 3; ++a) {
      if (extent[a] > extent[axis]) axis = a;
    }
    const std::size_t middle = begin + (end - begin) / 2;
    const auto first = order.begin() + static_cast<std::ptrdiff_t>(begin);
    std::nth_element(first,
                     order.begin() + static_cast<std::ptrdiff_t>(middle),
                     order.begin() + static_cast<std::ptrdiff_t>(end),
                     [&](std::uint32_t a, std::uint32_t b) {
                       // A total order (ties by id), so the two halves are unique.
                       return std::pair(centroid[a][axis], a) < std::pair(centroid[b][axis], b);
                     });
    Split(order, begin, middle);
    Split(order, middle, end);
  }
};

}  // namespace

std::vector<std::uint32_t> CentroidBlocks(const CellComplex& complex, std::size_t max_cells) {
  LINESURF_ASSERT(max_cells >= 1);
  const std::size_t n = complex.NumCells();
  std::vector<Vec3> centroid(n);
  for (std::size_t c = 0; c < n; ++c) centroid[c] = partition::CellCentroid(complex, CellId(c));
  std::vector<std::uint32_t> order(n);
  for (std::size_t c = 0; c < n; ++c) order[c] = static_cast<std::uint32_t>(c);
  std::vector<std::uint32_t> block_of_cell(n, 0);
  Splitter splitter{centroid, max_cells, block_of_cell};
  if (n > 0) splitter.Split(order, 0, n);
  return block_of_cell;
}

}  // namespace linesurf::pipeline
