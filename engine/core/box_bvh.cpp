#include "engine/core/box_bvh.h"

#include <algorithm>
#include <limits>
#include <utility>

namespace linesurf {
namespace {

/// Boxes per leaf at most.
constexpr std::uint32_t kLeafBoxes = 4;

}  // namespace

BoxBvh::BoxBvh(const std::vector<Box3>& boxes) : boxes_(boxes) {
  for (std::size_t i = 0; i < boxes_.size(); ++i) {
    if (!boxes_[i].IsEmpty()) order_.push_back(static_cast<std::uint32_t>(i));
  }
  if (order_.empty()) return;
  nodes_.reserve(2 * order_.size());
  nodes_.emplace_back();
  Build(0, 0, static_cast<std::uint32_t>(order_.size()));
}

void BoxBvh::Build(std::uint32_t node, std::uint32_t begin, std::uint32_t end) {
  Box3 box;
  Box3 centres;
  for (std::uint32_t k = begin; k < end; ++k) {
    const Box3& b = boxes_[order_[k]];
    box.Extend(b.min);
    box.Extend(b.max);
    centres.Extend(b.Center());
  }
  nodes_[node].box = box;
  if (end - begin <= kLeafBoxes) {
    nodes_[node].first = begin;
    nodes_[node].count = end - begin;
    return;
  }
  int axis = 0;
  centres.Extent().maxCoeff(&axis);
  const std::uint32_t mid = begin + (end - begin) / 2;
  // Ties broken by index: the tree, and so the order of the answers, is fixed by the boxes.
  std::nth_element(order_.begin() + begin,
                   order_.begin() + mid,
                   order_.begin() + end,
                   [&](std::uint32_t a, std::uint32_t b) {
                     const double ca = boxes_[a].Center()[axis];
                     const double cb = boxes_[b].Center()[axis];
                     return ca < cb || (ca == cb && a < b);
                   });
  const auto left = static_cast<std::uint32_t>(nodes_.size());
  nodes_[node].first = left;
  nodes_[node].count = 0;
  nodes_.emplace_back();
  nodes_.emplace_back();
  Build(left, begin, mid);
  Build(left + 1, mid, end);
}

bool BoxBvh::RayMeetsBox(const Vec3& origin, const Vec3& direction, const Box3& box) {
  double t_min = 0.0;
  double t_max = std::numeric_limits<double>::infinity();
  for (int a = 0; a < 3; ++a) {
    if (direction[a] == 0.0) {
      if (origin[a] < box.min[a] || origin[a] > box.max[a]) return false;
      continue;
    }
    double t0 = (box.min[a] - origin[a]) / direction[a];
    double t1 = (box.max[a] - origin[a]) / direction[a];
    if (t0 > t1) std::swap(t0, t1);
    t_min = std::max(t_min, t0);
    t_max = std::min(t_max, t1);
    if (t_min > t_max) return false;
  }
  return true;
}

}  // namespace linesurf
