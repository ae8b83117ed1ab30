// Acceptance tests of plane detection on linesurf_synth scenes: planes recovered within
// angle and offset tolerances, and the ablations of the paper's robustness study.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>


#include "engine/detect/detect_planes.h"
#include "tools/eval/evaluate_planes.h"
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
  RunContext ctx;
  Expected<PlaneDetectionResult> r = DetectPlanes(synthetic.scene, options, ctx);
  EXPECT_TRUE(r.has_value()) << r.error().ToString();
  if (!r) return 0.0;
  const eval::PlaneRecovery recovery =
      eval::EvaluatePlaneRecovery(synthetic.scene, r->planes, 2.0, 2.0 * r->stats.epsilon, 5);
  EXPECT_GT(recovery.checked, 5);
  return recovery.Fraction();
}

TEST(DetectPlanesSynth, HouseWithNoiseAndOutliersGivesEveryWellSupportedPlane) {
  for (std::uint64_t seed : {3, 4}) EXPECT_EQ(FractionOfWellSupportedPlanesFound(Make("house", seed)), 1.0);
}

// Known gap (docs/design/plane_detection.md): the room's niches put parallel planes 5 to 8 cm apart
// (2.5 to 4 eps); slightly tilted planes spanning two of them win, so not every plane is found.
// This pins the current level so that regressions show.
TEST(DetectPlanesSynth, RoomWithNoiseAndOutliersGivesMostWellSupportedPlanes) {
  EXPECT_GE(FractionOfWellSupportedPlanesFound(Make("room", 3)), 0.55);  // 19 of 32 today
}

// Per-block detection (15 m blocks cut most buildings of the 30 m lots) finds at least what
// the whole-scene run finds on a city of 9 buildings (today 92.6 % vs 77.8 % of the true planes
// with >= 5 segments).
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

// One plane, one piece (docs/design/plane_detection.md): at 2 cm noise, 7 % outliers and the residual
// split, flat roofs of two buildings a few eps apart in height can come out as one plane
// tilted across both, about 1 eps under one roof's far edge, which raises a block on that roof
// (docs/design/plane_detection.md, "One plane, one piece"). Counts the flat roofs (true planes with |n_z| > 0.99 above the ground) held
// by one detected plane within 0.5 degrees and eps at every ground-truth corner: all of them
// with the support kept in one piece (seeds 1 and 2 of city-4: 4 + 4), fewer without (3 + 1).
int FlatRoofsHeld(const synth::SyntheticScene& city, const PlaneDetectionOptions& options) {
  RunContext ctx;
  Expected<PlaneDetectionResult> r = DetectPlanes(city.scene, options, ctx);
  EXPECT_TRUE(r.has_value()) << r.error().ToString();
  if (!r) return 0;
  const PolygonMesh& mesh = city.ground_truth;
  int held = 0;
  for (const Plane3& truth : city.scene.planes) {
    if (std::abs(truth.normal.z()) < 0.99 || std::abs(truth.normal.dot(truth.point)) < 0.5) {
      continue;
    }
    std::vector<Vec3> corners;
    for (std::size_t f = 0; f < mesh.NumFaces(); ++f) {
      const auto face = mesh.Face(f);
      if (std::all_of(face.begin(), face.end(), [&](std::uint32_t v) {
            return std::abs(truth.SignedDistance(mesh.vertices[v])) < 1e-9;
          })) {
        for (const std::uint32_t v : face) corners.push_back(mesh.vertices[v]);
      }
    }
    held += std::any_of(r->planes.begin(), r->planes.end(), [&](const Plane3& p) {
      return std::abs(p.normal.dot(truth.normal)) > std::cos(0.5 * std::numbers::pi / 180.0) &&
             std::all_of(corners.begin(), corners.end(), [&](const Vec3& c) {
               return std::abs(p.SignedDistance(c)) <= r->stats.epsilon;
             });
    });
  }
  return held;
}

TEST(DetectPlanesSynth, FlatRoofsOfBuildingsAtNearbyHeightsAreSeparatePlanes) {
  int held = 0;
  int held_without = 0;
  for (const std::uint64_t seed : {1, 2}) {
    synth::SynthSpec spec;
    spec.family = "city";
    spec.seed = seed;
    spec.size = 4;
    spec.noise_sigma = 0.02;
    spec.outlier_fraction = 0.07;
    spec.residual_split = true;
    Expected<synth::SyntheticScene> city = synth::Synthesize(spec);
    ASSERT_TRUE(city.has_value()) << city.error().ToString();
    held += FlatRoofsHeld(*city, PlaneDetectionOptions{});
    PlaneDetectionOptions without;
    without.support_gap = 0.0;
    held_without += FlatRoofsHeld(*city, without);
  }
  EXPECT_EQ(held, 8);
  EXPECT_LT(held_without, held);
}

// The second ablation of the paper's robustness study, in the setting of the robustness study
// (docs/design/plane_detection.md): without the structural condition, outliers and near-parallel
// hijacks cost faces (118 vs 109 faces held over 20 trials).
TEST(DetectPlanesSynth, NoStructuralConditionAblationFindsFewerCubeFacesAmongOutliers) {
  int full = 0;
  int ablation = 0;
  for (std::uint64_t trial = 0; trial < 20; ++trial) {
    synth::SynthSpec spec;
    spec.family = "cube";
    spec.seed = 1000 + trial;
    spec.noise_sigma = 0.05;
    spec.noise_model = synth::NoiseModel::kUniformBall;
    spec.outlier_count = 50;
    Expected<synth::SyntheticScene> cube = synth::Synthesize(spec);
    ASSERT_TRUE(cube.has_value());
    PlaneDetectionOptions options;
    options.epsilon = 0.06;
    options.iterations = 100;
    options.seed = trial;
    RunContext ctx;
    const Expected<PlaneDetectionResult> with = DetectPlanes(cube->scene, options, ctx);
    options.no_structural_condition = true;
    const Expected<PlaneDetectionResult> without = DetectPlanes(cube->scene, options, ctx);
    ASSERT_TRUE(with.has_value() && without.has_value());
    full += eval::CountTruePlanesHeld(cube->scene, with->memberships);
    ablation += eval::CountTruePlanesHeld(cube->scene, without->memberships);
  }
  EXPECT_LT(ablation, full);
  EXPECT_GE(full, 110);  // of 120
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
