#include "partition/voxel/face_keep_off_ranges.h"

#include "engine/core/endpoint_box.h"

#include <cmath>

namespace linesurf::partition::internal {
namespace {

/// A plane's inliers form a slab along an axis when they span less than this many block sizes.
constexpr double kSlabWidth = 0.1;

// The range of the plane's coordinate along `axis` over the box, when that range is narrower
// than `width`; empty (lo > hi) otherwise.
std::pair<double, double> NarrowRange(const Plane3& plane,
                                      const Box3& box,
                                      int axis,
                                      double width) {
  const double na = plane.normal[axis];
  if (na == 0.0) return {1.0, 0.0};
  const int b = (axis + 1) % 3;
  const int c = (axis + 2) % 3;
  double lo = std::numeric_limits<double>::infinity();
  double hi = -lo;
  for (const double yb : {box.min[b], box.max[b]}) {
    for (const double yc : {box.min[c], box.max[c]}) {
      const double x =
          (plane.normal.dot(plane.point) - plane.normal[b] * yb - plane.normal[c] * yc) / na;
      lo = std::min(lo, x);
      hi = std::max(hi, x);
    }
  }
  if (!(hi - lo < width)) return {1.0, 0.0};
  return {lo, hi};
}

/// The ranges of the planes nearly parallel to the faces of each axis (perpendicular to it: the
/// plane's coordinate along the axis varies by less than `width` over the box).
AxisRanges ParallelPlaneRanges(const Box3& box, std::span<const Plane3> planes, double width) {
  AxisRanges ranges;
  for (const Plane3& plane : planes) {
    for (int a = 0; a < 3; ++a) {
      const auto range = NarrowRange(plane, box, a, width);
      if (range.first <= range.second) ranges.Add(a, range);
    }
  }
  return ranges;
}

/// Adds, per axis, the span of each plane's inlier endpoints when it is narrower than `width`.
void AddInlierSlabs(std::span<const Segment3> segments,
                    std::span<const std::vector<SegmentId>> inliers,
                    double width,
                    AxisRanges& ranges) {
  for (const std::vector<SegmentId>& list : inliers) {
    if (list.empty()) continue;
    const Box3 span = EndpointBox(segments, list);
    for (int a = 0; a < 3; ++a) {
      if (span.max[a] - span.min[a] < width) ranges.Add(a, {span.min[a], span.max[a]});
    }
  }
}

}  // namespace

KeepOffRanges BuildKeepOffRanges(const Box3& box,
                                 double size,
                                 std::span<const Plane3> planes,
                                 std::span<const Segment3> segments,
                                 std::span<const std::vector<SegmentId>> inliers,
                                 double clearance) {
  KeepOffRanges ranges;
  ranges.planes = ParallelPlaneRanges(box, planes, clearance * size);
  ranges.planes_and_slabs = ranges.planes;
  AddInlierSlabs(segments, inliers, kSlabWidth * size, ranges.planes_and_slabs);
  ranges.planes.Seal();
  ranges.planes_and_slabs.Seal();
  return ranges;
}

}  // namespace linesurf::partition::internal
