#include "partition/voxel/face_clearance.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <utility>
#include <vector>

namespace linesurf::partition {
namespace {

constexpr int kSteps = 1024;
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

}  // namespace

/// Per axis, coordinate ranges that faces must keep off: sorted by their low end, with the
/// running maximum of the high ends, so a face is tested in O(log n). (Outside the anonymous
/// namespace: SplitFaceChooser holds two.)
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

namespace {

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

/// Adds, per axis, the span of each plane's inlier endpoints when it is narrower than `width`.
void AddInlierSlabs(std::span<const Segment3> segments,
                    std::span<const std::vector<SegmentId>> inliers,
                    double width,
                    AxisRanges& ranges) {
  for (const std::vector<SegmentId>& list : inliers) {
    if (list.empty()) continue;
    Box3 span;
    for (const SegmentId id : list) {
      span.Extend(segments[id.index()].p1);
      span.Extend(segments[id.index()].p2);
    }
    for (int a = 0; a < 3; ++a) {
      if (span.max[a] - span.min[a] < width) ranges.Add(a, {span.min[a], span.max[a]});
    }
  }
}

/// The ranges of the planes nearly parallel to each axis (coordinate varying by less than
/// `width` over the box).
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

}  // namespace

double SizeClearOfParallelPlanes(const Box3& box,
                                 double size,
                                 std::span<const Plane3> planes,
                                 std::span<const Segment3> segments,
                                 std::span<const std::vector<SegmentId>> inliers,
                                 double clearance) {
  AxisRanges ranges = ParallelPlaneRanges(box, planes, clearance * size);
  if (!inliers.empty()) {
    AxisRanges with_slabs = ranges;
    AddInlierSlabs(segments, inliers, kSlabWidth * size, with_slabs);
    with_slabs.Seal();
    if (const auto s = FirstClearSize(box, size, with_slabs, clearance)) return *s;
  }
  ranges.Seal();
  return FirstClearSize(box, size, ranges, clearance).value_or(size);
}

struct SplitFaceChooser::Ranges {
  AxisRanges planes;
  AxisRanges planes_and_slabs;
};

SplitFaceChooser::SplitFaceChooser(const Box3& box,
                                   double size,
                                   std::span<const Plane3> planes,
                                   std::span<const Segment3> segments,
                                   std::span<const std::vector<SegmentId>> inliers,
                                   double clearance)
    : ranges_(std::make_unique<Ranges>()), margin_(clearance * size) {
  ranges_->planes = ParallelPlaneRanges(box, planes, clearance * size);
  ranges_->planes_and_slabs = ranges_->planes;
  AddInlierSlabs(segments, inliers, kSlabWidth * size, ranges_->planes_and_slabs);
  ranges_->planes.Seal();
  ranges_->planes_and_slabs.Seal();
}

SplitFaceChooser::~SplitFaceChooser() = default;

double SplitFaceChooser::Choose(int axis, double lo, double hi) const {
  const double mid = 0.5 * (lo + hi);
  const double step = (hi - lo) / (4.0 * kSteps);
  for (const AxisRanges* ranges : {&ranges_->planes_and_slabs, &ranges_->planes}) {
    for (int k = 0; k <= 2 * kSteps; ++k) {
      const double offset = static_cast<double>((k + 1) / 2) * step;
      const double x = k % 2 == 0 ? mid - offset : mid + offset;
      if (!ranges->Near(axis, x, margin_)) return x;
    }
  }
  return mid;
}

}  // namespace linesurf::partition
