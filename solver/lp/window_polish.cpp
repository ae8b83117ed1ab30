#include "solver/lp/window_polish.h"

#include "engine/core/exception.h"
#include "engine/core/parallel.h"
#include "solver/energy/build_lp.h"
#include "solver/energy/sub_energy.h"
#include "solver/lp/backends/cbc/cbc_backend.h"
#include "solver/lp/lp_backend.h"
#include "solver/lp/round_labels.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/partitioner.h>

#include <algorithm>
#include <cmath>

namespace linesurf::solver {
namespace {

constexpr const char* kWindowPolishStage = "solve_labeling";
// A relaxed value this far from 0 and 1 makes its cell a seed: the first-order backends stop at
// a relative tolerance (pdhg 1e-4, pdhg-energy 1e-3), so their cells are never exactly integral.
constexpr double kSeedDistance = 1e-3;

// Windows solved from the same labels before their results are taken in order.
constexpr std::size_t kWindowBatch = 64;

// Up to `size` free cells reached from `seed` through shared terms, breadth first in term order.
std::vector<CellId> GrowWindow(const EnergyInput& e,
                               const TermIncidence& incidence,
                               std::span<const CellId> free,
                               std::uint32_t seed,
                               std::size_t size,
                               std::vector<std::uint8_t>& in_window) {
  std::vector<std::uint32_t> slots = {seed};
  in_window[seed] = 1;
  for (std::size_t head = 0; head < slots.size() && slots.size() < size; ++head) {
    for (const TermRef& t : incidence.Terms(slots[head])) {
      CellId pair[2];
      for (CellId c : TermCells(e, t, pair)) {
        const std::uint32_t s = incidence.Slot(c);
        if (s == TermIncidence::kNone || in_window[s] != 0 || slots.size() >= size) continue;
        in_window[s] = 1;
        slots.push_back(s);
      }
    }
  }
  std::vector<CellId> window;
  for (std::uint32_t s : slots) {
    in_window[s] = 0;
    window.push_back(free[s]);
  }
  return window;
}

// The windows in seed order, each grown from the first seed no earlier window covers; they do
// not depend on the labels.
std::vector<std::vector<CellId>> PlanWindows(const EnergyInput& energy,
                                             const TermIncidence& incidence,
                                             std::span<const CellId> free,
                                             std::span<const std::uint32_t> seeds,
                                             const WindowPolishOptions& options) {
  std::vector<std::vector<CellId>> windows;
  std::vector<std::uint8_t> covered(free.size(), 0), in_window(free.size(), 0);
  for (std::uint32_t seed : seeds) {
    if (covered[seed] != 0) continue;
    if (windows.size() == options.max_windows) break;
    // Few enough free cells: one window holds them all, connected or not.
    windows.push_back(
        free.size() <= options.window_cells
            ? std::vector<CellId>(free.begin(), free.end())
            : GrowWindow(energy, incidence, free, seed, options.window_cells, in_window));
    for (CellId c : windows.back()) covered[incidence.Slot(c)] = 1;
  }
  return windows;
}

// A window's integer program solved with every other cell at its label in `labels`.
struct WindowSolve {
  bool proven = false;
  bool improves = false;
  std::vector<std::uint8_t> labels;  // per window cell, when it improves
};

WindowSolve SolveWindow(const EnergyInput& energy,
                        const TermIncidence& incidence,
                        std::span<const CellId> window,
                        const std::vector<std::uint8_t>& labels,
                        const IlpLimits& limits,
                        const RunContext& ctx) {
  ctx.ThrowIfCancelled(kWindowPolishStage);
  const SubEnergy sub = RestrictEnergy(energy, incidence, window, labels);
  const ReducedEnergy reduced = ReduceEnergy(sub.energy);
  LINESURF_ASSERT(reduced.NumFree() == window.size());
  std::vector<double> start(window.size());
  for (std::size_t j = 0; j < window.size(); ++j) start[j] = labels[window[j].index()];
  const double start_energy = reduced.Evaluate(start);
  const LpSolution solution =
      SolveIlpWithCbc(BuildLpModel(reduced), window.size(), start, limits, ctx);
  WindowSolve out;
  out.proven = solution.status == "optimal";
  out.improves =
      solution.objective < start_energy - kImproveTolerance * (1.0 + std::abs(start_energy));
  if (out.improves) {
    for (double x : solution.columns) out.labels.push_back(x > 0.5 ? 1 : 0);
  }
  return out;
}

}  // namespace

WindowPolishStats PolishInWindows(const EnergyInput& energy,
                                  std::span<const double> relaxed,
                                  const WindowPolishOptions& options,
                                  const RunContext& ctx,
                                  std::vector<std::uint8_t>& labels) {
  LINESURF_ASSERT(labels.size() == energy.NumCells() && relaxed.size() == energy.NumCells());
  WindowPolishStats stats;
  if (options.window_cells == 0 || options.max_windows == 0 || !CbcAvailable()) return stats;
  std::vector<CellId> free;
  std::vector<std::uint32_t> seeds;
  for (std::size_t c = 0; c < energy.NumCells(); ++c) {
    if (energy.fixed[CellId(c)] != CellFix::kFree) continue;
    const double x = relaxed[c];
    const bool fractional = std::abs(x - std::round(x)) > kSeedDistance;
    if (fractional || labels[c] != (x > 0.5 ? 1 : 0)) {
      seeds.push_back(static_cast<std::uint32_t>(free.size()));
    }
    free.push_back(CellId(c));
  }
  if (seeds.empty()) return stats;
  const TermIncidence incidence(energy, free);
  const std::vector<std::vector<CellId>> windows =
      PlanWindows(energy, incidence, free, seeds, options);
  IlpLimits limits;
  limits.max_nodes = options.max_nodes;
  // Each batch is solved in parallel from the labels at its start; then, in window order, a
  // window takes its solve unless an earlier window of the batch changed a cell it shares a term
  // with (marked stale), in which case it is solved again on the current labels. Every window
  // sees the labels the serial order gives it: the same result for any thread count.
  std::vector<std::uint8_t> stale(free.size(), 0);
  std::vector<WindowSolve> solves;
  // One thread: batches of one window, the serial order itself.
  const std::size_t batch = ArenaConcurrency(ctx.num_threads) > 1 ? kWindowBatch : 1;
  for (std::size_t first = 0; first < windows.size(); first += batch) {
    const std::size_t last = std::min(windows.size(), first + batch);
    solves.assign(last - first, WindowSolve{});
    RunInArena(ctx, [&] {
      tbb::parallel_for(
          tbb::blocked_range<std::size_t>(first, last, 1),
          [&](const tbb::blocked_range<std::size_t>& r) {
            for (std::size_t w = r.begin(); w != r.end(); ++w) {
              solves[w - first] = SolveWindow(energy, incidence, windows[w], labels, limits, ctx);
            }
          },
          tbb::simple_partitioner{});
    });
    std::vector<std::uint32_t> marked;
    for (std::size_t w = first; w < last; ++w) {
      const std::vector<CellId>& window = windows[w];
      WindowSolve& solve = solves[w - first];
      const bool is_stale = std::any_of(
          window.begin(), window.end(), [&](CellId c) { return stale[incidence.Slot(c)] != 0; });
      if (is_stale) solve = SolveWindow(energy, incidence, window, labels, limits, ctx);
      ++stats.windows;
      stats.proven_windows += solve.proven ? 1 : 0;
      if (window.size() == free.size()) stats.whole_energy_proven = solve.proven;
      if (!solve.improves) continue;
      ++stats.improved_windows;
      for (std::size_t j = 0; j < window.size(); ++j) {
        const std::uint32_t slot = incidence.Slot(window[j]);
        if (solve.labels[j] == labels[window[j].index()]) continue;
        ++stats.changed_cells;
        labels[window[j].index()] = solve.labels[j];
        MarkAround(energy, incidence, slot, stale);
        marked.push_back(slot);
      }
    }
    // The next batch starts from the current labels: nothing is stale.
    for (std::uint32_t slot : marked) MarkAround(energy, incidence, slot, stale, 0);
  }
  return stats;
}

WindowPolishStats PolishResultInWindows(const EnergyInput& energy,
                                        const ImproveOptions& options,
                                        const RunContext& ctx,
                                        LabelingResult& result) {
  WindowPolishOptions windows;
  windows.window_cells = options.window_cells;
  windows.max_nodes = options.window_max_nodes;
  windows.max_windows = options.window_max_count;
  const WindowPolishStats polished =
      PolishInWindows(energy, result.relaxed, windows, ctx, result.labels);
  result.windows = polished.windows;
  result.improved_windows = polished.improved_windows;
  result.window_changes = polished.changed_cells;
  return polished;
}

void AppendImprovementSteps(const ImproveOptions& options,
                            const WindowPolishStats& polished,
                            std::string& method) {
  if (options.local_search_passes > 0) method += ", local search";
  if (options.group_move_passes > 0) method += ", group moves";
  if (polished.windows > 0) {
    method += ", exact windows of ";
    method += std::to_string(options.window_cells);
    method += " cells (cbc)";
  }
}

}  // namespace linesurf::solver
