#pragma once
/// @file extract_surface.h
/// @brief Labels of the cells of a complex -> the closed, outward-oriented 2-manifold surface
/// between full and empty cells (DESIGN 2.4).
///
/// The surface is the set of facets whose two cells have different labels (the space outside the
/// box has the label ExtractOptions::outside_full). Each face is oriented from the full to the
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

#include <cstdint>
#include <span>
#include <vector>

#include "engine/core/cell_complex.h"
#include "engine/core/polygon_mesh.h"
#include "linesurf/error.h"

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
[[nodiscard]] Expected<ExtractResult> ExtractSurface(const CellComplex& complex,
                                                     std::span<const std::uint8_t> labels,
                                                     const ExtractOptions& options) noexcept;

}  // namespace linesurf::pipeline
