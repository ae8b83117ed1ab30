#pragma once
// Typed element ids (never raw ints) and per-element containers indexed by them.

#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <vector>

namespace linesurf {

template <typename Tag>
class StrongId {
 public:
  using ValueType = std::uint32_t;
  static constexpr ValueType kInvalidValue = std::numeric_limits<ValueType>::max();

  constexpr StrongId() = default;
  constexpr explicit StrongId(ValueType value) : value_(value) {}
  constexpr explicit StrongId(std::size_t value) : value_(static_cast<ValueType>(value)) {}
  static constexpr StrongId Invalid() { return StrongId(); }

  [[nodiscard]] constexpr ValueType value() const { return value_; }
  [[nodiscard]] constexpr std::size_t index() const { return value_; }
  [[nodiscard]] constexpr bool IsValid() const { return value_ != kInvalidValue; }

  friend constexpr auto operator<=>(StrongId, StrongId) = default;

 private:
  ValueType value_ = kInvalidValue;
};

struct SegmentTag {};
struct ViewpointTag {};
struct PlaneTag {};
struct BlockTag {};
struct CellTag {};
struct FacetTag {};
struct EdgeTag {};
struct VertexTag {};

using SegmentId = StrongId<SegmentTag>;
using ViewpointId = StrongId<ViewpointTag>;
using PlaneId = StrongId<PlaneTag>;
using BlockId = StrongId<BlockTag>;
using CellId = StrongId<CellTag>;
using FacetId = StrongId<FacetTag>;
using EdgeId = StrongId<EdgeTag>;
using VertexId = StrongId<VertexTag>;

/// A std::vector indexed by a StrongId.
template <typename Id, typename T>
class IdVector {
 public:
  IdVector() = default;
  explicit IdVector(std::size_t n, const T& value = T()) : data_(n, value) {}

  T& operator[](Id id) { return data_[id.index()]; }
  const T& operator[](Id id) const { return data_[id.index()]; }
  [[nodiscard]] std::size_t size() const { return data_.size(); }
  [[nodiscard]] bool empty() const { return data_.empty(); }
  void push_back(T value) { data_.push_back(std::move(value)); }
  template <typename... Args>
  T& emplace_back(Args&&... args) {
    return data_.emplace_back(std::forward<Args>(args)...);
  }
  void resize(std::size_t n) { data_.resize(n); }
  void reserve(std::size_t n) { data_.reserve(n); }
  void clear() { data_.clear(); }
  [[nodiscard]] Id NextId() const { return Id(data_.size()); }
  auto begin() { return data_.begin(); }
  auto end() { return data_.end(); }
  auto begin() const { return data_.begin(); }
  auto end() const { return data_.end(); }
  std::vector<T>& raw() { return data_; }
  const std::vector<T>& raw() const { return data_; }

 private:
  std::vector<T> data_;
};

}  // namespace linesurf

template <typename Tag>
struct std::hash<linesurf::StrongId<Tag>> {
  std::size_t operator()(linesurf::StrongId<Tag> id) const noexcept {
    return std::hash<std::uint32_t>()(id.value());
  }
};
