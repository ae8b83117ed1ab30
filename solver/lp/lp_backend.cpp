#include "solver/lp/lp_backend.h"

#include <chrono>
#include <cmath>
#include <limits>

#include "engine/core/exception.h"
#include "solver/energy/build_lp.h"
#include "solver/lp/band_fixing.h"
#include "solver/lp/backends/clp/clp_backend.h"
#include "solver/lp/backends/maxflow/maxflow_backend.h"
#include "solver/lp/backends/pdhg/pdhg_backend.h"
#include "solver/lp/round_labels.h"

namespace linesurf::solver {
namespace {

constexpr const char* kStage = "solve_labeling";

Error InvalidOption(const std::string& message) {
  return Error{ErrorCode::kInvalidOptions, kStage, message};
}

std::string ResolveBackend(const std::string& requested, const ReducedEnergy& reduced,
                           std::size_t lp_columns, const LabelingOptions& options) {
  if (requested != "auto") return requested;
  if (!reduced.HasHigherOrderTerms()) return "maxflow";
  if (lp_columns > options.auto_band_min_columns) return "band";
  return lp_columns <= options.auto_clp_max_columns ? "clp" : "pdhg";
}

LabelingResult Solve(const EnergyInput& energy, const LabelingOptions& options,
                     const RunContext& ctx);

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
  LabelingResult result = Solve(banded, inner, ctx);
  result.backend = "band+" + result.backend;
  result.band_lp_columns = result.lp_columns;
  result.lp_columns = full.lp_columns;
  result.lp_rows = full.lp_rows;
  result.lp_nonzeros = full.lp_nonzeros;
  result.seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

LabelingResult Solve(const EnergyInput& energy, const LabelingOptions& options,
                     const RunContext& ctx) {
  const auto start = std::chrono::steady_clock::now();
  const ReducedEnergy reduced = ReduceEnergy(energy);
  const LpModel lp = BuildLpModel(reduced);
  LabelingResult result;
  result.lp_columns = lp.NumColumns();
  result.lp_rows = lp.NumRows();
  result.lp_nonzeros = lp.NumNonzeros();
  result.backend = ResolveBackend(options.backend, reduced, lp.NumColumns(), options);
  ctx.ThrowIfCancelled(kStage);
  if (result.backend == "band") return SolveInBand(energy, options, ctx, result);

  LpSolution solution;
  if (result.backend == "clp") {
    solution = SolveLpWithClp(lp, ClpAlgorithm::kDualSimplex, options, ctx);
  } else if (result.backend == "clp-barrier") {
    solution = SolveLpWithClp(lp, ClpAlgorithm::kBarrier, options, ctx);
  } else if (result.backend == "maxflow") {
    solution = SolveWithMaxflow(reduced, ctx);
  } else if (result.backend == "pdhg") {
    solution = SolveLpWithPdhg(lp, options, ctx);
  } else {
    ThrowError(ErrorCode::kInvalidOptions, kStage, "unknown backend '" + result.backend + "'");
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
  result.local_search_flips = ImproveLabels(energy, options.local_search_passes, result.labels);
  result.labels_objective = result.local_search_flips == 0
                                ? result.rounded_objective
                                : energy.Evaluate(std::span<const std::uint8_t>(result.labels));
  result.status = solution.status;
  result.iterations = solution.iterations;
  result.seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace

Status LabelingOptions::Validate() const {
  if (backend != "auto" && backend != "clp" && backend != "clp-barrier" && backend != "maxflow" &&
      backend != "pdhg" && backend != "band") {
    return InvalidOption("backend: '" + backend +
                         "' is not one of auto, clp, clp-barrier, maxflow, pdhg, band");
  }
  if (band_rings < 0 || band_rings > 16) return InvalidOption("band_rings: must be in [0, 16]");
  if (!(clp_tolerance > 0.0 && clp_tolerance <= 1e-2)) {
    return InvalidOption("clp_tolerance: must be in (0, 1e-2]");
  }
  if (!(pdhg_tolerance > 0.0 && pdhg_tolerance <= 1e-1)) {
    return InvalidOption("pdhg_tolerance: must be in (0, 1e-1]");
  }
  if (pdhg_max_iterations < 1) return InvalidOption("pdhg_max_iterations: must be >= 1");
  if (local_search_passes < 0 || local_search_passes > 1000) {
    return InvalidOption("local_search_passes: must be in [0, 1000]");
  }
  if (!(time_limit_seconds >= 0.0) || !std::isfinite(time_limit_seconds)) {
    return InvalidOption("time_limit_seconds: must be finite and >= 0");
  }
  return {};
}

Expected<LabelingResult> SolveLabeling(const EnergyInput& energy, const LabelingOptions& options,
                                       const RunContext& ctx) noexcept {
  if (Status s = options.Validate(); !s) return s.error();
  if (Status s = energy.Validate(); !s) return s.error();
  return CatchAll(kStage, [&] { return Solve(energy, options, ctx); });
}

}  // namespace linesurf::solver
