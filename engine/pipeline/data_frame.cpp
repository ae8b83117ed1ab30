#include "engine/pipeline/data_frame.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <numeric>
#include <optional>
#include <utility>
#include <vector>

#include <Eigen/Eigenvalues>

namespace linesurf::pipeline {
namespace {

/// Candidate axes tried for a dominant direction: the directions of the longest segments.
constexpr std::size_t kCandidateAxes = 256;
/// Refinement steps of a dominant direction (each the principal axis of the lines near it).
constexpr int kRefineSteps = 8;
/// Two axes whose viewpoint spreads are within this ratio are told apart by the lines.
constexpr double kSpreadRatio = 1.5;

/// A segment's unit direction (either sign) and its length.
struct DirectionSample {
  Vec3 direction;
  double length = 0.0;
};

std::vector<DirectionSample> SampleDirections(const Scene& scene) {
  const std::size_t n = scene.NumSegments();
  const std::size_t stride =
      std::max<std::size_t>(1, (n + kMaxFrameSamples - 1) / kMaxFrameSamples);
  std::vector<DirectionSample> out;
  out.reserve(n / stride + 1);
  for (std::size_t s = 0; s < n; s += stride) {
    const Segment3& seg = scene.segments[SegmentId(s)];
    const Vec3 d = seg.p2 - seg.p1;
    const double length = d.norm();
    if (length > 0.0) out.push_back({d / length, length});
  }
  return out;
}

/// 1 along the axis, falling to 0 at the tolerance angle (cos_tolerance), in |cos|.
double AxisKernel(double abs_cos, double cos_tolerance) {
  return abs_cos <= cos_tolerance ? 0.0 : (abs_cos - cos_tolerance) / (1.0 - cos_tolerance);
}

/// Line length near `axis`, weighted by the kernel.
double AxisSupport(const std::vector<DirectionSample>& samples, const Vec3& axis, double cos_tol) {
  double sum = 0.0;
  for (const DirectionSample& s : samples) {
    sum += s.length * AxisKernel(std::abs(s.direction.dot(axis)), cos_tol);
  }
  return sum;
}

/// Moves `axis` to the principal direction of the lines near it until it stays.
Vec3 RefineAxis(const std::vector<DirectionSample>& samples, Vec3 axis, double cos_tol) {
  for (int step = 0; step < kRefineSteps; ++step) {
    Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero();
    for (const DirectionSample& s : samples) {
      const double k = s.length * AxisKernel(std::abs(s.direction.dot(axis)), cos_tol);
      if (k > 0.0) scatter += k * s.direction * s.direction.transpose();
    }
    if (scatter.isZero()) break;
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(scatter);
    const Vec3 next = eigen.eigenvectors().col(2).normalized();
    const bool settled = std::abs(next.dot(axis)) >= 1.0 - 1e-15;
    axis = next;
    if (settled) break;
  }
  return axis;
}

/// The direction most line length follows: the best of the longest segments' directions by
/// support, then refined. Zero when there is no sample.
Vec3 DominantAxis(const std::vector<DirectionSample>& samples, double cos_tol) {
  std::vector<std::size_t> order(samples.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  const std::size_t count = std::min(kCandidateAxes, order.size());
  std::partial_sort(order.begin(), order.begin() + static_cast<std::ptrdiff_t>(count), order.end(),
                    [&](std::size_t a, std::size_t b) {
                      return samples[a].length > samples[b].length ||
                             (samples[a].length == samples[b].length && a < b);
                    });
  Vec3 best = Vec3::Zero();
  double best_support = 0.0;
  for (std::size_t k = 0; k < count; ++k) {
    const Vec3& candidate = samples[order[k]].direction;
    const double support = AxisSupport(samples, candidate, cos_tol);
    if (support > best_support) {
      best_support = support;
      best = candidate;
    }
  }
  return best_support > 0.0 ? RefineAxis(samples, best, cos_tol) : Vec3::Zero();
}

/// The samples within the tolerance of orthogonal to `axis`, projected onto its normal plane.
std::vector<DirectionSample> OrthogonalSamples(const std::vector<DirectionSample>& samples,
                                               const Vec3& axis, double sin_tol) {
  std::vector<DirectionSample> out;
  for (const DirectionSample& s : samples) {
    const double along = s.direction.dot(axis);
    if (std::abs(along) >= sin_tol) continue;
    const Vec3 across = s.direction - along * axis;
    const double norm = across.norm();
    if (norm > 0.0) out.push_back({across / norm, s.length});
  }
  return out;
}

/// Weighted mean and standard deviation of values along an axis.
struct Spread {
  double mean = 0.0;
  double deviation = 0.0;
};

/// The spread of (value, weight) pairs; zeros when no weight.
Spread SpreadOf(const std::vector<std::pair<double, double>>& values) {
  double weight = 0.0;
  double sum = 0.0;
  for (const auto& [value, w] : values) {
    weight += w;
    sum += w * value;
  }
  Spread s;
  if (weight <= 0.0) return s;
  s.mean = sum / weight;
  double sum_sq = 0.0;
  for (const auto& [value, w] : values) sum_sq += w * (value - s.mean) * (value - s.mean);
  s.deviation = std::sqrt(sum_sq / weight);
  return s;
}

/// Per viewpoint, the number of observations that name it (its weight: a camera that sees
/// nothing says nothing about where the cameras are).
std::vector<double> ViewpointWeights(const Scene& scene) {
  std::vector<double> weight(scene.viewpoints.size(), 0.0);
  for (const ViewpointId v : scene.observations.items()) weight[v.index()] += 1.0;
  return weight;
}

/// Segment endpoints along `axis`, each weighted by half its segment's length.
std::vector<std::pair<double, double>> EndpointsAlong(const Scene& scene, const Vec3& axis) {
  std::vector<std::pair<double, double>> out;
  out.reserve(2 * scene.NumSegments());
  for (const Segment3& s : scene.segments) {
    const double half = 0.5 * s.Length();
    out.emplace_back(s.p1.dot(axis), half);
    out.emplace_back(s.p2.dot(axis), half);
  }
  return out;
}

/// The value below which `share` of the weight lies.
double WeightedQuantile(std::vector<std::pair<double, double>> values, double share) {
  std::sort(values.begin(), values.end());
  double total = 0.0;
  for (const auto& v : values) total += v.second;
  double below = 0.0;
  for (const auto& [value, weight] : values) {
    below += weight;
    if (below >= share * total) return value;
  }
  return values.empty() ? 0.0 : values.back().first;
}

/// Viewpoints along `axis`, each weighted by its observations.
std::vector<std::pair<double, double>> ViewpointsAlong(const Scene& scene,
                                                       const std::vector<double>& weight,
                                                       const Vec3& axis) {
  std::vector<std::pair<double, double>> out;
  for (std::size_t v = 0; v < weight.size(); ++v) {
    if (weight[v] > 0.0) out.emplace_back(scene.viewpoints[ViewpointId(v)].dot(axis), weight[v]);
  }
  return out;
}

/// Which of `axes` is up, and how that was told.
std::pair<int, UpEvidence> UpAxis(const Scene& scene, const std::array<Vec3, 3>& axes) {
  const std::vector<double> weight = ViewpointWeights(scene);
  if (ViewpointsAlong(scene, weight, axes[0]).empty()) {
    int nearest = 0;
    for (int k = 1; k < 3; ++k) {
      if (std::abs(axes[k].z()) > std::abs(axes[nearest].z())) nearest = k;
    }
    return {nearest, UpEvidence::kInputZ};
  }
  std::array<double, 3> view{};
  for (int k = 0; k < 3; ++k) view[k] = SpreadOf(ViewpointsAlong(scene, weight, axes[k])).deviation;
  std::array<int, 3> order{0, 1, 2};
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return view[a] < view[b]; });
  if (view[order[1]] > kSpreadRatio * view[order[0]]) {
    return {order[0], UpEvidence::kViewpointSpread};
  }
  // A straight track: the cameras hold one height and one distance from the façades; the
  // façades rise more than they recede.
  const double first = SpreadOf(EndpointsAlong(scene, axes[order[0]])).deviation;
  const double second = SpreadOf(EndpointsAlong(scene, axes[order[1]])).deviation;
  return {second > first ? order[1] : order[0], UpEvidence::kLineSpread};
}

/// The lines and the viewpoints along an axis.
struct Heights {
  std::vector<std::pair<double, double>> views;  ///< (position, observations)
  double line_low = 0.0;   ///< 5 % of the line length lies below
  double line_high = 0.0;  ///< 95 % of the line length lies below
  double eye = 0.0;        ///< the median viewpoint
};

/// Heights along `axis`; nullopt without a viewpoint.
std::optional<Heights> HeightsAlong(const Scene& scene, const Vec3& axis) {
  Heights h;
  h.views = ViewpointsAlong(scene, ViewpointWeights(scene), axis);
  if (h.views.empty()) return std::nullopt;
  const std::vector<std::pair<double, double>> lines = EndpointsAlong(scene, axis);
  h.line_low = WeightedQuantile(lines, 0.05);
  h.line_high = WeightedQuantile(lines, 0.95);
  h.eye = WeightedQuantile(h.views, 0.5);
  return h;
}

/// +1 or -1: the sign that makes `axis` point up, and why. Nobody films a building from under
/// the ground: cameras beyond the lines look down on them; cameras among the lines stand on the
/// ground, so the end of the lines next to the nearest extreme of the cameras is the ground.
std::pair<double, std::string> UpSign(const Scene& scene, const Vec3& axis) {
  const std::optional<Heights> h = HeightsAlong(scene, axis);
  if (!h) return {1.0, "no viewpoint: the sign of the dominant axes"};
  if (h->eye > h->line_high || h->eye < h->line_low) {
    return {h->eye > h->line_high ? 1.0 : -1.0,
            "the viewpoints lie beyond 95 % of the line length: up points towards them (seen "
            "from above)"};
  }
  const double gap_low = std::abs(WeightedQuantile(h->views, 0.05) - h->line_low);
  const double gap_high = std::abs(WeightedQuantile(h->views, 0.95) - h->line_high);
  return {gap_low <= gap_high ? 1.0 : -1.0,
          "the viewpoints stand among the lines: the ground is the end of the lines nearest "
          "the lowest viewpoints"};
}

/// +1 or -1 by the third moment of the line endpoints along `axis` (a rule that turns with the
/// data; a symmetric scene gets +1).
double SkewSign(const Scene& scene, const Vec3& axis) {
  const std::vector<std::pair<double, double>> endpoints = EndpointsAlong(scene, axis);
  const double mean = SpreadOf(endpoints).mean;
  double third = 0.0;
  for (const auto& [value, weight] : endpoints) third += weight * std::pow(value - mean, 3);
  return third >= 0.0 ? 1.0 : -1.0;
}

}  // namespace

const char* UpEvidenceName(UpEvidence evidence) noexcept {
  switch (evidence) {
    case UpEvidence::kNone: return "none";
    case UpEvidence::kViewpointSpread: return "viewpoint_spread";
    case UpEvidence::kLineSpread: return "line_spread";
    case UpEvidence::kInputZ: return "input_z";
  }
  return "";
}

void OrientUpInside(const Scene& scene, DataFrame& frame) {
  const std::optional<Heights> h =
      frame.found ? HeightsAlong(scene, Vec3::UnitZ()) : std::nullopt;
  if (!h) return;
  // Local +z is frame.axes' z; up is +z or -z of it.
  const double up_sign = frame.up.dot(frame.axes.col(2)) >= 0.0 ? 1.0 : -1.0;
  const double inside_sign = h->eye - h->line_low >= h->line_high - h->eye ? 1.0 : -1.0;
  frame.up_sign_reason =
      "inside a room: the cameras stand nearer the ceiling than the floor, so the floor is the "
      "end of the lines farther from the median viewpoint";
  if (inside_sign != up_sign) frame.up = -frame.up;
}

DataFrame EstimateDataFrame(const Scene& scene) {
  DataFrame frame;
  const double tolerance = kAxisToleranceDegrees * std::numbers::pi / 180.0;
  const double cos_tol = std::cos(tolerance);
  const std::vector<DirectionSample> samples = SampleDirections(scene);
  const Vec3 first = DominantAxis(samples, cos_tol);
  if (first.isZero()) return frame;
  Vec3 second = DominantAxis(OrthogonalSamples(samples, first, std::sin(tolerance)), cos_tol);
  if (second.isZero()) return frame;
  second = (second - second.dot(first) * first).normalized();
  const std::array<Vec3, 3> axes{first, second, first.cross(second).normalized()};

  const auto [up_index, evidence] = UpAxis(scene, axes);
  const auto [up_sign, reason] = UpSign(scene, axes[up_index]);
  const Vec3 up = up_sign * axes[up_index];
  // x: the horizontal axis with more line length along it.
  const int a = (up_index + 1) % 3;
  const int b = (up_index + 2) % 3;
  const bool a_first =
      AxisSupport(samples, axes[a], cos_tol) >= AxisSupport(samples, axes[b], cos_tol);
  Vec3 x = axes[a_first ? a : b];
  x *= SkewSign(scene, x);

  frame.found = true;
  frame.axes.col(0) = x;
  frame.axes.col(1) = up.cross(x);
  frame.axes.col(2) = up;
  frame.up = up;
  frame.up_evidence = evidence;
  frame.up_sign_reason = reason;
  double near = 0.0;
  double total = 0.0;
  for (const DirectionSample& s : samples) {
    total += s.length;
    const double best = std::max({std::abs(s.direction.dot(axes[0])),
                                  std::abs(s.direction.dot(axes[1])),
                                  std::abs(s.direction.dot(axes[2]))});
    if (best > cos_tol) near += s.length;
  }
  frame.axis_share = total > 0.0 ? near / total : 0.0;
  return frame;
}

}  // namespace linesurf::pipeline
