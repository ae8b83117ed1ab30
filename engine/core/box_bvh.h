#pragma once
// A bounding volume hierarchy over axis-aligned boxes, queried by rays, plane slabs and boxes:
// which boxes may a ray, a slab or a box meet, in O(log n + answers) instead of n box tests (the
// scene-mode decision casts 14 rays per viewpoint against every plane's outline, the surface
// quality asks every plane whether some face lies on it, plane fusion pairs the planes whose
// boxes come near: all quadratic in the scene without it).

#include "engine/core/geometry.h"

#include <cstdint>
#include <vector>

namespace linesurf {

class BoxBvh {
 public:
  /// Boxes are referred to by their index in `boxes`; empty boxes are never met.
  explicit BoxBvh(const std::vector<Box3>& boxes);

  /// Calls fn(i) for every box i that the ray {origin + t direction, t >= 0} meets (its boundary
  /// included), in an order fixed by the boxes and the ray, until fn returns true. Returns
  /// whether some fn(i) returned true.
  template <typename Fn>
  bool AnyAlongRay(const Vec3& origin, const Vec3& direction, Fn&& fn) const {
    return AnyMeeting([&](const Box3& box) { return RayMeetsBox(origin, direction, box); }, fn);
  }

  /// Calls fn(i) for every box i that comes within `half_thickness` of `plane` (BoxMeetsSlab),
  /// in an order fixed by the boxes and the plane, until fn returns true. Returns whether some
  /// fn(i) returned true.
  template <typename Fn>
  bool AnyInSlab(const Plane3& plane, double half_thickness, Fn&& fn) const {
    return AnyMeeting(
        [&](const Box3& box) {
          return BoxMeetsSlab(box.Center(), 0.5 * box.Extent(), plane, half_thickness);
        },
        fn);
  }

  /// Calls fn(i) for every box i that overlaps `box` (boundaries included), in an order fixed by
  /// the boxes and `box`, until fn returns true. Returns whether some fn(i) returned true.
  template <typename Fn>
  bool AnyOverlapping(const Box3& box, Fn&& fn) const {
    return AnyMeeting([&](const Box3& b) { return box.Overlaps(b); }, fn);
  }

  /// Whether the ray {origin + t direction, t >= 0} meets `box` (boundary included).
  [[nodiscard]] static bool RayMeetsBox(const Vec3& origin, const Vec3& direction, const Box3& box);

 private:
  /// A leaf holds order_[first, first + count); an inner node (count 0) has its children at
  /// nodes_[first] and nodes_[first + 1].
  struct Node {
    Box3 box;
    std::uint32_t first = 0;
    std::uint32_t count = 0;
  };

  /// The traversal of the queries: `meets` must hold for a node's box whenever it holds for a
  /// box inside it.
  template <typename Meets, typename Fn>
  bool AnyMeeting(Meets&& meets, Fn&& fn) const {
    if (nodes_.empty()) return false;
    std::vector<std::uint32_t> stack{0};
    while (!stack.empty()) {
      const Node& node = nodes_[stack.back()];
      stack.pop_back();
      if (!meets(node.box)) continue;
      if (node.count > 0) {
        for (std::uint32_t k = node.first; k < node.first + node.count; ++k) {
          if (meets(boxes_[order_[k]]) && fn(order_[k])) return true;
        }
      } else {
        stack.push_back(node.first + 1);  // right child
        stack.push_back(node.first);      // left child
      }
    }
    return false;
  }

  void Build(std::uint32_t node, std::uint32_t begin, std::uint32_t end);

  std::vector<Box3> boxes_;
  std::vector<std::uint32_t> order_;
  std::vector<Node> nodes_;
};

}  // namespace linesurf
