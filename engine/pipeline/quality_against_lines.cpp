#include "engine/pipeline/quality_against_lines.h"

#include "engine/core/exception.h"
#include "engine/detect/estimate_epsilon.h"
#include "engine/pipeline/sanitize_scene.h"

#include <utility>

namespace linesurf::pipeline {

Expected<SurfaceQuality> MeasureQualityAgainstLines(const PolygonMesh& mesh,
                                                    Scene lines,
                                                    const PlaneDetectionOptions& detection,
                                                    const RunContext& ctx) noexcept {
  return CatchAll("quality_against_lines", [&] {
    const bool given = !lines.planes.empty() && lines.HasMemberships();
    Scene scene = ValueOrThrow(SanitizeScene(std::move(lines), {})).scene;
    if (!given) {
      scene.planes.clear();
      scene.memberships.clear();
      PlaneDetectionResult detected = ValueOrThrow(DetectPlanes(scene, detection, ctx));
      scene.planes = std::move(detected.planes);
      scene.memberships = std::move(detected.memberships);
    }
    const EpsilonEstimate eps = ValueOrThrow(ResolveEpsilon(scene, detection, ctx));
    PolygonMesh local = mesh;
    for (Vec3& v : local.vertices) v = scene.world_from_local.ApplyInverse(v);
    return ValueOrThrow(MeasureSurfaceQuality(local, scene, eps.epsilon, {}, ctx));
  });
}

}  // namespace linesurf::pipeline
