#pragma once
// The scene of the block studies: read and sanitised (local frame), and its box: the box of the
// segments and viewpoints grown by 5 % of each extent on every side (the reconstruct default
// box_margin).

#include "engine/core/geometry.h"
#include "engine/core/scene.h"
#include "engine/io/read_scene.h"
#include "engine/pipeline/sanitize_scene.h"

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
  Box3 box;
  for (const Segment3& s : scene.segments) {
    box.Extend(s.p1);
    box.Extend(s.p2);
  }
  for (const Vec3& v : scene.viewpoints) box.Extend(v);
  const Vec3 grow = 0.05 * box.Extent();
  box.min -= grow;
  box.max += grow;
  return box;
}

}  // namespace linesurf
