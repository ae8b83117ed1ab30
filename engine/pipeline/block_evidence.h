#pragma once
/// @file block_evidence.h
/// @brief The evidence of the block engine (docs/design/block_engine.md, section 4): the energy
/// terms of evidence.h over the cells of all blocks of a BlockComplexes, with global cell
/// ids (partition::GlobalCellOffsets), seam facets carrying visibility like any facet.
///
/// Sight rays are walked block by block: inside a block with its CellLocator, and where a ray
/// leaves a block through a face it crosses the seam facet of that face holding the crossing
/// point (the cells on both sides located with one tie rule, so the two cells always share a
/// seam facet). Points on block faces go to the block the locator's tie rule puts them in.
/// Regularisation: the edges and vertices inside a block as within one complex; those on block
/// faces and block edges (not on the scene box) once, with the cells of every block around them
/// (partition::ComputeSeamRegularisation). Boundary conditions apply to the cells on the scene
/// box only, never to seams. Sums are fixed point: bit-identical for any thread count. With one
/// block the result equals the terms on that one complex, term for term
/// (tests/support/one_complex_evidence.h composes them there).

#include "linesurf/error.h"

#include "engine/core/run_context.h"
#include "engine/core/scene.h"
#include "engine/pipeline/evidence.h"
#include "partition/arrangement/block_complexes.h"

namespace linesurf::pipeline {

/// @brief The energy over the global cells of `complexes` (local frame; the scene box is the
/// grid's box) from the segments, planes, memberships and viewpoints of `scene`.
/// @return kInvalidOptions, kInvalidInput (memberships size or plane ids out of range),
/// kCancelled. EvidenceResult::viewpoint_cells holds global cells.
[[nodiscard]] Expected<EvidenceResult> ComputeBlockEvidence(
    const partition::BlockComplexes& complexes,
    const Scene& scene,
    const EnergyOptions& options,
    BoundaryMode boundary,
    const RunContext& ctx) noexcept;

}  // namespace linesurf::pipeline
