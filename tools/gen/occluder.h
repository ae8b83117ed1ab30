#pragma once
// Occlusion queries against the ground-truth solid: is the sight ray from a viewpoint to a point
// on (or near) the surface free of faces? Triangles are grouped per component with a bounding box,
// and the boxes are bucketed in a uniform xy grid so that city-sized models stay fast.

#include <cstdint>
#include <vector>

#include "engine/core/geometry.h"
#include "tools/gen/solid_model.h"

namespace linesurf::synth {

class Occluder {
 public:
  explicit Occluder(const SolidModel& model);

  /// True when no face crosses the sight ray from `eye` to `target` before the target (a
  /// crossing within kTargetGap of the target does not count: targets lie on faces).
  /// `scratch` is a caller-owned buffer reused across calls (no allocation per ray).
  /// Thread-safe (const, no caches) when each thread passes its own scratch.
  [[nodiscard]] bool IsClear(const Vec3& eye, const Vec3& target,
                             std::vector<std::uint32_t>& scratch) const;

 private:
  struct Triangle {
    Vec3 a, e1, e2;
  };
  struct Group {
    Box3 box;
    std::uint32_t first = 0;
    std::uint32_t last = 0;
  };
  [[nodiscard]] bool HitsGroup(const Group& g, const Vec3& eye, const Vec3& dir,
                               double t_max) const;

  std::vector<Triangle> triangles_;
  std::vector<Group> groups_;
  // xy grid of group ids: cell (i, j) holds cell_items_[cell_offsets_[c] .. cell_offsets_[c+1]).
  double origin_x_ = 0.0;
  double origin_y_ = 0.0;
  double cell_ = 1.0;
  std::int64_t nx_ = 1;
  std::int64_t ny_ = 1;
  std::vector<std::uint32_t> cell_offsets_;
  std::vector<std::uint32_t> cell_items_;
};

}  // namespace linesurf::synth
