#pragma once
// The engine's results as the facade's plain result structs (linesurf/result.h).

#include "linesurf/options.h"
#include "linesurf/result.h"

#include "engine/pipeline/detect_scene_planes.h"
#include "engine/pipeline/reconstruct.h"

namespace linesurf::api {

/// The mesh, planes and memberships in the facade's types; the stats are the engine's own.
[[nodiscard]] ReconstructResult ToPublicResult(const pipeline::ReconstructResult& result);

/// The planes detected on the sanitised scene, in world coordinates; memberships index the
/// input segments; the warnings end with the plane-cap warning for `max_planes` (if any).
[[nodiscard]] DetectResult ToPublicResult(const pipeline::DetectedScene& detected,
                                          std::int32_t max_planes);

}  // namespace linesurf::api
