#pragma once
// Distances of segments to planes and to crease lines, and the length-weighted plane fit used
// by plane detection (internal to engine/detect).

#include <cmath>
#include <span>

#include "engine/core/geometry.h"
#include "engine/core/strong_id.h"
#include "engine/detect/detect_planes.h"

namespace linesurf::detect {

/// Combines two endpoint distances according to `mode`.
inline double CombineEndpoints(double d1, double d2, SegmentDistance mode) {
  return mode == SegmentDistance::kMeanEndpoint ? 0.5 * (d1 + d2) : std::max(d1, d2);
}

inline double SegmentPlaneDistance(const Segment3& s, const Plane3& p, SegmentDistance mode) {
  return CombineEndpoints(std::abs(p.SignedDistance(s.p1)), std::abs(p.SignedDistance(s.p2)),
                          mode);
}

/// The line where two planes meet: a point and a unit direction.
struct CreaseLine {
  Vec3 point = Vec3::Zero();
  Vec3 direction = Vec3::UnitX();
};

/// The intersection line of two planes whose normals make at least the angle whose sine is
/// `min_sin` (returns false otherwise).
inline bool IntersectPlanes(const Plane3& a, const Plane3& b, double min_sin, CreaseLine& line) {
  const Vec3 d = a.normal.cross(b.normal);
  const double d2 = d.squaredNorm();
  if (d2 < min_sin * min_sin) return false;
  const double ha = a.normal.dot(a.point);
  const double hb = b.normal.dot(b.point);
  // The point of the line closest to the origin: n_a.x = h_a, n_b.x = h_b, d.x = 0.
  line.point = (ha * b.normal.cross(d) + hb * d.cross(a.normal)) / d2;
  line.direction = d / std::sqrt(d2);
  return true;
}

inline double SegmentLineDistance(const Segment3& s, const CreaseLine& l, SegmentDistance mode) {
  return CombineEndpoints((s.p1 - l.point).cross(l.direction).norm(),
                          (s.p2 - l.point).cross(l.direction).norm(), mode);
}

/// Length-weighted least-squares plane through the endpoints of `ids` (serial, in the given
/// order, so the result is deterministic). The normal keeps the sign of `hint` when possible.
/// `width`, when given, receives the RMS spread of the endpoints across their main direction
/// within the plane (0 for collinear ones): how well the fit's tilt is determined.
Plane3 FitPlane(std::span<const Segment3> segments, std::span<const SegmentId> ids,
                const Vec3& hint, double* width = nullptr);

}  // namespace linesurf::detect
