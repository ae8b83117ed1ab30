#pragma once
/// @file labeling_backends.h
/// @brief The table of SolveLabeling's backends, keyed by linesurf::SolverBackend: per backend
/// its capabilities (as CGAL's MixedIntegerProgramTraits describes a solver), whether this build
/// has it, how it runs and how it proves its lower bound (docs/design/lp_backend.md, "Backend
/// table"). A backend's name is SolverBackendName's; nothing here compares names.

#include "linesurf/options.h"

#include "engine/core/run_context.h"
#include "solver/energy/build_lp.h"
#include "solver/energy/energy_input.h"
#include "solver/lp/labeling_options.h"
#include "solver/lp/lp_solution.h"

#include <cstddef>
#include <span>
#include <string>

namespace linesurf::solver {

/// What a backend guarantees and needs.
struct BackendCapabilities {
  /// Proves the optimum of what it solves (the LP relaxation, or the integer program), not an
  /// optimum within a tolerance.
  bool exact = false;
  /// Solves the integer program (cells 0/1) itself: no rounding, no exact windows after it.
  bool integral = false;
  /// Refuses (kInvalidOptions) an energy left with structural or parity terms once the fixed
  /// cells are substituted.
  bool pairwise_only = false;
  /// Uses a partition of the cells into blocks when one is given.
  bool takes_partition = false;
  /// Runs only with a partition (the SolveLabeling overload that takes one).
  bool needs_partition = false;
  /// Can solve each block of "blocks" (BlocksOptions::backend).
  bool per_block = false;
};

/// How a backend runs.
enum class BackendStrategy {
  kRule,    ///< "auto": ResolveBackend picks the backend that runs
  kSolve,   ///< one solve of the reduced energy by LabelingBackend::solve, then rounding (unless
            ///< integral) and the improvement passes
  kBand,    ///< composite: max-flow, then the LP of the cells near its surface (band_fixing.h)
  kBlocks,  ///< composite: per-block solves by the block backend (block_labeling.h)
};

/// How a backend proves LabelingResult::lower_bound (its lower_bound_source text).
enum class BoundProof {
  kNone,             ///< proves nothing ("auto" before it is resolved)
  kLpOptimum,        ///< the LP optimum it proves ("lp optimum")
  kIntegerOptimum,   ///< its labels are an integral optimum ("integer optimum")
  kEnergyDual,       ///< its best multiplier point of the energy's saddle form
                     ///< ("energy dual bound")
  kLpDual,           ///< the Lagrangian bound of its LP dual point, dual_bound.h ("lp dual bound")
  kBranchAndBound,   ///< branch and bound's best bound ("integer optimum" when it proves it,
                     ///< else "branch and bound")
  kPairwiseOptimum,  ///< the max-flow minimum of the unary and pairwise terms ("pairwise optimum")
  kBlockBounds,      ///< the best of the pairwise optimum, dual ascent and the block split
                     ///< (block_labeling.h)
};

/// What a kSolve backend solves: the energy and the same reduced to its free cells (a backend
/// that solves the LP model builds it from `reduced`, build_lp.h).
struct BackendInput {
  const EnergyInput& energy;
  const ReducedEnergy& reduced;
};

/// Runs a kSolve backend with its own options struct of `options` and the time limit. The
/// solution has one value per free cell first (LpSolution::columns), then any slacks.
using SolveFunction = LpSolution (*)(const BackendInput& input,
                                     const LabelingOptions& options,
                                     const RunContext& ctx);

/// Whether this build has a backend.
struct BackendAvailability {
  bool (*in_this_build)() noexcept = nullptr;
  /// What brings it into a build that lacks it ("" for a backend every build has).
  const char* missing_hint = "";
};

struct LabelingBackend {
  SolverBackend backend = SolverBackend::kAuto;
  BackendCapabilities capabilities;
  /// cbc is optional at build time; every other backend is in every build.
  BackendAvailability availability;
  BackendStrategy strategy = BackendStrategy::kSolve;
  /// kSolve: runs it; null for the other strategies.
  SolveFunction solve = nullptr;
  BoundProof bound = BoundProof::kNone;
};

/// Every backend once, in the order of their names in messages (auto, clp, clp-barrier, maxflow,
/// pdhg, pdhg-energy, band, blocks, cbc).
[[nodiscard]] std::span<const LabelingBackend> LabelingBackends() noexcept;

/// The entry of `backend`; nullptr for a value outside the enum.
[[nodiscard]] const LabelingBackend* FindBackend(SolverBackend backend) noexcept;

/// The entry of `backend`; throws kInvalidOptions for a value outside the enum.
[[nodiscard]] const LabelingBackend& LookupBackend(SolverBackend backend);

/// The names of the backends for which `keep` holds, in table order, ", "-separated.
[[nodiscard]] std::string BackendNames(bool (*keep)(const LabelingBackend&));

/// What the "auto" rule looks at.
struct AutoRuleInput {
  /// Structural or parity terms left after the fixed cells are substituted.
  bool higher_order_terms = false;
  std::size_t lp_columns = 0;
  /// Blocks holding a free cell in the partition given (0 without one).
  std::size_t num_blocks = 0;
};

/// `requested` unless it is kAuto; kAuto resolves to maxflow when the energy is pairwise (exact),
/// else blocks above rule.blocks_min_columns LP columns when more than one block is given, else
/// band above rule.band_min_columns, else clp up to rule.clp_max_columns, else pdhg-energy.
[[nodiscard]] SolverBackend ResolveBackend(SolverBackend requested,
                                           const AutoRuleInput& input,
                                           const AutoRuleOptions& rule) noexcept;

}  // namespace linesurf::solver
