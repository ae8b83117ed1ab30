#pragma once
// Triangles of one planar polygon face of a PolygonMesh: the fan of a convex face, ear clipping
// of a non-convex one (faces merged across block seams, ExtractOptions::merge_coplanar).

#include "engine/core/geometry.h"

#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace linesurf {

/// Triangles (vertex indices, in the face's orientation) covering the simple planar polygon
/// `face` of `vertices`:
/// - no reflex corner (convex, straight corners allowed): the fan from the first corner, as
///   every face was triangulated before non-convex faces existed;
/// - otherwise ear clipping in the face's plane. Straight corners are cut off as degenerate
///   triangles (their edges stay edges of the triangles, so no T-junction appears); if no ear is
///   found (a polygon that is not simple), the rest is fanned.
/// Faces of fewer than 3 corners give no triangle. Deterministic.
[[nodiscard]] std::vector<std::array<std::uint32_t, 3>> FaceTriangles(
    std::span<const Vec3> vertices, std::span<const std::uint32_t> face);

}  // namespace linesurf
