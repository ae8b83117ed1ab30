#pragma once
// Compressed rows: a list of variable-length lists, indexed by a StrongId.

#include <cstdint>
#include <span>
#include <vector>

namespace linesurf {

template <typename Id, typename T>
class Csr {
 public:
  /// Appends one row and returns its id.
  template <typename Range>
  Id AddRow(const Range& row) {
    items_.insert(items_.end(), row.begin(), row.end());
    offsets_.push_back(static_cast<std::uint32_t>(items_.size()));
    return Id(offsets_.size() - 2);
  }
  [[nodiscard]] std::span<const T> operator[](Id id) const {
    return {items_.data() + offsets_[id.index()], items_.data() + offsets_[id.index() + 1]};
  }
  [[nodiscard]] std::span<T> Mutable(Id id) {
    return {items_.data() + offsets_[id.index()], items_.data() + offsets_[id.index() + 1]};
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
