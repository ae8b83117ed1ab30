#pragma once
// The facade's options (linesurf/options.h) as the engine's option structs. Fields the facade
// does not expose keep the engine's defaults.

#include "linesurf/options.h"

#include "engine/detect/detect_planes.h"
#include "engine/io/mesh_io.h"
#include "engine/io/read_scene.h"
#include "engine/pipeline/reconstruct.h"

namespace linesurf::api {

[[nodiscard]] PlaneDetectionOptions ToEngineOptions(const DetectionParameters& detection,
                                                    std::uint64_t seed);
[[nodiscard]] pipeline::ReconstructOptions ToEngineOptions(const ReconstructOptions& options);
[[nodiscard]] io::SceneReadOptions ToEngineOptions(const ReadOptions& options);
[[nodiscard]] io::MeshWriteOptions ToEngineOptions(const MeshWriteOptions& options);

}  // namespace linesurf::api
