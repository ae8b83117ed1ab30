// "lshape": an L-shaped building, 16 x 12 m with a 7 x 5 m notch, flat roof at 7 m, facade
// texture on every wall, the house's two exterior rings of viewpoints (radius 20 and 25 m).

#include "tools/gen/family_layout.h"

namespace linesurf::synth {
namespace {

constexpr double kWidth = 16.0;  // x
constexpr double kDepth = 12.0;  // y
constexpr double kNotchWidth = 7.0;
constexpr double kNotchDepth = 5.0;
constexpr double kHeight = 7.0;
constexpr double kLshapeStorey = 3.2;
constexpr double kLshapeEyeHeight = 1.6;
constexpr double kLshapeOutlierMargin = 1.0;

}  // namespace

FamilyLayout LShapeLayout(const SynthSpec& /*spec*/) {
  FamilyLayout layout;
  // Centred on the origin; counter-clockwise from the reflex corner (star-shaped from it).
  const double x0 = -0.5 * kWidth, y0 = -0.5 * kDepth;
  const double xr = x0 + kWidth - kNotchWidth, yr = y0 + kDepth - kNotchDepth;
  const Vec3 base[6] = {{xr, yr, 0},
                        {xr, y0 + kDepth, 0},
                        {x0, y0 + kDepth, 0},
                        {x0, y0, 0},
                        {x0 + kWidth, y0, 0},
                        {x0 + kWidth, yr, 0}};
  layout.solid.AddPrism(base, Vec3(0, 0, kHeight));
  layout.volume = (kWidth * kDepth - kNotchWidth * kNotchDepth) * kHeight;
  AddFacadeTexture(layout, layout.solid.components().back(), kLshapeStorey);
  AddViewRing(layout, 16, 20.0, kLshapeEyeHeight);
  AddViewRing(layout, 12, 25.0, 14.0);
  layout.outliers.box.Extend(Vec3(x0 - kLshapeOutlierMargin, y0 - kLshapeOutlierMargin, 0));
  layout.outliers.box.Extend(Vec3(x0 + kWidth + kLshapeOutlierMargin,
                                  y0 + kDepth + kLshapeOutlierMargin,
                                  kHeight + kLshapeOutlierMargin));
  return layout;
}

}  // namespace linesurf::synth
