#pragma once
// Invariant checker of a CellComplex (engine/core/cell_complex.h): sizes, incidences, closed and
// exactly convex cells, facet vertices exactly on their planes, V - E + F = 2 per cell, the
// cyclic order around edges and the 2-colouring. For tests and debugging; cost is about
// sum over cells of (vertices x facets) exact predicates.

#include "engine/core/cell_complex.h"
#include "linesurf/error.h"

namespace linesurf::partition {

/// OK, or kInternal naming the first violated invariant.
[[nodiscard]] Status ValidateCellComplex(const CellComplex& complex) noexcept;

}  // namespace linesurf::partition
