#pragma once
// A lower bound on the LP relaxation of an energy (build_lp.h) from its Lagrangian dual, raised
// by coordinate ascent: every term of the reduced energy carries one multiplier (the difference
// of the multipliers of its two rows, or the multiplier of its one row), and a pass visits the
// terms in order, each time setting that multiplier to the middle of its best range given the
// others. With delta_t the multiplier of term t:
//   pair  w |x_a - x_b|:          delta in [-w, w], adds +delta to x_a's cost, -delta to x_b's;
//   structural w max(0, 1 - sum x): delta in [0, w], adds delta, and -delta to each cell's cost;
//   parity w |sum nu x + k|:       delta in [-w, w], adds k delta, and nu_c delta to each cell's;
// the dual value is constant + sum of those additions + sum over cells of min(0, reduced cost)
// (cells boxed in [0, 1], slacks priced >= 0 by the ranges). Any multipliers in their ranges give
// a valid bound, so every pass gives one, and passes never lower it. Each pass is O(nonzeros),
// serial and deterministic. Like any coordinate ascent on a non-smooth dual it may stop below
// the LP optimum (measured in docs/design/lp_backend.md, "Per-block solve").

#include "solver/energy/build_lp.h"

namespace linesurf::solver {

struct DualAscentResult {
  double bound = 0.0;
  int passes = 0;
};

/// `max_passes` >= 0; stops early when a pass raises the bound by less than `relative_gain` of
/// its magnitude.
[[nodiscard]] DualAscentResult DualAscentBound(const ReducedEnergy& reduced,
                                               int max_passes,
                                               double relative_gain);

}  // namespace linesurf::solver
