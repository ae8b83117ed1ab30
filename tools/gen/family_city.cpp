// "city": N buildings on a grid of 30 m lots separated by streets; rectangular footprints with
// flat or gable roofs and L-shaped footprints with flat roofs, heights 6..30 m; viewpoints along
// the street axes at eye height and high above every crossing.

#include <algorithm>
#include <cmath>
#include <vector>

#include "tools/gen/family_layout.h"

namespace linesurf::synth {
namespace {

constexpr double kLot = 30.0;         // lot pitch (street axis to street axis)
constexpr double kSetback = 5.0;      // street axis to the buildable area
constexpr double kCityStorey = 3.2;
constexpr double kMinFlatHeight = 6.0;
constexpr double kMaxFlatHeight = 30.0;
constexpr double kStreetViewSpacing = 10.0;
constexpr double kCityEyeHeight = 1.6;
constexpr double kHighViewHeight = 40.0;
constexpr double kMaxViewDistance = 60.0;
/// Building type shares: rectangle flat, rectangle gable, L-shape flat.
constexpr double kShareFlat = 0.45;
constexpr double kShareGable = 0.30;

/// A rectangle [0,w]x[0,d] with the corner [w-nw,w]x[d-nd,d] removed, counter-clockwise from the
/// reflex vertex (the polygon is star-shaped from it).
std::vector<Vec3> LFootprint(double w, double d, double nw, double nd) {
  return {{w - nw, d - nd, 0}, {w - nw, d, 0}, {0, d, 0}, {0, 0, 0}, {w, 0, 0}, {w, d - nd, 0}};
}

}  // namespace

FamilyLayout CityLayout(const SynthSpec& spec) {
  FamilyLayout layout;
  layout.max_view_distance = kMaxViewDistance;
  const int n = CityBuildingCount(spec);
  const int cols = static_cast<int>(std::ceil(std::sqrt(static_cast<double>(n))));
  const int rows = (n + cols - 1) / cols;
  const double buildable = kLot - 2.0 * kSetback;
  for (int b = 0; b < n; ++b) {
    Rng rng = StreamRng(spec.seed, SynthStream::kLayout, static_cast<std::uint64_t>(b));
    const double lot_x = (b % cols) * kLot + kSetback;
    const double lot_y = (b / cols) * kLot + kSetback;
    const double type = rng.Uniform();
    if (type < kShareFlat + kShareGable) {
      const double w = rng.Uniform(8.0, buildable);
      const double d = rng.Uniform(8.0, buildable);
      const double x0 = lot_x + rng.Uniform(0.0, buildable - w);
      const double y0 = lot_y + rng.Uniform(0.0, buildable - d);
      if (type < kShareFlat) {
        const double h = rng.Uniform(kMinFlatHeight, kMaxFlatHeight);
        const Vec3 base[4] = {{x0, y0, 0}, {x0 + w, y0, 0}, {x0 + w, y0 + d, 0}, {x0, y0 + d, 0}};
        layout.solid.AddPrism(base, Vec3(0, 0, h));
        layout.volume += w * d * h;
      } else {
        const double h = rng.Uniform(5.0, 12.0);
        const double r = rng.Uniform(2.0, 5.0);
        if (w >= d) {  // ridge along x: profile in the plane x = x0, counter-clockwise around +x
          const double ym = y0 + 0.5 * d;
          const Vec3 profile[5] = {{x0, y0, 0}, {x0, y0 + d, 0}, {x0, y0 + d, h}, {x0, ym, h + r}, {x0, y0, h}};
          layout.solid.AddPrism(profile, Vec3(w, 0, 0));
        } else {  // ridge along y: profile in the plane y = y0, counter-clockwise around +y
          const double xm = x0 + 0.5 * w;
          const Vec3 profile[5] = {{x0 + w, y0, 0}, {x0, y0, 0}, {x0, y0, h}, {xm, y0, h + r}, {x0 + w, y0, h}};
          layout.solid.AddPrism(profile, Vec3(0, d, 0));
        }
        layout.volume += w * d * h + 0.5 * std::min(w, d) * r * std::max(w, d);
      }
    } else {
      const double w = rng.Uniform(12.0, buildable);
      const double d = rng.Uniform(12.0, buildable);
      const double nw = w * rng.Uniform(0.35, 0.65);
      const double nd = d * rng.Uniform(0.35, 0.65);
      const auto turns = rng.Below(4);
      const double h = rng.Uniform(kMinFlatHeight, kMaxFlatHeight);
      std::vector<Vec3> base = LFootprint(w, d, nw, nd);
      for (std::uint64_t t = 0; t < turns; ++t) {
        for (Vec3& p : base) p = Vec3(-p.y(), p.x(), 0);  // +90 degrees: orientation kept
      }
      Vec3 lo = base[0];
      for (const Vec3& p : base) lo = lo.cwiseMin(p);
      const double span_x = (turns % 2 == 0) ? w : d;
      const double span_y = (turns % 2 == 0) ? d : w;
      // y before x: the order g++ evaluated the constructor's arguments in, which keeps its
      // cities (C++ leaves that order unspecified, clang went the other way).
      const double offset_y = rng.Uniform(0.0, buildable - span_y);
      const double offset_x = rng.Uniform(0.0, buildable - span_x);
      const Vec3 shift(lot_x + offset_x - lo.x(), lot_y + offset_y - lo.y(), 0);
      for (Vec3& p : base) p += shift;
      layout.solid.AddPrism(base, Vec3(0, 0, h));
      layout.volume += (w * d - nw * nd) * h;
    }
    AddFacadeTexture(layout, layout.solid.components().back(), kCityStorey);
  }

  // Viewpoints along the street axes x = i * kLot and y = j * kLot, and high above crossings.
  const int steps_per_lot = static_cast<int>(std::lround(kLot / kStreetViewSpacing));
  for (int i = 0; i <= cols; ++i) {
    for (int s = 0; s <= rows * steps_per_lot; ++s) {
      layout.viewpoints.emplace_back(i * kLot, s * kStreetViewSpacing, kCityEyeHeight);
    }
  }
  for (int j = 0; j <= rows; ++j) {
    for (int s = 0; s <= cols * steps_per_lot; ++s) {
      if (s % steps_per_lot == 0) continue;  // crossings are already listed
      layout.viewpoints.emplace_back(s * kStreetViewSpacing, j * kLot, kCityEyeHeight);
    }
  }
  for (int j = 0; j <= rows; ++j) {
    for (int i = 0; i <= cols; ++i) layout.viewpoints.emplace_back(i * kLot, j * kLot, kHighViewHeight);
  }
  layout.outliers.box.Extend(Vec3(0, 0, 0));
  layout.outliers.box.Extend(Vec3(cols * kLot, rows * kLot, kMaxFlatHeight));
  return layout;
}

}  // namespace linesurf::synth
