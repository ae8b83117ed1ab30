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

// A separating-axis candidate with the polygon's projection on it.
struct Axis {
  Vec3 direction;
  double lo = 0.0;
  double hi = 0.0;
};

Axis ProjectPolygon(const Vec3& direction, std::span<const Vec3> polygon) {
  Axis axis{
      direction, std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()};
  for (const Vec3& p : polygon) {
    const double x = direction.dot(p);
    axis.lo = std::min(axis.lo, x);
    axis.hi = std::max(axis.hi, x);
  }
  return axis;
}

// Whether the polygon's and the box's projections on `axis` are apart by more than `tol`.
bool Separates(const Axis& axis, const Vec3& centre, const Vec3& half, double tol) {
  const double c = axis.direction.dot(centre);
  const double r = half.dot(axis.direction.cwiseAbs());
  const double slack = tol * axis.direction.norm();
  return axis.lo > c + r + slack || axis.hi < c - r - slack;
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
  // Separating axes: the box's, the polygon's normal, and its edges x the box's; the polygon is
  // projected on each once.
  std::vector<Vec3> directions{Vec3::UnitX(), Vec3::UnitY(), Vec3::UnitZ()};
  Vec3 normal = Vec3::Zero();
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const Vec3 edge = polygon[(i + 1) % polygon.size()] - polygon[i];
    normal += (polygon[i] - polygon[0]).cross(edge);
    for (int a = 0; a < 3; ++a) directions.push_back(edge.cross(Vec3::Unit(a)));
  }
  directions.push_back(normal);
  std::vector<Axis> axes;
  for (const Vec3& d : directions) {
    if (d.squaredNorm() > 0.0) axes.push_back(ProjectPolygon(d, polygon));
  }
  for (int z = first.z(); z <= last.z(); ++z) {
    for (int y = first.y(); y <= last.y(); ++y) {
      for (int x = first.x(); x <= last.x(); ++x) {
        const Eigen::Vector3i base(x, y, z);
        const Box3 box = grid.BlockBox({0, base});
        const Vec3 centre = box.Center();
        const Vec3 half = 0.5 * box.Extent();
        const bool apart = std::any_of(axes.begin(), axes.end(), [&](const Axis& axis) {
          return Separates(axis, centre, half, tol);
        });
        if (!apart) out.push_back(grid.LinearIndex(base));
      }
    }
  }
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace linesurf::partition
