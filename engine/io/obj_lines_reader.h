#pragma once
// OBJ `v` / `l` records as 3D segments without views (ELSR, LIMAP exports; docs/user/formats.md).

#include <filesystem>

#include "engine/core/scene.h"

namespace linesurf::io {

/// Reads `v x y z` and `l i j [k ...]` records (1-based or negative indices, `i/t` forms
/// accepted); a polyline gives one segment per consecutive pair. Segments have no observations.
/// Other records are ignored. Throws kInvalidInput naming the file and line.
Scene ReadObjLines(const std::filesystem::path& path);

}  // namespace linesurf::io
