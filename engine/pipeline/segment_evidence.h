#pragma once
/// @file segment_evidence.h
/// @brief Internal to engine/pipeline: the integration of the segments' evidence (samples,
/// textural and structural terms, sight rays, viewpoint prior; see evidence.h) over the cells
/// and facets of an EvidenceSpace: the blocks joined by seams of ComputeBlockEvidence, or one
/// complex (the tests' tests/support/one_complex_evidence.h). Sums are fixed-point integers, so the result
/// does not depend on the thread count or the schedule.

#include "engine/core/geometry.h"
#include "engine/core/run_context.h"
#include "engine/core/scene.h"
#include "engine/pipeline/evidence.h"
#include "solver/energy/energy_input.h"

#include <array>
#include <cstdint>
#include <functional>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace linesurf::pipeline {

/// Fixed-point scale of the accumulated evidence weights: 2^-32 resolution, totals up to 2^31.
/// Integer sums make the totals independent of the order the threads add them in.
inline constexpr double kEvidenceFixedPointScale = 4294967296.0;

/// The cells and facets sight rays are walked through, with ids global to the space. Methods
/// are const and thread-safe.
class EvidenceSpace {
 public:
  using FacetVisitor = std::function<void(std::size_t facet)>;

  virtual ~EvidenceSpace() = default;
  [[nodiscard]] virtual const Box3& box() const = 0;
  [[nodiscard]] virtual std::size_t NumCells() const = 0;
  /// Facets that may carry visibility: ids 0 .. NumFacets() - 1.
  [[nodiscard]] virtual std::size_t NumFacets() const = 0;
  /// The two cells of a facet (either invalid on the box).
  [[nodiscard]] virtual std::pair<CellId, CellId> FacetCells(std::size_t facet) const = 0;
  [[nodiscard]] virtual double FacetArea(std::size_t facet) const = 0;
  /// The cell holding p perturbed by the tie directions (the rule of partition::CellLocator),
  /// invalid outside the box; `hint` is a cell near p or invalid (it changes the speed only).
  [[nodiscard]] virtual CellId Locate(const Vec3& p,
                                      std::span<const Vec3> ties,
                                      CellId hint) const = 0;
  /// Walks the straight segment from `from` (in from_cell) to `to` (in to_cell) and calls
  /// `visit` for every facet crossed, in order.
  virtual void Walk(const Vec3& from,
                    CellId from_cell,
                    const Vec3& to,
                    CellId to_cell,
                    const FacetVisitor& visit) const = 0;
};

/// A structural group as found by one sample: up to three cells (sorted, padded invalid).
struct StructuralEntry {
  std::array<CellId, 4> cells{};
  std::int64_t weight = 0;
};

/// The crease term of a structural segment seen from one view, on the cells across each of its
/// planes from the cell facing the view (`across`, sorted) and the cell across both (`opposite`):
/// weight * x_opposite * |x_across[0] - x_across[1]| on 0/1 labels, i.e. the surface lies flat on
/// one plane through the crease. AddIntegratedTerms writes it as two parity groups
/// |x_a + x_d - x_b - 1| / 2 (one per order of the across cells) and a unary reward
/// -weight * (1 - x_opposite), whose sum is exactly that on 0/1 labels and is its convex
/// extension max(0, x_a + x_d - x_b - 1) + max(0, x_b + x_d - x_a - 1) on [0,1].
struct CreaseEntry {
  std::array<CellId, 2> across{};
  CellId opposite;
  std::int64_t weight = 0;
};

/// The evidence of all segments and viewpoints, in fixed point over the space's ids.
struct IntegratedEvidence {
  std::vector<std::int64_t> cost_if_empty;
  std::vector<std::int64_t> cost_if_full;
  std::vector<std::int64_t> facet_weight;
  /// Sorted by cells, identical groups merged.
  std::vector<StructuralEntry> structural;
  /// Sorted by cells, identical terms merged.
  std::vector<CreaseEntry> creases;
  IdVector<ViewpointId, CellId> viewpoint_cells;
};

/// Checks the scene against the options (memberships, observations, plane and viewpoint ids,
/// the scale of `box`) and fills sigma and the counts of `stats`. Throws LinesurfException.
void CheckEvidenceInput(const Scene& scene,
                        const Box3& box,
                        const EnergyOptions& options,
                        EvidenceStats& stats);

/// Integrates every segment and viewpoint over `space` (segments in parallel in an arena of
/// ctx.num_threads) and fills the crease weight (CreaseWeight under `boundary`) and the sample
/// and walk counts of `stats`. Throws LinesurfException (kCancelled).
[[nodiscard]] IntegratedEvidence IntegrateSegments(const EvidenceSpace& space,
                                                   const Scene& scene,
                                                   const EnergyOptions& options,
                                                   BoundaryMode boundary,
                                                   EvidenceStats& stats,
                                                   const RunContext& ctx);

/// Unary costs, one pair term per facet of the space with weight (visibility plus area), the
/// structural groups and the crease terms, into `energy` (resized to the space's cells).
void AddIntegratedTerms(const EvidenceSpace& space,
                        const IntegratedEvidence& evidence,
                        const EnergyOptions& options,
                        double sigma,
                        solver::EnergyInput& energy);

/// The area of a planar polygon: half the length of its vector area (engine/core/vector_area.h).
[[nodiscard]] double PolygonArea(std::span<const Vec3> points);
/// The area of a facet of `complex` (from its rounded vertices).
[[nodiscard]] double FacetArea(const CellComplex& complex, FacetId f);

/// The warnings of the counts in `stats`.
[[nodiscard]] std::vector<std::string> EvidenceWarnings(const EvidenceStats& stats);

}  // namespace linesurf::pipeline
