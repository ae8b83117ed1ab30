#include "engine/detect/inlier_test.h"

#include <algorithm>
#include <cmath>

#include "engine/detect/detect_stage.h"
#include "engine/detect/segment_geometry.h"

namespace linesurf::detect {

InlierTest::InlierTest(std::span<const Segment3> segments,
                       const PlaneDetectionOptions& options,
                       double epsilon,
                       const SegmentBvh& bvh,
                       const std::vector<PlaneMembership>& memberships,
                       const std::vector<SupportedPlane>& planes)
    : segments_(segments),
      options_(options),
      epsilon_(epsilon),
      slab_(options.distance == SegmentDistance::kMeanEndpoint ? 2.0 * epsilon : epsilon),
      sin_crease_(std::sin(DegToRad(options.min_crease_angle_deg))),
      bvh_(bvh),
      memberships_(memberships),
      planes_(planes) {}

double InlierTest::InlierDistance(SegmentId s, const Plane3& plane) const {
  const PlaneMembership& m = memberships_[s.index()];
  const Segment3& seg = segments_[s.index()];
  if (m.count >= 2) return -1.0;
  if (m.count == 0 || options_.no_structural_condition) {
    if (m.count == 1 && options_.single_support) return -1.0;
    return SegmentPlaneDistance(seg, plane, options_.distance);
  }
  if (options_.single_support) return -1.0;
  // Structural condition: a segment already on P' joins P only along the crease P ∩ P'.
  CreaseLine line;
  if (!IntersectPlanes(plane, planes_[m.planes[0].index()].plane, sin_crease_, line)) {
    return -1.0;
  }
  return SegmentLineDistance(seg, line, options_.distance);
}

bool InlierTest::IsInlier(SegmentId s, const Plane3& plane) const {
  const double d = InlierDistance(s, plane);
  return d >= 0.0 && d <= epsilon_;
}

std::pair<std::uint32_t, double> InlierTest::Count(const Plane3& plane) const {
  std::uint32_t count = 0;
  double score = 0.0;
  bvh_.ForEachInSlab(plane, slab_, [&](SegmentId s) {
    const double d = InlierDistance(s, plane);
    if (d < 0.0 || d > epsilon_) return;
    ++count;
    const double r = d / epsilon_;
    score += options_.score_by_residual ? 1.0 - r * r : 1.0;
  });
  return {count, score};
}

std::vector<SegmentId> InlierTest::Collect(const Plane3& plane) const {
  std::vector<SegmentId> inliers;
  bvh_.ForEachInSlab(plane, slab_, [&](SegmentId s) {
    if (IsInlier(s, plane)) inliers.push_back(s);
  });
  std::sort(inliers.begin(), inliers.end());
  return inliers;
}

}  // namespace linesurf::detect
