#pragma once
// Plain geometric value types shared by every module (local-frame doubles, metres).

#include <Eigen/Core>

#include <cmath>
#include <limits>

namespace linesurf {

using Vec3 = Eigen::Vector3d;

/// A 3D line segment between two endpoints.
struct Segment3 {
  Vec3 p1 = Vec3::Zero();
  Vec3 p2 = Vec3::Zero();

  [[nodiscard]] double Length() const { return (p2 - p1).norm(); }
  [[nodiscard]] Vec3 Midpoint() const { return 0.5 * (p1 + p2); }
};

/// A plane through `point` with unit `normal`; signed distance n.(x - point).
struct Plane3 {
  Vec3 point = Vec3::Zero();
  Vec3 normal = Vec3::UnitZ();

  [[nodiscard]] double SignedDistance(const Vec3& x) const { return normal.dot(x - point); }
  [[nodiscard]] double Offset() const { return -normal.dot(point); }  ///< d in n.x + d = 0
};

/// An axis-aligned box.
struct Box3 {
  Vec3 min = Vec3::Constant(std::numeric_limits<double>::infinity());
  Vec3 max = Vec3::Constant(-std::numeric_limits<double>::infinity());

  [[nodiscard]] bool IsEmpty() const { return !(min.array() <= max.array()).all(); }
  void Extend(const Vec3& p) {
    min = min.cwiseMin(p);
    max = max.cwiseMax(p);
  }
  [[nodiscard]] Vec3 Extent() const { return max - min; }
  [[nodiscard]] Vec3 Center() const { return 0.5 * (min + max); }
  [[nodiscard]] bool Contains(const Vec3& p) const {
    return (p.array() >= min.array()).all() && (p.array() <= max.array()).all();
  }
  /// Whether the two boxes share a point (boundaries included); an empty box meets none.
  [[nodiscard]] bool Overlaps(const Box3& other) const {
    return (min.array() <= other.max.array()).all() && (other.min.array() <= max.array()).all();
  }
};

/// Whether the box of `center` and `half_extent` comes within `half_thickness` of the plane:
/// no point of a box that fails it lies closer, so neither does any segment inside it.
inline bool BoxMeetsSlab(const Vec3& center, const Vec3& half_extent, const Plane3& plane,
                         double half_thickness) {
  return std::abs(plane.SignedDistance(center)) <=
         plane.normal.cwiseAbs().dot(half_extent) + half_thickness;
}

/// Rigid transform: world = rotation * local + translation. Sanitation sets the translation
/// (georeferenced inputs sit 1e6 m from the origin) and, when it aligns the scene with the data's
/// own axes (engine/pipeline/data_frame.h), the rotation; an identity rotation is never applied,
/// so that a translation-only frame keeps its values exact.
struct Rigid3 {
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  Vec3 translation = Vec3::Zero();

  [[nodiscard]] bool HasRotation() const { return rotation != Eigen::Matrix3d::Identity(); }
  /// A direction (a normal, an axis) from local to world.
  [[nodiscard]] Vec3 Rotate(const Vec3& local) const {
    return HasRotation() ? Vec3(rotation * local) : local;
  }
  [[nodiscard]] Vec3 Apply(const Vec3& local) const { return Rotate(local) + translation; }
  [[nodiscard]] Vec3 ApplyInverse(const Vec3& world) const {
    const Vec3 moved = world - translation;
    return HasRotation() ? Vec3(rotation.transpose() * moved) : moved;
  }
};

}  // namespace linesurf
