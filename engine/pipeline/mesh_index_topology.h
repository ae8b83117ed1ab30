#pragma once
/// @file mesh_index_topology.h
/// @brief Combinatorial checks of a polygon mesh by vertex index (no welding by coordinates):
/// what ExtractBlockSurface guarantees and RunStats reports. Geometric checks (self-intersection,
/// welding coincident points) live in engine/pipeline/mesh_validity.h.

#include <cstddef>

#include "engine/core/polygon_mesh.h"

namespace linesurf::pipeline {

struct IndexTopology {
  /// Every directed edge is used once and its opposite once (closed and consistently oriented).
  bool closed = false;
  /// Closed, and the faces around every vertex form a single fan.
  bool manifold = false;
  std::size_t boundary_or_repeated_edges = 0;  ///< directed edges without a unique opposite
  std::size_t non_manifold_vertices = 0;       ///< vertices whose faces form several fans
  /// Signed volume (divergence theorem), positive for an outward-oriented closed mesh.
  double signed_volume = 0.0;
};

/// O(F log F); deterministic. Faces with an index out of range make the mesh neither closed nor
/// manifold.
[[nodiscard]] IndexTopology CheckIndexTopology(const PolygonMesh& mesh);

}  // namespace linesurf::pipeline
