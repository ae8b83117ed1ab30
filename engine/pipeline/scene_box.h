#pragma once
// The box a reconstruction works in: the bounding box of the segments and viewpoints, grown.

#include "engine/core/geometry.h"
#include "engine/core/scene.h"

namespace linesurf::pipeline {

/// The bounding box of the segments and viewpoints grown on each side by `margin` times its
/// extent along that axis (the reference's rule); an axis thinner than 1 % of the largest extent
/// grows as if it were that thick, so that a flat scene still gets a box with room around it.
/// The growth of an axis depends on the other axes only when it is that thin, so a city twice as
/// wide gets no more empty air above it (docs/design/reconstruction.md, "Box"). `margin` > 0; a scene
/// whose points all coincide gets a box of no size, a scene without points an empty box.
[[nodiscard]] Box3 SceneBox(const Scene& scene, double margin);

}  // namespace linesurf::pipeline
