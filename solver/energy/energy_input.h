#pragma once
/// @file energy_input.h
/// @brief Plain data of the labelling energy over the cells of a complex (x_c = 1 full, 0 empty).
///
/// The pipeline fills it from the evidence; the solver minimises
///
///   E(x) = sum_c [ cost_if_empty_c * (1 - x_c) + cost_if_full_c * x_c ]            (unary)
///        + sum_pairs      w * |x_a - x_b|                                             (pairwise)
///        + sum_structural w * max(0, 1 - sum_{c in group} x_c)                        (structural)
///        + sum_parity     w * |k + sum_{c in group} nu_c x_c|                         (parity)
///
/// over x in {0,1}^cells with the fixed cells held at their label. Every weight is already
/// multiplied by its user weight (lambda_vis, lambda_edge, ...): the solver sees one number per
/// term. The solver relaxes x to [0,1] (an LP, see build_lp.h) and rounds at 0.5.
///
/// Cells are identified by CellId; cell c's data is at index c.index() of the per-cell vectors.
/// Groups are stored compressed (CSR): group g holds items [offsets[g], offsets[g+1]).
/// Term order is free (the LP follows it canonically); the pipeline may merge identical groups
/// by adding their weights, and should, since it shrinks the LP.
///
/// Thread-safety: plain data, immutable during a solve.

#include <cstdint>
#include <span>
#include <vector>

#include "engine/core/strong_id.h"
#include "linesurf/error.h"

namespace linesurf::solver {

/// Boundary condition of a cell. Fixed cells are substituted as constants when the LP is built
/// (never big-M costs): their terms fold into the remaining ones and the objective constant.
enum class CellFix : std::uint8_t {
  kFree,   ///< the solver decides
  kEmpty,  ///< forced to x = 0 (e.g. cells on the box of an exterior scene)
  kFull,   ///< forced to x = 1 (e.g. cells on the box of an interior scene)
};

/// Pairwise term weight * |x_a - x_b| (visibility through the facet between a and b, plus the
/// optional area term). a != b.
struct PairTerm {
  CellId a;
  CellId b;
  double weight = 0.0;  ///< >= 0, finite
};

struct EnergyInput {
  // ---- per cell (all three vectors have NumCells() entries) ------------------------------------
  /// Cost paid when the cell ends up empty (x = 0): textural evidence (segment length behind the
  /// cell / sigma, times the textural weight). Finite; usually >= 0.
  IdVector<CellId, double> cost_if_empty;
  /// Cost paid when the cell ends up full (x = 1): the viewpoint prior (cell holds a viewpoint).
  /// Finite; usually >= 0.
  IdVector<CellId, double> cost_if_full;
  /// Boundary condition; kFree for cells the solver decides.
  IdVector<CellId, CellFix> fixed;

  // ---- pairwise terms ---------------------------------------------------------------------------
  /// weight * |x_a - x_b|, one per facet with visibility (or area) evidence.
  std::vector<PairTerm> pairs;

  // ---- structural groups: weight * max(0, 1 - sum_{c in group} x_c) ----------------------------
  /// The cells around a structural edge except the one facing the view: penalised only when all
  /// of them are empty. Group g = structural_cells[structural_offsets[g] .. structural_offsets[g+1]).
  std::vector<std::uint32_t> structural_offsets{0};
  /// Cells of every group, concatenated; distinct within a group.
  std::vector<CellId> structural_cells;
  /// One weight per group: >= 0, finite.
  std::vector<double> structural_weights;

  // ---- parity groups: weight * |k + sum_{c in group} nu_c x_c| --------------------------------
  /// Edge and corner regularisation (Boulch et al. 2014) with the 2-colouring nu_c = +-1 of the
  /// cells around an edge (weight = lambda_edge * edge length) or a vertex (weight =
  /// lambda_corner), k = 0: 0 for a flat or no surface, 1 for a crease or corner, 2 for a
  /// checkerboard. The crease terms of structural segments are groups with k = -1
  /// (engine/pipeline/segment_evidence.h).
  std::vector<std::uint32_t> parity_offsets{0};
  /// Cells of every group, concatenated; distinct within a group.
  std::vector<CellId> parity_cells;
  /// nu_c of parity_cells[i]: +1 or -1.
  std::vector<std::int8_t> parity_signs;
  /// One weight per group: >= 0, finite.
  std::vector<double> parity_weights;
  /// One constant k per group.
  std::vector<std::int8_t> parity_constants;

  // ---- building ---------------------------------------------------------------------------------
  /// Appends a cell with its unary costs and boundary condition; returns its id.
  CellId AddCell(double cost_if_empty_value, double cost_if_full_value,
                 CellFix fix = CellFix::kFree);
  /// Resizes the per-cell vectors to `num_cells` (new cells: zero costs, free).
  void ResizeCells(std::size_t num_cells);
  void AddPair(CellId a, CellId b, double weight);
  void AddStructuralGroup(std::span<const CellId> cells, double weight);
  /// `signs[i]` is nu of `cells[i]` (+1 or -1); `constant` is k.
  void AddParityGroup(std::span<const CellId> cells,
                      std::span<const std::int8_t> signs,
                      double weight,
                      std::int8_t constant = 0);

  // ---- queries ----------------------------------------------------------------------------------
  [[nodiscard]] std::size_t NumCells() const { return cost_if_empty.size(); }
  /// The cells with CellFix::kFree, in id order.
  [[nodiscard]] std::vector<CellId> FreeCells() const;
  [[nodiscard]] std::size_t NumPairs() const { return pairs.size(); }
  [[nodiscard]] std::size_t NumStructuralGroups() const { return structural_weights.size(); }
  [[nodiscard]] std::size_t NumParityGroups() const { return parity_weights.size(); }
  [[nodiscard]] std::span<const CellId> StructuralGroup(std::size_t g) const {
    return {structural_cells.data() + structural_offsets[g],
            structural_cells.data() + structural_offsets[g + 1]};
  }
  [[nodiscard]] std::span<const CellId> ParityGroup(std::size_t g) const {
    return {parity_cells.data() + parity_offsets[g], parity_cells.data() + parity_offsets[g + 1]};
  }
  [[nodiscard]] std::span<const std::int8_t> ParitySigns(std::size_t g) const {
    return {parity_signs.data() + parity_offsets[g], parity_signs.data() + parity_offsets[g + 1]};
  }

  /// Checks sizes, offsets, cell ids in range, distinct cells within a term, finite costs,
  /// weights >= 0 and finite, signs +-1, one constant per parity group. Names the first offending
  /// term. O(size).
  [[nodiscard]] Status Validate() const;

  /// E(x) for a labelling x in [0,1]^cells (fixed cells must carry their label; relaxed values
  /// are evaluated with the same formula, which is the LP objective at its optimal slacks).
  [[nodiscard]] double Evaluate(std::span<const double> x) const;
  /// E(labels) for 0/1 labels.
  [[nodiscard]] double Evaluate(std::span<const std::uint8_t> labels) const;
};

}  // namespace linesurf::solver
