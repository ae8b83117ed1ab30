#pragma once
// A bounding-volume hierarchy over segments for slab queries ("which segments can lie within t
// of this plane") and a spatial order of the segments (its leaf order) for near-pair sampling.

#include "engine/core/geometry.h"
#include "engine/core/strong_id.h"

#include <cstdint>
#include <span>
#include <vector>

namespace linesurf::detect {

class SegmentBvh {
 public:
  /// Builds over `segments` (deterministic: depends only on the input).
  explicit SegmentBvh(std::span<const Segment3> segments);

  /// Calls `fn(SegmentId)` for every segment whose bounding box meets the slab
  /// |n.(x - o)| <= half_thickness, in leaf order.
  template <typename Fn>
  void ForEachInSlab(const Plane3& plane, double half_thickness, Fn&& fn) const {
    AnyInSlab(plane, half_thickness, [&](SegmentId s) {
      fn(s);
      return false;
    });
  }

  /// ForEachInSlab until `fn(SegmentId)` returns true; returns whether it did.
  template <typename Fn>
  bool AnyInSlab(const Plane3& plane, double half_thickness, Fn&& fn) const;

  /// Segments in leaf order (nearby segments are mostly close in this order).
  [[nodiscard]] const std::vector<SegmentId>& Order() const { return order_; }
  /// Position of a segment in Order().
  [[nodiscard]] std::uint32_t PositionOf(SegmentId s) const { return position_[s.index()]; }

 private:
  struct Node {
    Vec3 center = Vec3::Zero();
    Vec3 half_extent = Vec3::Zero();
    std::uint32_t begin = 0;  ///< leaf: range in order_; inner: children at begin, begin+1
    std::uint32_t end = 0;
    bool leaf = true;
  };
  void Build(std::span<const Segment3> segments);

  std::vector<Node> nodes_;
  std::vector<SegmentId> order_;
  std::vector<std::uint32_t> position_;
};

template <typename Fn>
bool SegmentBvh::AnyInSlab(const Plane3& plane, double half_thickness, Fn&& fn) const {
  if (nodes_.empty()) return false;
  std::uint32_t stack[128];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const Node& node = nodes_[stack[--top]];
    if (!BoxMeetsSlab(node.center, node.half_extent, plane, half_thickness)) continue;
    if (node.leaf) {
      for (std::uint32_t i = node.begin; i < node.end; ++i) {
        if (fn(order_[i])) return true;
      }
    } else {
      stack[top++] = node.begin + 1;
      stack[top++] = node.begin;
    }
  }
  return false;
}

}  // namespace linesurf::detect
