#include "solver/lp/lp_backend.h"

#include "engine/core/exception.h"
#include "solver/energy/build_lp.h"
#include "solver/lp/band_fixing.h"
#include "solver/lp/block_labeling.h"
#include "solver/lp/group_moves.h"
#include "solver/lp/labeling_backends.h"
#include "solver/lp/round_labels.h"
#include "solver/lp/window_polish.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

namespace linesurf::solver {
namespace {

constexpr const char* kLpBackendStage = "solve_labeling";

LabelingResult Solve(const EnergyInput& energy, std::span<const std::uint32_t> block_of_cell,
                     const LabelingOptions& options, const RunContext& ctx);

// Blocks holding a free cell.
std::size_t CountBlocks(const EnergyInput& energy, std::span<const std::uint32_t> block_of_cell) {
  std::vector<std::uint32_t> used;
  for (std::size_t c = 0; c < block_of_cell.size(); ++c) {
    if (energy.fixed[CellId(c)] == CellFix::kFree) used.push_back(block_of_cell[c]);
  }
  std::sort(used.begin(), used.end());
  return static_cast<std::size_t>(std::unique(used.begin(), used.end()) - used.begin());
}

// What the backend proves about the integral optimum (its entry's BoundProof; band and blocks
// prove theirs themselves).
void SetLowerBound(BoundProof proof, const LpSolution& solution, LabelingResult& result) {
  switch (proof) {
    case BoundProof::kLpOptimum:
      result.lower_bound = result.relaxed_objective;
      result.lower_bound_source = "lp optimum";
      break;
    case BoundProof::kIntegerOptimum:
      result.lower_bound = result.labels_objective;
      result.lower_bound_source = "integer optimum";
      break;
    case BoundProof::kEnergyDual:
      result.lower_bound = std::min(solution.lower_bound, result.labels_objective);
      result.lower_bound_source = "energy dual bound";
      break;
    case BoundProof::kLpDual:  // the Lagrangian bound of the dual point, when there is one
      if (solution.row_duals.empty()) break;
      result.lower_bound = std::min(solution.lower_bound, result.labels_objective);
      result.lower_bound_source = "lp dual bound";
      break;
    case BoundProof::kBranchAndBound:
      result.lower_bound = std::min(solution.lower_bound, result.labels_objective);
      result.lower_bound_source =
          result.status == "optimal" ? "integer optimum" : "branch and bound";
      break;
    case BoundProof::kNone:
    case BoundProof::kPairwiseOptimum:
    case BoundProof::kBlockBounds:
      break;
  }
}

// After rounding: local search, group moves and exact windows (each optional), the energy of
// the labels and the method. Returns true when one exact window held every free cell.
bool Improve(const EnergyInput& energy, const LabelingOptions& options, const RunContext& ctx,
             LabelingResult& result) {
  const ImproveOptions& improve = options.improve;
  result.local_search_flips = ImproveLabels(energy, improve.local_search_passes, result.labels);
  result.group_move_changes =
      ImproveByGroupMoves(energy, improve.group_move_passes, ctx, result.labels);
  // A backend that solves the integer program itself (maxflow, cbc) gets no windows.
  const bool integral = LookupBackend(result.backend).capabilities.integral;
  const WindowPolishStats polished =
      integral ? WindowPolishStats{} : PolishResultInWindows(energy, improve, ctx, result);
  result.labels_objective =
      result.local_search_flips + result.group_move_changes + result.window_changes == 0
          ? result.rounded_objective
          : energy.Evaluate(std::span<const std::uint8_t>(result.labels));
  result.method = SolverBackendName(result.backend);
  result.method += integral ? " integer program" : " lp, rounding";
  AppendImprovementSteps(improve, polished, result.method);
  return polished.whole_energy_proven;
}

// Band strategy (band_fixing.h): max-flow of the pairwise part, then the LP of the cells near
// its surface with every other cell fixed. Sizes reported are those of the full LP (`full`);
// band_lp_backend names the backend of the band's own LP.
LabelingResult SolveInBand(const EnergyInput& energy, const LabelingOptions& options,
                           const RunContext& ctx, const LabelingResult& full) {
  const auto start = std::chrono::steady_clock::now();
  const std::vector<std::uint8_t> pairwise = PairwiseLabels(energy, ctx);
  const EnergyInput banded = FixCellsOutsideBand(energy, pairwise, options.band.rings);
  LabelingOptions inner = options;
  inner.backend = SolverBackend::kAuto;
  inner.auto_rule.band_min_columns = std::numeric_limits<std::size_t>::max();
  inner.improve.local_search_passes = inner.improve.group_move_passes = 0;
  inner.improve.window_cells = 0;
  LabelingResult result = Solve(banded, {}, inner, ctx);
  // The moves and windows work on the whole energy: they may change cells outside the band.
  Improve(energy, options, ctx, result);
  result.band_lp_backend = result.backend;
  result.backend = SolverBackend::kBand;
  result.method = "band (lp of the cells near the max-flow surface, the others fixed), " +
                  result.method;
  // The band's LP optimum bounds nothing of the full energy; the pairwise minimum does.
  result.lower_bound = energy.Evaluate(std::span<const std::uint8_t>(pairwise)) -
                       HigherOrderEnergy(energy, pairwise);
  result.lower_bound_source = "pairwise optimum";
  result.band_lp_columns = result.lp_columns;
  result.lp_columns = full.lp_columns;
  result.lp_rows = full.lp_rows;
  result.lp_nonzeros = full.lp_nonzeros;
  result.seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

// Blocks strategy (block_labeling.h); sizes reported are those of the full LP (`full`).
LabelingResult SolveByBlocks(const EnergyInput& energy,
                             const ReducedEnergy& reduced,
                             std::span<const std::uint32_t> block_of_cell,
                             const LabelingOptions& options,
                             const RunContext& ctx,
                             const LabelingResult& full) {
  LabelingResult blocks = SolveInBlocks(energy, reduced, block_of_cell, options, ctx);
  blocks.lp_columns = full.lp_columns;
  blocks.lp_rows = full.lp_rows;
  blocks.lp_nonzeros = full.lp_nonzeros;
  return blocks;
}

// A kSolve backend: one solve of the reduced energy (or its LP), then rounding, the improvement
// passes and the backend's lower bound.
void SolveOnce(const EnergyInput& energy,
               const ReducedEnergy& reduced,
               const LabelingBackend& backend,
               const LabelingOptions& options,
               const RunContext& ctx,
               LabelingResult& result) {
  const LpSolution solution =
      backend.solve(BackendInput{.energy = energy, .reduced = reduced}, options, ctx);
  LINESURF_ASSERT(solution.columns.size() >= reduced.NumFree());

  // Cell values: clip the first-order backends' small bound violations.
  const auto num_free = static_cast<std::ptrdiff_t>(reduced.NumFree());
  std::vector<double> columns(solution.columns.begin(), solution.columns.begin() + num_free);
  for (double& x : columns) x = std::clamp(x, 0.0, 1.0);
  result.relaxed = ExpandToCells(energy, reduced, columns);
  // The energy of the relaxed cell values, i.e. the LP objective with optimal slacks: equal to
  // Clp's optimum, and a feasible (upper) value for first-order backends.
  result.relaxed_objective = energy.Evaluate(std::span<const double>(result.relaxed));
  RoundedLabels rounded = RoundLabels(energy, result.relaxed);
  result.labels = std::move(rounded.labels);
  result.fractional_cells = rounded.fractional_cells;
  result.tie_cells = rounded.tie_cells;
  result.rounded_objective = energy.Evaluate(std::span<const std::uint8_t>(result.labels));
  const bool whole_energy_proven = Improve(energy, options, ctx, result);
  result.status = solution.status;
  result.iterations = solution.iterations;
  SetLowerBound(backend.bound, solution, result);
  if (whole_energy_proven) {  // one window held every free cell
    result.lower_bound = result.labels_objective;
    result.lower_bound_source = "integer optimum";
  }
}

LabelingResult Solve(const EnergyInput& energy,
                     std::span<const std::uint32_t> block_of_cell,
                     const LabelingOptions& options,
                     const RunContext& ctx) {
  const auto start = std::chrono::steady_clock::now();
  const ReducedEnergy reduced = ReduceEnergy(energy);
  const LpShape shape = ShapeOfLp(reduced);
  LabelingResult result;
  result.lp_columns = shape.columns;
  result.lp_rows = shape.rows;
  result.lp_nonzeros = shape.nonzeros;
  const AutoRuleInput facts{
      .higher_order_terms = reduced.HasHigherOrderTerms(),
      .lp_columns = shape.columns,
      .num_blocks = block_of_cell.empty() ? 0 : CountBlocks(energy, block_of_cell)};
  result.backend = ResolveBackend(options.backend, facts, options.auto_rule);
  const LabelingBackend& backend = LookupBackend(result.backend);
  ctx.ThrowIfCancelled(kLpBackendStage);
  LINESURF_THROW_IF(backend.capabilities.needs_partition && block_of_cell.empty(),
                    kInvalidOptions,
                    kLpBackendStage,
                    "backend '" << SolverBackendName(result.backend)
                                << "' needs a partition of the cells into blocks");
  switch (backend.strategy) {
    case BackendStrategy::kBand:
      return SolveInBand(energy, options, ctx, result);
    case BackendStrategy::kBlocks:
      result = SolveByBlocks(energy, reduced, block_of_cell, options, ctx, result);
      break;
    case BackendStrategy::kSolve:
      SolveOnce(energy, reduced, backend, options, ctx, result);
      break;
    case BackendStrategy::kRule:  // ResolveBackend never returns the rule itself
      ThrowError(ErrorCode::kInternal, kLpBackendStage, "the auto rule picked no backend");
  }
  result.seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace

std::string BackendReportName(const LabelingResult& result) {
  std::string name = SolverBackendName(result.backend);
  if (result.band_lp_backend) {
    name += "+";
    name += SolverBackendName(*result.band_lp_backend);
  }
  return name;
}

Expected<LabelingResult> SolveLabeling(const EnergyInput& energy, const LabelingOptions& options,
                                       const RunContext& ctx) noexcept {
  return SolveLabeling(energy, {}, options, ctx);
}

Expected<LabelingResult> SolveLabeling(const EnergyInput& energy,
                                       std::span<const std::uint32_t> block_of_cell,
                                       const LabelingOptions& options,
                                       const RunContext& ctx) noexcept {
  if (Status s = options.Validate(); !s) return s.error();
  if (Status s = energy.Validate(); !s) return s.error();
  if (!block_of_cell.empty() && block_of_cell.size() != energy.NumCells()) {
    return Error{ErrorCode::kInvalidInput,
                 kLpBackendStage,
                 "block of cell: " + std::to_string(block_of_cell.size()) + " entries for " +
                     std::to_string(energy.NumCells()) + " cells"};
  }
  return CatchAll(kLpBackendStage, [&] { return Solve(energy, block_of_cell, options, ctx); });
}

}  // namespace linesurf::solver
