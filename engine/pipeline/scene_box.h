#pragma once
// The box a reconstruction works in: the bounding box of the segments and viewpoints, grown.

#include "engine/core/geometry.h"
#include "engine/core/scene.h"

namespace linesurf::pipeline {

/// The bounding box of the segments and viewpoints grown on each side by `margin` times its
/// extent along that axis, and at least `margin` times its diagonal (so that a flat scene still
/// gets a box with room around it). `margin` > 0.
[[nodiscard]] Box3 SceneBox(const Scene& scene, double margin);

}  // namespace linesurf::pipeline
