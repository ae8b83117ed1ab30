#pragma once
// Planes and their inlier segments as PolyFit / abspy vertex groups (.vg, docs/user/formats.md).

#include "linesurf/error.h"

#include "engine/core/scene.h"

#include <filesystem>

namespace linesurf::io {

/// @brief Writes the .vg subset PolyFit and abspy read: points = both endpoints of every segment
/// (segment i -> points 2i, 2i+1), world coordinates, grey colours, normals = the first plane's
/// normal (0 when none); one group per plane (type 0, parameters a b c d of ax+by+cz+d = 0)
/// listing its inliers' endpoints (a structural segment's endpoints are in both groups).
/// Written to a temporary name then renamed.
/// @return kInvalidInput when the file cannot be written or a value is not finite.
[[nodiscard]] Status WriteVertexGroups(const Scene& scene,
                                       const std::filesystem::path& path) noexcept;

}  // namespace linesurf::io
