#include "engine/detect/estimate_epsilon.h"

#include "engine/core/exception.h"
#include "engine/core/median_segment_length.h"
#include "engine/detect/collinear_groups.h"
#include "engine/detect/segment_geometry.h"
#include "engine/detect/truncated_noise_scale.h"

#include <algorithm>
#include <cmath>
#include <span>
#include <vector>

namespace linesurf {
namespace {

constexpr const char* kEstimateEpsilonStage = "estimate_epsilon";
/// eps_0 of the first probe, as a fraction of the median segment length: 2 cm on the ~1 m
/// segments of metric scenes (the paper's default), 0.019 on Andalusian.
constexpr double kInitialOverMedianLength = 0.02;
/// The estimate stays within [eps_0 / 8, 8 eps_0]: noise-free data would otherwise drive eps to
/// zero, and a probe that merged everything would blow it up.
constexpr double kMaxChange = 8.0;
/// Probes stop when one covers the noise (kCoveredPassRate, kMinPairsForScale), when eps changes
/// by less than this fraction, or after kMaxRounds.
constexpr double kConvergence = 0.1;
constexpr int kMaxRounds = 6;
/// A probe covers the noise when its test passes this share of lines at the estimated scale
/// (a tolerance of about 1.4 noise scales).
constexpr double kCoveredPassRate = 0.9;
/// Fewer (line, plane) pairs than this do not fix the scale (its standard error is about 20 %
/// at 100 pairs seen through a tolerance of 1.5 noise scales).
constexpr std::size_t kMinPairsForScale = 128;
/// A probe only needs the largest planes.
constexpr std::int32_t kProbePlanes = 24;
/// Parts of one line: every endpoint within this fraction of the median segment length of the
/// other's line (the reference's split and ours leave them collinear to rounding).
constexpr double kCollinearPartsOverMedianLength = 1e-5;
/// Planes with fewer distinct lines do not give residuals (see LineResiduals).
constexpr std::size_t kMinLinesForScale = 6;
/// 1 / Phi^-1(3/4): median absolute deviation -> standard deviation of a Gaussian.
constexpr double kMadToSigma = 1.482602218505602;

double SceneDiagonal(const Scene& scene) {
  Box3 box;
  for (const Segment3& s : scene.segments) {
    box.Extend(s.p1);
    box.Extend(s.p2);
  }
  return box.IsEmpty() ? 0.0 : box.Extent().norm();
}

/// The endpoint distances of every distinct line to each of its planes. The parts of one line
/// (a residual split) count once, as the line itself: a line seen by 30 cameras must not weigh
/// 30 times. Only planes holding at least kMinLinesForScale lines count when there are such
/// planes: a plane through two or three lines fits their noise and shows residuals near zero.
std::vector<detect::EndpointDistances> LineResiduals(
    const Scene& scene,
    const IdVector<PlaneId, Plane3>& planes,
    const IdVector<SegmentId, PlaneMembership>& memberships) {
  const std::size_t n = std::min(memberships.size(), scene.NumSegments());
  const double length = MedianSegmentLength(scene);
  if (n == 0 || !(length > 0.0)) return {};
  const detect::CollinearGroups groups =
      detect::GroupCollinearSegments(std::span<const Segment3>(scene.segments.raw().data(), n),
                                     kCollinearPartsOverMedianLength * length);
  std::vector<SegmentId> lines;  // the first part of every line that lies on a plane
  std::vector<std::size_t> lines_on_plane(planes.size(), 0);
  for (std::size_t g = 0; g < groups.members.NumRows(); ++g) {
    const SegmentId first = groups.members[SegmentId(g)].front();
    const PlaneMembership& m = memberships[first];
    bool on_plane = false;
    for (std::uint8_t k = 0; k < m.count; ++k) {
      if (m.planes[k].index() >= planes.size()) continue;
      ++lines_on_plane[m.planes[k].index()];
      on_plane = true;
    }
    if (on_plane) lines.push_back(first);
  }
  const bool any_large = std::any_of(lines_on_plane.begin(),
                                     lines_on_plane.end(),
                                     [](std::size_t c) { return c >= kMinLinesForScale; });
  std::vector<detect::EndpointDistances> out;
  for (SegmentId s : lines) {
    const PlaneMembership& m = memberships[s];
    const Segment3& seg = scene.segments[s];
    for (std::uint8_t k = 0; k < m.count; ++k) {
      const std::size_t p = m.planes[k].index();
      if (p >= planes.size() || (any_large && lines_on_plane[p] < kMinLinesForScale)) continue;
      out.push_back({.first = std::abs(planes[m.planes[k]].SignedDistance(seg.p1)),
                     .second = std::abs(planes[m.planes[k]].SignedDistance(seg.p2))});
    }
  }
  return out;
}

/// Given planes were not chosen at our eps, so their residuals are not truncated: the median
/// absolute deviation, robust to the up to 50 % of wrong memberships.
EpsilonEstimate MadScale(std::span<const detect::EndpointDistances> pairs,
                         double epsilon_over_noise) {
  std::vector<double> d;
  d.reserve(2 * pairs.size());
  for (const detect::EndpointDistances& p : pairs) {
    d.push_back(p.first);
    d.push_back(p.second);
  }
  EpsilonEstimate e;
  e.residuals = d.size();
  if (d.empty()) return e;
  const auto mid = d.begin() + static_cast<std::ptrdiff_t>(d.size() / 2);
  std::nth_element(d.begin(), mid, d.end());
  e.noise_scale = kMadToSigma * *mid;
  e.epsilon = epsilon_over_noise * e.noise_scale;
  return e;
}

EpsilonEstimate Probe(const Scene& scene,
                      const PlaneDetectionOptions& options,
                      const RunContext& ctx) {
  const double length = MedianSegmentLength(scene);
  if (!(length > 0.0)) {  // nothing to detect: any eps gives no plane
    EpsilonEstimate none;
    none.epsilon = 1.0;
    none.source = "none";
    return none;
  }
  const double eps0 = kInitialOverMedianLength * length;
  PlaneDetectionOptions probe = options;
  probe.relative_epsilon.reset();
  probe.max_planes = std::min(options.max_planes, kProbePlanes);
  probe.split_blocks_at_cap = false;  // the cap is the point: the largest planes of each block
  double eps = eps0;
  EpsilonEstimate out;
  // The probes report as stage estimate_epsilon (round r covers ((r - 1) / kMaxRounds,
  // r / kMaxRounds]), so detect_planes progress runs once, for the detection itself.
  int round = 1;
  RunContext probe_ctx;
  probe_ctx.num_threads = ctx.num_threads;
  probe_ctx.is_cancelled = [&ctx] { return ctx.ShouldStop(); };
  probe_ctx.on_progress = [&ctx, &round](const Progress& p) {
    ctx.ReportProgress(kEstimateEpsilonStage, (round - 1 + p.stage_fraction) / kMaxRounds);
  };
  probe_ctx.log = ctx.log;
  ctx.ReportProgress(kEstimateEpsilonStage, 0.0);
  for (; round <= kMaxRounds; ++round) {
    probe.epsilon = eps;
    Expected<PlaneDetectionResult> found = DetectPlanes(scene, probe, probe_ctx);
    if (!found) throw LinesurfException(found.error());
    const detect::TruncatedScale scale = detect::TruncatedNoiseScale(
        LineResiduals(scene, found->planes, found->memberships), eps);
    out.rounds = round;
    out.residuals = 2 * scale.pairs;
    out.noise_scale = scale.sigma;
    if (scale.pairs == 0) break;  // nothing coplanar at this eps: keep it
    // A probe whose test passes most noisy lines at the estimated scale saw enough of the
    // noise; a narrower one saw a sliver of it, on planes refitted to that sliver (which biases
    // the scale low), and the next probe widens to the estimate. A probe that kept too few
    // lines says little about either: the next one doubles its tolerance at least.
    const bool enough = scale.pairs >= kMinPairsForScale;
    const bool covered =
        enough && detect::MeanDistancePassRate(eps / scale.sigma) >= kCoveredPassRate;
    const double wanted = options.epsilon_over_noise * scale.sigma;
    const double next =
        std::clamp(enough ? wanted : std::max(wanted, 2.0 * eps), eps0 / kMaxChange,
                   eps0 * kMaxChange);
    const bool converged = std::abs(next - eps) <= kConvergence * eps;
    eps = next;
    if (covered || converged) break;
  }
  ctx.ReportProgress(kEstimateEpsilonStage, 1.0);
  out.epsilon = eps;
  out.initial_epsilon = eps0;
  out.source = "probe";
  return out;
}

}  // namespace

EpsilonEstimate EstimateEpsilonFromPlanes(const Scene& scene, double epsilon_over_noise) {
  EpsilonEstimate e =
      MadScale(LineResiduals(scene, scene.planes, scene.memberships), epsilon_over_noise);
  e.source = "planes";
  return e;
}

Expected<EpsilonEstimate> ResolveEpsilon(const Scene& scene,
                                         const PlaneDetectionOptions& options,
                                         const RunContext& ctx) noexcept {
  if (Status valid = options.Validate(); !valid) return valid.error();
  return CatchAll(kEstimateEpsilonStage, [&]() -> EpsilonEstimate {
    EpsilonEstimate e;
    if (options.relative_epsilon) {
      e.epsilon = *options.relative_epsilon * SceneDiagonal(scene);
      e.source = "relative";
      LINESURF_THROW_IF(!(e.epsilon > 0.0),
                        kDegenerate,
                        kEstimateEpsilonStage,
                        "relative_epsilon needs a scene of non-zero extent");
      return e;
    }
    if (options.epsilon) {
      e.epsilon = *options.epsilon;
      e.source = "given";
      return e;
    }
    if (scene.HasMemberships()) {
      e = EstimateEpsilonFromPlanes(scene, options.epsilon_over_noise);
      if (e.epsilon > 0.0) return e;
    }
    return Probe(scene, options, ctx);
  });
}

}  // namespace linesurf
