#pragma once
// Where a crowded block's slab is cut (docs/design/block_engine.md, section 1): near the middle of
// its interval, kept off the planes parallel to the face and off the planes' inlier slabs, for the
// reasons of face_clearance.h (a face a hair from a wall leaves a cell too thin to triangulate;
// one through a noisy wall's slab splits its evidence).

#include "engine/core/geometry.h"
#include "engine/core/strong_id.h"
#include "partition/voxel/face_keep_off_ranges.h"

#include <span>
#include <vector>

namespace linesurf::partition {

class SplitFaceChooser {
 public:
  /// `size` is the grid's nominal block side: the clearance is clearance * size, the slabs those
  /// of SizeClearOfParallelPlanes at that size.
  SplitFaceChooser(const Box3& box,
                   double size,
                   std::span<const Plane3> planes,
                   std::span<const Segment3> segments,
                   std::span<const std::vector<SegmentId>> inliers,
                   double clearance = 1e-6);

  /// A face coordinate for cutting [lo, hi] along `axis`: the first of mid, mid + d, mid - d,
  /// mid + 2d, ... (d = (hi - lo) / 4096, within a quarter of the interval either way, so each
  /// piece keeps at least a quarter of it) that keeps clear of the planes and the slabs; else the
  /// first that clears the planes alone; else mid.
  [[nodiscard]] double Choose(int axis, double lo, double hi) const;

 private:
  internal::KeepOffRanges keep_off_;
  double margin_ = 0.0;
};

}  // namespace linesurf::partition
