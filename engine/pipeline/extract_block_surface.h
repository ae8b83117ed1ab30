#pragma once
/// @file extract_block_surface.h
/// @brief The stitch of the block engine (docs/design/block_engine.md, section 6): labels of the
/// cells of all blocks -> one closed, outward-oriented, conforming 2-manifold surface.
///
/// Within one complex: the surface is the set of facets whose two cells have different labels
/// (the space outside the box has the label ExtractOptions::outside_full). Each face is oriented from the full to the
/// empty cell (counter-clockwise seen from the empty side: normals point outwards). Vertices are
/// shared by complex vertex (plane triple), never welded by coordinates. Where the full region
/// pinches (two full cells meeting only along an edge or at a vertex) the surface is made a
/// 2-manifold by splitting: around every complex vertex the faces are walked as umbrellas, two
/// faces at an edge being joined when they bound the same run of full cells around it; each
/// umbrella gets its own output vertex. Where an edge keeps several face pairs between the same
/// two output vertices (both ends single umbrellas), every face pair of that edge gets a vertex
/// of its own at the edge midpoint (all of them, also pairs whose ends are other umbrellas at the
/// same points, so no midpoint lies on another face's edge: no T-junction). The result is closed,
/// 2-manifold and consistently oriented by construction.
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
/// block's edge star inside a block (as within one complex), by exact angular order around the
/// edge on block faces. Then the back end (umbrella split, midpoints, output; surface_assembly.h)
/// runs on the one surface.

#include "linesurf/error.h"

#include "engine/core/polygon_mesh.h"
#include "engine/core/run_context.h"
#include "partition/arrangement/block_complexes.h"

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace linesurf::pipeline {

struct ExtractOptions {
  /// Label of the space outside the box: false (empty) for exterior scenes, true (full) for
  /// interior scenes. Box facets join the surface only where a cell on the box differs from it.
  bool outside_full = false;
  /// Triangulate the convex faces: a fan from the first corner, or from an added centroid
  /// vertex when a face has straight corners (vertices of neighbouring facets on its sides), so
  /// no triangle is degenerate. Default false: convex polygons.
  bool triangulate = false;
  /// Block engine only (ExtractBlockSurface): faces of one plane (an input plane, or a block face
  /// carrying seam facets), on the same side of it, that meet alone across an edge (on a block
  /// face, or where a plane without surface there cuts them) are merged into one polygon where
  /// the union is one simple polygon (it may then be non-convex, so not together with
  /// `triangulate`). Default false: the facets of the blocks and seams.
  bool merge_coplanar = false;
};

struct ExtractStats {
  std::size_t surface_facets = 0;
  /// Output vertices beyond one per complex vertex used (umbrella splits of pinched vertices,
  /// edge midpoints).
  std::size_t split_vertices = 0;
  /// Complex edges with more than two surface facets (split into manifold pairs).
  std::size_t non_manifold_edges = 0;
};

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
/// their first (block, vertex) occurrence.
[[nodiscard]] Expected<BlockExtractResult> ExtractBlockSurface(
    const partition::BlockComplexes& complexes,
    std::span<const std::uint8_t> labels,
    const ExtractOptions& options,
    const RunContext& ctx) noexcept;

}  // namespace linesurf::pipeline
