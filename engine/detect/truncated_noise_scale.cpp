#include "engine/detect/truncated_noise_scale.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace linesurf::detect {
namespace {

/// The search covers [tolerance / kRange, kRange x tolerance] on a log grid, then refines.
constexpr double kRange = 64.0;
constexpr int kGridSteps = 256;
constexpr int kRefineSteps = 48;
/// Simpson intervals of MeanDistancePassRate; the half-normal density is negligible beyond
/// kDensityEnd noise scales.
constexpr int kSimpsonIntervals = 256;
constexpr double kDensityEnd = 10.0;

/// The log-likelihood per pair of sigma = exp(u) x tolerance, up to a constant: two half-normal
/// densities over the probability that a pair passes the test. In units of the tolerance, so
/// that a scene in other units gets the same search and a scale in proportion.
double LogLikelihood(double u, double mean_square_sum) {
  const double sigma = std::exp(u);
  const double pass = MeanDistancePassRate(1.0 / sigma);
  if (!(pass > 0.0)) return -INFINITY;
  return -2.0 * u - mean_square_sum / (2.0 * sigma * sigma) - std::log(pass);
}

}  // namespace

double MeanDistancePassRate(double c) noexcept {
  if (!(c > 0.0)) return 0.0;
  // P = integral over a in [0, 2c] of the half-normal density at a times P(|X2| <= 2c - a).
  const double end = std::min(2.0 * c, kDensityEnd);
  const double h = end / kSimpsonIntervals;
  const auto integrand = [c](double a) {
    return std::sqrt(2.0 / std::numbers::pi) * std::exp(-0.5 * a * a) *
           std::erf((2.0 * c - a) / std::numbers::sqrt2);
  };
  double sum = integrand(0.0) + integrand(end);
  for (int i = 1; i < kSimpsonIntervals; ++i) sum += (i % 2 == 1 ? 4.0 : 2.0) * integrand(i * h);
  return std::clamp(sum * h / 3.0, 0.0, 1.0);
}

TruncatedScale TruncatedNoiseScale(std::span<const EndpointDistances> pairs,
                                   double tolerance) noexcept {
  if (!(tolerance > 0.0)) return {};
  double square_sum = 0.0;
  std::size_t kept = 0;
  for (const EndpointDistances& p : pairs) {
    if (!(0.5 * (p.first + p.second) <= tolerance)) continue;
    const double first = p.first / tolerance;
    const double second = p.second / tolerance;
    square_sum += first * first + second * second;
    ++kept;
  }
  if (kept == 0) return {};
  const double mean_square_sum = square_sum / static_cast<double>(kept);
  const double lo = -std::log(kRange);
  const double step = 2.0 * std::log(kRange) / kGridSteps;
  int best = 0;
  double best_value = -INFINITY;
  for (int i = 0; i <= kGridSteps; ++i) {
    const double value = LogLikelihood(lo + i * step, mean_square_sum);
    if (value > best_value) {
      best_value = value;
      best = i;
    }
  }
  // Golden-section refinement inside the grid cells either side of the best grid point.
  double a = lo + std::max(best - 1, 0) * step;
  double b = lo + std::min(best + 1, kGridSteps) * step;
  const double ratio = (std::sqrt(5.0) - 1.0) / 2.0;
  for (int k = 0; k < kRefineSteps; ++k) {
    const double x1 = b - ratio * (b - a);
    const double x2 = a + ratio * (b - a);
    if (LogLikelihood(x1, mean_square_sum) >= LogLikelihood(x2, mean_square_sum)) {
      b = x2;
    } else {
      a = x1;
    }
  }
  return {.sigma = tolerance * std::exp(0.5 * (a + b)), .pairs = kept};
}

}  // namespace linesurf::detect
