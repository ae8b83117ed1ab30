#include "partition/voxel/face_clearance.h"

#include "partition/voxel/face_keep_off_ranges.h"

#include <algorithm>
#include <cmath>
#include <optional>

namespace linesurf::partition {
namespace {

using internal::AxisRanges;

constexpr int kSteps = 1024;

bool FacesClear(const Box3& box, double size, const AxisRanges& ranges, double margin) {
  for (int a = 0; a < 3; ++a) {
    const double extent = box.max[a] - box.min[a];
    const int blocks = std::max(1, static_cast<int>(std::ceil(extent / size)));
    for (int i = 1; i < blocks; ++i) {
      if (ranges.Near(a, box.min[a] + i * size, margin)) return false;
    }
  }
  return true;
}

/// The first size of the search whose faces clear `ranges`, if any.
std::optional<double> FirstClearSize(const Box3& box,
                                     double size,
                                     const AxisRanges& ranges,
                                     double clearance) {
  for (int k = 0; k < kSteps; ++k) {
    const double s = size * (1.0 + static_cast<double>(k) / kSteps);
    if (FacesClear(box, s, ranges, clearance * s)) return s;
  }
  return std::nullopt;
}

}  // namespace

double SizeClearOfParallelPlanes(const Box3& box,
                                 double size,
                                 std::span<const Plane3> planes,
                                 std::span<const Segment3> segments,
                                 std::span<const std::vector<SegmentId>> inliers,
                                 double clearance) {
  const internal::KeepOffRanges keep_off =
      internal::BuildKeepOffRanges(box, size, planes, segments, inliers, clearance);
  // Without inliers both sets are the planes': one search is enough.
  if (!inliers.empty()) {
    if (const auto s = FirstClearSize(box, size, keep_off.planes_and_slabs, clearance)) return *s;
  }
  return FirstClearSize(box, size, keep_off.planes, clearance).value_or(size);
}

}  // namespace linesurf::partition
