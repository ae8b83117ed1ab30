#pragma once
// Camera centres from structure-from-motion models, keyed by the camera id Line3D++ writes:
// VisualSfM .nvm (0-based index into the camera list) and COLMAP models, text or binary
// (IMAGE_ID).

#include <cstdint>
#include <filesystem>
#include <map>

#include "engine/core/geometry.h"

namespace linesurf::io {

/// Camera id -> centre in world coordinates (ordered: deterministic iteration).
using CameraCentres = std::map<std::int64_t, Vec3>;

/// Reads the first model of a VisualSfM NVM file: header `NVM_V3` (optionally followed by
/// `FixedK fx cx fy cy [r]` on the same line), the camera count, then one line per camera
/// `<name> <focal> <qw> <qx> <qy> <qz> <cx> <cy> <cz> <radial> 0`; the centre is stored on the
/// line. Key = 0-based camera index. Throws kInvalidInput naming the file and line.
CameraCentres ReadNvmCameraCentres(const std::filesystem::path& path);

/// Reads the registered images of a COLMAP model, text or binary. `path` is the model directory
/// (images.bin when present, else images.txt) or one of those files. Text: after `#` comments,
/// two lines per image, `IMAGE_ID QW QX QY QZ TX TY TZ CAMERA_ID NAME` and the 2D points line
/// (skipped, may be empty). Binary: COLMAP's little-endian images.bin record layout. Centre =
/// -R(q)^T t. Key = IMAGE_ID (not CAMERA_ID, which several images share). When cameras.txt /
/// cameras.bin of the same kind sits beside the images file, every image's CAMERA_ID must be in
/// it. Throws kInvalidInput naming the file and line (text) or image index and byte (binary).
CameraCentres ReadColmapCameraCentres(const std::filesystem::path& path);

}  // namespace linesurf::io
