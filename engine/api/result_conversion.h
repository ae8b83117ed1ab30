#pragma once
// The engine's results as the facade's plain result structs (linesurf/result.h).

#include "linesurf/result.h"

#include "engine/pipeline/detect_scene_planes.h"
#include "engine/pipeline/reconstruct.h"

namespace linesurf::api {

[[nodiscard]] ReconstructResult ToPublicResult(const pipeline::ReconstructResult& result);

/// The planes detected on the sanitised scene, in world coordinates; memberships index the
/// input segments.
[[nodiscard]] DetectResult ToPublicResult(const pipeline::DetectedScene& detected);

}  // namespace linesurf::api
