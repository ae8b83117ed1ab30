#include "engine/detect/segment_bvh.h"

#include <algorithm>

namespace linesurf::detect {
namespace {
constexpr std::uint32_t kLeafSize = 8;
}  // namespace

SegmentBvh::SegmentBvh(std::span<const Segment3> segments) {
  const auto n = static_cast<std::uint32_t>(segments.size());
  order_.reserve(n);
  for (std::uint32_t i = 0; i < n; ++i) order_.emplace_back(i);
  if (n == 0) return;
  nodes_.reserve(2 * (n / kLeafSize + 1));
  nodes_.emplace_back();
  Build(segments);
  position_.assign(n, 0);
  for (std::uint32_t i = 0; i < n; ++i) position_[order_[i].index()] = i;
}

// Builds the tree under the root nodes_[0] over all of order_; children are allocated as a pair
// so that a node stores only the index of its first child. Depth is O(log n) (median splits).
void SegmentBvh::Build(std::span<const Segment3> segments) {
  struct Task {
    std::uint32_t node, begin, end;
  };
  std::vector<Task> tasks{{0, 0, static_cast<std::uint32_t>(order_.size())}};
  while (!tasks.empty()) {
    const Task task = tasks.back();
    tasks.pop_back();
    Box3 box;
    Box3 mid_box;
    for (std::uint32_t i = task.begin; i < task.end; ++i) {
      const Segment3& s = segments[order_[i].index()];
      box.Extend(s.p1);
      box.Extend(s.p2);
      mid_box.Extend(s.Midpoint());
    }
    Node& node = nodes_[task.node];
    node.center = box.Center();
    node.half_extent = 0.5 * box.Extent();
    node.begin = task.begin;
    node.end = task.end;
    node.leaf = task.end - task.begin <= kLeafSize;
    if (node.leaf) continue;
    int axis = 0;
    mid_box.Extent().maxCoeff(&axis);
    const std::uint32_t mid = task.begin + (task.end - task.begin) / 2;
    // Total order (coordinate, then id): the split does not depend on the sort implementation.
    std::nth_element(order_.begin() + task.begin, order_.begin() + mid, order_.begin() + task.end,
                     [&](SegmentId a, SegmentId b) {
                       const double ca = segments[a.index()].Midpoint()[axis];
                       const double cb = segments[b.index()].Midpoint()[axis];
                       return ca < cb || (ca == cb && a < b);
                     });
    const auto first_child = static_cast<std::uint32_t>(nodes_.size());
    nodes_[task.node].leaf = false;
    nodes_[task.node].begin = first_child;
    nodes_.emplace_back();
    nodes_.emplace_back();
    // Push right first so that the left subtree is built (and laid out) first.
    tasks.push_back({first_child + 1, mid, task.end});
    tasks.push_back({first_child, task.begin, mid});
  }
}

}  // namespace linesurf::detect
