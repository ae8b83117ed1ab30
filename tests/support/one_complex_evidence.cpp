#include "tests/support/one_complex_evidence.h"

#include <utility>

#include "engine/core/exception.h"
#include "engine/pipeline/complex_regularisation.h"
#include "engine/pipeline/segment_evidence.h"
#include "partition/arrangement/cell_locator.h"

namespace linesurf::pipeline::testing {
namespace {

/// One complex: its cells and facets, walked with its locator.
class ComplexSpace final : public EvidenceSpace {
 public:
  explicit ComplexSpace(const CellComplex& cx) : cx_(cx), locator_(cx) {}
  const Box3& box() const override { return cx_.box; }
  std::size_t NumCells() const override { return cx_.NumCells(); }
  std::size_t NumFacets() const override { return cx_.NumFacets(); }
  std::pair<CellId, CellId> FacetCells(std::size_t f) const override {
    return {cx_.facet_positive_cell[FacetId(f)], cx_.facet_negative_cell[FacetId(f)]};
  }
  double FacetArea(std::size_t f) const override { return pipeline::FacetArea(cx_, FacetId(f)); }
  CellId Locate(const Vec3& p, std::span<const Vec3> ties, CellId hint) const override {
    return locator_.Locate(p, ties, hint);
  }
  void Walk(const Vec3& from,
            CellId from_cell,
            const Vec3& to,
            CellId to_cell,
            const FacetVisitor& visit) const override {
    locator_.WalkSegment(from, from_cell, to, to_cell, [&](FacetId f, double /*t*/) {
      visit(f.index());
    });
  }

 private:
  const CellComplex& cx_;
  partition::CellLocator locator_;
};

void ApplyBoundary(const CellComplex& cx, BoundaryMode boundary, solver::EnergyInput& energy,
                   EvidenceStats& stats) {
  if (boundary == BoundaryMode::kNone) return;
  const solver::CellFix fix =
      boundary == BoundaryMode::kExterior ? solver::CellFix::kEmpty : solver::CellFix::kFull;
  for (std::size_t f = 0; f < cx.NumFacets(); ++f) {
    const FacetId id(f);
    if (!cx.IsBoxFacet(id)) continue;
    for (const CellId cell : {cx.facet_positive_cell[id], cx.facet_negative_cell[id]}) {
      if (!cell.IsValid() || energy.fixed[cell] == fix) continue;
      energy.fixed[cell] = fix;
      ++stats.fixed_cells;
    }
  }
}

}  // namespace

Expected<EvidenceResult> ComputeOneComplexEvidence(const CellComplex& cx,
                                                  const Scene& scene,
                                                  const EnergyOptions& options,
                                                  BoundaryMode boundary,
                                                  const RunContext& ctx) noexcept {
  return CatchAll("evidence", [&]() -> EvidenceResult {
    EvidenceResult result;
    CheckEvidenceInput(scene, cx.box, options, result.stats);
    const ComplexSpace space(cx);
    IntegratedEvidence evidence =
        IntegrateSegments(space, scene, options, boundary, result.stats, ctx);
    AddIntegratedTerms(space, evidence, options, result.stats.sigma, result.energy);
    AddComplexRegularisation(cx, options, result.stats.sigma, 0, result.energy);
    ApplyBoundary(cx, boundary, result.energy, result.stats);
    result.warnings = EvidenceWarnings(result.stats);
    result.viewpoint_cells = std::move(evidence.viewpoint_cells);
    return result;
  });
}

}  // namespace linesurf::pipeline::testing
