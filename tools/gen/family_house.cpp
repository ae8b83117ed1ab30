// "house": a 10 x 8 m box with 6 m walls and a gable roof (ridge along x, 3 m rise), door and
// windows as texture lines, two exterior rings of viewpoints.

#include <cmath>
#include <numbers>

#include "tools/gen/family_layout.h"

namespace linesurf::synth {
namespace {

constexpr double kHalfWidth = 5.0;   // x
constexpr double kHalfDepth = 4.0;   // y
constexpr double kWallHeight = 6.0;
constexpr double kRoofRise = 3.0;
constexpr double kHouseStorey = 3.0;
constexpr int kGroundRingViews = 16;
constexpr double kGroundRingRadius = 18.0;
constexpr double kHouseEyeHeight = 1.6;
constexpr int kHighRingViews = 12;
constexpr double kHighRingRadius = 22.0;
constexpr double kHighRingHeight = 12.0;
constexpr double kHouseOutlierMargin = 1.0;

}  // namespace

void AddViewRing(FamilyLayout& layout, int count, double radius, double height) {
  for (int i = 0; i < count; ++i) {
    const double a = 2.0 * std::numbers::pi * (i + 0.5) / count;
    layout.viewpoints.emplace_back(radius * std::cos(a), radius * std::sin(a), height);
  }
}

FamilyLayout HouseLayout(const SynthSpec& /*spec*/) {
  FamilyLayout layout;
  const double w = kHalfWidth;
  const double d = kHalfDepth;
  const double h = kWallHeight;
  // Gable profile in the plane x = -w, counter-clockwise around +x, swept along +x.
  const Vec3 profile[5] = {{-w, -d, 0}, {-w, d, 0}, {-w, d, h}, {-w, 0, h + kRoofRise}, {-w, -d, h}};
  layout.solid.AddPrism(profile, Vec3(2 * w, 0, 0));
  layout.volume = (2 * w) * (2 * d) * h + 0.5 * (2 * d) * kRoofRise * (2 * w);

  AddFacadeTexture(layout, layout.solid.components().back(), kHouseStorey);
  // Door (three sides; its sill is the wall's bottom edge) on the south wall.
  const Vec3 south(0, -1, 0);
  AddTextureLine(layout, {-0.45, -d, 0}, {-0.45, -d, 2.1}, south);
  AddTextureLine(layout, {-0.45, -d, 2.1}, {0.45, -d, 2.1}, south);
  AddTextureLine(layout, {0.45, -d, 2.1}, {0.45, -d, 0}, south);
  // Upper-floor windows on both long walls.
  for (double x : {-3.0, 0.0, 3.0}) {
    AddTextureRectangle(layout, {x - 0.5, -d, 3.6}, {1.0, 0, 0}, {0, 0, 1.2}, south);
    AddTextureRectangle(layout, {x + 0.5, d, 3.6}, {-1.0, 0, 0}, {0, 0, 1.2}, Vec3(0, 1, 0));
  }
  // Tile rows on both roof slopes, parallel to the ridge.
  for (double side : {-1.0, 1.0}) {
    const Vec3 outward = Vec3(0, side * kRoofRise, d).normalized();
    for (double f : {1.0 / 3.0, 2.0 / 3.0}) {
      const double y = side * d * (1.0 - f);
      const double z = h + kRoofRise * f;
      AddTextureLine(layout, {-w + 0.3, y, z}, {w - 0.3, y, z}, outward);
    }
  }

  AddViewRing(layout, kGroundRingViews, kGroundRingRadius, kHouseEyeHeight);
  AddViewRing(layout, kHighRingViews, kHighRingRadius, kHighRingHeight);
  layout.outliers.box.Extend(Vec3(-w - kHouseOutlierMargin, -d - kHouseOutlierMargin, 0));
  layout.outliers.box.Extend(
      Vec3(w + kHouseOutlierMargin, d + kHouseOutlierMargin, h + kRoofRise + kHouseOutlierMargin));
  return layout;
}

}  // namespace linesurf::synth
