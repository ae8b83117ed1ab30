#include "engine/pipeline/detect_scene_planes.h"

#include "engine/core/exception.h"

#include <utility>

namespace linesurf::pipeline {
namespace {

constexpr const char* kDetectScenePlanesStage = "detect_scene_planes";

}  // namespace

Expected<DetectedScene> SanitizeAndDetectPlanes(
    Scene scene,
    const SanitizeOptions& sanitize,
    const PlaneDetectionOptions& detect,
    const RunContext& ctx,
    StageTimer* timer,
    const partition::BlockSizeRule* auto_blocks,
    detect::DetectionRunner* runner) noexcept {
  return CatchAll(kDetectScenePlanesStage, [&]() -> DetectedScene {
    DetectedScene out;
    if (timer != nullptr) timer->Start("sanitize");
    out.given_planes = scene.planes.size();
    scene.planes.clear();
    scene.memberships.clear();
    SanitizeResult sane = ValueOrThrow(SanitizeScene(std::move(scene), sanitize));
    out.scene = std::move(sane.scene);
    out.input_segment = std::move(sane.input_segment);
    out.sanitize_stats = sane.stats;
    out.frame = std::move(sane.frame);
    out.warnings = std::move(sane.warnings);
    ctx.ThrowIfCancelled(kDetectScenePlanesStage);

    if (timer != nullptr) timer->Start("detect");
    PlaneDetectionOptions options = detect;
    if (auto_blocks != nullptr && options.block_size == 0.0) {
      const std::span<const Segment3> segments = out.scene.segments.raw();
      Box3 box;
      for (const Segment3& s : segments) {
        box.Extend(s.p1);
        box.Extend(s.p2);
      }
      // A box flat on some axis (one segment, lines in one axis plane) has no block grid: the
      // detection runs as one block.
      if ((box.Extent().array() > 0.0).all()) {
        const partition::BlockSizeChoice choice =
            ValueOrThrow(partition::ChooseBlockSize(segments, box, *auto_blocks));
        // One block is the whole scene: keep the monolithic detection (its exact result).
        if (!choice.whole_scene) options.block_size = choice.block_size;
      }
    }
    out.detection_block_size = options.block_size;
    PlaneDetectionResult detected = ValueOrThrow(DetectPlanes(out.scene, options, ctx, runner));
    out.scene.planes = std::move(detected.planes);
    out.scene.memberships = std::move(detected.memberships);
    out.support = std::move(detected.support);
    out.detection_stats = detected.stats;
    return out;
  });
}

}  // namespace linesurf::pipeline
