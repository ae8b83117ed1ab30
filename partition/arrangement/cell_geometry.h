#pragma once
// Approximate (double) measures of cells and facets of a CellComplex, for output, debugging and
// tests. Never used for decisions.

#include <vector>

#include "engine/core/cell_complex.h"

namespace linesurf::partition {

/// The vertices of facet f in cyclic order, counter-clockwise seen from outside cell c (c must
/// be one of the facet's cells).
std::vector<VertexId> OutwardFacetCycle(const CellComplex& complex, FacetId f, CellId c);

/// The average of the cell's distinct vertices (inside the cell: cells are convex).
Vec3 CellCentroid(const CellComplex& complex, CellId c);

/// The cell's volume from its outward facet cycles (divergence theorem, fan triangulation).
double CellVolume(const CellComplex& complex, CellId c);

/// The distinct vertices of a cell, sorted by id.
std::vector<VertexId> CellVertices(const CellComplex& complex, CellId c);

}  // namespace linesurf::partition
