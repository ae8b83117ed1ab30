#pragma once
// Twice the vector area of a planar polygon: the sum of the fan's cross products about its first
// corner. Its direction is the polygon's counter-clockwise normal and its length twice the area,
// for non-convex polygons too; taken about the first corner, so polygons far from the origin
// lose no precision.

#include "engine/core/geometry.h"

#include <Eigen/Geometry>

#include <cstddef>
#include <cstdint>
#include <span>

namespace linesurf {

/// Twice the vector area of the polygon whose corner k is point(k), k in [0, n).
template <typename Point>
Vec3 TwiceVectorArea(std::size_t n, Point&& point) {
  Vec3 sum = Vec3::Zero();
  if (n < 3) return sum;
  const Vec3 origin = point(0);
  for (std::size_t k = 1; k + 1 < n; ++k) sum += (point(k) - origin).cross(point(k + 1) - origin);
  return sum;
}

/// Twice the vector area of the polygon `face` (indices into `vertices`).
inline Vec3 TwiceVectorArea(std::span<const Vec3> vertices, std::span<const std::uint32_t> face) {
  return TwiceVectorArea(face.size(),
                         [&](std::size_t k) -> const Vec3& { return vertices[face[k]]; });
}

/// Twice the vector area of the polygon with corners `points`.
inline Vec3 TwiceVectorArea(std::span<const Vec3> points) {
  return TwiceVectorArea(points.size(), [&](std::size_t k) -> const Vec3& { return points[k]; });
}

}  // namespace linesurf
