#include "tools/eval/evaluate_planes.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

namespace linesurf::eval {

int CountTruePlanesHeld(const Scene& truth, const IdVector<SegmentId, PlaneMembership>& detected) {
  int held = 0;
  for (std::size_t p = 0; p < truth.planes.size(); ++p) {
    // Detected planes holding every supporting segment so far (at most 2 candidates).
    std::vector<PlaneId> common;
    bool first = true;
    for (std::size_t s = 0; s < truth.memberships.size(); ++s) {
      if (!truth.memberships[SegmentId(s)].Contains(PlaneId(p))) continue;
      const PlaneMembership& m = detected[SegmentId(s)];
      if (first) {
        common.assign(m.planes.begin(), m.planes.begin() + m.count);
        first = false;
      } else {
        std::erase_if(common, [&](PlaneId q) { return !m.Contains(q); });
      }
      if (common.empty()) break;
    }
    held += !first && !common.empty() ? 1 : 0;
  }
  return held;
}

PlaneRecovery EvaluatePlaneRecovery(const Scene& truth, const IdVector<PlaneId, Plane3>& detected,
                                    double max_angle_deg, double max_offset, int min_support) {
  std::vector<int> support(truth.planes.size(), 0);
  for (const PlaneMembership& m : truth.memberships) {
    for (std::uint8_t i = 0; i < m.count; ++i) ++support[m.planes[i].index()];
  }
  const double min_cos = std::cos(max_angle_deg * std::numbers::pi / 180.0);
  PlaneRecovery recovery;
  for (std::size_t q = 0; q < truth.planes.size(); ++q) {
    if (support[q] < min_support) continue;
    ++recovery.checked;
    const Plane3& t = truth.planes[PlaneId(q)];
    const bool found = std::any_of(detected.begin(), detected.end(), [&](const Plane3& p) {
      const double cosine = p.normal.dot(t.normal);
      if (std::abs(cosine) < min_cos) return false;
      const double sign = cosine < 0.0 ? -1.0 : 1.0;
      return std::abs(sign * p.Offset() - t.Offset()) <= max_offset;
    });
    recovery.found += found ? 1 : 0;
  }
  return recovery;
}

}  // namespace linesurf::eval
