#include "solver/lp/window_polish.h"

#include "engine/core/exception.h"
#include "solver/energy/build_lp.h"
#include "solver/energy/sub_energy.h"
#include "solver/lp/backends/cbc/cbc_backend.h"
#include "solver/lp/lp_backend.h"
#include "solver/lp/round_labels.h"

#include <cmath>

namespace linesurf::solver {
namespace {

constexpr const char* kWindowPolishStage = "solve_labeling";
// A relaxed value this far from 0 and 1 makes its cell a seed: well above the error of the
// first-order backend (pdhg stops at a relative 1e-4), whose cells are never exactly integral.
constexpr double kSeedDistance = 1e-3;

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
      const auto visit = [&](CellId c) {
        const std::uint32_t s = incidence.Slot(c);
        if (s == TermIncidence::kNone || in_window[s] != 0 || slots.size() >= size) return;
        in_window[s] = 1;
        slots.push_back(s);
      };
      if (t.kind == TermKind::kPair) {
        visit(e.pairs[t.index].a);
        visit(e.pairs[t.index].b);
      } else {
        for (CellId c : t.kind == TermKind::kStructural ? e.StructuralGroup(t.index)
                                                        : e.ParityGroup(t.index)) {
          visit(c);
        }
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
  std::vector<std::uint8_t> covered(free.size(), 0), in_window(free.size(), 0);
  IlpLimits limits;
  limits.max_nodes = options.max_nodes;
  for (std::uint32_t seed : seeds) {
    if (covered[seed] != 0) continue;
    if (stats.windows == options.max_windows) break;
    ctx.ThrowIfCancelled(kWindowPolishStage);
    // Few enough free cells: one window holds them all, connected or not.
    const std::vector<CellId> window =
        free.size() <= options.window_cells
            ? free
            : GrowWindow(energy, incidence, free, seed, options.window_cells, in_window);
    for (CellId c : window) covered[incidence.Slot(c)] = 1;
    const SubEnergy sub = RestrictEnergy(energy, incidence, window, labels);
    const ReducedEnergy reduced = ReduceEnergy(sub.energy);
    LINESURF_ASSERT(reduced.NumFree() == window.size());
    std::vector<double> start(window.size());
    for (std::size_t j = 0; j < window.size(); ++j) start[j] = labels[window[j].index()];
    const double start_energy = reduced.Evaluate(start);
    const LpSolution solution =
        SolveIlpWithCbc(BuildLpModel(reduced), window.size(), start, limits, ctx);
    ++stats.windows;
    const bool proven = solution.status == "optimal";
    stats.proven_windows += proven ? 1 : 0;
    if (window.size() == free.size()) stats.whole_energy_proven = proven;
    if (!(solution.objective < start_energy - kImproveTolerance * (1.0 + std::abs(start_energy)))) {
      continue;
    }
    ++stats.improved_windows;
    for (std::size_t j = 0; j < window.size(); ++j) {
      const std::uint8_t label = solution.columns[j] > 0.5 ? 1 : 0;
      stats.changed_cells += label != labels[window[j].index()] ? 1 : 0;
      labels[window[j].index()] = label;
    }
  }
  return stats;
}

WindowPolishStats PolishResultInWindows(const EnergyInput& energy,
                                        const LabelingOptions& options,
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

}  // namespace linesurf::solver
