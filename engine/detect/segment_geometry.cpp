#include "engine/detect/segment_geometry.h"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>

namespace linesurf::detect {
namespace {
/// A fit whose two largest spreads differ by more than this ratio is collinear: keep the hint.
constexpr double kCollinearEigenRatio = 1e-12;
}  // namespace

Plane3 FitPlane(std::span<const Segment3> segments, std::span<const SegmentId> ids,
                const Vec3& hint, double* width) {
  if (width != nullptr) *width = 0.0;
  double total = 0.0;
  Vec3 centroid = Vec3::Zero();
  for (const SegmentId s : ids) {
    const Segment3& seg = segments[s.index()];
    const double w = seg.Length();
    total += 2.0 * w;
    centroid += w * (seg.p1 + seg.p2);
  }
  Plane3 plane;
  plane.normal = hint.normalized();
  if (!(total > 0.0)) return plane;
  centroid /= total;
  plane.point = centroid;
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  for (const SegmentId s : ids) {
    const Segment3& seg = segments[s.index()];
    const double w = seg.Length();
    const Vec3 a = seg.p1 - centroid;
    const Vec3 b = seg.p2 - centroid;
    cov += w * (a * a.transpose() + b * b.transpose());
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(cov);
  const Vec3 values = eig.eigenvalues();  // ascending
  if (width != nullptr) *width = std::sqrt(std::max(0.0, values[1]) / total);
  if (values[1] <= kCollinearEigenRatio * values[2]) return plane;  // collinear: keep hint
  Vec3 normal = eig.eigenvectors().col(0).normalized();
  if (normal.dot(hint) < 0.0) normal = -normal;
  plane.normal = normal;
  return plane;
}

}  // namespace linesurf::detect
