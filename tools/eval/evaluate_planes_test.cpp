#include "tools/eval/evaluate_planes.h"

#include <gtest/gtest.h>

namespace linesurf::eval {
namespace {

PlaneMembership On(std::initializer_list<std::uint32_t> planes) {
  PlaneMembership m;
  for (const std::uint32_t p : planes) m.Add(PlaneId(p));
  return m;
}

// Two true planes z = 0 and x = 0; segments 0-2 on z = 0, 2-4 on x = 0 (2 is the crease).
Scene Truth() {
  Scene truth;
  truth.planes.push_back({Vec3::Zero(), Vec3::UnitZ()});
  truth.planes.push_back({Vec3::Zero(), Vec3::UnitX()});
  for (const auto& m : {On({0}), On({0}), On({0, 1}), On({1}), On({1})}) {
    truth.memberships.push_back(m);
  }
  return truth;
}

TEST(CountTruePlanesHeld, APlaneIsHeldOnlyWhenOneDetectedPlaneHasAllItsSegments) {
  const Scene truth = Truth();
  IdVector<SegmentId, PlaneMembership> detected;
  for (const auto& m : {On({5}), On({5}), On({5, 7}), On({7}), On({8})}) detected.push_back(m);
  EXPECT_EQ(CountTruePlanesHeld(truth, detected), 1);  // z = 0 by 5; x = 0 split over 7 and 8
  detected[SegmentId(4u)] = On({7});
  EXPECT_EQ(CountTruePlanesHeld(truth, detected), 2);
}

TEST(EvaluatePlaneRecovery, CountsPlanesWithinTheAngleAndOffsetEitherOrientation) {
  const Scene truth = Truth();
  IdVector<PlaneId, Plane3> detected;
  detected.push_back({Vec3(0, 0, 0.03), -Vec3::UnitZ()});  // flipped, 3 cm off
  const PlaneRecovery loose = EvaluatePlaneRecovery(truth, detected, 2.0, 0.04, 3);
  EXPECT_EQ(loose.checked, 2);
  EXPECT_EQ(loose.found, 1);
  EXPECT_EQ(EvaluatePlaneRecovery(truth, detected, 2.0, 0.02, 3).found, 0);
  EXPECT_EQ(EvaluatePlaneRecovery(truth, detected, 2.0, 0.04, 4).checked, 0);
}

}  // namespace
}  // namespace linesurf::eval
