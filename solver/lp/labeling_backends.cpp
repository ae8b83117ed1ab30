#include "solver/lp/labeling_backends.h"

#include "engine/core/exception.h"
#include "solver/lp/backends/cbc/cbc_backend.h"
#include "solver/lp/backends/clp/clp_backend.h"
#include "solver/lp/backends/maxflow/maxflow_backend.h"
#include "solver/lp/backends/pdhg/pdhg_backend.h"
#include "solver/lp/backends/pdhg_energy/pdhg_energy_backend.h"
#include "solver/lp/band_fixing.h"

#include <algorithm>
#include <vector>

namespace linesurf::solver {
namespace {

bool InEveryBuild() noexcept { return true; }

LpSolution RunClp(const BackendInput& input,
                  const LabelingOptions& options,
                  const RunContext& ctx) {
  return SolveLpWithClp(
      input.lp, ClpAlgorithm::kDualSimplex, options.clp, options.time_limit_seconds, ctx);
}

LpSolution RunClpBarrier(const BackendInput& input,
                         const LabelingOptions& options,
                         const RunContext& ctx) {
  return SolveLpWithClp(
      input.lp, ClpAlgorithm::kBarrier, options.clp, options.time_limit_seconds, ctx);
}

LpSolution RunMaxflow(const BackendInput& input,
                      const LabelingOptions& /*options*/,
                      const RunContext& ctx) {
  return SolveWithMaxflow(input.reduced, ctx);
}

LpSolution RunPdhg(const BackendInput& input,
                   const LabelingOptions& options,
                   const RunContext& ctx) {
  return SolveLpWithPdhg(input.lp, options.pdhg, options.time_limit_seconds, ctx);
}

LpSolution RunPdhgEnergy(const BackendInput& input,
                         const LabelingOptions& options,
                         const RunContext& ctx) {
  return SolveEnergyWithPdhg(input.reduced, options.pdhg_energy, options.time_limit_seconds, ctx);
}

LpSolution RunCbc(const BackendInput& input,
                  const LabelingOptions& options,
                  const RunContext& ctx) {
  IlpLimits limits;
  limits.time_limit_seconds = options.time_limit_seconds;
  // First incumbent: the max-flow labels of the pairwise part (any labelling is feasible).
  const std::vector<std::uint8_t> pairwise = PairwiseLabels(input.energy, ctx);
  std::vector<double> incumbent(input.reduced.NumFree());
  for (std::size_t j = 0; j < incumbent.size(); ++j) {
    incumbent[j] = pairwise[input.reduced.cell_of_column[j].index()];
  }
  return SolveIlpWithCbc(input.lp, input.reduced.NumFree(), incumbent, limits, ctx);
}

// In the order of their names in messages.
constexpr LabelingBackend kBackends[] = {
    {.backend = SolverBackend::kAuto,
     .capabilities = {.exact = false,
                      .integral = false,
                      .pairwise_only = false,
                      .takes_partition = true,
                      .needs_partition = false,
                      .per_block = true},
     .available = InEveryBuild,
     .missing_hint = "",
     .strategy = BackendStrategy::kRule,
     .solves_lp_model = false,
     .solve = nullptr,
     .bound = BoundProof::kNone},
    {.backend = SolverBackend::kClp,
     .capabilities = {.exact = true,
                      .integral = false,
                      .pairwise_only = false,
                      .takes_partition = false,
                      .needs_partition = false,
                      .per_block = true},
     .available = InEveryBuild,
     .missing_hint = "",
     .strategy = BackendStrategy::kSolve,
     .solves_lp_model = true,
     .solve = RunClp,
     .bound = BoundProof::kLpOptimum},
    {.backend = SolverBackend::kClpBarrier,
     .capabilities = {.exact = true,
                      .integral = false,
                      .pairwise_only = false,
                      .takes_partition = false,
                      .needs_partition = false,
                      .per_block = false},
     .available = InEveryBuild,
     .missing_hint = "",
     .strategy = BackendStrategy::kSolve,
     .solves_lp_model = true,
     .solve = RunClpBarrier,
     .bound = BoundProof::kLpOptimum},
    {.backend = SolverBackend::kMaxflow,
     .capabilities = {.exact = true,
                      .integral = true,
                      .pairwise_only = true,
                      .takes_partition = false,
                      .needs_partition = false,
                      .per_block = false},
     .available = InEveryBuild,
     .missing_hint = "",
     .strategy = BackendStrategy::kSolve,
     .solves_lp_model = false,
     .solve = RunMaxflow,
     .bound = BoundProof::kIntegerOptimum},
    {.backend = SolverBackend::kPdhg,
     .capabilities = {.exact = false,
                      .integral = false,
                      .pairwise_only = false,
                      .takes_partition = false,
                      .needs_partition = false,
                      .per_block = true},
     .available = InEveryBuild,
     .missing_hint = "",
     .strategy = BackendStrategy::kSolve,
     .solves_lp_model = true,
     .solve = RunPdhg,
     .bound = BoundProof::kLpDual},
    {.backend = SolverBackend::kPdhgEnergy,
     .capabilities = {.exact = false,
                      .integral = false,
                      .pairwise_only = false,
                      .takes_partition = false,
                      .needs_partition = false,
                      .per_block = true},
     .available = InEveryBuild,
     .missing_hint = "",
     .strategy = BackendStrategy::kSolve,
     .solves_lp_model = false,
     .solve = RunPdhgEnergy,
     .bound = BoundProof::kEnergyDual},
    {.backend = SolverBackend::kBand,
     .capabilities = {.exact = false,
                      .integral = false,
                      .pairwise_only = false,
                      .takes_partition = false,
                      .needs_partition = false,
                      .per_block = false},
     .available = InEveryBuild,
     .missing_hint = "",
     .strategy = BackendStrategy::kBand,
     .solves_lp_model = false,
     .solve = nullptr,
     .bound = BoundProof::kPairwiseOptimum},
    {.backend = SolverBackend::kBlocks,
     .capabilities = {.exact = false,
                      .integral = false,
                      .pairwise_only = false,
                      .takes_partition = true,
                      .needs_partition = true,
                      .per_block = false},
     .available = InEveryBuild,
     .missing_hint = "",
     .strategy = BackendStrategy::kBlocks,
     .solves_lp_model = false,
     .solve = nullptr,
     .bound = BoundProof::kBlockBounds},
    {.backend = SolverBackend::kCbc,
     .capabilities = {.exact = true,
                      .integral = true,
                      .pairwise_only = false,
                      .takes_partition = false,
                      .needs_partition = false,
                      .per_block = true},
     .available = CbcAvailable,
     .missing_hint = "install coinor-libcbc-dev and reconfigure",
     .strategy = BackendStrategy::kSolve,
     .solves_lp_model = true,
     .solve = RunCbc,
     .bound = BoundProof::kBranchAndBound},
};

}  // namespace

std::span<const LabelingBackend> LabelingBackends() noexcept { return kBackends; }

const LabelingBackend* FindBackend(SolverBackend backend) noexcept {
  const auto* it =
      std::find_if(std::begin(kBackends), std::end(kBackends), [backend](const LabelingBackend& b) {
        return b.backend == backend;
      });
  return it == std::end(kBackends) ? nullptr : it;
}

const LabelingBackend& LookupBackend(SolverBackend backend) {
  const LabelingBackend* entry = FindBackend(backend);
  LINESURF_THROW_IF(entry == nullptr,
                    kInvalidOptions,
                    "solve_labeling",
                    "backend: value " << static_cast<int>(backend) << " is not a backend");
  return *entry;
}

std::string BackendNames(bool (*keep)(const LabelingBackend&)) {
  std::string names;
  for (const LabelingBackend& b : kBackends) {
    if (!keep(b)) continue;
    if (!names.empty()) names += ", ";
    names += SolverBackendName(b.backend);
  }
  return names;
}

SolverBackend ResolveBackend(SolverBackend requested,
                             const AutoRuleInput& input,
                             const AutoRuleOptions& rule) noexcept {
  if (requested != SolverBackend::kAuto) return requested;
  if (!input.higher_order_terms) return SolverBackend::kMaxflow;
  if (input.num_blocks > 1 && input.lp_columns > rule.blocks_min_columns) {
    return SolverBackend::kBlocks;
  }
  if (input.lp_columns > rule.band_min_columns) return SolverBackend::kBand;
  return input.lp_columns <= rule.clp_max_columns ? SolverBackend::kClp
                                                  : SolverBackend::kPdhgEnergy;
}

}  // namespace linesurf::solver
