#pragma once
// The exact overlay of the two subdivisions of a block face shared by two blocks
// (docs/design/block_engine.md, section 3). Internal to partition/arrangement: used by
// BuildBlockComplexes and ValidateBlockComplexes.

#include "partition/arrangement/block_complexes.h"

#include <vector>

namespace linesurf::partition {

/// A facet of one block on a block face, as a convex polygon of the face: its vertex cycle and,
/// for edge i (vertex i to i + 1), the plane whose trace on the face carries the edge and the
/// side of that plane the polygon lies on (side * sign(plane) >= 0 inside).
struct SeamPolygon {
  FacetId facet;
  CellId cell;
  std::vector<VertexKey> vertices;
  std::vector<PlaneKey> edge_planes;
  std::vector<int> edge_sides;
  std::vector<Vec3> points;  ///< rounded vertices
  Vec3 lo = Vec3::Zero();    ///< box of the rounded vertices
  Vec3 hi = Vec3::Zero();
};

/// Global key of box plane `local` (0..5) of a block.
PlaneKey BoxPlaneKey(const Eigen::Vector3i& base, int local);

/// Exact sign of plane `plane` at the vertex `vertex`.
int SignAt(const BlockComplexes& complexes, const VertexKey& vertex, PlaneKey plane);

/// The facets of `block` on its box plane `local_face`, as polygons.
std::vector<SeamPolygon> FacePolygons(const BlockComplex& block, int local_face);

/// The seam facets of one face: every intersection of positive area of a lower polygon with an
/// upper polygon, by exact clipping, in (lower polygon, upper polygon) order.
std::vector<SeamFacet> OverlayFace(const BlockComplexes& complexes,
                                   PlaneKey face,
                                   const std::vector<SeamPolygon>& lower,
                                   const std::vector<SeamPolygon>& upper);

/// true when the polygon has a vertex strictly off the line of one of its edges (exact): a
/// convex polygon then has positive area.
bool HasArea(const BlockComplexes& complexes,
             const std::vector<VertexKey>& vertices,
             const std::vector<PlaneKey>& edge_planes);

/// The area of a planar polygon from its rounded points.
double PolygonArea(const std::vector<Vec3>& points);

}  // namespace linesurf::partition
