#pragma once
// Exact geometric predicates on planes given by double coefficients (a, b, c, d) and on points
// with double coordinates. Each one is a floating-point filter with an exact fallback; the
// CGAL number types stay inside exact_predicates.cpp (the only CGAL translation unit of the
// arrangement).
//
// A vertex is the intersection of three independent planes (i, j, k). The sign of plane l at it
// is sign(det4[[ni di]; [nj dj]; [nk dk]; [nl dl]]) * sign(det3[ni; nj; nk]) (expanding det4 along
// its last row gives det3 * (nl . x + dl)).

#include <atomic>
#include <cstdint>

#include <Eigen/Core>

#include "engine/core/geometry.h"

namespace linesurf::partition {

/// Counts how often a predicate needed exact arithmetic (may be shared by threads).
struct ExactCounter {
  std::atomic<std::uint64_t> exact_fallbacks{0};
};

/// -1 / +1 when a*x + b*y + c*z + d is certainly of that sign over the whole box [lo, hi], by a
/// double evaluation with a rigorous rounding bound; 0 when it cannot tell. The filter in front
/// of the exact predicates below, and of the cell complex's tests over vertex and cell boxes.
int FilteredBoxSide(const Eigen::Vector4d& plane, const Vec3& lo, const Vec3& hi);

/// sign(a*x + b*y + c*z + d) exactly, in {-1, 0, +1}.
int ExactSignAtPoint(const Eigen::Vector4d& plane, const Vec3& p, ExactCounter* counter = nullptr);

/// sign(n . v) exactly.
int ExactSignDot(const Vec3& n, const Vec3& v, ExactCounter* counter = nullptr);

/// sign(det[n1; n2; n3]) exactly.
int ExactSignDet3(const Vec3& n1, const Vec3& n2, const Vec3& n3, ExactCounter* counter = nullptr);

/// The sign of plane `l` at the vertex of the independent planes (i, j, k), exactly.
int ExactSignAtVertex(const Eigen::Vector4d& i, const Eigen::Vector4d& j, const Eigen::Vector4d& k,
                      const Eigen::Vector4d& l, ExactCounter* counter = nullptr);

/// +1 when p = s*q with s > 0, -1 when s < 0, 0 when p and q are not proportional (exact).
int ExactProportionality(const Eigen::Vector4d& p, const Eigen::Vector4d& q,
                         ExactCounter* counter = nullptr);

/// true when the normals of the two planes are parallel (exact; cross product zero).
bool ExactParallelNormals(const Eigen::Vector4d& p, const Eigen::Vector4d& q,
                          ExactCounter* counter = nullptr);

/// Around the line of direction l = p x q (p, q normals of two planes through it), the
/// directions a x l and b x l: the sign of l . ((a x l) x (b x l)) (> 0: b x l is less than half a
/// turn counter-clockwise about l from a x l) and the sign of their dot product, exactly.
struct AngularSigns {
  int orientation = 0;
  int dot = 0;
};
AngularSigns ExactAngularSigns(const Vec3& a, const Vec3& b, const Vec3& p, const Vec3& q,
                               ExactCounter* counter = nullptr);

/// A box that certainly contains the vertex of the independent planes (i, j, k), and its
/// rounded coordinates (for output only).
struct VertexBounds {
  Vec3 lo = Vec3::Zero();
  Vec3 hi = Vec3::Zero();
  Vec3 approx = Vec3::Zero();
};
VertexBounds ComputeVertexBounds(const Eigen::Vector4d& i, const Eigen::Vector4d& j,
                                 const Eigen::Vector4d& k, ExactCounter* counter = nullptr);

}  // namespace linesurf::partition
