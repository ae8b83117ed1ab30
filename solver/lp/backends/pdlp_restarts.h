#pragma once
/// @file pdlp_restarts.h
/// @brief The restart rules that the first-order backends ("pdhg" on the LP, "pdhg-energy" on
/// the saddle form) share, after PDLP (Applegate et al. 2021, section 3.2): restart to the
/// better of the current and the average iterate when its merit fell enough, and rebalance the
/// primal weight by the movement since the last restart.

#include <cmath>
#include <cstdint>

namespace linesurf::solver {

/// Iterations between restart and termination checks.
inline constexpr std::int64_t kRestartCheckPeriod = 64;

/// Whether to restart, given the merit (KKT error or duality gap) of the candidate point, the
/// merit at the last restart, the candidate's merit at the previous check, the iterations since
/// the last restart and in all: sufficient decay (0.2), necessary decay (0.8) with no progress
/// since the previous check, or an artificial restart after 36 % of the iterations.
inline bool ShouldRestart(double candidate_merit,
                          double merit_at_restart,
                          double previous_candidate_merit,
                          std::int64_t since_restart,
                          std::int64_t iterations) {
  constexpr double kSufficient = 0.2;
  constexpr double kNecessary = 0.8;
  constexpr double kArtificial = 0.36;
  return candidate_merit <= kSufficient * merit_at_restart ||
         (candidate_merit <= kNecessary * merit_at_restart &&
          candidate_merit > previous_candidate_merit) ||
         static_cast<double>(since_restart) >= kArtificial * static_cast<double>(iterations);
}

/// The primal weight after a restart: the ratio of the dual to the primal distance moved since
/// the last restart, smoothed in log space (half the old weight); kept when either barely moved.
inline double SmoothedPrimalWeight(double weight, double primal_distance, double dual_distance) {
  constexpr double kSmoothing = 0.5;
  constexpr double kMinMovement = 1e-10;
  if (primal_distance <= kMinMovement || dual_distance <= kMinMovement) return weight;
  return std::exp(kSmoothing * std::log(dual_distance / primal_distance) +
                  (1.0 - kSmoothing) * std::log(weight));
}

}  // namespace linesurf::solver
