#pragma once
// The reference JSON scene format of the paper's public implementation (docs/user/formats.md):
// {"lines": [{"pt1", "pt2", "pt_views", "plane_index"?, "residual_per_pt_view"?}],
//  "planes"?: [{"inlier", "normal"}], other top-level string fields}.

#include <filesystem>
#include <string>
#include <vector>

#include "linesurf/error.h"
#include "engine/core/scene.h"

namespace linesurf::io {

/// A scene read from reference JSON plus what the reader fixed or ignored on the way.
struct ReferenceJsonReadResult {
  Scene scene;
  /// One line per kind of issue, e.g. "3 lines: plane_index repeats a plane (kept once)".
  std::vector<std::string> warnings;
};

/// @brief Reads a reference JSON file with a streaming (SAX) parse.
/// Coordinates stay in the file's world frame (world_from_local is the identity); viewpoints are
/// deduplicated exactly (equal coordinates share one ViewpointId, numbered in first-seen order).
/// Fails with kInvalidInput naming the file and the JSON index and field of the first problem
/// (malformed or truncated JSON, missing pt1/pt2/pt_views, wrong shapes, non-finite numbers,
/// zero-length normals, plane_index out of range). plane_index repeats and entries beyond the
/// second are dropped with a warning. A file may hold only `planes`: then 0 segments.
[[nodiscard]] Expected<ReferenceJsonReadResult> ReadReferenceJsonWithWarnings(
    const std::filesystem::path& path) noexcept;

/// ReadReferenceJsonWithWarnings without the warnings.
[[nodiscard]] Expected<Scene> ReadReferenceJson(const std::filesystem::path& path) noexcept;

/// @brief Writes `scene` as reference JSON in world coordinates (local + translation).
/// Every double is written with the shortest text that reads back to the same bits; no `null`;
/// the same scene always gives the same bytes. `plane_index` is written when the scene has
/// memberships, `planes` when it has planes or memberships, `residual_per_pt_view` when it has
/// residuals. The file is written to a temporary name and renamed, so a failure leaves no
/// partial file. Fails with kInvalidInput on non-finite values.
[[nodiscard]] Status WriteReferenceJson(const Scene& scene,
                                        const std::filesystem::path& path) noexcept;

}  // namespace linesurf::io
