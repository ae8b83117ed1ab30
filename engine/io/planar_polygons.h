#pragma once
// Faces of one plane joined into polygons with holes: what GIS and BIM formats store per plane
// instead of the convex cell faces the engine extracts (docs/user/formats.md, CityJSON).

#include "engine/core/geometry.h"
#include "engine/core/polygon_mesh.h"

#include <cstdint>
#include <span>
#include <vector>

namespace linesurf::io {

/// A planar polygon: `rings[0]` its outer boundary, counter-clockwise about the plane's normal,
/// the others its holes, clockwise; each ring a cycle of distinct vertex indices.
struct PlanarPolygon {
  std::vector<std::vector<std::uint32_t>> rings;
};

/// @brief Joins the faces `faces` of `mesh` (all on one plane, counter-clockwise about `normal`)
/// across every edge exactly two of them share, in opposite directions: one polygon per
/// edge-connected group, its rings traced along the group's boundary edges so that no ring
/// passes a vertex twice (a hole touching the outer ring at a point stays a hole; corners that
/// touch at a point only are two groups). Vertices inside a group are dropped; boundary
/// vertices, collinear ones included,
/// are kept, so the polygons share every vertex the faces shared with the rest of the mesh.
/// A group whose boundary does not trace into one outer ring and holes inside it stays as its
/// faces. Polygons in the order of their first face in `faces`; deterministic.
[[nodiscard]] std::vector<PlanarPolygon> JoinIntoPlanarPolygons(const PolygonMesh& mesh,
                                                              std::span<const std::uint32_t> faces,
                                                              const Vec3& normal);

}  // namespace linesurf::io
