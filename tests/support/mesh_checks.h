#pragma once
// Mesh invariants for tests, checked with CGAL Polygon_mesh_processing (library
// linesurf_mesh_checks; CGAL stays private to mesh_checks.cpp).

#include <cstddef>
#include <vector>

#include "engine/core/polygon_mesh.h"

namespace linesurf::testing {

/// Everything the checks below compute, in one pass.
struct MeshCheckReport {
  std::size_t num_components = 0;  ///< connected components (faces sharing vertices)
  bool two_manifold = false;       ///< every component is an oriented 2-manifold polygon mesh
  bool closed = false;             ///< 2-manifold and without border edges
  bool outward_oriented = false;   ///< closed, and each component's signed volume has the sign
                                   ///< of its nesting (outer shells > 0, cavities < 0)
  double volume = 0.0;             ///< signed volume, sum over components (closed meshes only)
};

/// Runs every check. Never throws; a mesh CGAL cannot read reports false everywhere.
MeshCheckReport CheckMesh(const PolygonMesh& mesh);

/// Each edge has at most two faces, orientations agree, vertices are manifold.
bool IsTwoManifold(const PolygonMesh& mesh);
/// 2-manifold with no border edge.
bool IsClosed(const PolygonMesh& mesh);
/// Closed and every face normal points from matter to empty space.
bool IsOutwardOriented(const PolygonMesh& mesh);
/// Signed enclosed volume (0 when the mesh is not closed).
double Volume(const PolygonMesh& mesh);
/// For each point: strictly inside the closed mesh (ray parity over all components, so cavities
/// count as outside). Points on the surface count as outside. Empty result if not triangulable.
std::vector<bool> PointsStrictlyInside(const PolygonMesh& mesh, const std::vector<Vec3>& points);

}  // namespace linesurf::testing
