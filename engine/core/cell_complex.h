#pragma once
// The convex cell complex of planes inside a box, as plain data with full incidence. Built by
// partition/arrangement (BuildCellComplex), read by the engine (evidence, extraction). One complex
// per block box; nothing here refers to any other complex.
//
// Conventions:
// - Complex planes are a*x + b*y + c*z + d = 0 in the local frame. The first six are the box
//   faces in the order xmin, ymin, zmin, xmax, ymax, zmax, with normals pointing into the box.
// - A facet lies on one complex plane; its positive cell is on the side the plane's normal points
//   to, its negative cell on the other side. A box facet has no outer cell (invalid CellId).
// - Facet vertex cycles are counter-clockwise seen from the positive side.
// - A vertex is identified by its canonical plane triple: the lexicographically smallest sorted
//   triple of linearly independent complex planes through it. Never by coordinates.

#include <array>
#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "engine/core/csr.h"
#include "engine/core/geometry.h"
#include "engine/core/strong_id.h"

namespace linesurf {

struct ComplexPlaneTag {};
using ComplexPlaneId = StrongId<ComplexPlaneTag>;

inline constexpr std::size_t kNumBoxPlanes = 6;

struct ComplexPlane {
  /// (a, b, c, d) with a*x + b*y + c*z + d = 0; (a, b, c) is not necessarily unit length.
  Eigen::Vector4d coefficients = Eigen::Vector4d::Zero();
  /// The input plane it comes from; invalid for box planes.
  PlaneId source;
};

struct CellComplex {
  Box3 box;
  IdVector<ComplexPlaneId, ComplexPlane> planes;

  // Vertices.
  IdVector<VertexId, Vec3> vertex_points;  ///< rounded from the exact point, for output/rays only
  IdVector<VertexId, std::array<ComplexPlaneId, 3>> vertex_planes;  ///< canonical triple, sorted

  // Edges: segments between two vertices.
  IdVector<EdgeId, std::array<VertexId, 2>> edge_vertices;  ///< (lower id, higher id); edges sorted
  /// Facets around the edge in cyclic (or, on the box boundary, chain) order. Interior edges
  /// start at their lowest facet id and turn towards that facet's positive cell first; boundary
  /// edges start at their lower-id box facet and end at the other box facet.
  Csr<EdgeId, FacetId> edge_facets;
  /// Cells around the edge: cell i lies between edge_facets[i] and edge_facets[i+1] (cyclically).
  /// For an edge on the box boundary the chain is open: one fewer cell than facets.
  Csr<EdgeId, CellId> edge_cells;

  // Facets.
  IdVector<FacetId, ComplexPlaneId> facet_plane;
  IdVector<FacetId, CellId> facet_positive_cell;
  IdVector<FacetId, CellId> facet_negative_cell;
  Csr<FacetId, VertexId> facet_vertices;  ///< counter-clockwise seen from the positive side
  Csr<FacetId, EdgeId> facet_edges;       ///< edge i joins facet vertices i and i+1

  // Cells.
  Csr<CellId, FacetId> cell_facets;
  /// +1/-1, adjacent cells differ: +1 when an even number of non-box planes have the cell on
  /// their positive side.
  IdVector<CellId, std::int8_t> cell_colour;

  [[nodiscard]] std::size_t NumVertices() const { return vertex_points.size(); }
  [[nodiscard]] std::size_t NumEdges() const { return edge_vertices.size(); }
  [[nodiscard]] std::size_t NumFacets() const { return facet_plane.size(); }
  [[nodiscard]] std::size_t NumCells() const { return cell_facets.NumRows(); }
  [[nodiscard]] bool IsBoxFacet(FacetId f) const { return facet_plane[f].index() < kNumBoxPlanes; }
  /// The cell across facet f from cell c (invalid across the box).
  [[nodiscard]] CellId Neighbour(FacetId f, CellId c) const {
    return facet_positive_cell[f] == c ? facet_negative_cell[f] : facet_positive_cell[f];
  }
};

}  // namespace linesurf
