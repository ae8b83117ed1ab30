#pragma once
// What block faces keep off (internal to partition/voxel: face_clearance.cpp and
// split_face_chooser.cpp): per axis, the coordinate ranges of the planes parallel to that axis'
// faces and of the planes' inlier slabs (docs/design/block_engine.md, section 1).

#include "engine/core/geometry.h"
#include "engine/core/strong_id.h"

#include <algorithm>
#include <array>
#include <limits>
#include <span>
#include <utility>
#include <vector>

namespace linesurf::partition::internal {

/// Per axis, coordinate ranges that faces must keep off: sorted by their low end, with the
/// running maximum of the high ends, so a face is tested in O(log n).
class AxisRanges {
 public:
  void Add(int axis, std::pair<double, double> range) { ranges_[axis].push_back(range); }

  void Seal() {
    for (int a = 0; a < 3; ++a) {
      std::sort(ranges_[a].begin(), ranges_[a].end());
      max_hi_[a].resize(ranges_[a].size());
      double hi = -std::numeric_limits<double>::infinity();
      for (std::size_t i = 0; i < ranges_[a].size(); ++i) {
        hi = std::max(hi, ranges_[a][i].second);
        max_hi_[a][i] = hi;
      }
    }
  }

  /// Whether `x` lies within `margin` of a range along `axis` (after Seal).
  [[nodiscard]] bool Near(int axis, double x, double margin) const {
    const auto& r = ranges_[axis];
    const auto end =
        std::upper_bound(r.begin(), r.end(), x + margin, [](double v, const auto& range) {
          return v < range.first;
        });
    if (end == r.begin()) return false;
    return max_hi_[axis][static_cast<std::size_t>(end - r.begin()) - 1] >= x - margin;
  }

 private:
  std::array<std::vector<std::pair<double, double>>, 3> ranges_;
  std::array<std::vector<double>, 3> max_hi_;
};

/// What faces keep off, strictest first (both sealed). A face that cannot clear the first set
/// clears the second.
struct KeepOffRanges {
  /// The planes nearly parallel to each axis' faces (the plane's coordinate along the axis varies
  /// by less than clearance * size over the box), and the slab of every plane whose inliers'
  /// endpoints span less than a tenth of `size` along the axis.
  AxisRanges planes_and_slabs;
  AxisRanges planes;  ///< the planes alone
};

/// The ranges for faces of blocks of side `size` in `box`; `inliers` holds one list per plane,
/// of `segments` (none: no slabs).
KeepOffRanges BuildKeepOffRanges(const Box3& box,
                                 double size,
                                 std::span<const Plane3> planes,
                                 std::span<const Segment3> segments,
                                 std::span<const std::vector<SegmentId>> inliers,
                                 double clearance);

}  // namespace linesurf::partition::internal
