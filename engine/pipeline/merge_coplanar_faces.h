#pragma once
/// @file merge_coplanar_faces.h
/// @brief Coplanar neighbouring faces of the stitched surface merged into one polygon
/// (ExtractOptions::merge_coplanar, docs/design/block_engine.md section 6).

#include "engine/pipeline/surface_assembly.h"

#include <cstdint>
#include <span>
#include <vector>

namespace linesurf::pipeline {

/// Two faces on one plane, on the same side of it, that are the only faces on edge `edge`.
struct FlatJoin {
  SurfaceEdgeId edge;
  SurfaceFaceId a;
  SurfaceFaceId b;
};

struct MergedCycles {
  SurfaceCycles cycles;
  /// The first (smallest) old face of every new face.
  std::vector<std::uint32_t> first_face;
  /// `crowded` with its faces renumbered.
  std::vector<EdgePair> crowded;
  std::size_t merged_faces = 0;  ///< old faces that became part of a larger face
};

/// Joins the faces connected through `joins` into one face each, where the union is one simple
/// polygon: its boundary is one cycle through distinct vertices, no two members meet across an
/// edge that is not a join, and the vertices it drops (inside the union) are used by no other
/// face. Other groups stay as they are. New faces in the order of their first old face; a merged
/// face starts at its first member's first boundary corner. Partners and `crowded` renumbered.
[[nodiscard]] MergedCycles MergeAcrossJoins(const SurfaceCycles& cycles,
                                            std::span<const FlatJoin> joins,
                                            std::span<const EdgePair> crowded,
                                            std::size_t num_vertices);

}  // namespace linesurf::pipeline
