#pragma once
// Reading a scene from any supported input format (docs/user/formats.md).

#include <filesystem>
#include <string>
#include <vector>

#include "linesurf/error.h"
#include "engine/core/scene.h"

namespace linesurf::io {

enum class SceneFormat {
  kAuto,           ///< from the extension (.json, .obj) and, for .txt, the first line
  kReferenceJson,  ///< the paper's reference JSON
  kLine3dpp,       ///< Line3D++ .txt with camera centres from an NVM file or a COLMAP model
  kLimapTracks,    ///< LIMAP alltracks.txt with camera centres from a COLMAP model (or NVM)
  kObjLines,       ///< OBJ `v` + `l` records: segments without views (plane detection only)
};

struct SceneReadOptions {
  /// Input format; kAuto picks it from the file extension.
  SceneFormat format = SceneFormat::kAuto;
  /// Line3D++ and LIMAP only: VisualSfM .nvm whose camera list the camera ids index (0-based).
  std::filesystem::path nvm;
  /// Line3D++ and LIMAP only: COLMAP model directory, text or binary (or its images.txt /
  /// images.bin); camera ids are IMAGE_IDs.
  std::filesystem::path colmap;

  /// Line3D++ and LIMAP need exactly one of `nvm` and `colmap`; other formats take neither.
  [[nodiscard]] Status Validate(SceneFormat resolved) const;
};

/// A scene plus what the reader fixed or ignored on the way.
struct SceneReadResult {
  Scene scene;
  std::vector<std::string> warnings;
};

/// The format `options` ask for, or the one the extension of `path` names (kAuto when unknown);
/// a .txt is LIMAP tracks when its first non-blank line is a single integer, else Line3D++.
[[nodiscard]] SceneFormat ResolveSceneFormat(const std::filesystem::path& path,
                                             const SceneReadOptions& options);

/// @brief Reads a scene in world coordinates (world_from_local identity; sanitation recentres).
/// @return kInvalidOptions for an unknown format or missing/extra camera files; kInvalidInput
/// naming the file and line/JSON path for malformed input.
[[nodiscard]] Expected<SceneReadResult> ReadSceneWithWarnings(
    const std::filesystem::path& path, const SceneReadOptions& options) noexcept;

/// ReadSceneWithWarnings without the warnings.
[[nodiscard]] Expected<Scene> ReadScene(const std::filesystem::path& path,
                                        const SceneReadOptions& options) noexcept;

}  // namespace linesurf::io
