#pragma once
// Block faces kept off the planes parallel to them (docs/design/block_engine.md, section 1). A
// plane a hair's breadth from a block face (a wall on the centre line of a symmetric scene, where
// the automatic size L / 2^k puts a face) cuts the block into a cell thinner than the rounding
// of its vertices: its faces come out with zero area and the surface cannot be triangulated.

#include "engine/core/geometry.h"

#include <span>

namespace linesurf::partition {

/// The first size s = size * (1 + k / 1024), k = 0, 1, ..., 1023, whose interior block faces in
/// `box` (box.min + i s per axis, as BlockGrid::Create places them) lie at least clearance * s
/// from every plane nearly parallel to them (whose coordinate along that axis varies by less than
/// clearance * s over the box); `size` when none does.
[[nodiscard]] double SizeClearOfParallelPlanes(const Box3& box,
                                               double size,
                                               std::span<const Plane3> planes,
                                               double clearance = 1e-6);

}  // namespace linesurf::partition
