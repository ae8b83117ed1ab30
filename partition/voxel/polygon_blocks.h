#pragma once
// The extent of a plane's evidence on the block grid (docs/design/block_engine.md section 2): the
// convex hull of its inliers in the plane, and the base blocks that hull meets. A roof seen only
// by its eaves still covers the blocks between them.

#include "engine/core/geometry.h"
#include "engine/core/strong_id.h"
#include "partition/voxel/block_grid.h"

#include <cstdint>
#include <span>
#include <vector>

namespace linesurf::partition {

/// The convex hull of the inliers' endpoints projected on `plane`, as points of the plane in
/// counter-clockwise order about its normal (CGAL's convex_hull_2 on exact predicates); fewer
/// than 3 points when the endpoints are collinear or coincide.
std::vector<Vec3> InlierHull(const Plane3& plane,
                             std::span<const Segment3> segments,
                             std::span<const SegmentId> inliers);

/// Base blocks met by the planar convex polygon `polygon` (>= 3 points), increasing linear
/// indices: a separating-axis test (box axes, polygon normal, edge x box axis) of the polygon
/// against each block of its bounding box, touching counted as meeting.
std::vector<std::int64_t> BlocksMetByConvexPolygon(const BlockGrid& grid,
                                                   std::span<const Vec3> polygon);

}  // namespace linesurf::partition
