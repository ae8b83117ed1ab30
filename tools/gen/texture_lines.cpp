// Texture-line helpers shared by the families (windows, doors, floor bands).

#include <algorithm>
#include <cmath>
#include <limits>

#include "engine/core/exception.h"
#include "tools/gen/family_layout.h"

namespace linesurf::synth {
namespace {

/// A vertex is on the ground when |z| is below this (metres).
constexpr double kGroundTolerance = 1e-9;
/// A face is vertical when |outward.z| is below this.
constexpr double kVerticalTolerance = 1e-9;
/// Facade texture: window size, sill height, spacing and margins (metres).
constexpr double kWindowWidth = 1.2;
constexpr double kWindowHeight = 1.3;
constexpr double kWindowSill = 1.0;
constexpr double kWindowSpacing = 3.5;
constexpr double kFacadeMargin = 0.3;

}  // namespace

void AddTextureLine(FamilyLayout& layout, const Vec3& a, const Vec3& b, const Vec3& outward) {
  TrueLine line;
  line.segment = Segment3{a, b};
  line.kind = SegmentKind::kTextural;
  const PlaneId plane = layout.solid.FindPlane(outward, a);
  LINESURF_ASSERT(plane.IsValid());  // texture lines lie on faces of the solid
  line.planes.Add(plane);
  line.outward[0] = outward;
  layout.texture_lines.push_back(line);
}

void AddTextureRectangle(FamilyLayout& layout, const Vec3& corner, const Vec3& u, const Vec3& v,
                         const Vec3& outward) {
  const Vec3 p[4] = {corner, corner + u, corner + u + v, corner + v};
  for (int i = 0; i < 4; ++i) AddTextureLine(layout, p[i], p[(i + 1) % 4], outward);
}

void AddFacadeTexture(FamilyLayout& layout, const SolidComponent& component, double storey) {
  for (const SolidFace& f : component.faces) {
    if (std::abs(f.outward.z()) > kVerticalTolerance) continue;
    // The bottom edge: consecutive vertices on the ground; the eave: lowest non-ground vertex.
    std::size_t n = f.vertices.size();
    const Vec3* a = nullptr;
    const Vec3* b = nullptr;
    double top = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < n; ++i) {
      const Vec3& p = component.vertices[f.vertices[i]];
      const Vec3& q = component.vertices[f.vertices[(i + 1) % n]];
      if (std::abs(p.z()) <= kGroundTolerance && std::abs(q.z()) <= kGroundTolerance) {
        a = &p;
        b = &q;
      }
      if (std::abs(p.z()) > kGroundTolerance) top = std::min(top, p.z());
    }
    if (a == nullptr || !std::isfinite(top)) continue;
    const double length = (*b - *a).norm();
    if (length < 2.0 * kFacadeMargin + kWindowWidth) continue;
    const Vec3 along = (*b - *a) / length;
    const Vec3 up = Vec3::UnitZ();
    for (double z = storey; z < top - kFacadeMargin; z += storey) {
      AddTextureLine(layout, *a + along * kFacadeMargin + up * z,
                     *b - along * kFacadeMargin + up * z, f.outward);
    }
    if (kWindowSill + kWindowHeight >= std::min(storey, top) - kFacadeMargin) continue;
    const int windows = static_cast<int>(std::floor((length - 2.0 * kFacadeMargin) / kWindowSpacing));
    if (windows < 1) continue;
    const double start = 0.5 * (length - (windows - 1) * kWindowSpacing) - 0.5 * kWindowWidth;
    for (int w = 0; w < windows; ++w) {
      const Vec3 corner = *a + along * (start + w * kWindowSpacing) + up * kWindowSill;
      AddTextureRectangle(layout, corner, along * kWindowWidth, up * kWindowHeight, f.outward);
    }
  }
}

}  // namespace linesurf::synth
