#include "engine/pipeline/block_evidence.h"

#include "engine/core/exception.h"
#include "engine/pipeline/complex_regularisation.h"
#include "engine/pipeline/open_seams.h"
#include "engine/pipeline/segment_evidence.h"
#include "partition/arrangement/cell_locator.h"
#include "partition/arrangement/seam_regularisation.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <vector>

namespace linesurf::pipeline {
namespace {

constexpr const char* kBlockEvidenceStage = "evidence";

using partition::BlockComplexes;
using partition::CellLocator;
using partition::FacetKind;

/// The blocks and seams as one space: global cells offsets[b] + local cell, global facets
/// (every facet of block 0, of block 1, ..., then every seam facet of seam face 0, 1, ...).
class BlockSpace final : public EvidenceSpace {
 public:
  explicit BlockSpace(const BlockComplexes& cx)
      : cx_(cx), cell_offsets_(partition::GlobalCellOffsets(cx)) {
    locators_.reserve(cx.blocks.size());
    facet_offsets_.push_back(0);
    for (const partition::BlockComplex& block : cx.blocks) {
      locators_.emplace_back(block.complex);
      facet_offsets_.push_back(facet_offsets_.back() + block.complex.NumFacets());
    }
    seam_offsets_.push_back(facet_offsets_.back());
    for (std::size_t s = 0; s < cx.seams.size(); ++s) {
      const partition::SeamFace& face = cx.seams[s];
      for (std::size_t k = 0; k < face.facets.size(); ++k) {
        const auto [a, b] = SeamCells(face, face.facets[k]);
        seam_slots_.push_back({PairKey(a, b), seam_offsets_.back() + k});
        upper_partners_.push_back(PairKey(b, a));
      }
      seam_offsets_.push_back(seam_offsets_.back() + face.facets.size());
    }
    std::sort(seam_slots_.begin(), seam_slots_.end());
    std::sort(upper_partners_.begin(), upper_partners_.end());
  }

  const Box3& box() const override { return cx_.grid.box(); }
  std::size_t NumCells() const override { return cell_offsets_.back(); }
  std::size_t NumFacets() const override { return seam_offsets_.back(); }

  std::pair<CellId, CellId> FacetCells(std::size_t f) const override {
    if (f < facet_offsets_.back()) {
      const std::size_t b = BlockOfFacet(f);
      const CellComplex& c = cx_.blocks[b].complex;
      const FacetId local(f - facet_offsets_[b]);
      return {Global(b, c.facet_positive_cell[local]), Global(b, c.facet_negative_cell[local])};
    }
    const auto [face, k] = SeamOfFacet(f);
    return SeamCells(cx_.seams[face], cx_.seams[face].facets[k]);
  }

  double FacetArea(std::size_t f) const override {
    if (f < facet_offsets_.back()) {
      const std::size_t b = BlockOfFacet(f);
      return pipeline::FacetArea(cx_.blocks[b].complex, FacetId(f - facet_offsets_[b]));
    }
    const auto [face, k] = SeamOfFacet(f);
    return PolygonArea(cx_.seams[face].facets[k].points);
  }

  CellId Locate(const Vec3& p, std::span<const Vec3> ties, CellId hint) const override {
    const std::size_t b = static_cast<std::size_t>(cx_.grid.LinearIndex(LocateBlock(p, ties)));
    const CellId local_hint =
        hint.IsValid() && BlockOfCell(hint) == b ? Local(b, hint) : CellId::Invalid();
    return Global(b, locators_[b].Locate(p, ties, local_hint));
  }

  void Walk(const Vec3& from,
            CellId from_cell,
            const Vec3& to,
            CellId to_cell,
            const FacetVisitor& visit) const override;

 private:
  /// The base block holding p perturbed by the ties (then +x, +y, +z: the locator's rule), so
  /// that the block's locator puts the perturbed point inside its box.
  Eigen::Vector3i LocateBlock(const Vec3& p, std::span<const Vec3> ties) const {
    Eigen::Vector3i base = cx_.grid.Locate(p);
    for (int a = 0; a < 3; ++a) {
      if (base[a] == 0 || p[a] != cx_.grid.FaceTable(a)[static_cast<std::size_t>(base[a])]) {
        continue;
      }
      int side = 1;
      for (const Vec3& d : ties) {
        if (d[a] != 0.0) {
          side = d[a] > 0.0 ? 1 : -1;
          break;
        }
      }
      if (side < 0) --base[a];
    }
    return base;
  }

  /// Walks inside block b from `from` (local cell c) to `to` (local cell c_to).
  void WalkInBlock(std::size_t b,
                   const Vec3& from,
                   CellId c,
                   const Vec3& to,
                   CellId c_to,
                   const FacetVisitor& visit) const {
    const std::size_t offset = facet_offsets_[b];
    locators_[b].WalkSegment(
        from, c, to, c_to, [&](FacetId f, double /*t*/) { visit(offset + f.index()); });
  }

  /// A cell sharing a seam facet with global cell `c` (the lower side when `c_is_lower`), as a
  /// local cell of block b: a start for locating a point near that seam. Invalid if none.
  CellId SeamPartner(CellId c, bool c_is_lower, std::size_t b) const {
    const std::uint64_t first = static_cast<std::uint64_t>(c.value()) << 32;
    std::uint64_t key = 0;
    if (c_is_lower) {
      const auto it = std::lower_bound(
          seam_slots_.begin(), seam_slots_.end(), std::make_pair(first, std::size_t{0}));
      if (it == seam_slots_.end() || (it->first >> 32) != c.value()) return CellId::Invalid();
      key = it->first;
    } else {
      const auto it = std::lower_bound(upper_partners_.begin(), upper_partners_.end(), first);
      if (it == upper_partners_.end() || (*it >> 32) != c.value()) return CellId::Invalid();
      key = *it;
    }
    return Local(b, CellId(static_cast<std::uint32_t>(key & 0xffffffffu)));
  }

  static std::uint64_t PairKey(CellId lower, CellId upper) {
    return (static_cast<std::uint64_t>(lower.value()) << 32) | upper.value();
  }
  std::pair<CellId, CellId> SeamCells(const partition::SeamFace& face,
                                      const partition::SeamFacet& facet) const {
    return {Global(face.lower_block, facet.lower_cell), Global(face.upper_block, facet.upper_cell)};
  }
  CellId Global(std::size_t b, CellId local) const {
    return local.IsValid() ? CellId(cell_offsets_[b] + local.index()) : CellId::Invalid();
  }
  CellId Local(std::size_t b, CellId global) const {
    return CellId(global.index() - cell_offsets_[b]);
  }
  std::size_t BlockOfCell(CellId global) const {
    return static_cast<std::size_t>(
        std::upper_bound(cell_offsets_.begin(), cell_offsets_.end(), global.index()) -
        cell_offsets_.begin() - 1);
  }
  std::size_t BlockOfFacet(std::size_t f) const {
    return static_cast<std::size_t>(
        std::upper_bound(facet_offsets_.begin(), facet_offsets_.end(), f) - facet_offsets_.begin() -
        1);
  }
  std::pair<std::size_t, std::size_t> SeamOfFacet(std::size_t f) const {
    const auto face =
        static_cast<std::size_t>(std::upper_bound(seam_offsets_.begin(), seam_offsets_.end(), f) -
                                 seam_offsets_.begin() - 1);
    return {face, f - seam_offsets_[face]};
  }

  const BlockComplexes& cx_;
  std::vector<std::size_t> cell_offsets_;
  std::vector<CellLocator> locators_;
  std::vector<std::size_t> facet_offsets_;
  std::vector<std::size_t> seam_offsets_;
  /// (lower global cell, upper global cell) -> global facet, sorted: a cell of each block
  /// shares at most one seam facet.
  std::vector<std::pair<std::uint64_t, std::size_t>> seam_slots_;
  /// (upper global cell, lower global cell), sorted.
  std::vector<std::uint64_t> upper_partners_;
};

void BlockSpace::Walk(const Vec3& from,
                      CellId from_cell,
                      const Vec3& to,
                      CellId to_cell,
                      const FacetVisitor& visit) const {
  const partition::BlockGrid& grid = cx_.grid;
  std::size_t b = BlockOfCell(from_cell);
  const std::size_t b_to = BlockOfCell(to_cell);
  Eigen::Vector3i block = grid.BaseFromLinear(static_cast<std::int64_t>(b));
  const Eigen::Vector3i target = grid.BaseFromLinear(static_cast<std::int64_t>(b_to));
  const Vec3 d = to - from;
  Vec3 x = from;
  CellId cell = Local(b, from_cell);
  double t_done = 0.0;
  // Each step moves one block along an axis where the target block differs, towards it, so the
  // walk reaches the target block after |dx| + |dy| + |dz| steps whatever the rounding.
  while (block != target) {
    int axis = -1;
    double t_exit = std::numeric_limits<double>::infinity();
    for (int a = 0; a < 3; ++a) {
      if (block[a] == target[a]) continue;
      const int step = target[a] > block[a] ? 1 : -1;
      const double face = grid.FaceTable(a)[static_cast<std::size_t>(block[a] + (step > 0))];
      const double t =
          d[a] != 0.0 ? (face - from[a]) / d[a] : std::numeric_limits<double>::infinity();
      if (axis < 0 || t < t_exit) {
        axis = a;
        t_exit = t;
      }
    }
    const int step = target[axis] > block[axis] ? 1 : -1;
    if (std::isfinite(t_exit)) t_done = std::clamp(t_exit, t_done, 1.0);
    // The crossing point: exactly on the face, inside the face's rectangle.
    Vec3 e = from + t_done * d;
    e[axis] = grid.FaceTable(axis)[static_cast<std::size_t>(block[axis] + (step > 0))];
    // One in-face perturbation for both sides: the ray's direction within the face (kept
    // inside the rectangle), then the face's axes pointing inwards, then into each block.
    Vec3 w = d;
    w[axis] = 0.0;
    std::array<Vec3, 4> ties_here;
    std::array<Vec3, 4> ties_next;
    int k = 1;
    for (int a = 0; a < 3; ++a) {
      if (a == axis) continue;
      const auto& table = grid.FaceTable(a);
      const double lo = table[static_cast<std::size_t>(block[a])];
      const double hi = table[static_cast<std::size_t>(block[a] + 1)];
      e[a] = std::clamp(e[a], lo, hi);
      if ((e[a] == lo && w[a] < 0.0) || (e[a] == hi && w[a] > 0.0)) w[a] = 0.0;
      Vec3 u = Vec3::Zero();
      u[a] = e[a] == hi ? -1.0 : 1.0;
      ties_here[static_cast<std::size_t>(k)] = u;
      ties_next[static_cast<std::size_t>(k)] = u;
      ++k;
    }
    ties_here[0] = w;
    ties_next[0] = w;
    ties_here[3] = Vec3::Zero();
    ties_here[3][axis] = -step;
    ties_next[3] = -ties_here[3];
    Eigen::Vector3i next = block;
    next[axis] += step;
    const std::size_t b_next = static_cast<std::size_t>(grid.LinearIndex(next));
    const std::size_t offset = facet_offsets_[b];
    const CellId exit_cell = locators_[b].WalkToPoint(
        x, cell, e, ties_here, [&](FacetId f, double /*t*/) { visit(offset + f.index()); });
    const CellId here = Global(b, exit_cell);
    // Start the location in the next block from a seam partner of the exit cell: near e.
    const CellId entry_cell =
        locators_[b_next].Locate(e, ties_next, SeamPartner(here, step > 0, b_next));
    if (!entry_cell.IsValid()) return;  // unreachable: e is in the next block
    const CellId there = Global(b_next, entry_cell);
    const std::uint64_t key = step > 0 ? PairKey(here, there) : PairKey(there, here);
    const auto it = std::lower_bound(
        seam_slots_.begin(), seam_slots_.end(), std::make_pair(key, std::size_t{0}));
    if (it != seam_slots_.end() && it->first == key) visit(it->second);
    x = e;
    cell = entry_cell;
    block = next;
    b = b_next;
  }
  WalkInBlock(b, x, cell, to, Local(b, to_cell), visit);
}

void ApplyBoundary(const BlockComplexes& cx,
                   const std::vector<std::size_t>& offsets,
                   BoundaryMode boundary,
                   solver::EnergyInput& energy,
                   EvidenceStats& stats) {
  if (boundary == BoundaryMode::kNone) return;
  const solver::CellFix fix =
      boundary == BoundaryMode::kExterior ? solver::CellFix::kEmpty : solver::CellFix::kFull;
  for (std::size_t b = 0; b < cx.blocks.size(); ++b) {
    const partition::BlockComplex& block = cx.blocks[b];
    for (std::size_t f = 0; f < block.complex.NumFacets(); ++f) {
      const FacetId id(f);
      if (block.facet_kind[id] != FacetKind::kSceneBoundary) continue;
      for (const CellId local :
           {block.complex.facet_positive_cell[id], block.complex.facet_negative_cell[id]}) {
        if (!local.IsValid()) continue;
        const CellId cell(offsets[b] + local.index());
        if (energy.fixed[cell] == fix) continue;
        energy.fixed[cell] = fix;
        ++stats.fixed_cells;
      }
    }
  }
}

/// The seam edges and vertices, as parity groups over global cells.
void AddSeamRegularisation(const partition::SeamRegularisation& seams,
                           const std::vector<std::size_t>& offsets,
                           const EnergyOptions& options,
                           double sigma,
                           solver::EnergyInput& energy) {
  std::vector<CellId> cells;
  const auto add = [&](const partition::SeamParityGroup& group, double weight) {
    if (!(weight > 0.0)) return;
    cells.clear();
    for (const partition::BlockCell& c : group.cells) {
      cells.emplace_back(offsets[c.block] + c.cell.index());
    }
    energy.AddParityGroup(cells, group.signs, weight);
  };
  if (options.weights.edge > 0.0) {
    for (const auto& group : seams.edges) add(group, options.weights.edge * group.length / sigma);
  }
  if (options.weights.corner > 0.0) {
    for (const auto& group : seams.vertices) add(group, options.weights.corner);
  }
}

/// The price of surface on seams that carry no plane (EnergyWeights::open_seam).
void AddOpenSeamTerms(const BlockComplexes& complexes,
                      const std::vector<std::size_t>& offsets,
                      double weight_per_area,
                      solver::EnergyInput& energy) {
  if (!(weight_per_area > 0.0)) return;
  for (std::size_t s = 0; s < complexes.seams.size(); ++s) {
    if (SeamCarriesPlane(complexes, s)) continue;
    const partition::SeamFace& face = complexes.seams[s];
    for (const partition::SeamFacet& facet : face.facets) {
      energy.AddPair(CellId(offsets[face.lower_block] + facet.lower_cell.index()),
                     CellId(offsets[face.upper_block] + facet.upper_cell.index()),
                     weight_per_area * PolygonArea(facet.points));
    }
  }
}

}  // namespace

Expected<EvidenceResult> ComputeBlockEvidence(const BlockComplexes& complexes,
                                              const Scene& scene,
                                              const EnergyOptions& options,
                                              BoundaryMode boundary,
                                              const RunContext& ctx) noexcept {
  return CatchAll(kBlockEvidenceStage, [&]() -> EvidenceResult {
    EvidenceResult result;
    CheckEvidenceInput(scene, complexes.grid.box(), options, result.stats);
    const BlockSpace space(complexes);
    IntegratedEvidence evidence =
        IntegrateSegments(space, scene, options, boundary, result.stats, ctx);
    AddIntegratedTerms(space, evidence, options, result.stats.sigma, result.energy);
    const std::vector<std::size_t> offsets = partition::GlobalCellOffsets(complexes);
    for (std::size_t b = 0; b < complexes.blocks.size(); ++b) {
      AddComplexRegularisation(
          complexes.blocks[b].complex, options, result.stats.sigma, offsets[b], result.energy);
    }
    if (options.weights.edge > 0.0 || options.weights.corner > 0.0) {
      Expected<partition::SeamRegularisation> seams =
          partition::ComputeSeamRegularisation(complexes, ctx);
      if (!seams) throw LinesurfException(seams.error());
      AddSeamRegularisation(*seams, offsets, options, result.stats.sigma, result.energy);
    }
    const double sigma = result.stats.sigma;
    AddOpenSeamTerms(complexes, offsets, options.weights.open_seam / (sigma * sigma), result.energy);
    ApplyBoundary(complexes, offsets, boundary, result.energy, result.stats);
    result.warnings = EvidenceWarnings(result.stats);
    result.viewpoint_cells = std::move(evidence.viewpoint_cells);
    return result;
  });
}

}  // namespace linesurf::pipeline
