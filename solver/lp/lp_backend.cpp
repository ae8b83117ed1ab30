#include "solver/lp/lp_backend.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

#include "engine/core/exception.h"
#include "solver/energy/build_lp.h"
#include "solver/lp/band_fixing.h"
#include "solver/lp/block_labeling.h"
#include "solver/lp/dual_bound.h"
#include "solver/lp/group_moves.h"
#include "solver/lp/backends/cbc/cbc_backend.h"
#include "solver/lp/backends/clp/clp_backend.h"
#include "solver/lp/backends/maxflow/maxflow_backend.h"
#include "solver/lp/backends/pdhg/pdhg_backend.h"
#include "solver/lp/backends/pdhg_energy/pdhg_energy_backend.h"
#include "solver/lp/round_labels.h"
#include "solver/lp/window_polish.h"

namespace linesurf::solver {
namespace {

constexpr const char* kLpBackendStage = "solve_labeling";

Error InvalidOption(const std::string& message) {
  return Error{ErrorCode::kInvalidOptions, kLpBackendStage, message};
}

std::string ResolveBackend(const std::string& requested, const ReducedEnergy& reduced,
                           std::size_t lp_columns, const LabelingOptions& options,
                           std::size_t num_blocks) {
  if (requested != "auto") return requested;
  if (!reduced.HasHigherOrderTerms()) return "maxflow";
  if (num_blocks > 1 && lp_columns > options.auto_blocks_min_columns) return "blocks";
  if (lp_columns > options.auto_band_min_columns) return "band";
  return lp_columns <= options.auto_clp_max_columns ? "clp" : "pdhg-energy";
}

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

// What the backend proves about the integral optimum.
void SetLowerBound(LabelingResult& result, const LpModel& lp, const LpSolution& solution) {
  if (result.backend == "clp" || result.backend == "clp-barrier") {
    result.lower_bound = result.relaxed_objective;
    result.lower_bound_source = "lp optimum";
  } else if (result.backend == "maxflow") {
    result.lower_bound = result.labels_objective;
    result.lower_bound_source = "integer optimum";
  } else if (result.backend == "pdhg-energy") {
    result.lower_bound = std::min(solution.lower_bound, result.labels_objective);
    result.lower_bound_source = "energy dual bound";
  } else if (result.backend == "pdhg" && !solution.row_duals.empty()) {
    // pdhg's relaxed objective is a primal value; its dual point proves a bound.
    result.lower_bound = std::min(LagrangianBound(lp, solution.row_duals), result.labels_objective);
    result.lower_bound_source = "lp dual bound";
  } else if (result.backend == "cbc") {
    result.lower_bound = std::min(solution.lower_bound, result.labels_objective);
    result.lower_bound_source = result.status == "optimal" ? "integer optimum" : "branch and bound";
  }
}

// After rounding: local search, group moves and exact windows (each optional), the energy of
// the labels and the method. Returns true when one exact window held every free cell.
bool Improve(const EnergyInput& energy, const LabelingOptions& options, const RunContext& ctx,
             LabelingResult& result) {
  result.local_search_flips = ImproveLabels(energy, options.local_search_passes, result.labels);
  result.group_move_changes =
      ImproveByGroupMoves(energy, options.group_move_passes, ctx, result.labels);
  // The exact backends (cbc, maxflow) solve the integer program themselves: no windows.
  const bool exact = result.backend == "cbc" || result.backend == "maxflow";
  const WindowPolishStats polished =
      exact ? WindowPolishStats{} : PolishResultInWindows(energy, options, ctx, result);
  result.labels_objective =
      result.local_search_flips + result.group_move_changes + result.window_changes == 0
          ? result.rounded_objective
          : energy.Evaluate(std::span<const std::uint8_t>(result.labels));
  result.method = result.backend + (exact ? " integer program" : " lp, rounding");
  if (options.local_search_passes > 0) result.method += ", local search";
  if (options.group_move_passes > 0) result.method += ", group moves";
  if (polished.windows > 0) {
    result.method += ", exact windows of " + std::to_string(options.window_cells) + " cells (cbc)";
  }
  return polished.whole_energy_proven;
}

// Band strategy (band_fixing.h): max-flow of the pairwise part, then the LP of the cells near
// its surface with every other cell fixed. Sizes reported are those of the full LP (`full`) and,
// in the backend name, the band's own backend.
LabelingResult SolveInBand(const EnergyInput& energy, const LabelingOptions& options,
                           const RunContext& ctx, const LabelingResult& full) {
  const auto start = std::chrono::steady_clock::now();
  const std::vector<std::uint8_t> pairwise = PairwiseLabels(energy, ctx);
  const EnergyInput banded = FixCellsOutsideBand(energy, pairwise, options.band_rings);
  LabelingOptions inner = options;
  inner.backend = "auto";
  inner.auto_band_min_columns = std::numeric_limits<std::size_t>::max();
  inner.local_search_passes = inner.group_move_passes = 0;
  inner.window_cells = 0;
  LabelingResult result = Solve(banded, {}, inner, ctx);
  // The moves and windows work on the whole energy: they may change cells outside the band.
  Improve(energy, options, ctx, result);
  result.backend = "band+" + result.backend;
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

LabelingResult Solve(const EnergyInput& energy, std::span<const std::uint32_t> block_of_cell,
                     const LabelingOptions& options, const RunContext& ctx) {
  const auto start = std::chrono::steady_clock::now();
  const ReducedEnergy reduced = ReduceEnergy(energy);
  const LpShape shape = ShapeOfLp(reduced);
  LabelingResult result;
  result.lp_columns = shape.columns;
  result.lp_rows = shape.rows;
  result.lp_nonzeros = shape.nonzeros;
  result.backend = ResolveBackend(options.backend, reduced, shape.columns, options,
                                  block_of_cell.empty() ? 0 : CountBlocks(energy, block_of_cell));
  ctx.ThrowIfCancelled(kLpBackendStage);
  if (result.backend == "band") return SolveInBand(energy, options, ctx, result);
  if (result.backend == "blocks") {
    LINESURF_THROW_IF(block_of_cell.empty(),
                      kInvalidOptions,
                      kLpBackendStage,
                      "backend 'blocks' needs a partition of the cells into blocks");
    LabelingResult blocks = SolveInBlocks(energy, reduced, block_of_cell, options, ctx);
    blocks.lp_columns = shape.columns;
    blocks.lp_rows = shape.rows;
    blocks.lp_nonzeros = shape.nonzeros;
    blocks.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return blocks;
  }
  const LpModel lp = result.backend == "pdhg-energy" ? LpModel{} : BuildLpModel(reduced);

  LpSolution solution;
  if (result.backend == "pdhg-energy") {
    solution = SolveEnergyWithPdhg(reduced, options, ctx);
  } else if (result.backend == "clp") {
    solution = SolveLpWithClp(lp, ClpAlgorithm::kDualSimplex, options, ctx);
  } else if (result.backend == "clp-barrier") {
    solution = SolveLpWithClp(lp, ClpAlgorithm::kBarrier, options, ctx);
  } else if (result.backend == "maxflow") {
    solution = SolveWithMaxflow(reduced, ctx);
  } else if (result.backend == "pdhg") {
    solution = SolveLpWithPdhg(lp, options, ctx);
  } else if (result.backend == "cbc") {
    IlpLimits limits;
    limits.time_limit_seconds = options.time_limit_seconds;
    // First incumbent: the max-flow labels of the pairwise part (any labelling is feasible).
    const std::vector<std::uint8_t> pairwise = PairwiseLabels(energy, ctx);
    std::vector<double> incumbent(reduced.NumFree());
    for (std::size_t j = 0; j < incumbent.size(); ++j) {
      incumbent[j] = pairwise[reduced.cell_of_column[j].index()];
    }
    solution = SolveIlpWithCbc(lp, reduced.NumFree(), incumbent, limits, ctx);
  } else {
    ThrowError(
        ErrorCode::kInvalidOptions, kLpBackendStage, "unknown backend '" + result.backend + "'");
  }
  LINESURF_ASSERT(solution.columns.size() >= reduced.NumFree());

  // Cell values: clip the first-order backends' small bound violations.
  std::vector<double> columns(solution.columns.begin(),
                              solution.columns.begin() + static_cast<std::ptrdiff_t>(reduced.NumFree()));
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
  SetLowerBound(result, lp, solution);
  if (whole_energy_proven) {  // one window held every free cell
    result.lower_bound = result.labels_objective;
    result.lower_bound_source = "integer optimum";
  }
  result.seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace

Status LabelingOptions::Validate() const {
  if (backend != "auto" && backend != "clp" && backend != "clp-barrier" && backend != "maxflow" &&
      backend != "pdhg" && backend != "pdhg-energy" && backend != "band" && backend != "blocks" &&
      backend != "cbc") {
    return InvalidOption("backend: '" + backend +
                         "' is not one of auto, clp, clp-barrier, maxflow, pdhg, pdhg-energy, "
                         "band, blocks, cbc");
  }
  if (block_backend != "auto" && block_backend != "clp" && block_backend != "pdhg" &&
      block_backend != "pdhg-energy" && block_backend != "cbc") {
    return InvalidOption("block_backend: '" + block_backend +
                         "' is not one of auto, clp, pdhg, pdhg-energy, cbc");
  }
  if ((backend == "cbc" || block_backend == "cbc") && !CbcAvailable()) {
    return InvalidOption("backend: 'cbc' is not in this build (install coinor-libcbc-dev and "
                         "reconfigure)");
  }
  if (block_sweeps < 0 || block_sweeps > 100) {
    return InvalidOption("block_sweeps: must be in [0, 100]");
  }
  if (block_max_cells < 1) return InvalidOption("block_max_cells: must be >= 1");
  if (block_halo < 0 || block_halo > 8) return InvalidOption("block_halo: must be in [0, 8]");
  if (block_bound_passes < 0 || block_bound_passes > 10000) {
    return InvalidOption("block_bound_passes: must be in [0, 10000]");
  }
  if (band_rings < 0 || band_rings > 16) return InvalidOption("band_rings: must be in [0, 16]");
  if (!(clp_tolerance > 0.0 && clp_tolerance <= 1e-2)) {
    return InvalidOption("clp_tolerance: must be in (0, 1e-2]");
  }
  if (!(pdhg_tolerance > 0.0 && pdhg_tolerance <= 1e-1)) {
    return InvalidOption("pdhg_tolerance: must be in (0, 1e-1]");
  }
  if (!(pdhg_energy_tolerance > 0.0 && pdhg_energy_tolerance <= 1e-1)) {
    return InvalidOption("pdhg_energy_tolerance: must be in (0, 1e-1]");
  }
  if (pdhg_max_iterations < 1) return InvalidOption("pdhg_max_iterations: must be >= 1");
  if (local_search_passes < 0 || local_search_passes > 1000) {
    return InvalidOption("local_search_passes: must be in [0, 1000]");
  }
  if (group_move_passes < 0 || group_move_passes > 1000) {
    return InvalidOption("group_move_passes: must be in [0, 1000]");
  }
  if (window_cells > 4096) return InvalidOption("window_cells: must be in [0, 4096]");
  if (window_max_nodes < 1) return InvalidOption("window_max_nodes: must be >= 1");
  if (!(time_limit_seconds >= 0.0) || !std::isfinite(time_limit_seconds)) {
    return InvalidOption("time_limit_seconds: must be finite and >= 0");
  }
  return {};
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
