#pragma once
// Test support: the evidence of the segments on one cell complex, composed from the pipeline's
// term builders (segment_evidence.h, complex_regularisation.h) exactly as ComputeBlockEvidence
// composes them per block, so the terms can be tested on hand-made complexes
// (tests/support/grid_complex.h) and the block engine compared with one global complex.

#include "engine/core/cell_complex.h"
#include "engine/core/run_context.h"
#include "engine/core/scene.h"
#include "engine/pipeline/evidence.h"
#include "linesurf/error.h"

namespace linesurf::pipeline::testing {

/// The energy over the cells of `complex` (the scene in its frame); `boundary` fixes the cells
/// with a facet on the box. Errors as ComputeBlockEvidence's.
[[nodiscard]] Expected<EvidenceResult> ComputeOneComplexEvidence(const CellComplex& complex,
                                                                 const Scene& scene,
                                                                 const EnergyOptions& options,
                                                                 BoundaryMode boundary,
                                                                 const RunContext& ctx) noexcept;

}  // namespace linesurf::pipeline::testing
