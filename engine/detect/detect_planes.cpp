#include "engine/detect/detect_planes.h"

#include "linesurf/option_schema.h"

#include "engine/core/exception.h"
#include "engine/core/parallel.h"
#include "engine/core/rng.h"
#include "engine/detect/collinear_groups.h"
#include "engine/detect/detection_blocks.h"
#include "engine/detect/estimate_epsilon.h"
#include "engine/detect/plane_fusion.h"
#include "engine/detect/segment_bvh.h"
#include "engine/detect/segment_geometry.h"
#include "engine/detect/support_clusters.h"

#include <Eigen/Eigenvalues>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <mutex>
#include <numbers>
#include <optional>
#include <sstream>
#include <tuple>

namespace linesurf {

namespace {
constexpr char kDetectPlanesStage[] = "detect_planes";
/// Candidates evaluated per parallel batch; fixed (not derived from the thread count) so that the
/// adaptive stop sees the same batches for any number of threads.
constexpr std::int64_t kBatchSize = 128;
/// Grain of the parallel loops over candidates (fixed: determinism does not depend on it, speed
/// does a little).
constexpr std::size_t kCandidateGrain = 4;
/// Segments shorter than this (relative to eps) have no usable direction and are never sampled.
constexpr double kMinSampleLengthOverEps = 1e-6;
/// A fit whose two largest spreads differ by more than this ratio is collinear: keep the hint.
constexpr double kCollinearEigenRatio = 1e-12;
/// A piece of a plane's support is judged on its own fit only when its endpoints spread at least
/// this many eps across their main direction (so that its tilt is not noise)...
constexpr double kPieceMinWidthOverEps = 10.0;
/// ... and it disagrees with the plane when its own fit is farther than this many eps from the
/// plane at one of its endpoints.
constexpr double kPieceDisagreementOverEps = 0.5;
/// Safety factors of the cheap pair rejections in PlaneFromPair (squared quantities): far from
/// 1 compared with rounding, close enough to 1 to reject nearly every invalid pair.
constexpr double kCheapRejectShrink = 1.0 - 1e-9;
constexpr double kCheapRejectGrow = 1.0 + 1e-9;
/// Tags the random streams of per-block detection (block b draws from (seed, kBlockStream, b)).
constexpr std::uint64_t kBlockStream = 0xb10c0000b10c0000ULL;

double DegToRad(double deg) { return deg * std::numbers::pi / 180.0; }

Status Invalid(const std::string& field, const std::string& range) {
  return Error{ErrorCode::kInvalidOptions,
               kDetectPlanesStage,
               "PlaneDetectionOptions." + field + " must be " + range};
}
}  // namespace

Status PlaneDetectionOptions::Validate() const {
  if (Status s = ValidateOptionValues(static_cast<const DetectionParameters&>(*this)); !s) {
    return s;
  }
  if (min_iterations < 1) return Invalid("min_iterations", ">= 1");
  if (!(confidence > 0.0 && confidence < 1.0)) return Invalid("confidence", "in (0, 1)");
  if (max_failed_draws < 1) return Invalid("max_failed_draws", ">= 1");
  if (max_draws_per_candidate < 1) return Invalid("max_draws_per_candidate", ">= 1");
  if (!(min_pair_angle_deg > 0.0 && min_pair_angle_deg < 90.0)) {
    return Invalid("min_pair_angle_deg", "in (0, 90)");
  }
  if (!(min_crease_angle_deg > 0.0 && min_crease_angle_deg < 90.0)) {
    return Invalid("min_crease_angle_deg", "in (0, 90)");
  }
  if (exhaustive_pairs_max_segments < 0 || exhaustive_pairs_max_segments > 4096) {
    return Invalid("exhaustive_pairs_max_segments", "in [0, 4096]");
  }
  if (near_window < 1) return Invalid("near_window", ">= 1");
  if (!(near_fraction >= 0.0 && near_fraction <= 1.0)) return Invalid("near_fraction", "in [0, 1]");
  if (max_refit_iterations < 0) return Invalid("max_refit_iterations", ">= 0");
  return {};
}

namespace detect {

Plane3 FitPlane(std::span<const Segment3> segments, std::span<const SegmentId> ids,
                const Vec3& hint, double* width) {
  if (width != nullptr) *width = 0.0;
  double total = 0.0;
  Vec3 centroid = Vec3::Zero();
  for (const SegmentId s : ids) {
    const Segment3& seg = segments[s.index()];
    const double w = seg.Length();
    total += 2.0 * w;
    centroid += w * (seg.p1 + seg.p2);
  }
  Plane3 plane;
  plane.normal = hint.normalized();
  if (!(total > 0.0)) return plane;
  centroid /= total;
  plane.point = centroid;
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  for (const SegmentId s : ids) {
    const Segment3& seg = segments[s.index()];
    const double w = seg.Length();
    const Vec3 a = seg.p1 - centroid;
    const Vec3 b = seg.p2 - centroid;
    cov += w * (a * a.transpose() + b * b.transpose());
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(cov);
  const Vec3 values = eig.eigenvalues();  // ascending
  if (width != nullptr) *width = std::sqrt(std::max(0.0, values[1]) / total);
  if (values[1] <= kCollinearEigenRatio * values[2]) return plane;  // collinear: keep hint
  Vec3 normal = eig.eigenvectors().col(0).normalized();
  if (normal.dot(hint) < 0.0) normal = -normal;
  plane.normal = normal;
  return plane;
}

namespace {

double MedianLength(std::span<const Segment3> segments) {
  std::vector<double> lengths;
  lengths.reserve(segments.size());
  for (const Segment3& seg : segments) lengths.push_back(seg.Length());
  if (lengths.empty()) return 0.0;
  const auto middle = lengths.begin() + static_cast<std::ptrdiff_t>(lengths.size() / 2);
  std::nth_element(lengths.begin(), middle, lengths.end());
  return *middle;
}

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

/// One run of the multi-support RANSAC over a scene (working state of DetectPlanes).
class Detector {
 public:
  /// `seed` replaces options.seed (per-block streams); `report_progress` is off when blocks run
  /// concurrently (they report per block instead).
  Detector(std::span<const Segment3> segments, const PlaneDetectionOptions& options,
           double epsilon, std::uint64_t seed, bool report_progress, const RunContext& ctx)
      : segments_(segments),
        options_(options),
        seed_(seed),
        report_progress_(report_progress),
        ctx_(ctx),
        epsilon_(epsilon),
        slab_(options.distance == SegmentDistance::kMeanEndpoint ? 2.0 * epsilon : epsilon),
        sin_pair_(std::sin(DegToRad(options.min_pair_angle_deg))),
        sin_crease_(std::sin(DegToRad(options.min_crease_angle_deg))),
        memberships_(segments_.size()),
        bvh_(segments_),
        support_gap_(options.support_gap * MedianLength(segments)) {
    direction_.resize(segments_.size(), Vec3::Zero());
    midpoint_.reserve(segments_.size());
    for (const Segment3& seg : segments_) midpoint_.push_back(seg.Midpoint());
    sampleable_.resize(segments_.size(), false);
    for (std::size_t i = 0; i < segments_.size(); ++i) {
      const Vec3 d = segments_[i].p2 - segments_[i].p1;
      const double len = d.norm();
      if (len > kMinSampleLengthOverEps * epsilon_) {
        direction_[i] = d / len;
        sampleable_[i] = true;
      }
    }
  }

  /// Extracts planes one by one until a stopping criterion holds.
  void ExtractAll(PlaneDetectionStats& stats) {
    while (static_cast<std::int32_t>(planes_.size()) < options_.max_planes) {
      ctx_.ThrowIfCancelled(kDetectPlanesStage);
      if (report_progress_) {
        ctx_.ReportProgress(kDetectPlanesStage,
                            static_cast<double>(planes_.size()) / options_.max_planes);
      }
      const std::vector<SegmentId> pool = SamplingPool();
      if (pool.size() < 2) break;
      const std::optional<CandidateResult> best = SearchPlane(pool, stats);
      if (!best || best->support < static_cast<std::uint32_t>(options_.min_support)) break;
      Plane3 plane = best->plane;
      std::vector<SegmentId> inliers = Collect(plane);
      for (std::int32_t it = 0; it < options_.max_refit_iterations; ++it) {
        const Plane3 refit = FitPlane(segments_, inliers, plane.normal);
        std::vector<SegmentId> again = Collect(refit);
        if (again.size() < inliers.size()) break;  // the refit lost support: keep the previous
        const bool stable = again == inliers;
        plane = refit;
        inliers = std::move(again);
        if (stable) break;
      }
      KeepOnePiece(plane, inliers);
      if (inliers.size() < static_cast<std::size_t>(options_.min_support)) break;
      const PlaneId id(planes_.size());
      for (const SegmentId s : inliers) memberships_[s.index()].Add(id);
      planes_.push_back({plane, std::move(inliers)});
    }
    if (static_cast<std::int32_t>(planes_.size()) >= options_.max_planes) stats.capped_blocks = 1;
  }

  std::vector<detect::SupportedPlane>& planes() { return planes_; }

 private:
  /// When the support of `plane` falls into pieces farther apart than the support gap that
  /// disagree about the plane (detect::PiecesDisagree), keeps the largest piece: refit on it,
  /// re-collect, and keep the piece of the new inliers that holds most of the old one, until
  /// stable. The other pieces' segments stay free for planes of their own. A largest piece under
  /// min_support leaves the plane as it was.
  void KeepOnePiece(Plane3& plane, std::vector<SegmentId>& inliers) const {
    if (support_gap_ <= 0.0) return;
    const auto min_lines = static_cast<std::size_t>(options_.min_support);
    std::vector<std::vector<SegmentId>> pieces =
        detect::SupportClusters(segments_, inliers, support_gap_);
    if (pieces.size() < 2 || pieces[0].size() < min_lines ||
        !detect::PiecesDisagree(segments_, pieces, plane, min_lines,
                                kPieceMinWidthOverEps * epsilon_,
                                kPieceDisagreementOverEps * epsilon_)) {
      return;
    }
    std::vector<SegmentId> kept = std::move(pieces[0]);
    Plane3 fitted = detect::FitPlane(segments_, kept, plane.normal);
    for (std::int32_t it = 0; it < options_.max_refit_iterations; ++it) {
      const Plane3 refit = detect::FitPlane(segments_, kept, fitted.normal);
      const std::vector<SegmentId> again = Collect(refit);
      std::vector<SegmentId> best;
      std::size_t best_overlap = 0;
      for (std::vector<SegmentId>& piece :
           detect::SupportClusters(segments_, again, support_gap_)) {
        std::vector<SegmentId> common;
        std::set_intersection(piece.begin(), piece.end(), kept.begin(), kept.end(),
                              std::back_inserter(common));
        if (common.size() > best_overlap) {
          best_overlap = common.size();
          best = std::move(piece);
        }
      }
      if (best.size() < kept.size()) break;  // the refit lost support: keep the previous
      const bool stable = best == kept;
      fitted = refit;
      kept = std::move(best);
      if (stable) break;
    }
    plane = fitted;
    inliers = std::move(kept);
  }

  bool Sampleable(SegmentId s) const {
    const PlaneMembership& m = memberships_[s.index()];
    if (!sampleable_[s.index()] || m.count >= 2) return false;
    return !(options_.single_support && m.count == 1);
  }

  std::vector<SegmentId> SamplingPool() const {
    std::vector<SegmentId> pool;
    for (std::size_t i = 0; i < segments_.size(); ++i) {
      if (Sampleable(SegmentId(i))) pool.emplace_back(i);
    }
    return pool;
  }

  /// Distance of `s` to `plane` under the inlier test that applies to it (textural or
  /// structural), or a negative value when `s` cannot join `plane`.
  double InlierDistance(SegmentId s, const Plane3& plane) const {
    const PlaneMembership& m = memberships_[s.index()];
    const Segment3& seg = segments_[s.index()];
    if (m.count >= 2) return -1.0;
    if (m.count == 0 || options_.no_structural_condition) {
      if (m.count == 1 && options_.single_support) return -1.0;
      return SegmentPlaneDistance(seg, plane, options_.distance);
    }
    if (options_.single_support) return -1.0;
    // Structural condition: a segment already on P' joins P only along the crease P ∩ P'.
    detect::CreaseLine line;
    if (!detect::IntersectPlanes(plane, planes_[m.planes[0].index()].plane, sin_crease_, line)) {
      return -1.0;
    }
    return detect::SegmentLineDistance(seg, line, options_.distance);
  }

  bool IsInlier(SegmentId s, const Plane3& plane) const {
    const double d = InlierDistance(s, plane);
    return d >= 0.0 && d <= epsilon_;
  }

  /// Support of a candidate: inlier count and score (count, or the truncated quadratic
  /// sum of (1 - (d / eps)^2) when options.score_by_residual), summed serially in BVH order.
  std::pair<std::uint32_t, double> Count(const Plane3& plane) const {
    std::uint32_t count = 0;
    double score = 0.0;
    bvh_.ForEachInSlab(plane, slab_, [&](SegmentId s) {
      const double d = InlierDistance(s, plane);
      if (d < 0.0 || d > epsilon_) return;
      ++count;
      const double r = d / epsilon_;
      score += options_.score_by_residual ? 1.0 - r * r : 1.0;
    });
    return {count, score};
  }

  std::vector<SegmentId> Collect(const Plane3& plane) const {
    std::vector<SegmentId> inliers;
    bvh_.ForEachInSlab(plane, slab_, [&](SegmentId s) {
      if (IsInlier(s, plane)) inliers.push_back(s);
    });
    std::sort(inliers.begin(), inliers.end());
    return inliers;
  }

  /// The plane through a and b (containing both directions, halfway between the two infinite
  /// lines), if the pair is valid: not near-parallel, lines within 2 eps, and b not on a plane
  /// of a (never re-propose a plane already extracted). `apart` is set when the only reason to
  /// reject the pair is that the lines pass farther than 2 eps apart.
  std::optional<Plane3> PlaneFromPair(SegmentId a, SegmentId b, bool* apart = nullptr) const {
    if (a == b) return std::nullopt;
    const PlaneMembership& ma = memberships_[a.index()];
    const PlaneMembership& mb = memberships_[b.index()];
    for (std::uint8_t i = 0; i < ma.count; ++i) {
      if (mb.Contains(ma.planes[i])) return std::nullopt;
    }
    const Vec3 cross = direction_[a.index()].cross(direction_[b.index()]);
    // Cheap rejections first, with relative margins of 1e-9 so that they never decide a
    // borderline pair (rounding stays far below them while midpoints are less than ~1e7 eps
    // apart): the exact tests below keep the result identical to doing them alone.
    const double sin2 = cross.squaredNorm();
    if (sin2 < kCheapRejectShrink * sin_pair_ * sin_pair_) return std::nullopt;
    const Vec3& mid_a = midpoint_[a.index()];
    const Vec3& mid_b = midpoint_[b.index()];
    const double gap = cross.dot(mid_a - mid_b);
    if (gap * gap > kCheapRejectGrow * 4.0 * epsilon_ * epsilon_ * sin2) {
      if (apart != nullptr && sin2 >= sin_pair_ * sin_pair_) *apart = true;
      return std::nullopt;
    }
    const double sin = std::sqrt(sin2);
    if (sin < sin_pair_) return std::nullopt;
    Plane3 plane;
    plane.normal = cross / sin;
    if (std::abs(plane.normal.dot(mid_a - mid_b)) > 2.0 * epsilon_) {
      if (apart != nullptr) *apart = true;
      return std::nullopt;
    }
    plane.point = 0.5 * (mid_a + mid_b);
    return plane;
  }

  /// Candidate k of plane j: draws from its own stream, so any thread may evaluate it.
  CandidateResult RandomCandidate(const std::vector<SegmentId>& pool, std::size_t plane_index,
                                  std::int64_t k) const {
    CandidateResult result;
    Rng rng(MixSeed(seed_, RngStage::kDetect, plane_index, static_cast<std::uint64_t>(k)));
    const auto& order = bvh_.Order();
    const auto window = static_cast<std::int64_t>(options_.near_window);
    const auto n = static_cast<std::int64_t>(order.size());
    for (std::int32_t attempt = 0; attempt < options_.max_draws_per_candidate; ++attempt) {
      const SegmentId a = pool[rng.Below(pool.size())];
      SegmentId b;
      if (rng.Uniform() < options_.near_fraction) {
        std::int64_t offset = static_cast<std::int64_t>(rng.Below(2 * window)) - window;
        if (offset >= 0) ++offset;  // in [-window, window] \ {0}
        const std::int64_t pos = std::clamp<std::int64_t>(bvh_.PositionOf(a) + offset, 0, n - 1);
        b = order[static_cast<std::size_t>(pos)];
        if (!Sampleable(b)) {
          ++result.failed_draws;
          continue;
        }
      } else {
        b = pool[rng.Below(pool.size())];
      }
      bool apart = false;
      const std::optional<Plane3> plane = PlaneFromPair(a, b, &apart);
      if (!plane) {
        ++result.failed_draws;
        result.apart_draws += apart ? 1 : 0;
        continue;
      }
      result.valid = true;
      result.plane = *plane;
      std::tie(result.support, result.score) = Count(*plane);
      return result;
    }
    return result;
  }

  /// Evaluates candidates [0, count) with `make(k)` in parallel and folds them, in k order, into
  /// `best` (score, then smallest k). Returns the batch's trials: valid candidates and apart
  /// draws.
  template <typename Make>
  std::int64_t EvaluateBatch(std::int64_t first,
                             std::int64_t count,
                             Make&& make,
                             std::optional<CandidateResult>& best,
                             PlaneDetectionStats& stats) const {
    std::vector<CandidateResult> results(static_cast<std::size_t>(count));
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, results.size(), kCandidateGrain),
                      [&](const tbb::blocked_range<std::size_t>& r) {
                        for (std::size_t i = r.begin(); i != r.end(); ++i) {
                          results[i] = make(first + static_cast<std::int64_t>(i));
                        }
                      });
    std::int64_t trials = 0;
    for (const CandidateResult& r : results) {
      stats.failed_draws += r.failed_draws;
      trials += r.apart_draws;
      if (!r.valid) continue;
      ++trials;
      ++stats.candidates_evaluated;
      if (!best || r.score > best->score) best = r;
    }
    return trials;
  }

  std::optional<CandidateResult> SearchPlane(const std::vector<SegmentId>& pool,
                                             PlaneDetectionStats& stats) const {
    std::optional<CandidateResult> best;
    const std::size_t plane_index = planes_.size();
    if (pool.size() <= static_cast<std::size_t>(options_.exhaustive_pairs_max_segments)) {
      std::vector<std::pair<SegmentId, SegmentId>> pairs;
      for (std::size_t i = 0; i < pool.size(); ++i) {
        for (std::size_t j = i + 1; j < pool.size(); ++j) pairs.emplace_back(pool[i], pool[j]);
      }
      EvaluateBatch(
          0, static_cast<std::int64_t>(pairs.size()),
          [&](std::int64_t k) {
            CandidateResult r;
            const auto& [a, b] = pairs[static_cast<std::size_t>(k)];
            const std::optional<Plane3> plane = PlaneFromPair(a, b);
            if (!plane) {
              r.failed_draws = 1;
              return r;
            }
            r.valid = true;
            r.plane = *plane;
            std::tie(r.support, r.score) = Count(*plane);
            return r;
          },
          best, stats);
      return best;
    }
    const double log_miss = std::log(1.0 - options_.confidence);
    const double n = static_cast<double>(pool.size());
    const double window = 2.0 * options_.near_window;
    std::int64_t done = 0;
    const std::int64_t failed_before = stats.failed_draws;
    std::int64_t trials = 0;
    while (done < options_.iterations) {
      const std::int64_t count = std::min(kBatchSize, options_.iterations - done);
      trials += EvaluateBatch(
          done,
          count,
          [&](std::int64_t k) { return RandomCandidate(pool, plane_index, k); },
          best,
          stats);
      done += count;
      if (stats.failed_draws - failed_before >= options_.max_failed_draws) break;
      if (best && done >= options_.min_iterations) {
        // Probability that one draw hits the best plane: the first segment on it, then the
        // second on it too (near draw: the plane fills the window up to its support).
        const double s = best->support;
        const double p_first = std::min(1.0, s / n);
        const double p_second = options_.near_fraction * std::min(1.0, s / window) +
                                (1.0 - options_.near_fraction) * p_first;
        const double w = p_first * p_second;
        if (w >= 1.0) break;
        const double needed = log_miss / std::log1p(-w);
        if (static_cast<double>(trials) >= needed) break;
      }
      ctx_.ThrowIfCancelled(kDetectPlanesStage);
    }
    return best;
  }

  std::span<const Segment3> segments_;
  const PlaneDetectionOptions& options_;
  std::uint64_t seed_;
  bool report_progress_;
  const RunContext& ctx_;
  double epsilon_;
  double slab_;
  double sin_pair_;
  double sin_crease_;
  std::vector<PlaneMembership> memberships_;
  std::vector<Vec3> direction_;
  std::vector<Vec3> midpoint_;
  std::vector<bool> sampleable_;
  detect::SegmentBvh bvh_;
  double support_gap_;  ///< scene units; 0 = a plane's support may come in pieces
  std::vector<detect::SupportedPlane> planes_;
};

/// Flips `plane` toward the majority of the viewpoints that observe its inliers (canonical sign
/// first: largest normal component positive, which also breaks ties).
void OrientPlane(const Scene& scene, const std::vector<SegmentId>& inliers, Plane3& plane) {
  int axis = 0;
  plane.normal.cwiseAbs().maxCoeff(&axis);
  if (plane.normal[axis] < 0.0) plane.normal = -plane.normal;
  if (scene.observations.NumRows() != scene.segments.size()) return;
  std::int64_t votes = 0;
  for (const SegmentId s : inliers) {
    for (const ViewpointId v : scene.observations[s]) {
      const double side = plane.SignedDistance(scene.viewpoints[v]);
      votes += side > 0.0 ? 1 : (side < 0.0 ? -1 : 0);
    }
  }
  if (votes < 0) plane.normal = -plane.normal;
}

/// The lines to detect on: collinear duplicates merged, or every segment on its own.
CollinearGroups LinesToDetect(const Scene& scene, const PlaneDetectionOptions& options,
                              double epsilon) {
  if (options.collinear_tolerance > 0.0) {
    return GroupCollinearSegments(scene.segments.raw(), options.collinear_tolerance * epsilon);
  }
  CollinearGroups groups;
  groups.lines = scene.segments.raw();
  for (std::size_t i = 0; i < scene.segments.size(); ++i) {
    groups.members.AddRow(std::array<SegmentId, 1>{SegmentId(i)});
  }
  return groups;
}

/// The block grid of per-block detection run on its own: whole cubes of side block_size from the
/// minimum of the lines' midpoints, floor(extent / block_size) + 1 per axis, so every midpoint
/// lies inside the grid (not on its last face) and results are those of the round-1 cubes.
partition::BlockGrid DetectionGrid(std::span<const Segment3> lines, double block_size) {
  const Box3 box = MidpointBox(lines);
  const Eigen::Vector3d blocks = (box.Extent() / block_size).array().floor() + 1.0;
  Expected<partition::BlockGrid> grid =
      partition::BlockGrid::CreateWholeBlocks(box.min, block_size, blocks);
  LINESURF_THROW_IF(!grid,
                    kInvalidOptions,
                    kDetectPlanesStage,
                    "PlaneDetectionOptions.block_size "
                        << block_size << " does not fit a scene of extent "
                        << box.Extent().maxCoeff() << ": " << grid.error().message);
  return std::move(grid).value();
}

/// The blocks of per-block detection and their grid; one block holding every line and no grid
/// when block_size is 0.
struct DetectionLayout {
  std::optional<partition::BlockGrid> grid;
  std::vector<DetectionBlock> blocks;
};

DetectionLayout SplitIntoBlocks(std::span<const Segment3> lines,
                                const PlaneDetectionOptions& options) {
  DetectionLayout layout;
  if (options.block_size > 0.0) {
    if (lines.empty()) return layout;
    layout.grid = DetectionGrid(lines, options.block_size);
    BlockLayout block_layout;
    block_layout.halo = options.block_halo;
    block_layout.max_home_segments = static_cast<std::size_t>(options.block_max_segments);
    layout.blocks = AssignDetectionBlocks(lines, *layout.grid, block_layout);
    return layout;
  }
  DetectionBlock all;
  all.segments.reserve(lines.size());
  for (std::size_t i = 0; i < lines.size(); ++i) all.segments.emplace_back(i);
  all.home_segments = all.segments;
  layout.blocks.push_back(std::move(all));
  return layout;
}

/// Replaces every plane's inlier lines by their member segments (ascending).
void ExpandToSegments(const CollinearGroups& groups, std::vector<SupportedPlane>& planes) {
  for (SupportedPlane& plane : planes) {
    std::vector<SegmentId> segments;
    for (const SegmentId line : plane.inliers) {
      const auto members = groups.members[line];
      segments.insert(segments.end(), members.begin(), members.end());
    }
    std::sort(segments.begin(), segments.end());
    plane.inliers = std::move(segments);
  }
}

/// Whether a block whose RANSAC reached max_planes is replaced by its 8 children: the options
/// allow it, the block lies on a grid below the deepest level, and it holds more home lines than
/// max_planes planes of min_support lines of its own need (a smaller block reached the cap on
/// shared or halo lines, which halving would not cure; the bound also ends the recursion).
bool SplitAtCap(const DetectionBlock& block,
                const DetectionLayout& layout,
                const PlaneDetectionOptions& options) {
  const std::size_t lines_for_cap =
      static_cast<std::size_t>(options.max_planes) * static_cast<std::size_t>(options.min_support);
  return options.split_blocks_at_cap && layout.grid.has_value() &&
         block.key.level < partition::kMaxBlockLevel &&
         block.home_segments.size() > lines_for_cap;
}

/// One block's RANSAC, or its replacement by children when it reached max_planes (SplitAtCap).
struct BlockRun {
  DetectionBlock block;
  double progress_share = 0.0;  ///< of the whole detection, handed on to its children
  std::vector<SupportedPlane> planes;
  PlaneDetectionStats stats;
  std::vector<DetectionBlock> children;  ///< set when the block is split
  std::vector<std::size_t> child_runs;   ///< indices of the children's runs
};

/// Runs the RANSAC of every block (blocks in parallel, each deterministic) and returns their
/// planes in block order, inliers as scene segment ids. A block that reached max_planes is
/// replaced by its children (SplitAtCap), run in the next round; they take its place in the
/// order. A single block keeps options.seed, so it reproduces the monolithic method exactly; the
/// run r of several (blocks first, then children in order of creation) draws from its own stream.
std::vector<SupportedPlane> DetectInBlocks(std::span<const Segment3> lines,
                                           const DetectionLayout& layout,
                                           const PlaneDetectionOptions& options,
                                           double epsilon,
                                           const RunContext& ctx,
                                           PlaneDetectionStats& stats) {
  const bool one_block = layout.blocks.size() == 1;
  // Without a grid nothing splits: the RANSAC's own progress (planes / max_planes) is the
  // detection's.
  const bool plane_progress = !layout.grid.has_value();
  std::vector<BlockRun> runs;
  const auto add_run = [&runs](DetectionBlock block, double progress_share) {
    BlockRun& run = runs.emplace_back();
    run.block = std::move(block);
    run.progress_share = progress_share;
    return runs.size() - 1;
  };
  std::vector<std::size_t> round;
  for (const DetectionBlock& block : layout.blocks) {
    round.push_back(add_run(block, 1.0 / static_cast<double>(layout.blocks.size())));
  }
  std::mutex progress_mutex;
  double progress = 0.0;
  while (!round.empty()) {
    tbb::parallel_for(std::size_t{0}, round.size(), [&](std::size_t i) {
      const std::size_t r = round[i];
      BlockRun& run = runs[r];
      const std::vector<SegmentId>& ids = run.block.segments;
      // A single block holds every line in order: it works on `lines` itself, without a copy.
      const bool single = one_block && r == 0;
      std::vector<Segment3> local;
      if (!single) {
        local.reserve(ids.size());
        for (const SegmentId id : ids) local.push_back(lines[id.index()]);
      }
      const std::uint64_t seed =
          single ? options.seed : MixSeed(options.seed, RngStage::kDetect, kBlockStream, r);
      Detector detector(single ? lines : std::span<const Segment3>(local),
                        options,
                        epsilon,
                        seed,
                        plane_progress,
                        ctx);
      detector.ExtractAll(run.stats);
      if (run.stats.capped_blocks > 0 && SplitAtCap(run.block, layout, options)) {
        run.children = SplitDetectionBlock(lines, *layout.grid, run.block, options.block_halo);
        run.stats.capped_blocks = 0;
        return;
      }
      run.planes = std::move(detector.planes());
      for (SupportedPlane& plane : run.planes) {
        for (SegmentId& s : plane.inliers) s = ids[s.index()];  // ascending stays ascending
      }
      const std::lock_guard lock(progress_mutex);
      progress += run.progress_share;
      ctx.ReportProgress(kDetectPlanesStage, std::min(progress, 1.0));
    });
    std::vector<std::size_t> next;
    for (const std::size_t r : round) {
      std::vector<DetectionBlock> children = std::move(runs[r].children);
      const double share = runs[r].progress_share / static_cast<double>(children.size());
      for (DetectionBlock& child : children) {
        const std::size_t c = add_run(std::move(child), share);
        runs[r].child_runs.push_back(c);
        next.push_back(c);
      }
    }
    round = std::move(next);
  }
  std::vector<SupportedPlane> planes;
  const auto collect = [&](const auto& self, std::size_t r) -> void {
    BlockRun& run = runs[r];
    stats.candidates_evaluated += run.stats.candidates_evaluated;
    stats.failed_draws += run.stats.failed_draws;
    for (const std::size_t child : run.child_runs) self(self, child);
    if (!run.child_runs.empty()) return;
    ++stats.blocks;
    stats.capped_blocks += run.stats.capped_blocks;
    for (SupportedPlane& plane : run.planes) planes.push_back(std::move(plane));
  };
  for (std::size_t r = 0; r < layout.blocks.size(); ++r) collect(collect, r);
  return planes;
}

}  // namespace
}  // namespace detect

std::string PlaneCapWarning(const PlaneDetectionStats& stats, std::int32_t max_planes) {
  if (stats.capped_blocks == 0) return "";
  std::ostringstream os;
  os << "plane detection stopped at max_planes (" << max_planes << ") in " << stats.capped_blocks
     << " block(s): planes may be missing; raise max_planes or detect per block (block_size)";
  return os.str();
}

Expected<PlaneDetectionResult> DetectPlanes(const Scene& scene,
                                            const PlaneDetectionOptions& options,
                                            const RunContext& ctx) noexcept {
  if (Status valid = options.Validate(); !valid) return valid.error();
  return CatchAll(kDetectPlanesStage, [&]() -> PlaneDetectionResult {
    const auto start = std::chrono::steady_clock::now();
    for (std::size_t i = 0; i < scene.segments.size(); ++i) {
      const Segment3& s = scene.segments.raw()[i];
      LINESURF_THROW_IF(!s.p1.allFinite() || !s.p2.allFinite(),
                        kInvalidInput,
                        kDetectPlanesStage,
                        "segment " << i << " has a non-finite endpoint");
    }
    PlaneDetectionResult result;
    Expected<EpsilonEstimate> resolved = ResolveEpsilon(scene, options, ctx);
    if (!resolved) throw LinesurfException(resolved.error());
    const double epsilon = resolved->epsilon;
    result.stats.epsilon = epsilon;
    result.stats.epsilon_estimate = std::move(*resolved);
    const detect::CollinearGroups groups = detect::LinesToDetect(scene, options, epsilon);
    const std::span<const Segment3> lines = groups.lines;
    result.stats.lines = static_cast<std::int64_t>(lines.size());
    const detect::DetectionLayout layout = detect::SplitIntoBlocks(lines, options);
    std::vector<detect::SupportedPlane> planes;
    RunInArena(ctx, [&] {
      planes = detect::DetectInBlocks(lines, layout, options, epsilon, ctx, result.stats);
    });
    result.stats.planes_before_fusion = static_cast<std::int32_t>(planes.size());
    const auto fusion_start = std::chrono::steady_clock::now();
    detect::FusionParameters fusion;
    fusion.epsilon = epsilon;
    fusion.epsilon_fusion = options.epsilon_fusion_factor * epsilon;
    fusion.max_angle_rad = DegToRad(options.theta_fusion_deg);
    fusion.min_shared_fraction = options.p_fusion;
    fusion.distance = options.distance;
    const bool several_blocks = result.stats.blocks > 1;
    if (several_blocks) fusion.max_gap = options.block_halo * options.block_size;
    result.stats.merges = detect::FusePlanes(lines, fusion, planes);
    if (several_blocks) {
      result.stats.memberships_dropped =
          detect::LimitMemberships(lines.size(), options.min_support, planes);
    }
    detect::ExpandToSegments(groups, planes);
    result.stats.seconds_fusion =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - fusion_start).count();
    result.stats.planes_after_fusion = static_cast<std::int32_t>(planes.size());

    result.memberships = IdVector<SegmentId, PlaneMembership>(scene.segments.size());
    for (detect::SupportedPlane& sp : planes) {
      const PlaneId id = result.planes.NextId();
      // Keep the detected plane; move its point to the projection of the inliers' centroid.
      const Plane3 fit = detect::FitPlane(scene.segments.raw(), sp.inliers, sp.plane.normal);
      Plane3 plane = sp.plane;
      plane.point = fit.point - plane.SignedDistance(fit.point) * plane.normal;
      detect::OrientPlane(scene, sp.inliers, plane);
      PlaneSupport support;
      support.inlier_count = static_cast<std::uint32_t>(sp.inliers.size());
      for (const SegmentId s : sp.inliers) {
        support.inlier_length += scene.segments[s].Length();
        LINESURF_ASSERT(result.memberships[s].Add(id));
      }
      support.inliers = std::move(sp.inliers);
      result.planes.push_back(plane);
      result.support.push_back(std::move(support));
    }
    for (const PlaneMembership& m : result.memberships) {
      (m.count == 0 ? result.stats.num_l0 : m.count == 1 ? result.stats.num_l1 : result.stats.num_l2)++;
    }
    result.stats.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return result;
  });
}

}  // namespace linesurf
