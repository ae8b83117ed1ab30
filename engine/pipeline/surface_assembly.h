#pragma once
/// @file surface_assembly.h
/// @brief The back end of ExtractBlockSurface (block complexes and their seams; the tests' one
/// complex extraction, tests/support/one_complex_surface.h, uses it too): oriented surface cycles whose edges are paired into
/// manifold fans -> output vertices per umbrella, midpoints on edges that would be shared by
/// several face pairs, optional triangulation, the mesh in face order.

#include "engine/core/cell_complex.h"
#include "engine/core/polygon_mesh.h"
#include "engine/core/strong_id.h"

#include <cstdint>
#include <span>
#include <vector>

namespace linesurf::pipeline {

/// A face of SurfaceCycles (in cycle order).
struct SurfaceFaceTag {};
using SurfaceFaceId = StrongId<SurfaceFaceTag>;
/// An edge of the surface, shared by every face on it (ids chosen by the front end).
struct SurfaceEdgeTag {};
using SurfaceEdgeId = StrongId<SurfaceEdgeTag>;
/// A candidate vertex: an index into the points given to AssembleSurface.
struct CandidateVertexTag {};
using CandidateVertexId = StrongId<CandidateVertexTag>;

/// The surface faces as cycles oriented from full to empty (counter-clockwise seen from the
/// empty side). Corner k of a face has a candidate vertex (an index into the points given to
/// AssembleSurface) and the edge from it to the next corner (an id shared by every face on that
/// edge); partner[k] is the face joined to it across that edge (the other face bounding the
/// same run of full cells around the edge; invalid until the front end fills it).
struct SurfaceCycles {
  std::vector<std::uint32_t> offsets{0};  ///< corners of face s: [offsets[s], offsets[s+1])
  std::vector<std::uint32_t> corner_vertex;
  std::vector<SurfaceEdgeId> corner_edge;
  std::vector<SurfaceFaceId> partner;

  [[nodiscard]] std::size_t NumFaces() const { return offsets.size() - 1; }
  /// Appends a face from a cycle stored counter-clockwise seen from the side its normal points
  /// to, with edge i from vertex i to i + 1; `reverse` when that side is the full one.
  void AddCycle(std::span<const std::uint32_t> vertices,
                std::span<const std::uint32_t> edges,
                bool reverse);
  /// Corner index of edge `edge` in face `face` (the corner the edge leaves from).
  [[nodiscard]] std::uint32_t EdgeSlot(SurfaceFaceId face, SurfaceEdgeId edge) const;
  /// The corner after corner k of face `face`.
  [[nodiscard]] std::uint32_t NextCorner(SurfaceFaceId face, std::uint32_t k) const {
    return k + 1 < offsets[face.index() + 1] ? k + 1 : offsets[face.index()];
  }
};

/// Two surface faces joined across an edge that holds more than two surface faces.
struct EdgePair {
  SurfaceEdgeId edge;
  SurfaceFaceId a;
  SurfaceFaceId b;
};

/// Pairs the surface facets around the edges of one complex by the runs of full cells in each
/// edge's star (an open chain on the box closes outside, whose label is `outside_full`).
/// `face_of_facet` maps a facet to its surface face (invalid when not on the surface); the
/// face's corner edges are `edge_offset + EdgeId::index()`. Edges with a facet flagged in
/// `skip_facet` (empty: none) are left to the caller. Appends the pairs of edges with more than
/// two surface facets to `crowded`, in edge order; returns the number of such edges.
std::size_t PairAroundComplexEdges(const CellComplex& cx,
                                   std::span<const std::uint8_t> labels,
                                   bool outside_full,
                                   std::span<const SurfaceFaceId> face_of_facet,
                                   std::uint32_t edge_offset,
                                   std::span<const std::uint8_t> skip_facet,
                                   SurfaceCycles& cycles,
                                   std::vector<EdgePair>& crowded);

struct AssembledSurface {
  PolygonMesh mesh;
  /// The surface face (index into the cycles) of every output face.
  std::vector<std::uint32_t> face_cycle;
  /// The candidate vertex of every output vertex (invalid for midpoints and centroids).
  std::vector<CandidateVertexId> vertex_source;
  /// Output vertices beyond one per candidate vertex used.
  std::size_t split_vertices = 0;
};

/// Output vertices per umbrella (fan of paired faces) of every candidate vertex, in candidate
/// order; midpoints where several pairs of `crowded` (grouped by edge) would share one output
/// edge; faces in cycle order, triangulated on request (a fan from the first corner, or from an
/// added centroid when the face has a straight corner). Throws kInternal on unpaired corners.
AssembledSurface AssembleSurface(const SurfaceCycles& cycles,
                                 std::span<const Vec3> points,
                                 std::span<const EdgePair> crowded,
                                 bool triangulate);

}  // namespace linesurf::pipeline
