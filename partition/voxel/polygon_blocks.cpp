#include "partition/voxel/polygon_blocks.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/convex_hull_2.h>
#include <Eigen/Geometry>

#include <algorithm>
#include <iterator>
#include <limits>

namespace linesurf::partition {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;

// An orthonormal basis (u, v) of the plane with u x v along the normal.
std::pair<Vec3, Vec3> PlaneBasis(const Vec3& normal) {
  const Vec3 n = normal.normalized();
  const Vec3 helper = std::abs(n.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY();
  const Vec3 u = helper.cross(n).normalized();
  return {u, n.cross(u)};
}

// Whether the projections of the polygon and the box on `axis` are apart by more than `tol`.
bool Separates(const Vec3& axis,
               std::span<const Vec3> polygon,
               const Vec3& centre,
               const Vec3& half,
               double tol) {
  double lo = std::numeric_limits<double>::infinity();
  double hi = -lo;
  for (const Vec3& p : polygon) {
    const double x = axis.dot(p);
    lo = std::min(lo, x);
    hi = std::max(hi, x);
  }
  const double c = axis.dot(centre);
  const double r = half.dot(axis.cwiseAbs());
  const double slack = tol * axis.norm();
  return lo > c + r + slack || hi < c - r - slack;
}

}  // namespace

std::vector<Vec3> InlierHull(const Plane3& plane,
                             std::span<const Segment3> segments,
                             std::span<const SegmentId> inliers) {
  const auto [u, v] = PlaneBasis(plane.normal);
  std::vector<Kernel::Point_2> points;
  points.reserve(2 * inliers.size());
  for (const SegmentId s : inliers) {
    for (const Vec3& p : {segments[s.index()].p1, segments[s.index()].p2}) {
      const Vec3 d = p - plane.point;
      points.emplace_back(u.dot(d), v.dot(d));
    }
  }
  std::vector<Kernel::Point_2> hull;
  CGAL::convex_hull_2(points.begin(), points.end(), std::back_inserter(hull));
  std::vector<Vec3> out;
  out.reserve(hull.size());
  for (const Kernel::Point_2& q : hull) out.push_back(plane.point + q.x() * u + q.y() * v);
  return out;
}

std::vector<std::int64_t> BlocksMetByConvexPolygon(const BlockGrid& grid,
                                                   std::span<const Vec3> polygon) {
  std::vector<std::int64_t> out;
  if (polygon.size() < 3) return out;
  Box3 bounds;
  for (const Vec3& p : polygon) bounds.Extend(p);
  const double tol = 1e-9 * grid.block_size();
  const Eigen::Vector3i first = grid.Locate(bounds.min - Vec3::Constant(tol));
  const Eigen::Vector3i last = grid.Locate(bounds.max + Vec3::Constant(tol));
  // Separating axes: the box's, the polygon's normal, and its edges x the box's.
  std::vector<Vec3> axes{Vec3::UnitX(), Vec3::UnitY(), Vec3::UnitZ()};
  Vec3 normal = Vec3::Zero();
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const Vec3 edge = polygon[(i + 1) % polygon.size()] - polygon[i];
    normal += (polygon[i] - polygon[0]).cross(edge);
    for (int a = 0; a < 3; ++a) axes.push_back(edge.cross(Vec3::Unit(a)));
  }
  axes.push_back(normal);
  for (int z = first.z(); z <= last.z(); ++z) {
    for (int y = first.y(); y <= last.y(); ++y) {
      for (int x = first.x(); x <= last.x(); ++x) {
        const Eigen::Vector3i base(x, y, z);
        const Box3 box = grid.BlockBox({0, base});
        const Vec3 centre = box.Center();
        const Vec3 half = 0.5 * box.Extent();
        const bool apart = std::any_of(axes.begin(), axes.end(), [&](const Vec3& axis) {
          return axis.squaredNorm() > 0.0 && Separates(axis, polygon, centre, half, tol);
        });
        if (!apart) out.push_back(grid.LinearIndex(base));
      }
    }
  }
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace linesurf::partition
