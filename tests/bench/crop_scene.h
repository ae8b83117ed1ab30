#pragma once
// A crop of a scene for the studies (tests/bench): the segments inside a box.

#include "engine/core/scene.h"

#include <vector>

namespace linesurf::bench {

// The segments with both ends in [lo, hi] and the planes that keep a member.
inline Scene CropScene(const Scene& scene, const Vec3& lo, const Vec3& hi) {
  auto inside = [&](const Vec3& p) {
    for (int a = 0; a < 3; ++a) {
      if (p[a] < lo[a] || p[a] > hi[a]) return false;
    }
    return true;
  };
  Scene out;
  out.viewpoints = scene.viewpoints;
  out.world_from_local = scene.world_from_local;
  std::vector<int> new_plane(scene.planes.size(), -1);
  for (std::size_t i = 0; i < scene.NumSegments(); ++i) {
    const SegmentId id(i);
    const Segment3& s = scene.segments[id];
    if (!inside(s.p1) || !inside(s.p2)) continue;
    out.segments.push_back(s);
    const auto views = scene.observations[id];
    out.observations.AddRow(views);
    if (scene.residuals.size() == scene.NumSegments()) out.residuals.push_back(scene.residuals[i]);
    PlaneMembership m;
    const PlaneMembership& old = scene.memberships[id];
    for (std::uint8_t k = 0; k < old.count; ++k) {
      int& p = new_plane[old.planes[k].index()];
      if (p < 0) {
        p = static_cast<int>(out.planes.size());
        out.planes.push_back(scene.planes[old.planes[k]]);
      }
      m.Add(PlaneId(static_cast<std::size_t>(p)));
    }
    out.memberships.push_back(m);
  }
  return out;
}

}  // namespace linesurf::bench
