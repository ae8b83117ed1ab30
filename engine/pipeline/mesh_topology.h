#pragma once
/// @file mesh_topology.h
/// @brief The edge and vertex-fan topology of a polygon mesh by vertex index (no welding by
/// coordinates), computed in one pass: what ExtractBlockSurface guarantees, RunStats reports
/// and CheckMeshValidity (engine/pipeline/mesh_validity.h) builds its checks on.

#include "engine/core/polygon_mesh.h"

#include <cstddef>
#include <cstdint>
#include <span>

namespace linesurf::pipeline {

struct MeshTopology {
  std::size_t num_boundary_edges = 0;      ///< undirected edges used by one face
  std::size_t num_non_manifold_edges = 0;  ///< undirected edges used by more than two faces
  /// Directed edges without a unique opposite (boundary, repeated or against their neighbour).
  std::size_t num_unpaired_half_edges = 0;
  std::size_t num_non_manifold_vertices = 0;  ///< vertices whose corners form several fans
  std::size_t num_components = 0;             ///< faces connected through shared edges
  /// Every undirected edge used by two faces is used once in each direction.
  bool consistent = true;
  /// There is a face and every directed edge is used once and its opposite once: closed and
  /// consistently oriented.
  bool paired = false;
  /// Signed volume (divergence theorem over a fan of every face), positive for an
  /// outward-oriented closed mesh.
  double signed_volume = 0.0;

  /// Paired, and the faces around every vertex form a single fan.
  [[nodiscard]] bool IsManifold() const { return paired && num_non_manifold_vertices == 0; }
};

/// @brief The topology of the faces `indices[offsets[f] .. offsets[f+1])` (PolygonMesh's
/// layout) over `vertices`.
/// @pre every index is below vertices.size() (kInternal otherwise). Deterministic; O(F log F).
[[nodiscard]] MeshTopology ComputeMeshTopology(std::span<const Vec3> vertices,
                                               std::span<const std::uint32_t> offsets,
                                               std::span<const std::uint32_t> indices);

/// @brief The topology of every face of `mesh`, as it is (no face folded or left out).
[[nodiscard]] MeshTopology ComputeMeshTopology(const PolygonMesh& mesh);

}  // namespace linesurf::pipeline
