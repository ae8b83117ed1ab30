#include "engine/detect/ransac_detector.h"

#include <algorithm>
#include <iterator>
#include <optional>
#include <utility>

#include "engine/detect/detect_stage.h"
#include "engine/detect/segment_geometry.h"
#include "engine/detect/support_clusters.h"

namespace linesurf::detect {
namespace {
/// A piece of a plane's support is judged on its own fit only when its endpoints spread at least
/// this many eps across their main direction (so that its tilt is not noise)...
constexpr double kPieceMinWidthOverEps = 10.0;
/// ... and it disagrees with the plane when its own fit is farther than this many eps from the
/// plane at one of its endpoints.
constexpr double kPieceDisagreementOverEps = 0.5;

double MedianLength(std::span<const Segment3> segments) {
  std::vector<double> lengths;
  lengths.reserve(segments.size());
  for (const Segment3& seg : segments) lengths.push_back(seg.Length());
  if (lengths.empty()) return 0.0;
  const auto middle = lengths.begin() + static_cast<std::ptrdiff_t>(lengths.size() / 2);
  std::nth_element(lengths.begin(), middle, lengths.end());
  return *middle;
}

/// The piece of `pieces` that shares most segments with `kept` (the first of equals; empty when
/// none shares any).
std::vector<SegmentId> PieceOverlappingMost(std::vector<std::vector<SegmentId>> pieces,
                                            const std::vector<SegmentId>& kept) {
  std::vector<SegmentId> best;
  std::size_t best_overlap = 0;
  for (std::vector<SegmentId>& piece : pieces) {
    std::vector<SegmentId> common;
    std::set_intersection(piece.begin(), piece.end(), kept.begin(), kept.end(),
                          std::back_inserter(common));
    if (common.size() > best_overlap) {
      best_overlap = common.size();
      best = std::move(piece);
    }
  }
  return best;
}
}  // namespace

RansacDetector::RansacDetector(const RansacInput& in,
                               std::uint64_t seed,
                               bool report_progress,
                               const RunContext& ctx)
    : in_(in),
      report_progress_(report_progress),
      ctx_(ctx),
      memberships_(in.segments.size()),
      bvh_(in.segments),
      support_gap_(in.options.support_gap * MedianLength(in.segments)),
      inlier_test_(in_, RansacState{bvh_, memberships_, planes_}),
      search_(in_, RansacState{bvh_, memberships_, planes_}, inlier_test_, seed) {}

void RansacDetector::ExtractAll(PlaneDetectionStats& stats) {
  while (static_cast<std::int32_t>(planes_.size()) < in_.options.max_planes) {
    ctx_.ThrowIfCancelled(kDetectPlanesStage);
    if (report_progress_) {
      ctx_.ReportProgress(kDetectPlanesStage,
                          static_cast<double>(planes_.size()) / in_.options.max_planes);
    }
    const std::vector<SegmentId> pool = search_.SamplingPool();
    if (pool.size() < 2) break;
    const std::optional<CandidateResult> best = search_.SearchPlane(pool, planes_.size(), ctx_, stats);
    if (!best || best->support < static_cast<std::uint32_t>(in_.options.min_support)) break;
    Plane3 plane = best->plane;
    std::vector<SegmentId> inliers = inlier_test_.Collect(plane);
    Refit(plane, inliers);
    KeepOnePiece(plane, inliers);
    if (inliers.size() < static_cast<std::size_t>(in_.options.min_support)) break;
    const PlaneId id(planes_.size());
    for (const SegmentId s : inliers) memberships_[s.index()].Add(id);
    planes_.push_back({plane, std::move(inliers)});
  }
  if (static_cast<std::int32_t>(planes_.size()) >= in_.options.max_planes) stats.capped_blocks = 1;
}

void RansacDetector::Refit(Plane3& plane, std::vector<SegmentId>& inliers) const {
  for (std::int32_t it = 0; it < in_.options.max_refit_iterations; ++it) {
    const Plane3 refit = FitPlane(in_.segments, inliers, plane.normal);
    std::vector<SegmentId> again = inlier_test_.Collect(refit);
    if (again.size() < inliers.size()) break;  // the refit lost support: keep the previous
    const bool stable = again == inliers;
    plane = refit;
    inliers = std::move(again);
    if (stable) break;
  }
}

void RansacDetector::KeepOnePiece(Plane3& plane, std::vector<SegmentId>& inliers) const {
  if (support_gap_ <= 0.0) return;
  const auto min_lines = static_cast<std::size_t>(in_.options.min_support);
  std::vector<std::vector<SegmentId>> pieces = SupportClusters(in_.segments, inliers, support_gap_);
  if (pieces.size() < 2 || pieces[0].size() < min_lines ||
      !PiecesDisagree(in_.segments, pieces, plane, min_lines, kPieceMinWidthOverEps * in_.epsilon,
                      kPieceDisagreementOverEps * in_.epsilon)) {
    return;
  }
  std::vector<SegmentId> kept = std::move(pieces[0]);
  Plane3 fitted = FitPlane(in_.segments, kept, plane.normal);
  for (std::int32_t it = 0; it < in_.options.max_refit_iterations; ++it) {
    const Plane3 refit = FitPlane(in_.segments, kept, fitted.normal);
    std::vector<SegmentId> best = PieceOverlappingMost(
        SupportClusters(in_.segments, inlier_test_.Collect(refit), support_gap_), kept);
    if (best.size() < kept.size()) break;  // the refit lost support: keep the previous
    const bool stable = best == kept;
    fitted = refit;
    kept = std::move(best);
    if (stable) break;
  }
  plane = fitted;
  inliers = std::move(kept);
}

}  // namespace linesurf::detect
