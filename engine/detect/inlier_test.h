#pragma once
// The inlier test of multi-support RANSAC and the support of a candidate plane (internal to
// engine/detect).

#include <cstdint>
#include <utility>
#include <vector>

#include "engine/core/geometry.h"
#include "engine/core/strong_id.h"
#include "engine/detect/ransac_state.h"

namespace linesurf::detect {

/// Which segments may join a plane and how far they are: a free segment by its distance to the
/// plane (textural), a segment already on one plane by its distance to the crease of the two
/// (structural), a segment on two planes never.
class InlierTest {
 public:
  InlierTest(const RansacInput& in, const RansacState& state);

  /// Distance of `s` to `plane` under the inlier test that applies to it (textural or
  /// structural), or a negative value when `s` cannot join `plane`.
  [[nodiscard]] double InlierDistance(SegmentId s, const Plane3& plane) const;

  [[nodiscard]] bool IsInlier(SegmentId s, const Plane3& plane) const;

  /// Support of a candidate: inlier count and score (count, or the truncated quadratic
  /// sum of (1 - (d / eps)^2) when options.score_by_residual), summed serially in BVH order.
  [[nodiscard]] std::pair<std::uint32_t, double> Count(const Plane3& plane) const;

  /// The inliers of `plane`, ascending.
  [[nodiscard]] std::vector<SegmentId> Collect(const Plane3& plane) const;

 private:
  RansacInput in_;
  RansacState state_;
  double slab_;
  double sin_crease_;
};

}  // namespace linesurf::detect
