#include "engine/detect/inlier_test.h"

#include <algorithm>
#include <cmath>

#include "engine/detect/detect_stage.h"
#include "engine/detect/segment_geometry.h"

namespace linesurf::detect {

InlierTest::InlierTest(const RansacInput& in, const RansacState& state)
    : in_(in),
      state_(state),
      slab_(in.options.distance == SegmentDistance::kMeanEndpoint ? 2.0 * in.epsilon : in.epsilon),
      sin_crease_(std::sin(DegToRad(in.options.min_crease_angle_deg))) {}

double InlierTest::InlierDistance(SegmentId s, const Plane3& plane) const {
  const PlaneMembership& m = state_.memberships[s.index()];
  const Segment3& seg = in_.segments[s.index()];
  if (m.count >= 2) return -1.0;
  if (m.count == 0 || in_.options.no_structural_condition) {
    if (m.count == 1 && in_.options.single_support) return -1.0;
    return SegmentPlaneDistance(seg, plane, in_.options.distance);
  }
  if (in_.options.single_support) return -1.0;
  // Structural condition: a segment already on P' joins P only along the crease P ∩ P'.
  CreaseLine line;
  if (!IntersectPlanes(plane, state_.planes[m.planes[0].index()].plane, sin_crease_, line)) {
    return -1.0;
  }
  return SegmentLineDistance(seg, line, in_.options.distance);
}

bool InlierTest::IsInlier(SegmentId s, const Plane3& plane) const {
  const double d = InlierDistance(s, plane);
  return d >= 0.0 && d <= in_.epsilon;
}

std::pair<std::uint32_t, double> InlierTest::Count(const Plane3& plane) const {
  std::uint32_t count = 0;
  double score = 0.0;
  state_.bvh.ForEachInSlab(plane, slab_, [&](SegmentId s) {
    const double d = InlierDistance(s, plane);
    if (d < 0.0 || d > in_.epsilon) return;
    ++count;
    const double r = d / in_.epsilon;
    score += in_.options.score_by_residual ? 1.0 - r * r : 1.0;
  });
  return {count, score};
}

std::vector<SegmentId> InlierTest::Collect(const Plane3& plane) const {
  std::vector<SegmentId> inliers;
  state_.bvh.ForEachInSlab(plane, slab_, [&](SegmentId s) {
    if (IsInlier(s, plane)) inliers.push_back(s);
  });
  std::sort(inliers.begin(), inliers.end());
  return inliers;
}

}  // namespace linesurf::detect
