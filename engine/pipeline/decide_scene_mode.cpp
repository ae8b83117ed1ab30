#include "engine/pipeline/decide_scene_mode.h"

#include <Eigen/Geometry>

#include <array>
#include <cmath>
#include <sstream>
#include <vector>

namespace linesurf::pipeline {
namespace {

/// Rays nearly parallel to a plane (|n.d| under this) do not hit it.
constexpr double kMinRayPlaneCosine = 1e-6;

std::array<Vec3, 14> RayDirections() {
  std::array<Vec3, 14> dirs;
  std::size_t k = 0;
  for (int a = 0; a < 3; ++a) {
    for (const double s : {1.0, -1.0}) {
      Vec3 d = Vec3::Zero();
      d[a] = s;
      dirs[k++] = d;
    }
  }
  for (const double x : {1.0, -1.0}) {
    for (const double y : {1.0, -1.0}) {
      for (const double z : {1.0, -1.0}) dirs[k++] = Vec3(x, y, z).normalized();
    }
  }
  return dirs;
}

}  // namespace

SceneModeDecision DecideSceneMode(const Scene& scene, double support_margin_rel) {
  SceneModeDecision decision;
  Box3 scene_box;
  for (const Segment3& s : scene.segments) {
    scene_box.Extend(s.p1);
    scene_box.Extend(s.p2);
  }
  std::vector<std::uint8_t> observing(scene.viewpoints.size(), 0);
  for (const ViewpointId v : scene.observations.items()) observing[v.index()] = 1;
  for (const std::uint8_t o : observing) decision.observing_viewpoints += o;
  if (scene.planes.empty() || !scene.HasMemberships() || scene_box.IsEmpty()) {
    decision.reason = "auto: no planes -> exterior";
    return decision;
  }
  // Support boxes of the planes.
  std::vector<Box3> support(scene.planes.size());
  for (std::size_t s = 0; s < scene.NumSegments(); ++s) {
    const PlaneMembership& m = scene.memberships[SegmentId(s)];
    for (std::uint8_t k = 0; k < m.count; ++k) {
      support[m.planes[k].index()].Extend(scene.segments[SegmentId(s)].p1);
      support[m.planes[k].index()].Extend(scene.segments[SegmentId(s)].p2);
    }
  }
  const double margin = support_margin_rel * scene_box.Extent().norm();
  for (Box3& b : support) {
    if (b.IsEmpty()) continue;
    b.min.array() -= margin;
    b.max.array() += margin;
  }
  const std::array<Vec3, 14> dirs = RayDirections();
  for (std::size_t v = 0; v < scene.viewpoints.size(); ++v) {
    if (observing[v] == 0) continue;
    const Vec3& o = scene.viewpoints[ViewpointId(v)];
    bool enclosed = true;
    for (const Vec3& d : dirs) {
      bool hit = false;
      for (std::size_t p = 0; p < scene.planes.size() && !hit; ++p) {
        if (support[p].IsEmpty()) continue;
        const Plane3& plane = scene.planes[PlaneId(p)];
        const double nd = plane.normal.dot(d);
        if (std::abs(nd) < kMinRayPlaneCosine) continue;
        const double t = -plane.SignedDistance(o) / nd;
        hit = t > 0.0 && support[p].Contains(o + t * d);
      }
      if (!hit) {
        enclosed = false;
        break;
      }
    }
    decision.enclosed_viewpoints += enclosed ? 1 : 0;
  }
  decision.interior = 2 * decision.enclosed_viewpoints > decision.observing_viewpoints;
  std::ostringstream os;
  os << "auto: " << decision.enclosed_viewpoints << " of " << decision.observing_viewpoints
     << " viewpoints enclosed by planes -> " << (decision.interior ? "interior" : "exterior");
  decision.reason = os.str();
  return decision;
}

}  // namespace linesurf::pipeline
