#include "engine/detect/collinear_groups.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <tuple>

#include <Eigen/Geometry>

#include "engine/detect/segment_geometry.h"

namespace linesurf::detect {
namespace {
/// Bucket widths of the line hash, as multiples of the tolerance (distance) and in radians
/// (direction): coarse enough that duplicates share a bucket, fine enough to keep buckets small.
constexpr double kFootBucketOverTolerance = 100.0;
constexpr double kDirectionBucket = 1e-3;

/// Both endpoints of `b` within `tolerance` of the infinite line of `a`.
bool OnLineOf(const Segment3& a, const Segment3& b, double tolerance) {
  const Vec3 d = a.p2 - a.p1;
  const double len = d.norm();
  if (!(len > 0.0)) return false;
  const CreaseLine line{a.p1, d / len};
  return SegmentLineDistance(b, line, SegmentDistance::kMaxEndpoint) <= tolerance;
}
}  // namespace

CollinearGroups GroupCollinearSegments(std::span<const Segment3> segments, double tolerance) {
  // Hash every segment's line (canonical direction, foot of the perpendicular from the origin);
  // a segment joins the first group of its bucket whose first member it is collinear with.
  using Key = std::tuple<std::int64_t, std::int64_t, std::int64_t, std::int64_t, std::int64_t,
                         std::int64_t>;
  std::map<Key, std::vector<std::uint32_t>> buckets;  // bucket -> groups
  std::vector<std::vector<SegmentId>> groups;
  const double foot_bucket = kFootBucketOverTolerance * tolerance;
  for (std::size_t i = 0; i < segments.size(); ++i) {
    const Segment3& s = segments[i];
    Vec3 u = s.p2 - s.p1;
    const double len = u.norm();
    std::uint32_t group = static_cast<std::uint32_t>(groups.size());
    if (len > 0.0) {
      u /= len;
      int axis = 0;
      u.cwiseAbs().maxCoeff(&axis);
      if (u[axis] < 0.0) u = -u;
      const Vec3 foot = s.p1 - s.p1.dot(u) * u;
      // Rounded, so that exact zeros (axis-aligned lines, feet at the origin) sit mid-bucket.
      auto q = [](double v, double w) {
        return static_cast<std::int64_t>(std::floor(v / w + 0.5));
      };
      const Key key{q(u.x(), kDirectionBucket), q(u.y(), kDirectionBucket),
                    q(u.z(), kDirectionBucket), q(foot.x(), foot_bucket),
                    q(foot.y(), foot_bucket),   q(foot.z(), foot_bucket)};
      std::vector<std::uint32_t>& bucket = buckets[key];
      for (const std::uint32_t g : bucket) {
        const Segment3& first = segments[groups[g].front().index()];
        if (OnLineOf(first, s, tolerance) && OnLineOf(s, first, tolerance)) {
          group = g;
          break;
        }
      }
      if (group == groups.size()) bucket.push_back(group);
    }
    if (group == groups.size()) groups.emplace_back();
    groups[group].emplace_back(i);
  }
  CollinearGroups out;
  out.lines.reserve(groups.size());
  for (const std::vector<SegmentId>& members : groups) {
    const Segment3& first = segments[members.front().index()];
    out.members.AddRow(members);
    if (members.size() == 1) {
      out.lines.push_back(first);
      continue;
    }
    const Vec3 u = (first.p2 - first.p1).normalized();
    double lo = 0.0;
    double hi = 0.0;
    for (const SegmentId m : members) {
      for (const Vec3& p : {segments[m.index()].p1, segments[m.index()].p2}) {
        const double t = (p - first.p1).dot(u);
        lo = std::min(lo, t);
        hi = std::max(hi, t);
      }
    }
    out.lines.push_back({first.p1 + lo * u, first.p1 + hi * u});
  }
  return out;
}

}  // namespace linesurf::detect
