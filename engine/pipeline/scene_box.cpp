#include "engine/pipeline/scene_box.h"

#include <algorithm>

namespace linesurf::pipeline {

Box3 SceneBox(const Scene& scene, double margin) {
  Box3 box;
  for (const Segment3& s : scene.segments) {
    box.Extend(s.p1);
    box.Extend(s.p2);
  }
  for (const Vec3& v : scene.viewpoints) box.Extend(v);
  const Vec3 extent = box.Extent();
  const double floor = margin * extent.norm();
  for (int a = 0; a < 3; ++a) {
    const double grow = std::max(margin * extent[a], floor);
    box.min[a] -= grow;
    box.max[a] += grow;
  }
  return box;
}

}  // namespace linesurf::pipeline
