#pragma once
// The engine's results as the facade's plain result structs (linesurf/result.h).

#include "linesurf/result.h"

#include "engine/detect/detect_planes.h"
#include "engine/pipeline/reconstruct.h"
#include "engine/pipeline/sanitize_scene.h"

namespace linesurf::api {

[[nodiscard]] ReconstructResult ToPublicResult(const pipeline::ReconstructResult& result);

/// Planes detected on the sanitised scene of `sane`, in world coordinates; memberships index the
/// input segments.
[[nodiscard]] DetectResult ToPublicResult(const PlaneDetectionResult& detected,
                                          const pipeline::SanitizeResult& sane);

}  // namespace linesurf::api
