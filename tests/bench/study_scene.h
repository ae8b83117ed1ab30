#pragma once
// The scene of the block studies: read and sanitised (local frame), and its box: reconstruct's
// (pipeline::SceneBox) at the default box_margin.

#include "engine/core/geometry.h"
#include "engine/core/scene.h"
#include "engine/io/read_scene.h"
#include "engine/pipeline/reconstruct.h"
#include "engine/pipeline/sanitize_scene.h"
#include "engine/pipeline/scene_box.h"

#include <cstdio>
#include <optional>
#include <string>

namespace linesurf {

/// The sanitised scene of `path`, or nullopt after printing the error to stderr.
inline std::optional<Scene> ReadStudyScene(const std::string& path) {
  Expected<Scene> read = io::ReadScene(path, {});
  if (!read) {
    std::fprintf(stderr, "%s\n", read.error().ToString().c_str());
    return std::nullopt;
  }
  Expected<pipeline::SanitizeResult> sane = pipeline::SanitizeScene(std::move(read).value(), {});
  if (!sane) {
    std::fprintf(stderr, "%s\n", sane.error().ToString().c_str());
    return std::nullopt;
  }
  return std::move(sane->scene);
}

inline Box3 StudySceneBox(const Scene& scene) {
  return pipeline::SceneBox(scene, pipeline::ReconstructOptions{}.box_margin);
}

}  // namespace linesurf
