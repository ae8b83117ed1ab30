#include "solver/lp/labeling_backends.h"

#include "engine/core/exception.h"
#include "solver/lp/backends/cbc/cbc_backend.h"
#include "solver/lp/backends/clp/clp_backend.h"
#include "solver/lp/backends/maxflow/maxflow_backend.h"
#include "solver/lp/backends/pdhg/pdhg_backend.h"
#include "solver/lp/backends/pdhg_energy/pdhg_energy_backend.h"
#include "solver/lp/band_fixing.h"
#include "solver/lp/dual_bound.h"

#include <initializer_list>
#include <vector>

namespace linesurf::solver {
namespace {

bool InEveryBuild() noexcept { return true; }

constexpr BackendAvailability kEveryBuild{.in_this_build = InEveryBuild, .missing_hint = ""};
constexpr BackendAvailability kWithCbc{.in_this_build = CbcAvailable,
                                       .missing_hint = "install coinor-libcbc-dev and reconfigure"};

enum class Capability {
  kExact,
  kIntegral,
  kPairwiseOnly,
  kTakesPartition,
  kNeedsPartition,
  kPerBlock
};

// The capabilities listed, the others false.
constexpr BackendCapabilities Can(std::initializer_list<Capability> list) {
  BackendCapabilities can{.exact = false,
                          .integral = false,
                          .pairwise_only = false,
                          .takes_partition = false,
                          .needs_partition = false,
                          .per_block = false};
  for (const Capability c : list) {
    switch (c) {
      case Capability::kExact:
        can.exact = true;
        break;
      case Capability::kIntegral:
        can.integral = true;
        break;
      case Capability::kPairwiseOnly:
        can.pairwise_only = true;
        break;
      case Capability::kTakesPartition:
        can.takes_partition = true;
        break;
      case Capability::kNeedsPartition:
        can.needs_partition = true;
        break;
      case Capability::kPerBlock:
        can.per_block = true;
        break;
    }
  }
  return can;
}

LpSolution RunClp(const BackendInput& input,
                  const LabelingOptions& options,
                  const RunContext& ctx) {
  return SolveLpWithClp(BuildLpModel(input.reduced),
                        ClpAlgorithm::kDualSimplex,
                        options.clp,
                        options.time_limit_seconds,
                        ctx);
}

LpSolution RunClpBarrier(const BackendInput& input,
                         const LabelingOptions& options,
                         const RunContext& ctx) {
  return SolveLpWithClp(BuildLpModel(input.reduced),
                        ClpAlgorithm::kBarrier,
                        options.clp,
                        options.time_limit_seconds,
                        ctx);
}

LpSolution RunMaxflow(const BackendInput& input,
                      const LabelingOptions& /*options*/,
                      const RunContext& ctx) {
  return SolveWithMaxflow(input.reduced, ctx);
}

LpSolution RunPdhg(const BackendInput& input,
                   const LabelingOptions& options,
                   const RunContext& ctx) {
  const LpModel lp = BuildLpModel(input.reduced);
  LpSolution solution = SolveLpWithPdhg(lp, options.pdhg, options.time_limit_seconds, ctx);
  // Its objective is a primal value; its dual point proves the bound (dual_bound.h).
  if (!solution.row_duals.empty()) solution.lower_bound = LagrangianBound(lp, solution.row_duals);
  return solution;
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
  return SolveIlpWithCbc(
      BuildLpModel(input.reduced), input.reduced.NumFree(), incumbent, limits, ctx);
}

// The table's own names: its rows read without the enums' names.
namespace table {

using enum BackendStrategy;
using enum BoundProof;
using enum Capability;

// In the order of their names in messages. Per row: backend, capabilities, availability; how it
// runs, how it proves its lower bound.
// clang-format off
constexpr LabelingBackend kBackends[] = {
    {SolverBackend::kAuto, Can({kTakesPartition, kPerBlock}), kEveryBuild,
     kRule, nullptr, kNone},
    {SolverBackend::kClp, Can({kExact, kPerBlock}), kEveryBuild,
     kSolve, RunClp, kLpOptimum},
    {SolverBackend::kClpBarrier, Can({kExact}), kEveryBuild,
     kSolve, RunClpBarrier, kLpOptimum},
    {SolverBackend::kMaxflow, Can({kExact, kIntegral, kPairwiseOnly}), kEveryBuild,
     kSolve, RunMaxflow, kIntegerOptimum},
    {SolverBackend::kPdhg, Can({kPerBlock}), kEveryBuild,
     kSolve, RunPdhg, kLpDual},
    {SolverBackend::kPdhgEnergy, Can({kPerBlock}), kEveryBuild,
     kSolve, RunPdhgEnergy, kEnergyDual},
    {SolverBackend::kBand, Can({}), kEveryBuild,
     kBand, nullptr, kPairwiseOptimum},
    {SolverBackend::kBlocks, Can({kTakesPartition, kNeedsPartition}), kEveryBuild,
     kBlocks, nullptr, kBlockBounds},
    {SolverBackend::kCbc, Can({kExact, kIntegral, kPerBlock}), kWithCbc,
     kSolve, RunCbc, kBranchAndBound},
};
// clang-format on

}  // namespace table
}  // namespace

std::span<const LabelingBackend> LabelingBackends() noexcept { return table::kBackends; }

const LabelingBackend* FindBackend(SolverBackend backend) noexcept {
  for (const LabelingBackend& b : LabelingBackends()) {
    if (b.backend == backend) return &b;
  }
  return nullptr;
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
  for (const LabelingBackend& b : LabelingBackends()) {
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
