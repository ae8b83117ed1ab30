#include "engine/pipeline/pinch_repair.h"

#include "engine/core/csr.h"
#include "engine/core/exception.h"
#include "solver/energy/term_incidence.h"

#include <algorithm>
#include <array>
#include <limits>
#include <numeric>
#include <tuple>

namespace linesurf::pipeline {
namespace {

constexpr const char* kPinchRepairStage = "pinch_repair";
constexpr std::size_t kOutside = std::numeric_limits<std::size_t>::max();

/// The output vertices of each position held by more than one, positions in coordinate order.
std::vector<std::vector<std::uint32_t>> SplitPoints(const PolygonMesh& mesh) {
  std::vector<std::uint32_t> order(mesh.vertices.size());
  std::iota(order.begin(), order.end(), 0u);
  const auto key = [&](std::uint32_t v) {
    const Vec3& p = mesh.vertices[v];
    return std::make_tuple(p.x(), p.y(), p.z(), v);
  };
  std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
    return key(a) < key(b);
  });
  std::vector<std::vector<std::uint32_t>> points;
  for (std::size_t i = 0; i < order.size();) {
    std::size_t j = i + 1;
    while (j < order.size() && mesh.vertices[order[j]] == mesh.vertices[order[i]]) ++j;
    if (j - i > 1)
      points.emplace_back(order.begin() + static_cast<std::ptrdiff_t>(i),
                          order.begin() + static_cast<std::ptrdiff_t>(j));
    i = j;
  }
  return points;
}

/// The global cells on both sides of the facet an output face comes from (kOutside beyond the
/// scene box).
std::array<std::size_t, 2> CellsOfFace(const partition::BlockComplexes& cx,
                                       const std::vector<std::size_t>& offsets,
                                       const BlockFacetRef& ref) {
  const auto global = [&](std::uint32_t block, CellId c) {
    return c.IsValid() ? offsets[block] + c.index() : kOutside;
  };
  if (ref.seam) {
    const partition::SeamFace& seam = cx.seams[ref.owner];
    const partition::SeamFacet& f = seam.facets[ref.facet];
    return {global(seam.lower_block, f.lower_cell), global(seam.upper_block, f.upper_cell)};
  }
  const CellComplex& complex = cx.blocks[ref.owner].complex;
  const FacetId f(static_cast<std::size_t>(ref.facet));
  return {global(ref.owner, complex.facet_positive_cell[f]),
          global(ref.owner, complex.facet_negative_cell[f])};
}

/// Per split position, the free cells next to the surface there that no round has changed yet:
/// the cells on both sides of the faces around each of its vertices, increasing.
std::vector<std::vector<CellId>> CandidateCells(
    const partition::BlockComplexes& cx,
    const std::vector<std::size_t>& offsets,
    const BlockExtractResult& surface,
    const std::vector<std::vector<std::uint32_t>>& points,
    const solver::EnergyInput& energy,
    const std::vector<std::uint8_t>& changed) {
  const PolygonMesh& mesh = surface.mesh;
  const auto faces_of_vertex = Csr<std::uint32_t, std::uint32_t>::FromPairs(
      mesh.vertices.size(),
      mesh.face_indices.size(),
      [&](std::size_t k) { return mesh.face_indices[k]; },
      [&](std::size_t k) {
        const auto f = std::upper_bound(mesh.face_offsets.begin(), mesh.face_offsets.end(), k);
        return static_cast<std::uint32_t>(f - mesh.face_offsets.begin() - 1);
      });
  std::vector<std::vector<CellId>> candidates(points.size());
  for (std::size_t p = 0; p < points.size(); ++p) {
    std::vector<CellId>& cells = candidates[p];
    for (const std::uint32_t v : points[p]) {
      for (const std::uint32_t f : faces_of_vertex[v]) {
        for (const std::size_t c : CellsOfFace(cx, offsets, surface.face_facet[f])) {
          if (c == kOutside || changed[c] != 0) continue;
          if (energy.fixed[CellId(c)] != solver::CellFix::kFree) continue;
          cells.push_back(CellId(c));
        }
      }
    }
    std::sort(cells.begin(), cells.end());
    cells.erase(std::unique(cells.begin(), cells.end()), cells.end());
  }
  return candidates;
}

/// One round: at every split position whose cells no earlier position of this round changed,
/// the candidate whose label change raises the energy least takes the other label (ties: the
/// lower cell id). Returns the cells changed.
std::size_t FlipOneCellPerPoint(const solver::EnergyInput& energy,
                                const std::vector<std::vector<CellId>>& candidates,
                                std::vector<std::uint8_t>& labels,
                                std::vector<std::uint8_t>& changed) {
  std::vector<CellId> all;
  for (const auto& cells : candidates) all.insert(all.end(), cells.begin(), cells.end());
  std::sort(all.begin(), all.end());
  all.erase(std::unique(all.begin(), all.end()), all.end());
  const solver::TermIncidence incidence(energy, all);
  const auto flip_cost = [&](CellId c) {
    const auto terms = incidence.Terms(incidence.Slot(c));
    const double before = solver::LocalEnergy(energy, terms, c, labels);
    labels[c.index()] ^= 1;
    const double after = solver::LocalEnergy(energy, terms, c, labels);
    labels[c.index()] ^= 1;
    return after - before;
  };
  std::size_t flips = 0;
  for (const std::vector<CellId>& cells : candidates) {
    const bool touched =
        std::any_of(cells.begin(), cells.end(), [&](CellId c) { return changed[c.index()] != 0; });
    if (cells.empty() || touched) continue;
    CellId best = cells.front();
    double best_cost = flip_cost(best);
    for (std::size_t i = 1; i < cells.size(); ++i) {
      const double cost = flip_cost(cells[i]);
      if (cost < best_cost) {
        best = cells[i];
        best_cost = cost;
      }
    }
    labels[best.index()] ^= 1;
    changed[best.index()] = 1;
    ++flips;
  }
  return flips;
}

}  // namespace

Expected<PinchRepair> ExtractWithoutPinches(const partition::BlockComplexes& complexes,
                                            const solver::EnergyInput& energy,
                                            const ExtractOptions& options,
                                            int max_rounds,
                                            std::vector<std::uint8_t>& labels,
                                            const RunContext& ctx) noexcept {
  return CatchAll(kPinchRepairStage, [&]() -> PinchRepair {
    LINESURF_THROW_IF(
        labels.size() != energy.NumCells(),
        kInvalidInput,
        kPinchRepairStage,
        "labels has " << labels.size() << " entries for " << energy.NumCells() << " cells");
    const std::vector<std::size_t> offsets = partition::GlobalCellOffsets(complexes);
    const double start_energy = energy.Evaluate(std::span<const std::uint8_t>(labels));
    PinchRepair out;
    out.surface = ValueOrThrow(ExtractBlockSurface(complexes, labels, options, ctx));
    std::vector<std::vector<std::uint32_t>> points = SplitPoints(out.surface.mesh);
    std::vector<std::uint8_t> changed(labels.size(), 0);
    while (!points.empty() && static_cast<int>(out.stats.rounds) < max_rounds) {
      ctx.ThrowIfCancelled(kPinchRepairStage);
      const auto candidates =
          CandidateCells(complexes, offsets, out.surface, points, energy, changed);
      const std::size_t flips = FlipOneCellPerPoint(energy, candidates, labels, changed);
      if (flips == 0) break;
      out.stats.flipped_cells += flips;
      ++out.stats.rounds;
      out.surface = ValueOrThrow(ExtractBlockSurface(complexes, labels, options, ctx));
      points = SplitPoints(out.surface.mesh);
    }
    out.stats.split_points = points.size();
    out.stats.energy_increase =
        energy.Evaluate(std::span<const std::uint8_t>(labels)) - start_energy;
    return out;
  });
}

}  // namespace linesurf::pipeline
