#include "engine/detect/collinear_groups.h"

#include "engine/detect/segment_geometry.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

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
  // a segment joins the first group of its bucket (groups in order of their first member) whose
  // first member it is collinear with. The buckets are runs of the segments sorted by key, not
  // a map: a city's 185k buckets in a tree of nodes cost 38x a 19k-segment city's time.
  using Key = std::array<std::int64_t, 6>;
  const double foot_bucket = kFootBucketOverTolerance * tolerance;
  std::vector<std::pair<Key, std::uint32_t>> keyed;  // (bucket, segment); degenerate ones aside
  std::vector<std::uint32_t> lone;                   // zero-length segments: groups of their own
  keyed.reserve(segments.size());
  for (std::size_t i = 0; i < segments.size(); ++i) {
    const Segment3& s = segments[i];
    Vec3 u = s.p2 - s.p1;
    const double len = u.norm();
    if (!(len > 0.0)) {
      lone.push_back(static_cast<std::uint32_t>(i));
      continue;
    }
    u /= len;
    int axis = 0;
    u.cwiseAbs().maxCoeff(&axis);
    if (u[axis] < 0.0) u = -u;
    const Vec3 foot = s.p1 - s.p1.dot(u) * u;
    // Rounded, so that exact zeros (axis-aligned lines, feet at the origin) sit mid-bucket.
    auto q = [](double v, double w) { return static_cast<std::int64_t>(std::floor(v / w + 0.5)); };
    keyed.push_back({Key{q(u.x(), kDirectionBucket),
                         q(u.y(), kDirectionBucket),
                         q(u.z(), kDirectionBucket),
                         q(foot.x(), foot_bucket),
                         q(foot.y(), foot_bucket),
                         q(foot.z(), foot_bucket)},
                     static_cast<std::uint32_t>(i)});
  }
  std::sort(keyed.begin(), keyed.end());  // by bucket, then by segment
  std::vector<std::vector<SegmentId>> groups;
  for (const std::uint32_t i : lone) groups.push_back({SegmentId(i)});
  for (std::size_t begin = 0; begin < keyed.size();) {
    std::size_t end = begin;
    while (end < keyed.size() && keyed[end].first == keyed[begin].first) ++end;
    const std::size_t first_group = groups.size();
    for (std::size_t k = begin; k < end; ++k) {
      const Segment3& s = segments[keyed[k].second];
      std::size_t g = first_group;
      for (; g < groups.size(); ++g) {
        const Segment3& first = segments[groups[g].front().index()];
        if (OnLineOf(first, s, tolerance) && OnLineOf(s, first, tolerance)) break;
      }
      if (g == groups.size()) groups.emplace_back();
      groups[g].emplace_back(keyed[k].second);
    }
    begin = end;
  }
  // Groups ordered by first member, as documented.
  std::vector<std::uint32_t> order(groups.size());
  for (std::size_t g = 0; g < order.size(); ++g) order[g] = static_cast<std::uint32_t>(g);
  std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
    return groups[a].front() < groups[b].front();
  });
  CollinearGroups out;
  out.lines.reserve(groups.size());
  for (const std::uint32_t g : order) {
    const std::vector<SegmentId>& members = groups[g];
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
