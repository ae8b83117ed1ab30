#include "engine/detect/candidate_search.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <tuple>
#include <utility>

#include "engine/core/rng.h"
#include "engine/detect/detect_stage.h"

namespace linesurf::detect {
namespace {
/// Candidates evaluated per parallel batch; fixed (not derived from the thread count) so that the
/// adaptive stop sees the same batches for any number of threads.
constexpr std::int64_t kBatchSize = 128;
/// Grain of the parallel loops over candidates (fixed: determinism does not depend on it, speed
/// does a little).
constexpr std::size_t kCandidateGrain = 4;
/// Segments shorter than this (relative to eps) have no usable direction and are never sampled.
constexpr double kMinSampleLengthOverEps = 1e-6;
/// Safety factors of the cheap pair rejections in PlaneFromPair (squared quantities): far from
/// 1 compared with rounding, close enough to 1 to reject nearly every invalid pair.
constexpr double kCheapRejectShrink = 1.0 - 1e-9;
constexpr double kCheapRejectGrow = 1.0 + 1e-9;

/// Evaluates candidates [first, first + count) with `make(k)` in parallel and folds them, in k
/// order, into `best` (score, then smallest k). Returns the batch's trials: valid candidates and
/// apart draws.
template <typename Make>
std::int64_t EvaluateBatch(std::int64_t first,
                           std::int64_t count,
                           Make&& make,
                           std::optional<CandidateResult>& best,
                           PlaneDetectionStats& stats) {
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
}  // namespace

CandidateSearch::CandidateSearch(const RansacInput& in,
                                 const RansacState& state,
                                 const InlierTest& inlier_test,
                                 std::uint64_t seed)
    : in_(in),
      state_(state),
      inlier_test_(inlier_test),
      seed_(seed),
      sin_pair_(std::sin(DegToRad(in.options.min_pair_angle_deg))) {
  const std::span<const Segment3> segments = in_.segments;
  direction_.resize(segments.size(), Vec3::Zero());
  midpoint_.reserve(segments.size());
  for (const Segment3& seg : segments) midpoint_.push_back(seg.Midpoint());
  sampleable_.resize(segments.size(), false);
  for (std::size_t i = 0; i < segments.size(); ++i) {
    const Vec3 d = segments[i].p2 - segments[i].p1;
    const double len = d.norm();
    if (len > kMinSampleLengthOverEps * in_.epsilon) {
      direction_[i] = d / len;
      sampleable_[i] = true;
    }
  }
}

bool CandidateSearch::Sampleable(SegmentId s) const {
  const PlaneMembership& m = state_.memberships[s.index()];
  if (!sampleable_[s.index()] || m.count >= 2) return false;
  return !(in_.options.single_support && m.count == 1);
}

std::vector<SegmentId> CandidateSearch::SamplingPool() const {
  std::vector<SegmentId> pool;
  for (std::size_t i = 0; i < in_.segments.size(); ++i) {
    if (Sampleable(SegmentId(i))) pool.emplace_back(i);
  }
  return pool;
}

std::optional<Plane3> CandidateSearch::PlaneFromPair(SegmentId a, SegmentId b, bool* apart) const {
  if (a == b) return std::nullopt;
  const PlaneMembership& ma = state_.memberships[a.index()];
  const PlaneMembership& mb = state_.memberships[b.index()];
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
  if (gap * gap > kCheapRejectGrow * 4.0 * in_.epsilon * in_.epsilon * sin2) {
    if (apart != nullptr && sin2 >= sin_pair_ * sin_pair_) *apart = true;
    return std::nullopt;
  }
  const double sin = std::sqrt(sin2);
  if (sin < sin_pair_) return std::nullopt;
  Plane3 plane;
  plane.normal = cross / sin;
  if (std::abs(plane.normal.dot(mid_a - mid_b)) > 2.0 * in_.epsilon) {
    if (apart != nullptr) *apart = true;
    return std::nullopt;
  }
  plane.point = 0.5 * (mid_a + mid_b);
  return plane;
}

CandidateResult CandidateSearch::RandomCandidate(const std::vector<SegmentId>& pool,
                                                 std::size_t plane_index,
                                                 std::int64_t k) const {
  CandidateResult result;
  Rng rng(MixSeed(seed_, RngStage::kDetect, plane_index, static_cast<std::uint64_t>(k)));
  const auto& order = state_.bvh.Order();
  const auto window = static_cast<std::int64_t>(in_.options.near_window);
  const auto n = static_cast<std::int64_t>(order.size());
  for (std::int32_t attempt = 0; attempt < in_.options.max_draws_per_candidate; ++attempt) {
    const SegmentId a = pool[rng.Below(pool.size())];
    SegmentId b;
    if (rng.Uniform() < in_.options.near_fraction) {
      std::int64_t offset = static_cast<std::int64_t>(rng.Below(2 * window)) - window;
      if (offset >= 0) ++offset;  // in [-window, window] \ {0}
      const std::int64_t pos = std::clamp<std::int64_t>(state_.bvh.PositionOf(a) + offset, 0, n - 1);
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
    std::tie(result.support, result.score) = inlier_test_.Count(*plane);
    return result;
  }
  return result;
}

std::optional<CandidateResult> CandidateSearch::SearchPlane(const std::vector<SegmentId>& pool,
                                                            std::size_t plane_index,
                                                            const RunContext& ctx,
                                                            PlaneDetectionStats& stats) const {
  if (pool.size() <= static_cast<std::size_t>(in_.options.exhaustive_pairs_max_segments)) {
    return SearchAllPairs(pool, stats);
  }
  return SearchRandom(pool, plane_index, ctx, stats);
}

std::optional<CandidateResult> CandidateSearch::SearchAllPairs(const std::vector<SegmentId>& pool,
                                                               PlaneDetectionStats& stats) const {
  std::optional<CandidateResult> best;
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
        std::tie(r.support, r.score) = inlier_test_.Count(*plane);
        return r;
      },
      best, stats);
  return best;
}

std::optional<CandidateResult> CandidateSearch::SearchRandom(const std::vector<SegmentId>& pool,
                                                             std::size_t plane_index,
                                                             const RunContext& ctx,
                                                             PlaneDetectionStats& stats) const {
  std::optional<CandidateResult> best;
  std::int64_t done = 0;
  const std::int64_t failed_before = stats.failed_draws;
  std::int64_t trials = 0;
  while (done < in_.options.iterations) {
    const std::int64_t count = std::min(kBatchSize, in_.options.iterations - done);
    trials += EvaluateBatch(
        done,
        count,
        [&](std::int64_t k) { return RandomCandidate(pool, plane_index, k); },
        best,
        stats);
    done += count;
    if (stats.failed_draws - failed_before >= in_.options.max_failed_draws) break;
    if (best && done >= in_.options.min_iterations && ConfidentOf(*best, pool.size(), trials)) break;
    ctx.ThrowIfCancelled(kDetectPlanesStage);
  }
  return best;
}

bool CandidateSearch::ConfidentOf(const CandidateResult& best,
                                  std::size_t pool_size,
                                  std::int64_t trials) const {
  const double log_miss = std::log(1.0 - in_.options.confidence);
  const double n = static_cast<double>(pool_size);
  const double window = 2.0 * in_.options.near_window;
  // Probability that one draw hits the best plane: the first segment on it, then the second on
  // it too (near draw: the plane fills the window up to its support).
  const double s = best.support;
  const double p_first = std::min(1.0, s / n);
  const double p_second = in_.options.near_fraction * std::min(1.0, s / window) +
                          (1.0 - in_.options.near_fraction) * p_first;
  const double w = p_first * p_second;
  if (w >= 1.0) return true;
  const double needed = log_miss / std::log1p(-w);
  return static_cast<double>(trials) >= needed;
}

}  // namespace linesurf::detect
