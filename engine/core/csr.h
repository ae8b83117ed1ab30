#pragma once
// Compressed rows: a list of variable-length lists, indexed by a StrongId.

#include <cstdint>
#include <span>
#include <type_traits>
#include <vector>

namespace linesurf {

/// The position of a row id: a StrongId's index, or the integer itself.
template <typename Id>
[[nodiscard]] constexpr std::size_t RowIndex(Id id) {
  if constexpr (std::is_integral_v<Id>) {
    return static_cast<std::size_t>(id);
  } else {
    return id.index();
  }
}

/// Rows indexed by `Id` (a StrongId or an unsigned integer) of items `T`.
template <typename Id, typename T>
class Csr {
 public:
  /// Rows from `num_pairs` (row, item) pairs, pair i being (row_of(i), item_of(i)): row r holds
  /// the items of the pairs whose row is r, in pair order (a stable counting sort). Every row is
  /// below `num_rows`.
  template <typename RowOf, typename ItemOf>
  [[nodiscard]] static Csr FromPairs(std::size_t num_rows,
                                     std::size_t num_pairs,
                                     RowOf&& row_of,
                                     ItemOf&& item_of) {
    Csr out;
    out.offsets_.assign(num_rows + 1, 0);
    for (std::size_t i = 0; i < num_pairs; ++i) ++out.offsets_[RowIndex(row_of(i)) + 1];
    for (std::size_t r = 0; r < num_rows; ++r) out.offsets_[r + 1] += out.offsets_[r];
    out.items_.resize(num_pairs);
    std::vector<std::uint32_t> fill(out.offsets_.begin(), out.offsets_.end() - 1);
    for (std::size_t i = 0; i < num_pairs; ++i) {
      out.items_[fill[RowIndex(row_of(i))]++] = item_of(i);
    }
    return out;
  }

  /// The inverse lists: row c of the result holds, in increasing order, the rows that hold
  /// item c (once per occurrence). Every item is below `num_columns`.
  [[nodiscard]] Csr<T, Id> Transpose(std::size_t num_columns) const {
    std::vector<Id> row_of_item(items_.size());
    for (std::size_t r = 0; r < NumRows(); ++r) {
      for (std::uint32_t k = offsets_[r]; k < offsets_[r + 1]; ++k) row_of_item[k] = Id(r);
    }
    return Csr<T, Id>::FromPairs(
        num_columns,
        items_.size(),
        [&](std::size_t k) { return items_[k]; },
        [&](std::size_t k) { return row_of_item[k]; });
  }

  /// Appends one row and returns its id.
  template <typename Range>
  Id AddRow(const Range& row) {
    items_.insert(items_.end(), row.begin(), row.end());
    offsets_.push_back(static_cast<std::uint32_t>(items_.size()));
    return Id(offsets_.size() - 2);
  }
  [[nodiscard]] std::span<const T> operator[](Id id) const {
    return {items_.data() + offsets_[RowIndex(id)], items_.data() + offsets_[RowIndex(id) + 1]};
  }
  [[nodiscard]] std::span<T> Mutable(Id id) {
    return {items_.data() + offsets_[RowIndex(id)], items_.data() + offsets_[RowIndex(id) + 1]};
  }
  [[nodiscard]] std::size_t NumRows() const { return offsets_.size() - 1; }
  [[nodiscard]] std::size_t NumItems() const { return items_.size(); }
  void Clear() {
    offsets_.assign(1, 0);
    items_.clear();
  }
  void Reserve(std::size_t rows, std::size_t items) {
    offsets_.reserve(rows + 1);
    items_.reserve(items);
  }
  [[nodiscard]] const std::vector<std::uint32_t>& offsets() const { return offsets_; }
  [[nodiscard]] const std::vector<T>& items() const { return items_; }

 private:
  std::vector<std::uint32_t> offsets_{0};
  std::vector<T> items_;
};

}  // namespace linesurf
