#pragma once
// Test support: the surface between full and empty cells of one cell complex, assembled by the
// pipeline's back end (surface_assembly.h) as ExtractBlockSurface assembles it within a block
// (the surface rules are extract_block_surface.h's), so the extraction can be tested on
// hand-made complexes (tests/support/grid_complex.h) and the stitch compared with one complex.

#include <cstdint>
#include <span>
#include <vector>

#include "engine/core/cell_complex.h"
#include "engine/core/polygon_mesh.h"
#include "engine/pipeline/extract_block_surface.h"
#include "linesurf/error.h"

namespace linesurf::pipeline::testing {

struct ExtractResult {
  /// Vertices in the complex's local frame.
  PolygonMesh mesh;
  /// The complex facet of every output face (several per facet when triangulated).
  std::vector<FacetId> face_facet;
  /// The complex vertex of every output vertex (invalid for added midpoints and centroids).
  std::vector<VertexId> vertex_source;
  ExtractStats stats;
};

/// @brief Extracts the surface between full (label 1) and empty (label 0) cells.
/// @param labels one label per cell, index = CellId::index().
/// @return kInvalidInput when `labels` has the wrong size; kInternal on a broken complex.
/// Deterministic (faces in FacetId order, vertices in VertexId order), O(size of the complex).
[[nodiscard]] Expected<ExtractResult> ExtractOneComplexSurface(
    const CellComplex& complex,
    std::span<const std::uint8_t> labels,
    const ExtractOptions& options) noexcept;

}  // namespace linesurf::pipeline::testing
