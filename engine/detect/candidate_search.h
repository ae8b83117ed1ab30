#pragma once
// The search for the next plane of multi-support RANSAC: candidate planes from pairs of lines,
// drawn at random (with an adaptive stop) or all pairs of a small pool, the best by support
// (internal to engine/detect).

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "engine/core/geometry.h"
#include "engine/core/run_context.h"
#include "engine/core/strong_id.h"
#include "engine/detect/inlier_test.h"
#include "engine/detect/ransac_state.h"

namespace linesurf::detect {

struct CandidateResult {
  bool valid = false;
  std::uint32_t support = 0;
  double score = 0.0;
  std::int64_t failed_draws = 0;
  /// Failed draws of lines farther than 2 eps apart: no pair on one plane fails so, so they
  /// count as trials of the adaptive stop (R-RANSAC's pre-test); the other failures do not.
  std::int64_t apart_draws = 0;
  Plane3 plane;
};

/// Proposes and scores candidate planes for one detection. Deterministic for any number of threads: candidate k of plane j draws from its
/// own stream and the best is chosen by (score, then smallest k).
class CandidateSearch {
 public:
  /// Candidates of plane j draw from the streams (seed, j, k).
  CandidateSearch(const RansacInput& in,
                  const RansacState& state,
                  const InlierTest& inlier_test,
                  std::uint64_t seed);

  /// The segments candidates may be drawn from, ascending.
  [[nodiscard]] std::vector<SegmentId> SamplingPool() const;

  /// The best candidate for plane `plane_index` from `pool`, if any was valid.
  [[nodiscard]] std::optional<CandidateResult> SearchPlane(const std::vector<SegmentId>& pool,
                                                           std::size_t plane_index,
                                                           const RunContext& ctx,
                                                           PlaneDetectionStats& stats) const;

 private:
  [[nodiscard]] bool Sampleable(SegmentId s) const;

  /// The plane through a and b (containing both directions, halfway between the two infinite
  /// lines), if the pair is valid: not near-parallel, lines within 2 eps, and b not on a plane
  /// of a (never re-propose a plane already extracted). `apart` is set when the only reason to
  /// reject the pair is that the lines pass farther than 2 eps apart.
  [[nodiscard]] std::optional<Plane3> PlaneFromPair(SegmentId a,
                                                    SegmentId b,
                                                    bool* apart = nullptr) const;

  /// Candidate k of plane j: draws from its own stream, so any thread may evaluate it.
  [[nodiscard]] CandidateResult RandomCandidate(const std::vector<SegmentId>& pool,
                                                std::size_t plane_index,
                                                std::int64_t k) const;

  /// Every pair of a pool small enough (options.exhaustive_pairs_max_segments).
  [[nodiscard]] std::optional<CandidateResult> SearchAllPairs(const std::vector<SegmentId>& pool,
                                                              PlaneDetectionStats& stats) const;

  /// Random candidates in batches until the adaptive stop, the iteration cap or the cap on
  /// failed draws.
  [[nodiscard]] std::optional<CandidateResult> SearchRandom(const std::vector<SegmentId>& pool,
                                                            std::size_t plane_index,
                                                            const RunContext& ctx,
                                                            PlaneDetectionStats& stats) const;

  /// Whether `trials` trials give the confidence of having drawn the plane of `best` once.
  [[nodiscard]] bool ConfidentOf(const CandidateResult& best,
                                 std::size_t pool_size,
                                 std::int64_t trials) const;

  RansacInput in_;
  RansacState state_;
  const InlierTest& inlier_test_;
  std::uint64_t seed_;
  double sin_pair_;
  std::vector<Vec3> direction_;
  std::vector<Vec3> midpoint_;
  std::vector<bool> sampleable_;
};

}  // namespace linesurf::detect
