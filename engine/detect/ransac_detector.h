#pragma once
// One run of the multi-support RANSAC over a set of lines: planes extracted one by one, each
// refitted and kept to one piece of its support (internal to engine/detect).

#include <cstdint>
#include <vector>

#include "engine/core/geometry.h"
#include "engine/core/run_context.h"
#include "engine/core/strong_id.h"
#include "engine/detect/candidate_search.h"
#include "engine/detect/inlier_test.h"
#include "engine/detect/ransac_state.h"

namespace linesurf::detect {

class RansacDetector {
 public:
  /// `seed` replaces options.seed (per-block streams); `report_progress` is off when blocks run
  /// concurrently (they report per block instead).
  RansacDetector(const RansacInput& in,
                 std::uint64_t seed,
                 bool report_progress,
                 const RunContext& ctx);

  /// Extracts planes one by one until a stopping criterion holds.
  void ExtractAll(PlaneDetectionStats& stats);

  std::vector<SupportedPlane>& planes() { return planes_; }

 private:
  /// Refits `plane` on its inliers and re-collects until the inliers are stable, the support
  /// shrinks (the previous fit is kept) or options.max_refit_iterations.
  void Refit(Plane3& plane, std::vector<SegmentId>& inliers) const;

  /// When the support of `plane` falls into pieces farther apart than the support gap that
  /// disagree about the plane (PiecesDisagree), keeps the largest piece: refit on it,
  /// re-collect, and keep the piece of the new inliers that holds most of the old one, until
  /// stable. The other pieces' segments stay free for planes of their own. A largest piece under
  /// min_support leaves the plane as it was.
  void KeepOnePiece(Plane3& plane, std::vector<SegmentId>& inliers) const;

  RansacInput in_;
  bool report_progress_;
  const RunContext& ctx_;
  std::vector<PlaneMembership> memberships_;
  SegmentBvh bvh_;
  double support_gap_;  ///< scene units; 0 = a plane's support may come in pieces
  std::vector<SupportedPlane> planes_;
  InlierTest inlier_test_;
  CandidateSearch search_;
};

}  // namespace linesurf::detect
