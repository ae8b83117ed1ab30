#include "partition/voxel/face_clearance.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

namespace linesurf::partition {
namespace {

constexpr int kSteps = 1024;

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

using AxisRanges = std::array<std::vector<std::pair<double, double>>, 3>;

bool FacesClear(const Box3& box, double size, const AxisRanges& ranges, double margin) {
  for (int a = 0; a < 3; ++a) {
    const double extent = box.max[a] - box.min[a];
    const int blocks = std::max(1, static_cast<int>(std::ceil(extent / size)));
    for (int i = 1; i < blocks; ++i) {
      const double face = box.min[a] + i * size;
      for (const auto& [lo, hi] : ranges[a]) {
        if (face >= lo - margin && face <= hi + margin) return false;
      }
    }
  }
  return true;
}

}  // namespace

double SizeClearOfParallelPlanes(const Box3& box,
                                 double size,
                                 std::span<const Plane3> planes,
                                 double clearance) {
  AxisRanges ranges;
  const double width = clearance * size;
  for (const Plane3& plane : planes) {
    for (int a = 0; a < 3; ++a) {
      const auto range = NarrowRange(plane, box, a, width);
      if (range.first <= range.second) ranges[a].push_back(range);
    }
  }
  for (int k = 0; k < kSteps; ++k) {
    const double s = size * (1.0 + static_cast<double>(k) / kSteps);
    if (FacesClear(box, s, ranges, clearance * s)) return s;
  }
  return size;
}

}  // namespace linesurf::partition
