#pragma once
/// @file mesh_topology.h
/// @brief Combinatorial and geometric checks of a polygon mesh: closed, 2-manifold, consistently
/// oriented, outward, self-intersecting, number of connected components.

#include <cstddef>

#include "engine/core/polygon_mesh.h"
#include "linesurf/error.h"

namespace linesurf {

/// What the checks found. Connectivity is by vertex index, as CGAL's halfedge meshes see it: two
/// vertices at the same position are different vertices (linesurf's extraction splits
/// non-manifold vertices that way on purpose); num_coincident_vertices counts them.
struct MeshTopology {
  /// No boundary edge: every undirected edge is used by exactly two faces (and the mesh has faces).
  bool closed = false;
  /// Every edge is used by at most two faces and the faces around every vertex form one fan.
  bool two_manifold = false;
  /// Every edge used by two faces is traversed once in each direction.
  bool oriented = false;
  /// Closed, oriented and with positive signed volume (normals point outwards).
  bool outward = false;
  /// Two faces intersect other than at a shared edge or vertex (CGAL self_intersections on the
  /// triangulated faces). Pairs that have a corner position in common are taken as touching
  /// there and not counted (split vertices; a crossing elsewhere in such a pair is missed).
  bool self_intersecting = false;
  /// Connected components, faces linked through shared edges.
  std::size_t num_components = 0;
  std::size_t num_faces = 0;
  std::size_t num_vertices = 0;
  /// Vertices at the bit-identical position of another vertex.
  std::size_t num_coincident_vertices = 0;
  std::size_t num_boundary_edges = 0;
  std::size_t num_non_manifold_edges = 0;    ///< used by more than two faces
  std::size_t num_non_manifold_vertices = 0;  ///< whose incident faces form several fans
  std::size_t num_degenerate_faces = 0;       ///< fewer than 3 distinct vertices
  /// Signed volume enclosed (divergence theorem over the faces); meaningful when closed.
  double signed_volume = 0.0;
  double area = 0.0;
};

/// @brief Checks the topology of `mesh`.
/// @return the checks, or kInvalidInput for an index out of range. Deterministic; O(F log F)
/// plus CGAL's self-intersection test (AABB box intersection, O(F log F) typical).
Expected<MeshTopology> CheckMeshTopology(const PolygonMesh& mesh) noexcept;

}  // namespace linesurf
