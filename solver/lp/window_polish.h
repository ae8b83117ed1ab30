#pragma once
// Exact solves of small windows: after rounding and local moves, the cells the LP left
// fractional (or whose label the moves changed) are covered by windows of at most
// `window_cells` free cells grown through shared terms; each window's integer program, every
// other cell held at its label (sub_energy.h), is solved by Cbc with a node limit and its labels
// are taken when they lower the energy. A window that holds every free cell is the whole integer
// program. Needs the Cbc backend (cbc_backend.h); without it nothing is done.

#include "engine/core/run_context.h"
#include "solver/energy/energy_input.h"
#include "solver/lp/lp_backend.h"

#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace linesurf::solver {

struct WindowPolishOptions {
  /// Free cells per window; 0 = no polish.
  std::size_t window_cells = 0;
  /// Branch-and-bound nodes per window (a bound on the work that does not depend on the clock).
  std::int64_t max_nodes = 0;
  /// Windows at most.
  std::size_t max_windows = 0;
};

struct WindowPolishStats {
  std::size_t windows = 0;
  /// Windows whose integer program Cbc solved to proven optimality.
  std::size_t proven_windows = 0;
  std::size_t improved_windows = 0;
  std::size_t changed_cells = 0;
  /// True when one window held every free cell and Cbc proved it optimal: the labels are an
  /// integral optimum.
  bool whole_energy_proven = false;
};

/// Improves `labels` (one 0/1 label per cell, fixed cells at their label) in place; never raises
/// the energy. `relaxed` (one value per cell) chooses the seeds: free cells whose value is more
/// than 1e-3 from 0 and 1, or whose label differs from its value rounded at 1/2, in id order.
/// Windows are solved in parallel batches (ctx.num_threads) with the result of the serial order:
/// the same labels for any thread count. Throws kCancelled when ctx.ShouldStop().
WindowPolishStats PolishInWindows(const EnergyInput& energy,
                                  std::span<const double> relaxed,
                                  const WindowPolishOptions& options,
                                  const RunContext& ctx,
                                  std::vector<std::uint8_t>& labels);

/// PolishInWindows as a labelling runs it: the windows of `options` (window_cells,
/// window_max_nodes, window_max_count) on result.labels, seeded by result.relaxed; the counts go
/// to result.windows, improved_windows and window_changes.
WindowPolishStats PolishResultInWindows(const EnergyInput& energy,
                                        const ImproveOptions& options,
                                        const RunContext& ctx,
                                        LabelingResult& result);

/// Appends to a labelling's method text the improvements that ran after it: local search,
/// group moves, and the exact windows when `polished` solved any.
void AppendImprovementSteps(const ImproveOptions& options,
                            const WindowPolishStats& polished,
                            std::string& method);

}  // namespace linesurf::solver
