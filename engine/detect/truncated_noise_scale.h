#pragma once
/// @file truncated_noise_scale.h
/// @brief The noise scale of segments that a detection accepted at tolerance T (eps auto,
/// docs/design/plane_detection.md). A probe keeps a line on a plane only where the mean of its
/// two endpoint distances is <= T, so its residuals are a truncated sample: their median or
/// spread says as much about T as about the noise (flat residuals up to T give a scale
/// proportional to T, and eps taken from it runs away). The maximum-likelihood scale of
/// the Gaussian truncated exactly as the test truncates recovers the noise from a probe whose T
/// is anywhere above about half of it.

#include <cstddef>
#include <span>

namespace linesurf::detect {

/// The two endpoint distances of one line to one plane.
struct EndpointDistances {
  double first = 0.0;
  double second = 0.0;
};

struct TruncatedScale {
  double sigma = 0.0;      ///< 0 when no pair passes the test or the tolerance is not > 0
  std::size_t pairs = 0;   ///< pairs that pass the test (the sample)
};

/// @brief sigma maximising the likelihood of the pairs with (first + second) / 2 <= tolerance
/// under endpoint distances |N(0, sigma^2)| conditioned on that test; pairs beyond it are
/// ignored. Searched over [tolerance / 64, 64 x tolerance] (a bound is returned when the
/// maximum lies beyond: exact data gives the lower one). Deterministic.
[[nodiscard]] TruncatedScale TruncatedNoiseScale(std::span<const EndpointDistances> pairs,
                                                 double tolerance) noexcept;

/// @brief P((|X1| + |X2|) / 2 <= c) for independent X1, X2 ~ N(0, 1): the share of a line's
/// endpoint pairs that pass a mean-distance test at c noise scales.
[[nodiscard]] double MeanDistancePassRate(double c) noexcept;

}  // namespace linesurf::detect
