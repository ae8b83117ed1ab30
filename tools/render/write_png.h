#pragma once
/// @file write_png.h
/// @brief Writes an Image as an 8-bit RGB PNG (libpng), byte-identical for identical images.

#include <filesystem>

#include "linesurf/error.h"
#include "tools/render/render_image.h"

namespace linesurf {

/// Writes `image` to `path` (no timestamp chunk, fixed compression settings).
Status WritePng(const Image& image, const std::filesystem::path& path) noexcept;

}  // namespace linesurf
