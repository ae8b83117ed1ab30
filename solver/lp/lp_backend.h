#pragma once
/// @file lp_backend.h
/// @brief SolveLabeling: minimise an EnergyInput over 0/1 labels through its LP relaxation.
///
/// Backends (LabelingOptions::backend, a linesurf::SolverBackend; each is an entry of the table
/// in labeling_backends.h, which gives its capabilities, how it runs and how it proves its lower
/// bound; each reads only its own options struct of labeling_options.h and the time limit):
///  - clp:     COIN-OR Clp, dual simplex with presolve on the exact LP relaxation (build_lp.h).
///             Deterministic. The reference. Options: ClpOptions.
///  - maxflow: Boykov-Kolmogorov max-flow (libmaxflow). Exact (an optimal integral labelling,
///             which is also an optimum of the LP) when, after fixed cells are substituted, no
///             structural or parity group is left; otherwise refused with kInvalidOptions.
///  - pdhg:    first-order primal-dual LP method (PDLP-style: diagonal preconditioning, restarts
///             to the average, adaptive primal weight); SpMV in fixed chunks with oneTBB so the
///             result is identical for any thread count. Approximate optimum (relative tolerance
///             PdhgOptions::tolerance), fast on large complexes.
///  - pdhg-energy: the same relaxation solved by first-order primal-dual steps on the energy's
///             saddle-point form (pdhg_energy_backend.h): one variable per free cell and one
///             bounded multiplier per term, no slack columns; every multiplier point proves a
///             lower bound. Identical for any thread count. Options: PdhgEnergyOptions.
///  - band:    for large complexes (band_fixing.h): exact max-flow of the unary and pairwise
///             terms, then the LP ("auto" among maxflow/clp/pdhg-energy, reported in
///             LabelingResult::band_lp_backend) of the cells near that surface only, every other
///             cell fixed at its max-flow label. A heuristic: not the full LP's optimum in
///             general. Options: BandOptions.
///  - auto:    maxflow when it is exact, else blocks above AutoRuleOptions::blocks_min_columns LP
///             columns when a partition of more than one block is given, else clp up to
///             clp_max_columns LP columns, else pdhg-energy (ResolveBackend; see
///             docs/design/lp_backend.md for the measurements). band only above
///             band_min_columns, which is off by default: band changes the result (measured on
///             an Andalusian crop, docs/user/results.md "Integral labelling").
///  - blocks:  per-block solve for large complexes (block_labeling.h), given a partition of the
///             cells into blocks: each block's interior energy solved by BlocksOptions::backend,
///             in parallel, each with a halo of its neighbours' cells; bound: pairwise optimum,
///             dual ascent, Lagrangian split. Needs the partition (the SolveLabeling overload
///             that takes one).
///  - clp-barrier: Clp's barrier with its built-in Cholesky; for measurements only (slow).
///  - cbc:     COIN-OR Cbc branch and cut on the integer program itself (cells 0/1): the integral
///             optimum when it proves one (status "optimal"), else the best labelling within
///             time_limit_seconds (status "time limit"). Exponential in the worst case: for
///             small energies, tests and measurements of the rounding gap. Optional at build
///             time (cbc_backend.h).
///
/// Rounding: label_c = 1 if x_c > 0.5 + kTieTolerance, 0 if x_c < 0.5 - kTieTolerance.
/// Ties (|x_c - 0.5| <= kTieTolerance) are decided one by one in increasing CellId order: each
/// takes the label of lower energy given the labels decided so far (undecided ties count as
/// empty); on equal energy the cell is empty. Fixed cells keep their label. Then (ImproveOptions)
/// local search (local_search_passes, on by default) flips single free cells in id order while
/// that lowers the energy, group moves (group_move_passes, on by default) give the free cells of
/// one term at a time their best joint labelling, and exact windows (window_cells, with Cbc)
/// solve small integer programs around what is left fractional. A backend that solves the
/// integer program itself (capability "integral": maxflow, cbc) gets no windows.

#include "linesurf/error.h"
#include "linesurf/options.h"

#include "engine/core/run_context.h"
#include "solver/energy/energy_input.h"
#include "solver/lp/labeling_options.h"

#include <cstdint>
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace linesurf::solver {

/// Half-width of the band around 0.5 in which a relaxed value counts as a tie.
inline constexpr double kTieTolerance = 1e-7;

struct LabelingResult {
  /// 0 (empty) or 1 (full) per cell, fixed cells included; index = CellId::index().
  std::vector<std::uint8_t> labels;
  /// Relaxed LP value per cell in [0,1] (fixed cells at their label).
  std::vector<double> relaxed;
  /// EnergyInput::Evaluate(relaxed): the LP objective (constant of fixed cells included) at the
  /// relaxed cell values with optimal slacks. For the exact backends (clp, maxflow) the LP
  /// optimum, a lower bound on the integral optimum; for pdhg within its tolerance of it.
  double relaxed_objective = 0.0;
  /// EnergyInput::Evaluate(labels) (after local search, if any).
  double labels_objective = 0.0;
  /// Energy of the rounded labels before local search.
  double rounded_objective = 0.0;
  /// The best proven lower bound on the integral optimum of the energy (so labels_objective -
  /// lower_bound bounds how far the labels are from optimal); -infinity when none is known.
  double lower_bound = -std::numeric_limits<double>::infinity();
  /// Where lower_bound comes from (the backend's BoundProof, labeling_backends.h): "lp optimum"
  /// (clp), "energy dual bound" (pdhg-energy: its best multiplier point), "lp dual bound" (pdhg:
  /// the Lagrangian bound of its dual point, dual_bound.h; its relaxed_objective is a primal
  /// value, not a bound), "integer optimum" (cbc proved it, maxflow, or one exact window held
  /// every free cell), "branch and bound" (cbc stopped early), "pairwise optimum" (band: the
  /// max-flow minimum of the unary and pairwise terms, the others being >= 0), "block split: ..."
  /// (blocks: the sum of the blocks' interior bounds, with how each was proven), "none".
  std::string lower_bound_source = "none";
  /// LP columns of the band's own LP ("band" backend only; 0 otherwise).
  std::size_t band_lp_columns = 0;
  /// "blocks" only (0 otherwise): blocks with free cells, terms whose free cells lie in more than
  /// one block, block solves (interior solves of the split bound included), those decided by the
  /// pairwise certificate (no LP), block proposals taken, sweeps run, and the LP columns of the
  /// largest block LP.
  std::size_t blocks = 0;
  std::size_t crossing_terms = 0;
  std::size_t block_solves = 0;
  std::size_t block_certified = 0;
  std::size_t block_improvements = 0;
  std::size_t block_sweeps = 0;
  std::size_t block_max_lp_columns = 0;
  /// Cells flipped by local search.
  std::size_t local_search_flips = 0;
  /// Cells changed by group moves (and the single flips between their sweeps).
  std::size_t group_move_changes = 0;
  /// Windows solved exactly after the moves, those that lowered the energy, cells changed.
  std::size_t windows = 0;
  std::size_t improved_windows = 0;
  std::size_t window_changes = 0;
  /// How the labels were made, e.g. "clp lp, rounding, local search, group moves".
  std::string method;
  /// "optimal", or the backend's own word for a successful stop.
  std::string status;
  /// Backend that ran ("auto" resolved; kBand for band, whose own LP backend is band_lp_backend).
  SolverBackend backend = SolverBackend::kAuto;
  /// The backend of the band's LP (band only: "auto" resolved among maxflow, clp, pdhg-energy).
  std::optional<SolverBackend> band_lp_backend;
  std::int64_t iterations = 0;
  double seconds = 0.0;
  /// Size of the LP after fixed cells were substituted (what "clp" and "pdhg" solve; for
  /// "maxflow" the LP it would have been).
  std::size_t lp_columns = 0;
  std::size_t lp_rows = 0;
  std::size_t lp_nonzeros = 0;
  /// Free cells whose relaxed value was not integral (|x - round(x)| > kTieTolerance).
  std::size_t fractional_cells = 0;
  /// Ties broken by the rule above.
  std::size_t tie_cells = 0;
};

/// The backend that ran as the reports name it: its name, for band "band+" and its LP's backend
/// (e.g. "band+clp").
[[nodiscard]] std::string BackendReportName(const LabelingResult& result);

/// Minimises `energy` over 0/1 labels through its LP relaxation (see the file comment).
/// @return kInvalidOptions (bad options, or maxflow on a higher-order energy), kInvalidInput
/// (energy fails Validate()), kSolverFailed (infeasible, unbounded, iteration or time limit; the
/// status is in the message), kCancelled (ctx.ShouldStop()).
/// Deterministic: same energy and options give the same result for any ctx.num_threads.
[[nodiscard]] Expected<LabelingResult> SolveLabeling(const EnergyInput& energy,
                                                     const LabelingOptions& options,
                                                     const RunContext& ctx) noexcept;

/// The same with a partition of the cells into blocks (one block id per cell, ids below
/// energy.NumCells(); ignored for fixed cells), which "blocks" needs and "auto" may use.
/// kInvalidInput when the partition does not fit the energy.
[[nodiscard]] Expected<LabelingResult> SolveLabeling(const EnergyInput& energy,
                                                     std::span<const std::uint32_t> block_of_cell,
                                                     const LabelingOptions& options,
                                                     const RunContext& ctx) noexcept;

}  // namespace linesurf::solver
