#include "engine/pipeline/scene_box.h"

#include <algorithm>

namespace linesurf::pipeline {

namespace {
/// An axis thinner than this share of the largest extent (a flat scene) grows as if it were
/// that thick.
constexpr double kFlatAxisShare = 0.01;
}  // namespace

Box3 SceneBox(const Scene& scene, double margin) {
  Box3 box;
  for (const Segment3& s : scene.segments) {
    box.Extend(s.p1);
    box.Extend(s.p2);
  }
  for (const Vec3& v : scene.viewpoints) box.Extend(v);
  const Vec3 extent = box.Extent();
  const double least_extent = kFlatAxisShare * extent.maxCoeff();
  for (int a = 0; a < 3; ++a) {
    const double grow = margin * std::max(extent[a], least_extent);
    box.min[a] -= grow;
    box.max[a] += grow;
  }
  return box;
}

}  // namespace linesurf::pipeline
