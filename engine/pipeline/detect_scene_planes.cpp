#include "engine/pipeline/detect_scene_planes.h"

#include "engine/core/exception.h"

#include <utility>

namespace linesurf::pipeline {
namespace {

constexpr const char* kStage = "detect_scene_planes";

/// Unwraps a stage result or rethrows its error unchanged.
template <typename T>
T Take(Expected<T>&& e) {
  if (!e) throw LinesurfException(e.error());
  return std::move(e.value());
}

}  // namespace

Expected<DetectedScene> SanitizeAndDetectPlanes(Scene scene,
                                                const SanitizeOptions& sanitize,
                                                const PlaneDetectionOptions& detect,
                                                const RunContext& ctx,
                                                StageTimer* timer) noexcept {
  return CatchAll(kStage, [&]() -> DetectedScene {
    DetectedScene out;
    if (timer != nullptr) timer->Start("sanitize");
    out.given_planes = scene.planes.size();
    scene.planes.clear();
    scene.memberships.clear();
    SanitizeResult sane = Take(SanitizeScene(std::move(scene), sanitize));
    out.scene = std::move(sane.scene);
    out.input_segment = std::move(sane.input_segment);
    out.sanitize_stats = sane.stats;
    out.warnings = std::move(sane.warnings);
    ctx.ThrowIfCancelled(kStage);

    if (timer != nullptr) timer->Start("detect");
    PlaneDetectionResult detected = Take(DetectPlanes(out.scene, detect, ctx));
    out.scene.planes = std::move(detected.planes);
    out.scene.memberships = std::move(detected.memberships);
    out.support = std::move(detected.support);
    out.detection_stats = detected.stats;
    return out;
  });
}

}  // namespace linesurf::pipeline
