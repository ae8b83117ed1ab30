#pragma once
/// @file render_image.h
/// @brief A small deterministic software rasteriser for pictures of inputs and results: line
/// segments coloured by plane membership, and a polygon mesh flat-shaded with outlined facets;
/// side by side when both are given. No window or GPU.

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "linesurf/error.h"
#include "linesurf/types.h"

namespace linesurf {

/// An 8-bit RGB image, rows top to bottom.
struct Image {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgb;  ///< 3 * width * height bytes

  [[nodiscard]] std::array<std::uint8_t, 3> Pixel(int x, int y) const {
    const std::size_t i = 3 * (static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
                               static_cast<std::size_t>(x));
    return {rgb[i], rgb[i + 1], rgb[i + 2]};
  }
};

/// A perspective camera looking from `eye` at `target`, z up (y up when looking straight down).
struct Camera {
  Vector3 eye{1.0, -1.0, 1.0};
  Vector3 target{0.0, 0.0, 0.0};
};

struct RenderOptions {
  /// Size of the whole image in pixels (both panels together when lines and mesh are given);
  /// each in [16, 8192].
  int width = 800;
  int height = 600;
  /// Fixed view framing everything: "iso", "iso-back", "front", "back", "left", "right", "top".
  std::string view = "iso";
  /// When set, replaces `view` (world coordinates).
  std::optional<Camera> camera;
  /// Vertical field of view in degrees, in (1, 120).
  double fov_degrees = 35.0;
  /// Samples per pixel along each axis (anti-aliasing by box filter), in [1, 4].
  int supersample = 3;
  /// Width of drawn segments in output pixels, in (0, 16].
  double line_width = 1.5;

  [[nodiscard]] Status Validate() const;
};

/// Colours of segments by plane membership (documented in docs/user/evaluation.md).
inline constexpr std::array<std::uint8_t, 3> kColourNoPlane{150, 150, 150};
inline constexpr std::array<std::uint8_t, 3> kColourTextural{40, 100, 220};
inline constexpr std::array<std::uint8_t, 3> kColourStructural{215, 40, 40};
inline constexpr std::array<std::uint8_t, 3> kColourBackground{255, 255, 255};

/// @brief Renders `lines` (segments, coloured by their number of memberships: 0 grey, 1 blue,
/// 2 red; all grey when the scene has no memberships)
/// and/or `mesh`; lines on the left, mesh on the right when both are given, one camera framing
/// both. Deterministic (serial); O(pixels + drawn length x width + triangles' pixels).
/// @return kInvalidOptions, or kInvalidInput when neither is given or a face index is bad.
Expected<Image> RenderImage(const SceneData* lines, const Mesh* mesh,
                            const RenderOptions& options) noexcept;

}  // namespace linesurf
