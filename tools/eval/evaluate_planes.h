#pragma once
// Evaluation of detected planes against a ground truth scene (synthetic scenes carry their true
// planes and memberships): used by the detection tests and studies.

#include "engine/core/geometry.h"
#include "engine/core/scene.h"
#include "engine/core/strong_id.h"

namespace linesurf::eval {

/// True planes whose supporting segments (truth.memberships) are all inliers of one detected
/// plane (`detected`: the detection's memberships, one per segment of `truth`). A true plane
/// without segments does not count.
int CountTruePlanesHeld(const Scene& truth, const IdVector<SegmentId, PlaneMembership>& detected);

struct PlaneRecovery {
  int checked = 0;  ///< true planes with at least min_support segments
  int found = 0;    ///< ... with a detected plane within the angle and offset
  [[nodiscard]] double Fraction() const { return checked ? static_cast<double>(found) / checked : 0.0; }
};

/// Of the true planes supported by at least `min_support` segments, how many have a detected
/// plane whose normal is within `max_angle_deg` (either orientation) and whose offset along it
/// is within `max_offset` of the true plane's.
PlaneRecovery EvaluatePlaneRecovery(const Scene& truth, const IdVector<PlaneId, Plane3>& detected,
                                    double max_angle_deg, double max_offset, int min_support);

}  // namespace linesurf::eval
