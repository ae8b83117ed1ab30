#pragma once
/// @file transpose_rows.h
/// @brief The transpose of a sparse matrix in compressed rows, by counting sort, for the
/// first-order backends (they walk both the rows and the columns every iteration).

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace linesurf::solver {

/// A sparse matrix's rows: row r holds the entries offsets[r] .. offsets[r + 1] - 1, entry k at
/// column index[k] with value[k].
template <typename Value>
struct CompressedRows {
  std::vector<std::uint32_t> offsets{0};
  std::vector<std::uint32_t> index;
  std::vector<Value> value;
};

/// The columns of the matrix with rows `offsets`, `index`, `value` over `num_cols` columns, as
/// compressed rows of its transpose: each column's entries in increasing row order.
template <typename Value>
CompressedRows<Value> TransposeRows(std::span<const std::uint32_t> offsets,
                                    std::span<const std::uint32_t> index,
                                    std::span<const Value> value,
                                    std::size_t num_cols) {
  CompressedRows<Value> t;
  t.offsets.assign(num_cols + 1, 0);
  for (std::uint32_t c : index) ++t.offsets[c + 1];
  for (std::size_t j = 0; j < num_cols; ++j) t.offsets[j + 1] += t.offsets[j];
  t.index.resize(index.size());
  t.value.resize(value.size());
  std::vector<std::uint32_t> next(t.offsets.begin(), t.offsets.end() - 1);
  for (std::size_t r = 0; r + 1 < offsets.size(); ++r) {
    for (std::uint32_t k = offsets[r]; k < offsets[r + 1]; ++k) {
      const std::uint32_t pos = next[index[k]]++;
      t.index[pos] = static_cast<std::uint32_t>(r);
      t.value[pos] = value[k];
    }
  }
  return t;
}

}  // namespace linesurf::solver
