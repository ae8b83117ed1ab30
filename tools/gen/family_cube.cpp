// "cube": the 12 edges of a cube of side 2 centred at the origin (robustness toy of Langlois et
// al. 2019, section 4), viewpoints on a sphere of radius 6.

#include <cmath>
#include <numbers>

#include "tools/gen/family_layout.h"

namespace linesurf::synth {
namespace {

constexpr int kNumViewpoints = 32;
constexpr double kViewRadius = 6.0;
constexpr double kHalfSide = 1.0;
constexpr double kOutlierBallRadius = 2.0;

}  // namespace

FamilyLayout CubeLayout(const SynthSpec& /*spec*/) {
  FamilyLayout layout;
  const double h = kHalfSide;
  const Vec3 base[4] = {{-h, -h, -h}, {h, -h, -h}, {h, h, -h}, {-h, h, -h}};
  layout.solid.AddPrism(base, Vec3(0, 0, 2 * h));
  layout.volume = 8.0 * h * h * h;
  // Fibonacci sphere: deterministic, near-uniform, no viewpoint on a face plane.
  const double golden = std::numbers::pi * (3.0 - std::sqrt(5.0));
  for (int i = 0; i < kNumViewpoints; ++i) {
    const double z = 1.0 - 2.0 * (i + 0.5) / kNumViewpoints;
    const double r = std::sqrt(1.0 - z * z);
    layout.viewpoints.push_back(kViewRadius *
                                Vec3(r * std::cos(golden * i), r * std::sin(golden * i), z));
  }
  layout.outliers.ball = true;
  layout.outliers.radius = kOutlierBallRadius;
  layout.default_max_pieces = 1;
  layout.default_max_trim = 0.0;
  return layout;
}

}  // namespace linesurf::synth
