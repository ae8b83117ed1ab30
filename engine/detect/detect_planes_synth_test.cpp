// Acceptance tests of plane detection on linesurf_synth scenes (issue 3, must-show 4).

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "engine/detect/detect_planes.h"
#include "tools/gen/synthesize.h"

namespace linesurf {
namespace {

synth::SyntheticScene Make(const std::string& family, std::uint64_t seed, int size = 1) {
  synth::SynthSpec spec;
  spec.family = family;
  spec.seed = seed;
  spec.size = size;
  spec.noise_sigma = 0.01;
  spec.outlier_fraction = 0.05;
  Expected<synth::SyntheticScene> s = synth::Synthesize(spec);
  EXPECT_TRUE(s.has_value()) << (s ? "" : s.error().ToString());
  return s ? std::move(s).value() : synth::SyntheticScene{};
}

// Fraction of the true planes with >= 5 supporting segments that have a detected plane with the
// normal within 2 degrees and the offset within 2 eps.
double FractionOfWellSupportedPlanesFound(const synth::SyntheticScene& synthetic,
                                          const PlaneDetectionOptions& options = {}) {
  const Scene& scene = synthetic.scene;
  EXPECT_FALSE(scene.planes.empty());
  RunContext ctx;
  Expected<PlaneDetectionResult> r = DetectPlanes(scene, options, ctx);
  EXPECT_TRUE(r.has_value()) << r.error().ToString();
  if (!r) return 0.0;
  const double max_angle = 2.0 * std::numbers::pi / 180.0;
  const double max_offset = 2.0 * r->stats.epsilon;
  int checked = 0;
  int found_count = 0;
  for (std::size_t q = 0; q < scene.planes.size(); ++q) {
    int support = 0;
    for (const PlaneMembership& m : scene.memberships) support += m.Contains(PlaneId(q)) ? 1 : 0;
    if (support < 5) continue;
    ++checked;
    const Plane3& truth = scene.planes[PlaneId(q)];
    bool found = false;
    for (const Plane3& p : r->planes) {
      const double cosine = p.normal.dot(truth.normal);
      if (std::acos(std::min(1.0, std::abs(cosine))) > max_angle) continue;
      const double sign = cosine < 0.0 ? -1.0 : 1.0;
      found = found || std::abs(sign * p.Offset() - truth.Offset()) <= max_offset;
    }
    found_count += found ? 1 : 0;
  }
  EXPECT_GT(checked, 5);
  return checked ? static_cast<double>(found_count) / checked : 0.0;
}

TEST(DetectPlanesSynth, HouseWithNoiseAndOutliersGivesEveryWellSupportedPlane) {
  for (std::uint64_t seed : {3, 4}) EXPECT_EQ(FractionOfWellSupportedPlanesFound(Make("house", seed)), 1.0);
}

// Known gap (docs/plane_detection.md): the room's niches put parallel planes 5 to 8 cm apart
// (2.5 to 4 eps); slightly tilted planes spanning two of them win, so not every plane is found.
// This pins the current level so that regressions show.
TEST(DetectPlanesSynth, RoomWithNoiseAndOutliersGivesMostWellSupportedPlanes) {
  EXPECT_GE(FractionOfWellSupportedPlanesFound(Make("room", 3)), 0.55);  // 19 of 32 today
}

// Per-block detection (15 m blocks cut most buildings of the 30 m lots) finds at least what
// the whole-scene run finds on a city of 9 buildings (today 92.6 % vs 81.5 %: the whole-scene
// RANSAC lets coplanar walls of different buildings absorb nearby hybrids).
TEST(DetectPlanesSynth, PerBlockDetectionOnACityFindsAtLeastWhatTheWholeSceneRunFinds) {
  const synth::SyntheticScene city = Make("city", 3, 9);
  PlaneDetectionOptions whole;
  whole.max_planes = 100000;
  PlaneDetectionOptions blocks = whole;
  blocks.block_size = 15.0;
  const double whole_fraction = FractionOfWellSupportedPlanesFound(city, whole);
  const double block_fraction = FractionOfWellSupportedPlanesFound(city, blocks);
  EXPECT_GE(block_fraction, whole_fraction);
  EXPECT_GE(block_fraction, 0.9);
}

TEST(DetectPlanesSynth, SynthCubeWithoutNoiseGivesTheSixFaces) {
  synth::SynthSpec spec;
  spec.family = "cube";
  Expected<synth::SyntheticScene> cube = synth::Synthesize(spec);
  ASSERT_TRUE(cube.has_value());
  PlaneDetectionOptions options;
  options.epsilon = 0.06;
  options.iterations = 100;
  RunContext ctx;
  Expected<PlaneDetectionResult> r = DetectPlanes(cube->scene, options, ctx);
  ASSERT_TRUE(r.has_value());
  EXPECT_EQ(r->planes.size(), 6u);
  EXPECT_EQ(r->stats.num_l2, static_cast<std::int64_t>(cube->scene.segments.size()));
}

}  // namespace
}  // namespace linesurf
