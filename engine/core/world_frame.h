#pragma once
/// @file world_frame.h
/// @brief Local to world coordinates without touching the bits of untranslated values.

#include "engine/core/geometry.h"

namespace linesurf {

/// world = local + translation, per coordinate; a zero translation component leaves the value's
/// bits alone (x + 0.0 would turn -0.0 into +0.0 and break bit-exact round trips).
[[nodiscard]] inline Vec3 ToWorldExact(const Vec3& local, const Vec3& translation) {
  Vec3 world = local;
  for (int k = 0; k < 3; ++k) {
    if (translation[k] != 0.0) world[k] += translation[k];
  }
  return world;
}

/// A point from the local frame to world coordinates: rotated (when the frame is), then
/// translated as ToWorldExact above.
[[nodiscard]] inline Vec3 ToWorldExact(const Vec3& local, const Rigid3& world_from_local) {
  return ToWorldExact(world_from_local.Rotate(local), world_from_local.translation);
}

}  // namespace linesurf
