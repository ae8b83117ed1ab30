#pragma once
/// @file labeling_options.h
/// @brief Options of SolveLabeling (lp_backend.h): the backend, and one struct per backend, per
/// strategy and for the improvement passes, each with its own Validate. SolveLabeling passes
/// each backend only its struct and the time limit (labeling_backends.h).

#include "linesurf/error.h"
#include "linesurf/options.h"

#include <cstdint>
#include <limits>

namespace linesurf::solver {

/// "auto": the rule that picks a backend by the energy and its LP size (ResolveBackend in
/// labeling_backends.h). Every threshold is a count of LP columns; any value is valid.
struct AutoRuleOptions {
  /// clp up to this many LP columns and pdhg-energy beyond. On grid energies with parity terms
  /// Clp's dual simplex grows about cubically (0.19 s CPU at 3.8k columns, 3.4 s at 12.6k, 151 s
  /// at 42k) while pdhg stays below 0.4 s up to 12.6k (docs/design/lp_backend.md).
  std::size_t clp_max_columns = 10000;
  /// band above this many LP columns. Default: never. Band is faster on whole real scenes (the
  /// full LP of Andalusian's 3e5-cell complex did not converge with pdhg in 26 min) but changes
  /// the result: on a 47-plane Andalusian crop its labels' energy is 1 % above the full LP's with
  /// 36 % fewer full cells (docs/user/results.md, "Integral labelling").
  std::size_t band_min_columns = std::numeric_limits<std::size_t>::max();
  /// blocks above this many LP columns, when a partition of the cells into more than one block
  /// is given. 20,000,000: with pdhg-energy's weighted steps the global solve is better and
  /// cheaper at every size measured, up to city-1000's 7.0M columns (23 s to a 0.04 % gap, where
  /// the per-block solve took 221 s and ended 1.1 % higher); above that the per-block solve
  /// keeps each solve's size bounded (docs/design/lp_backend.md, "Per-block solve").
  std::size_t blocks_min_columns = 20000000;
};

/// "clp" and "clp-barrier".
struct ClpOptions {
  /// Primal/dual feasibility tolerance of the simplex (Clp's primal and dual tolerances); range
  /// (0, 1e-2]. Clp's default.
  double tolerance = 1e-7;

  /// Names the first offending field.
  [[nodiscard]] Status Validate() const;
};

/// "pdhg".
struct PdhgOptions {
  /// Relative tolerance on primal residual, dual residual and duality gap; range (0, 1e-1].
  /// 1e-4 keeps labels equal to Clp's on our tests (docs/design/solver.md).
  double tolerance = 1e-4;
  /// Iteration cap; >= 1. Reaching it is a failure (kSolverFailed).
  std::int64_t max_iterations = 200000;

  /// Names the first offending field.
  [[nodiscard]] Status Validate() const;
};

/// "pdhg-energy".
struct PdhgEnergyOptions {
  /// Relative duality gap at which it stops; range (0, 1e-1]. Its relaxed optimum is only
  /// rounded: on Andalusian 1e-3 takes 9,536 iterations where 1e-4 took 14,272, and the final
  /// labels' energy is within 0.3 % (3,081.5 vs 3,096.3 with detected planes, 5,287.8 vs 5,279.9
  /// with the given ones; docs/design/solver.md, "pdhg-energy tolerance").
  double tolerance = 1e-3;
  /// Iteration cap; >= 1. Reaching it is a failure (kSolverFailed).
  std::int64_t max_iterations = 200000;

  /// Names the first offending field.
  [[nodiscard]] Status Validate() const;
};

/// "band" (band_fixing.h).
struct BandOptions {
  /// Growth steps of the band through shared parity groups (edges and vertices); [0, 16].
  int rings = 1;

  /// Names the first offending field.
  [[nodiscard]] Status Validate() const;
};

/// "blocks" (block_labeling.h).
struct BlocksOptions {
  /// Backend of each block's solve: one the backend table marks usable per block ("auto":
  /// maxflow, clp or pdhg-energy by the block's size; "clp", "pdhg", "pdhg-energy", "cbc").
  SolverBackend backend = SolverBackend::kAuto;
  /// Sweeps (each solves the blocks whose cells or neighbours changed since their last solve);
  /// [0, 100]. 0 = the max-flow start and the final moves only.
  int sweeps = 2;
  /// Also solves every block's interior energy for the bound of the Lagrangian split
  /// (block_labeling.h): one more LP per block. Off: the bound is the pairwise optimum.
  bool split_bound = false;
  /// Term hops around a block whose free cells are solved with it (the others held at their
  /// labels); [0, 8]. 0 = the block alone, its seams fixed. 1 (default) lets the surface move
  /// across a seam: on an Andalusian crop 888.9 against 905.1 without (global LP: 878.6).
  int halo = 1;
  /// Passes of dual coordinate ascent on the global LP for the bound (dual_ascent.h; it stops
  /// earlier when a pass gains less than 1e-4); [0, 10000]; 0 = none. Off by default: from zero
  /// multipliers it climbs slowly on large energies (whole Andalusian: 516 after 50 passes,
  /// below the pairwise optimum 968; the 47-plane crop: 800, above the pairwise 704, LP optimum
  /// 877).
  int bound_passes = 0;

  /// Names the first offending field; the block backend must be usable per block and available
  /// in this build.
  [[nodiscard]] Status Validate() const;
};

/// The passes after rounding (lp_backend.h's file comment), run by every backend that does not
/// solve the integer program itself.
struct ImproveOptions {
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

struct LabelingOptions {
  /// The backend (labeling_backends.h's table); kAuto (default) picks one per energy and size.
  SolverBackend backend = SolverBackend::kAuto;
  AutoRuleOptions auto_rule;
  ClpOptions clp;
  PdhgOptions pdhg;
  PdhgEnergyOptions pdhg_energy;
  BandOptions band;
  BlocksOptions blocks;
  ImproveOptions improve;
  /// Wall-time limit of the solve in seconds; 0 = none; >= 0. Exceeding it is a failure.
  double time_limit_seconds = 0.0;

  /// Names the first offending field: the backend must be in the table and available in this
  /// build, then every struct's own Validate.
  [[nodiscard]] Status Validate() const;
};

}  // namespace linesurf::solver
