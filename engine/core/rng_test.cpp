#include "engine/core/rng.h"

#include <gtest/gtest.h>

namespace linesurf {
namespace {

TEST(Rng, SameSeedSameStream) {
  Rng a(MixSeed(7, RngStage::kDetect, 3));
  Rng b(MixSeed(7, RngStage::kDetect, 3));
  for (int i = 0; i < 100; ++i) EXPECT_EQ(a.NextU64(), b.NextU64());
}

TEST(Rng, StreamsDiffer) {
  Rng a(MixSeed(7, RngStage::kDetect, 3));
  Rng b(MixSeed(7, RngStage::kDetect, 4));
  EXPECT_NE(a.NextU64(), b.NextU64());
}

TEST(Rng, UniformAndBelowInRange) {
  Rng r(1);
  double sum = 0.0;
  for (int i = 0; i < 10000; ++i) {
    const double u = r.Uniform();
    ASSERT_GE(u, 0.0);
    ASSERT_LT(u, 1.0);
    sum += u;
    ASSERT_LT(r.Below(7), 7u);
  }
  EXPECT_NEAR(sum / 10000.0, 0.5, 0.02);
}

TEST(Rng, NormalHasUnitVariance) {
  Rng r(2);
  double s = 0.0, s2 = 0.0;
  const int n = 20000;
  for (int i = 0; i < n; ++i) {
    const double x = r.Normal();
    s += x;
    s2 += x * x;
  }
  EXPECT_NEAR(s / n, 0.0, 0.03);
  EXPECT_NEAR(s2 / n, 1.0, 0.05);
}

}  // namespace
}  // namespace linesurf
