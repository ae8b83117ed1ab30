#pragma once
/// @file lp_backend.h
/// @brief SolveLabeling: minimise an EnergyInput over 0/1 labels through its LP relaxation.
///
/// Backends (LabelingOptions::backend):
///  - "clp":     COIN-OR Clp, dual simplex with presolve on the exact LP relaxation (build_lp.h).
///               Deterministic. The reference.
///  - "maxflow": Boykov-Kolmogorov max-flow (libmaxflow). Exact (an optimal integral labelling,
///               which is also an optimum of the LP) when, after fixed cells are substituted, no
///               structural or parity group is left; otherwise refused with kInvalidOptions.
///  - "pdhg":    first-order primal-dual LP method (PDLP-style: diagonal preconditioning,
///               restarts to the average, adaptive primal weight); SpMV in fixed chunks with oneTBB
///               so the result is identical for any thread count. Approximate optimum (relative
///               tolerance pdhg_tolerance), fast on large complexes.
///  - "pdhg-energy": the same relaxation solved by first-order primal-dual steps on the energy's
///               saddle-point form (pdhg_energy_backend.h): one variable per free cell and one
///               bounded multiplier per term, no slack columns; every multiplier point proves a
///               lower bound. Identical for any thread count.
///  - "band":    for large complexes (band_fixing.h): exact max-flow of the unary and pairwise
///               terms, then the LP ("auto" among clp/pdhg-energy) of the cells near that surface only,
///               every other cell fixed at its max-flow label. A heuristic: not the full LP's
///               optimum in general.
///  - "auto":    "maxflow" when it is exact, else "blocks" above auto_blocks_min_columns LP
///               columns when a partition of more than one block is given, else "clp" up to
///               auto_clp_max_columns LP columns, else "pdhg-energy" (see
///               docs/design/lp_backend.md for the measurements). "band" only above
///               auto_band_min_columns, which is off by default: band changes the result
///               (measured on an Andalusian crop, docs/user/results.md "Integral labelling").
///  - "blocks":  per-block solve for large complexes (block_labeling.h), given a partition of
///               the cells into blocks: each block's interior energy solved by
///               LabelingOptions::block_backend, in parallel, each with a halo of its
///               neighbours' cells; bound: pairwise optimum, dual ascent, Lagrangian split.
///               Needs the partition (the SolveLabeling overload that takes one).
///  - "clp-barrier": Clp's barrier with its built-in Cholesky; for measurements only (slow).
///  - "cbc":     COIN-OR Cbc branch and cut on the integer program itself (cells 0/1): the
///               integral optimum when it proves one (status "optimal"), else the best labelling
///               within time_limit_seconds (status "time limit"). Exponential in the worst case:
///               for small energies, tests and measurements of the rounding gap. Optional at
///               build time (cbc_backend.h).
///
/// Rounding: label_c = 1 if x_c > 0.5 + kTieTolerance, 0 if x_c < 0.5 - kTieTolerance.
/// Ties (|x_c - 0.5| <= kTieTolerance) are decided one by one in increasing CellId order: each
/// takes the label of lower energy given the labels decided so far (undecided ties count as
/// empty); on equal energy the cell is empty. Fixed cells keep their label. Then local search
/// (LabelingOptions::local_search_passes, on by default) flips single free cells in id order
/// while that lowers the energy, and group moves (group_move_passes, on by default) give the free
/// cells of one term at a time their best joint labelling.

#include <cstdint>
#include <limits>
#include <span>
#include <string>
#include <vector>

#include "engine/core/run_context.h"
#include "linesurf/error.h"
#include "solver/energy/energy_input.h"

namespace linesurf::solver {

/// Half-width of the band around 0.5 in which a relaxed value counts as a tie.
inline constexpr double kTieTolerance = 1e-7;

struct LabelingOptions {
  /// "auto" (default: picks per model size, see above), "clp", "clp-barrier", "maxflow",
  /// "pdhg", "pdhg-energy", "band", "blocks" or "cbc".
  std::string backend = "auto";
  /// Primal/dual feasibility tolerance of the simplex (Clp's primal and dual tolerances); range
  /// (0, 1e-2]. Clp's default.
  double clp_tolerance = 1e-7;
  /// Relative tolerance of pdhg on primal residual, dual residual and duality gap; range
  /// (0, 1e-1]. 1e-4 keeps labels equal to Clp's on our tests (docs/design/solver.md).
  double pdhg_tolerance = 1e-4;
  /// Relative duality gap at which pdhg-energy stops; range (0, 1e-1]. Its relaxed optimum is
  /// only rounded: on Andalusian 1e-3 takes 9,536 iterations where 1e-4 took 14,272, and the
  /// final labels' energy is within 0.3 % (3,081.5 vs 3,096.3 with detected planes, 5,287.8 vs
  /// 5,279.9 with the given ones; docs/design/solver.md, "pdhg-energy tolerance").
  double pdhg_energy_tolerance = 1e-3;
  /// Iteration cap of pdhg and pdhg-energy; >= 1. Reaching it is a failure (kSolverFailed).
  std::int64_t pdhg_max_iterations = 200000;
  /// "auto" uses clp up to this many LP columns and pdhg-energy beyond; >= 0. On grid energies with
  /// parity terms Clp's dual simplex grows about cubically (0.19 s CPU at 3.8k columns, 3.4 s at
  /// 12.6k, 151 s at 42k) while pdhg stays below 0.4 s up to 12.6k (docs/design/lp_backend.md).
  std::size_t auto_clp_max_columns = 10000;
  /// "auto" uses the band strategy above this many LP columns. Default: never. Band is faster
  /// on whole real scenes (the full LP of Andalusian's 3e5-cell complex did not converge with
  /// pdhg in 26 min) but changes the result: on a 47-plane Andalusian crop its labels' energy is
  /// 1 % above the full LP's with 36 % fewer full cells (docs/user/results.md, "Integral labelling").
  std::size_t auto_band_min_columns = std::numeric_limits<std::size_t>::max();
  /// "auto" uses the per-block solve above this many LP columns, when a partition of the cells
  /// into more than one block is given; >= 0. 20,000,000: with pdhg-energy's weighted steps
  /// the global solve is better and cheaper at every size measured, up to
  /// city-1000's 7.0M columns (23 s to a 0.04 % gap, where the per-block solve took 221 s and
  /// ended 1.1 % higher); above that the per-block solve keeps each solve's size bounded
  /// (docs/design/lp_backend.md, "Per-block solve").
  std::size_t auto_blocks_min_columns = 20000000;
  /// Cells per block at most in the partition `reconstruct` makes for "blocks" on a monolithic
  /// complex (k-d blocks of the cells' centroids, pipeline::CentroidBlocks; the block engine
  /// uses its own blocks); >= 1. The solver itself takes any partition it is given.
  std::size_t block_max_cells = 4000;
  /// Backend of each block's solve in "blocks": "auto" (maxflow, clp or pdhg-energy by the
  /// block's size), "clp", "pdhg", "pdhg-energy" or "cbc".
  std::string block_backend = "auto";
  /// Sweeps of "blocks" (each solves the blocks whose cells or neighbours changed since their
  /// last solve); [0, 100]. 0 = the max-flow start and the final moves only.
  int block_sweeps = 2;
  /// "blocks" also solves every block's interior energy for the bound of the Lagrangian split
  /// (block_labeling.h): one more LP per block. Off: the bound is the pairwise optimum.
  bool block_split_bound = false;
  /// Term hops around a block whose free cells "blocks" solves with it (the others held at their
  /// labels); [0, 8]. 0 = the block alone, its seams fixed. 1 (default) lets the surface move
  /// across a seam: on an Andalusian crop 888.9 against 905.1 without (global LP: 878.6).
  int block_halo = 1;
  /// Passes of dual coordinate ascent on the global LP for the bound of "blocks"
  /// (dual_ascent.h; it stops earlier when a pass gains less than 1e-4); [0, 10000]; 0 = none.
  /// Off by default: from zero multipliers it climbs slowly on large energies (whole
  /// Andalusian: 516 after 50 passes, below the pairwise optimum 968; the 47-plane crop: 800,
  /// above the pairwise 704, LP optimum 877).
  int block_bound_passes = 0;
  /// Growth steps of the band through shared parity groups (edges and vertices); [0, 16].
  int band_rings = 1;
  /// Wall-time limit of the solve in seconds; 0 = none; >= 0. Exceeding it is a failure.
  double time_limit_seconds = 0.0;
  /// Sweeps of local search after rounding (each free cell, in id order, flips when that lowers
  /// the energy; stops early when a sweep flips nothing); 0 = plain rounding as in the paper;
  /// range [0, 1000]. It only ever lowers the energy of the labels: on grid energies with
  /// parity terms the rounded labels' energy drops by 30-40 % (docs/design/solver.md).
  int local_search_passes = 10;
  /// Sweeps of group moves after the local search (group_moves.h: the free cells of one term
  /// take their best joint labelling); 0 = none; range [0, 1000]. Never raises the energy.
  int group_move_passes = 10;
  /// Exact solves of windows after the moves (window_polish.h; needs the Cbc backend, skipped
  /// in a build without it): free cells per window, 0 = none; range [0, 4096].
  std::size_t window_cells = 64;
  /// Branch-and-bound nodes per window, >= 1 (deterministic, unlike a time limit).
  std::int64_t window_max_nodes = 200;
  /// Windows at most; >= 0.
  std::size_t window_max_count = 100000;

  /// Names the first offending field.
  [[nodiscard]] Status Validate() const;
};

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
  /// Where lower_bound comes from: "block split: ..." (blocks: the sum of the blocks'
  /// interior bounds, with how each was proven), "lp optimum" (clp), "energy dual bound" (pdhg-energy: its best multiplier point),
  /// "lp dual bound" (pdhg: the Lagrangian
  /// bound of its dual point, dual_bound.h; its relaxed_objective is a primal value, not a
  /// bound), "integer optimum" (cbc proved it, maxflow, or one exact window held every free
  /// cell), "branch and bound" (cbc stopped early), "pairwise optimum" (band: the max-flow
  /// minimum of the unary and pairwise terms, the others being >= 0), "none".
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
  /// Backend that actually ran ("auto" resolved).
  std::string backend;
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
