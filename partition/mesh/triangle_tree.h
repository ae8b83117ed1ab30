#pragma once
/// @file triangle_tree.h
/// @brief The faces of a polygon mesh split into triangles (FaceTriangles), in a CGAL AABB tree
/// (Epick: exact predicates) for nearest-point, distance and segment queries. One helper for every
/// tool that measures a mesh (surface quality without ground truth, evaluation against one); CGAL
/// stays in the implementation.

#include "engine/core/geometry.h"
#include "engine/core/polygon_mesh.h"

#include <array>
#include <cstdint>
#include <memory>
#include <string_view>
#include <vector>

namespace linesurf::partition {

class TriangleTree {
 public:
  /// Splits every face into triangles (FaceTriangles: the fan from its first corner when convex,
  /// ear clipping when not); degenerate triangles (exact collinearity test) have no area and are
  /// skipped. Throws kInvalidInput (stage `stage`, message starting with `name`)
  /// when face offsets or indices are out of range or no triangle has positive area.
  TriangleTree(const PolygonMesh& mesh, std::string_view stage, std::string_view name);
  ~TriangleTree();
  TriangleTree(TriangleTree&&) noexcept;
  TriangleTree& operator=(TriangleTree&&) noexcept;
  TriangleTree(const TriangleTree&) = delete;
  TriangleTree& operator=(const TriangleTree&) = delete;

  [[nodiscard]] std::size_t NumTriangles() const;
  /// Face of the mesh that triangle t comes from.
  [[nodiscard]] std::uint32_t FaceOf(std::size_t t) const;
  [[nodiscard]] std::array<Vec3, 3> Corners(std::size_t t) const;
  [[nodiscard]] double Area(std::size_t t) const;

  struct Nearest {
    Vec3 point;
    double squared_distance = 0.0;
    std::uint32_t triangle = 0;
  };
  /// Nearest point of the mesh to p, and its triangle. Thread-safe (the tree is immutable).
  [[nodiscard]] Nearest Closest(const Vec3& p) const;
  [[nodiscard]] double SquaredDistance(const Vec3& p) const;
  /// True when the closed segment a-b meets a triangle.
  [[nodiscard]] bool Intersects(const Vec3& a, const Vec3& b) const;
  /// Every triangle the closed segment a-b meets (cleared first, in the tree's order).
  void IntersectedTriangles(const Vec3& a, const Vec3& b, std::vector<std::uint32_t>& out) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace linesurf::partition
