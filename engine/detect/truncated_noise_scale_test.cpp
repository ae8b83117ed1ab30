#include "engine/detect/truncated_noise_scale.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "engine/core/rng.h"

namespace linesurf::detect {
namespace {

/// Endpoint distances |N(0, sigma^2)| of `count` lines, the pairs a mean-distance test at
/// `tolerance` keeps.
std::vector<EndpointDistances> AcceptedPairs(double sigma, double tolerance, int count) {
  Rng rng(17);
  std::vector<EndpointDistances> out;
  for (int i = 0; i < count; ++i) {
    const EndpointDistances p{.first = std::abs(sigma * rng.Normal()),
                              .second = std::abs(sigma * rng.Normal())};
    if (0.5 * (p.first + p.second) <= tolerance) out.push_back(p);
  }
  return out;
}

TEST(MeanDistancePassRate, MatchesMonteCarloValues) {
  // 2M draws of (|X1| + |X2|) / 2 <= c: 0.0764, 0.2709, 0.7105, 0.9907.
  EXPECT_NEAR(MeanDistancePassRate(0.25), 0.0764, 1e-3);
  EXPECT_NEAR(MeanDistancePassRate(0.5), 0.2709, 1e-3);
  EXPECT_NEAR(MeanDistancePassRate(1.0), 0.7105, 1e-3);
  EXPECT_NEAR(MeanDistancePassRate(2.0), 0.9907, 1e-3);
  EXPECT_NEAR(MeanDistancePassRate(40.0), 1.0, 1e-9);
  EXPECT_EQ(MeanDistancePassRate(0.0), 0.0);
}

TEST(TruncatedNoiseScale, RecoversTheNoiseWhateverTheTolerance) {
  // The median of the kept distances follows the tolerance (x 1.4826 it gives 0.42 sigma at a
  // tolerance of half a sigma); the truncated likelihood does not.
  for (const double tolerance : {0.5, 1.0, 2.5, 6.0}) {
    const std::vector<EndpointDistances> pairs = AcceptedPairs(0.03, 0.03 * tolerance, 40000);
    const TruncatedScale s = TruncatedNoiseScale(pairs, 0.03 * tolerance);
    EXPECT_EQ(s.pairs, pairs.size());
    // The sample thins as the tolerance falls (27 % of the pairs pass at half a sigma).
    const double within = tolerance < 1.0 ? 0.1 : 0.05;
    EXPECT_NEAR(s.sigma, 0.03, 0.03 * within) << "tolerance " << tolerance << " sigma";
  }
}

TEST(TruncatedNoiseScale, IgnoresPairsBeyondTheTestAndIsScaleFree) {
  std::vector<EndpointDistances> pairs = AcceptedPairs(1.0, 1.5, 20000);
  const TruncatedScale base = TruncatedNoiseScale(pairs, 1.5);
  pairs.push_back({.first = 5.0, .second = 4.0});  // fails the test at 1.5
  const TruncatedScale with_far = TruncatedNoiseScale(pairs, 1.5);
  EXPECT_EQ(with_far.pairs, base.pairs);
  EXPECT_DOUBLE_EQ(with_far.sigma, base.sigma);
  std::vector<EndpointDistances> scaled;
  for (const EndpointDistances& p : pairs) {
    scaled.push_back({.first = 37.1 * p.first, .second = 37.1 * p.second});
  }
  EXPECT_NEAR(TruncatedNoiseScale(scaled, 37.1 * 1.5).sigma, 37.1 * base.sigma,
              1e-9 * 37.1 * base.sigma);
}

TEST(TruncatedNoiseScale, ExactDataGivesTheLowerBoundAndNoDataNothing) {
  const std::vector<EndpointDistances> exact(100, EndpointDistances{});
  EXPECT_NEAR(TruncatedNoiseScale(exact, 0.02).sigma, 0.02 / 64.0, 1e-9);
  EXPECT_EQ(TruncatedNoiseScale({}, 0.02).sigma, 0.0);
  EXPECT_EQ(TruncatedNoiseScale(exact, 0.0).pairs, 0u);
}

}  // namespace
}  // namespace linesurf::detect
