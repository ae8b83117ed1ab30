#pragma once
/// @file decide_scene_mode.h
/// @brief The automatic choice between an exterior scene (an object seen from outside: cells on
/// the box empty) and an interior scene (a room seen from inside: cells on the box full).
///
/// Rule (docs/reconstruction.md): a viewpoint is enclosed when each of 14 rays from it (the 6
/// axis directions and the 8 diagonals) hits some plane inside the bounding box of that plane's
/// inlier segments (grown by `support_margin_rel` of the scene diagonal). The scene is interior
/// when more than half of the observing viewpoints are enclosed. A room has walls, floor and
/// ceiling all around its cameras; a house seen from a ring of cameras, or a street seen from
/// street level, leaves open directions (away from the house, or the sky).

#include <string>

#include "engine/core/scene.h"

namespace linesurf::pipeline {

struct SceneModeDecision {
  bool interior = false;
  std::size_t enclosed_viewpoints = 0;
  std::size_t observing_viewpoints = 0;
  /// One sentence, e.g. "auto: 12 of 12 viewpoints enclosed by planes -> interior".
  std::string reason;
};

/// Decides from the planes, memberships and viewpoints of `scene` (scenes without planes or
/// memberships are exterior). Deterministic; O(viewpoints x planes).
[[nodiscard]] SceneModeDecision DecideSceneMode(const Scene& scene,
                                                double support_margin_rel = 0.02);

}  // namespace linesurf::pipeline
