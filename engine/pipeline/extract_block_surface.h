#pragma once
/// @file extract_block_surface.h
/// @brief The stitch of the block engine (docs/design/block_engine.md, section 6): labels of the
/// cells of all blocks -> one closed, outward-oriented, conforming 2-manifold surface, the same
/// kind of result as ExtractSurface gives for one complex.
///
/// Surface faces are the block facets between cells of different labels (interior facets, and
/// scene-boundary facets against the outside, whose label is ExtractOptions::outside_full) and
/// the seam facets of the overlay whose two cells differ (a block's own facets on a shared face
/// never are: the overlay replaces them). Vertices are plane triples with global keys; a point
/// named by different triples in different facets or blocks becomes one vertex, merged by exact
/// coincidence tests (rounded coordinates only find candidates). Every output vertex lying inside
/// an edge on a block face (a seam vertex of the other side, a vertex of a neighbouring block on a
/// block edge) is inserted into that edge in exact order, so there are no T-junctions. Faces
/// around an edge are paired into manifold fans by the runs of full cells around it: from the
/// block's edge star inside a block (as ExtractSurface does), by exact angular order around the
/// edge on block faces. Then the back end of ExtractSurface (umbrella split, midpoints, output)
/// runs on the one surface.

#include "linesurf/error.h"

#include "engine/core/polygon_mesh.h"
#include "engine/core/run_context.h"
#include "engine/pipeline/extract_surface.h"
#include "partition/arrangement/block_complexes.h"

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace linesurf::pipeline {

/// The facet an output face comes from: facet `facet` of block `owner`, or seam facet `facet` of
/// BlockComplexes::seams[owner] (the first of the merged facets with merge_coplanar).
struct BlockFacetRef {
  bool seam = false;
  std::uint32_t owner = 0;
  std::uint32_t facet = 0;
  friend bool operator==(const BlockFacetRef&, const BlockFacetRef&) = default;
};

struct StitchStats {
  std::size_t seam_surface_facets = 0;   ///< surface faces from seam facets
  std::size_t merged_vertex_keys = 0;    ///< distinct triples merged into another triple's vertex
  std::size_t inserted_vertices = 0;     ///< vertices inserted into edges (T-junctions removed)
  std::size_t edges_on_block_faces = 0;  ///< surface edges paired across blocks and seams
  std::size_t merged_faces = 0;  ///< faces merged into larger ones (ExtractOptions::merge_coplanar)
};

struct BlockExtractResult {
  /// Vertices in the frame of the block complexes.
  PolygonMesh mesh;
  /// The facet of every output face (several per facet when triangulated).
  std::vector<BlockFacetRef> face_facet;
  /// A triple of every output vertex (none for added midpoints and centroids).
  std::vector<std::optional<partition::VertexKey>> vertex_key;
  ExtractStats stats;
  StitchStats stitch;
};

/// @brief Extracts the surface between full (label 1) and empty (label 0) cells of all blocks.
/// @param labels one label per global cell (partition::GlobalCellOffsets).
/// @return kInvalidInput when `labels` has the wrong size; kInvalidOptions for merge_coplanar
/// with triangulate; kInternal on broken complexes.
/// Deterministic for any ctx.num_threads: faces in block order (each block's facets in FacetId
/// order, then the seam facets of the faces it is the lower block of), vertices in order of
/// their first (block, vertex) occurrence. With one block the mesh is ExtractSurface's.
[[nodiscard]] Expected<BlockExtractResult> ExtractBlockSurface(
    const partition::BlockComplexes& complexes,
    std::span<const std::uint8_t> labels,
    const ExtractOptions& options,
    const RunContext& ctx) noexcept;

}  // namespace linesurf::pipeline
