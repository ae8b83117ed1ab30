#pragma once
// LIMAP line tracks (`alltracks.txt`, written by limap.util.io.save_txt_linetracks; format in
// docs/user/formats.md).

#include "engine/core/scene.h"
#include "engine/io/camera_centres.h"

#include <filesystem>
#include <string_view>

namespace linesurf::io {

/// Reads a LIMAP alltracks.txt: the track count on the first line, then five lines per track:
/// `track_id n_lines n_images`, the 3D start point, the 3D end point, the n_lines image ids and
/// the n_lines 2D line ids of its supporting segments. Every track becomes one scene segment
/// observed from centres[image_id] of each supporting segment (in file order; sanitation drops
/// repeated images); line ids are dropped; the file has no 2D coordinates, so no residuals.
/// Throws kInvalidInput naming the file and line.
Scene ReadLimapTracks(const std::filesystem::path& path, const CameraCentres& centres);

/// True when `text` starts like an alltracks.txt (first non-blank line: one integer), which a
/// Line3D++ line never does (it holds at least the segment and observation counts).
bool LooksLikeLimapTracks(std::string_view text);

}  // namespace linesurf::io
