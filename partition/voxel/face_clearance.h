#pragma once
// Block faces kept off the planes parallel to them (docs/design/block_engine.md, section 1). A
// plane a hair's breadth from a block face (a wall on the centre line of a symmetric scene, where
// halving the extent puts a face) cuts the block into a cell thinner than the rounding of its
// vertices: its faces come out with zero area and the surface cannot be triangulated. A face
// through the slab of a noisy wall's inliers leaves that wall's evidence split between two
// blocks and a sliver between them (synth house at 2 cm, seed 4: a notch in the wall).

#include "engine/core/geometry.h"
#include "engine/core/strong_id.h"

#include <span>
#include <vector>

namespace linesurf::partition {

/// The first size s = size * (1 + k / 1024), k = 0, 1, ..., 1023, whose interior block faces in
/// `box` (box.min + i s per axis, as BlockGrid::Create places them) lie at least clearance * s
/// - from every plane nearly parallel to them (whose coordinate along that axis varies by less
///   than clearance * s over the box), and
/// - when `inliers` (one list per plane, of `segments`) are given, from the slab of every plane
///   whose inliers' endpoints span less than a tenth of `size` along that axis.
/// When no size clears the slabs as well, the first that clears the planes; `size` when none
/// does.
[[nodiscard]] double SizeClearOfParallelPlanes(const Box3& box,
                                               double size,
                                               std::span<const Plane3> planes,
                                               std::span<const Segment3> segments = {},
                                               std::span<const std::vector<SegmentId>> inliers = {},
                                               double clearance = 1e-6);

}  // namespace linesurf::partition
