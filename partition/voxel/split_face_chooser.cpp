#include "partition/voxel/split_face_chooser.h"

namespace linesurf::partition {
namespace {

/// Candidates on each side of the middle.
constexpr int kCandidatesPerSide = 1024;

}  // namespace

SplitFaceChooser::SplitFaceChooser(const Box3& box,
                                   double size,
                                   std::span<const Plane3> planes,
                                   std::span<const Segment3> segments,
                                   std::span<const std::vector<SegmentId>> inliers,
                                   double clearance)
    : keep_off_(internal::BuildKeepOffRanges(box, size, planes, segments, inliers, clearance)),
      margin_(clearance * size) {}

double SplitFaceChooser::Choose(int axis, double lo, double hi) const {
  const double mid = 0.5 * (lo + hi);
  const double step = (hi - lo) / (4.0 * kCandidatesPerSide);
  for (const internal::AxisRanges* ranges : {&keep_off_.planes_and_slabs, &keep_off_.planes}) {
    for (int k = 0; k <= 2 * kCandidatesPerSide; ++k) {
      const double offset = static_cast<double>((k + 1) / 2) * step;
      const double x = k % 2 == 0 ? mid - offset : mid + offset;
      if (!ranges->Near(axis, x, margin_)) return x;
    }
  }
  return mid;
}

}  // namespace linesurf::partition
