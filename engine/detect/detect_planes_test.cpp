#include "engine/detect/detect_planes.h"

#include "engine/core/rng.h"
#include "tests/support/thread_count.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <numbers>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace linesurf {
namespace {

// A point drawn uniformly in the ball of radius 2 about the origin.
Vec3 InBall(Rng& rng) {
  Vec3 x;
  do {
    x = Vec3(rng.Uniform(-2, 2), rng.Uniform(-2, 2), rng.Uniform(-2, 2));
  } while (x.norm() > 2.0);
  return x;
}

// The 12 edges of the cube [-1, 1]^3 (side 2), with optional endpoint noise and outliers in a
// ball of radius 2, and one viewpoint per edge outside the cube. (Hand-made: the acceptance tests
// on synthetic scenes use linesurf_synth.)
Scene NoisyCube(double noise, int outliers, std::uint64_t seed) {
  Scene scene;
  Rng rng(seed);
  auto jitter = [&](const Vec3& p) {
    return noise > 0.0 ? Vec3(p + noise * Vec3(rng.Normal(), rng.Normal(), rng.Normal())) : p;
  };
  for (int axis = 0; axis < 3; ++axis) {
    for (int a = -1; a <= 1; a += 2) {
      for (int b = -1; b <= 1; b += 2) {
        Vec3 p;
        Vec3 q;
        p[axis] = -1;
        q[axis] = 1;
        p[(axis + 1) % 3] = q[(axis + 1) % 3] = a;
        p[(axis + 2) % 3] = q[(axis + 2) % 3] = b;
        // One viewpoint outside both faces of the edge.
        scene.observations.AddRow(std::array<ViewpointId, 1>{scene.viewpoints.NextId()});
        scene.viewpoints.push_back(1.5 * (p + q));
        scene.segments.push_back({jitter(p), jitter(q)});
      }
    }
  }
  for (int i = 0; i < outliers; ++i) {
    scene.segments.push_back({InBall(rng), InBall(rng)});
    scene.observations.AddRow(std::array<ViewpointId, 1>{ViewpointId(0u)});
  }
  return scene;
}

// Number of cube faces whose 4 edges one detected plane holds.
int FacesFound(const PlaneDetectionResult& r) {
  int found = 0;
  for (int axis = 0; axis < 3; ++axis) {
    for (int side = -1; side <= 1; side += 2) {
      std::vector<SegmentId> edges;
      for (std::size_t e = 0; e < 12; ++e) {
        const int edge_axis = static_cast<int>(e / 4);
        if (edge_axis == axis) continue;
        const int a = (e % 4) / 2 == 0 ? -1 : 1;
        const int b = e % 2 == 0 ? -1 : 1;
        // Coordinates of the edge on axes edge_axis+1 and edge_axis+2.
        const int coord = (edge_axis + 1) % 3 == axis ? a : b;
        if (coord == side) edges.emplace_back(e);
      }
      bool face = false;
      for (const PlaneSupport& sp : r.support) {
        const bool all = std::all_of(edges.begin(), edges.end(), [&](SegmentId s) {
          return std::binary_search(sp.inliers.begin(), sp.inliers.end(), s);
        });
        face = face || (all && edges.size() == 4);
      }
      found += face ? 1 : 0;
    }
  }
  return found;
}

PlaneDetectionResult Detect(const Scene& scene, const PlaneDetectionOptions& options,
                            int threads = 1) {
  RunContext ctx;
  ctx.num_threads = threads;
  Expected<PlaneDetectionResult> r = DetectPlanes(scene, options, ctx);
  EXPECT_TRUE(r.has_value()) << (r ? "" : r.error().ToString());
  return r ? std::move(r).value() : PlaneDetectionResult{};
}

PlaneDetectionOptions CubeOptions() {
  PlaneDetectionOptions o;
  o.epsilon = 0.06;
  o.iterations = 100;
  return o;
}

TEST(DetectPlanes, CleanCubeGivesExactlyTheSixFacesAndEveryEdgeIsStructural) {
  const Scene cube = NoisyCube(0.0, 0, 1);
  const PlaneDetectionResult r = Detect(cube, CubeOptions());
  ASSERT_EQ(r.planes.size(), 6u);
  EXPECT_EQ(FacesFound(r), 6);
  for (const PlaneMembership& m : r.memberships) EXPECT_EQ(m.count, 2);
  EXPECT_EQ(r.stats.num_l2, 12);
  for (const Plane3& p : r.planes) {
    EXPECT_NEAR(p.normal.norm(), 1.0, 1e-12);
    EXPECT_NEAR(p.normal.cwiseAbs().maxCoeff(), 1.0, 1e-9);
    EXPECT_NEAR(std::abs(p.Offset()), 1.0, 1e-9);
    // The viewpoints are outside: every normal points away from the cube centre.
    EXPECT_GT(p.normal.dot(p.point), 0.0);
  }
}

TEST(DetectPlanes, CleanCubeAlsoWithRandomSampling) {
  PlaneDetectionOptions o = CubeOptions();
  o.exhaustive_pairs_max_segments = 0;
  o.iterations = 2000;
  const PlaneDetectionResult r = Detect(NoisyCube(0.0, 0, 1), o);
  EXPECT_EQ(r.planes.size(), 6u);
  EXPECT_EQ(FacesFound(r), 6);
}

// 40 lines on the plane z = 0 among 2,000 outlier segments in the ball of radius 2: most pair
// draws meet lines that pass far apart. Such a draw is a trial of the adaptive stop (it could
// have hit the plane), so one batch of candidates is enough at this confidence; counting only
// valid candidates took 2,290 of them.
TEST(DetectPlanes, AdaptiveStopCountsPairsOfLinesTooFarApartAsTrials) {
  Scene scene;
  Rng rng(7);
  scene.viewpoints.push_back(Vec3(0.0, 0.0, 5.0));
  for (int i = 0; i < 2040; ++i) {
    if (i < 40) {
      scene.segments.push_back({Vec3(rng.Uniform(-2, 2), rng.Uniform(-2, 2), 0.0),
                                Vec3(rng.Uniform(-2, 2), rng.Uniform(-2, 2), 0.0)});
    } else {
      scene.segments.push_back({InBall(rng), InBall(rng)});
    }
    scene.observations.AddRow(std::array<ViewpointId, 1>{ViewpointId(0u)});
  }
  PlaneDetectionOptions o;
  o.epsilon = 0.03;
  o.min_iterations = 1;
  o.max_planes = 1;  // one search
  const PlaneDetectionResult r = Detect(scene, o);
  ASSERT_EQ(r.planes.size(), 1u);
  EXPECT_GE(r.support[PlaneId(0u)].inliers.size(), 36u);
  EXPECT_NEAR(std::abs(r.planes[PlaneId(0u)].normal.z()), 1.0, 1e-3);
  EXPECT_LE(r.stats.candidates_evaluated, 2 * 128);
}

TEST(DetectPlanes, SingleSupportAblationFindsFewerCubeFaces) {
  int full = 0;
  int single = 0;
  for (std::uint64_t seed = 1; seed <= 10; ++seed) {
    const Scene cube = NoisyCube(0.01, 10, seed);
    PlaneDetectionOptions o = CubeOptions();
    o.seed = seed;
    full += FacesFound(Detect(cube, o));
    o.single_support = true;
    single += FacesFound(Detect(cube, o));
  }
  EXPECT_EQ(full, 60);
  EXPECT_LE(single, 30);  // two opposite faces take all 12 edges, the other 4 are parallel
}

// Floor z = 0 (a grid of segments) and a plane tilted by 4 degrees through the floor's middle:
// without the structural condition the tilted plane takes the floor segments near the line where
// the two planes meet (they are within eps of it) although they are not on that line; with it
// only segments on the crease may join.
TEST(DetectPlanes, StructuralConditionKeepsNearlyParallelPlanesFromStealingSegments) {
  Scene scene;
  for (int i = 0; i <= 20; ++i) {
    const double t = -5.0 + 0.5 * i;
    scene.segments.push_back({Vec3(t, -5, 0), Vec3(t, 5, 0)});
    scene.segments.push_back({Vec3(-5, t, 0), Vec3(5, t, 0)});
  }
  const std::size_t floor_count = scene.segments.size();
  const double slope = std::tan(4.0 * std::numbers::pi / 180.0);
  for (int i = 0; i <= 10; ++i) {
    const double t = -5.0 + 1.0 * i;
    // Tilted plane z = slope * x, only for x > 0.
    scene.segments.push_back({Vec3(0.5, t, 0.5 * slope), Vec3(5, t, 5 * slope)});
    scene.segments.push_back({Vec3(0.5 + 0.45 * i, -5, (0.5 + 0.45 * i) * slope),
                              Vec3(0.5 + 0.45 * i, 5, (0.5 + 0.45 * i) * slope)});
  }
  PlaneDetectionOptions o;
  o.epsilon = 0.05;
  o.exhaustive_pairs_max_segments = 0;
  o.iterations = 2000;
  o.p_fusion = 1.0;  // keep the two planes apart
  auto stolen = [&](const PlaneDetectionResult& r) {
    int count = 0;
    for (std::size_t s = 0; s < floor_count; ++s) count += r.memberships[SegmentId(s)].count == 2;
    return count;
  };
  const PlaneDetectionResult full = Detect(scene, o);
  o.no_structural_condition = true;
  const PlaneDetectionResult ablation = Detect(scene, o);
  ASSERT_GE(full.planes.size(), 2u);
  ASSERT_GE(ablation.planes.size(), 2u);
  EXPECT_EQ(stolen(full), 0);
  EXPECT_GT(stolen(ablation), 0);
}

// Eight noisy cubes on a grid 3 apart: enough segments for random (non-exhaustive) sampling.
Scene CubeGrid() {
  Scene scene;
  scene.viewpoints.push_back(Vec3(50, 40, 30));
  for (int c = 0; c < 8; ++c) {
    const Scene cube = NoisyCube(0.005, 6, 100 + c);
    const Vec3 shift(3.0 * (c % 4), 3.0 * (c / 4), 0.2 * c);
    for (const Segment3& s : cube.segments) {
      scene.segments.push_back({s.p1 + shift, s.p2 + shift});
      scene.observations.AddRow(std::array<ViewpointId, 1>{ViewpointId(0u)});
    }
  }
  return scene;
}

void ExpectSameResult(const PlaneDetectionResult& a, const PlaneDetectionResult& b) {
  ASSERT_EQ(a.planes.size(), b.planes.size());
  for (std::size_t i = 0; i < a.planes.size(); ++i) {
    const PlaneId p(i);
    EXPECT_EQ(a.planes[p].normal, b.planes[p].normal) << i;
    EXPECT_EQ(a.planes[p].point, b.planes[p].point) << i;
    EXPECT_EQ(a.support[p].inliers, b.support[p].inliers) << i;
  }
  EXPECT_EQ(a.stats.candidates_evaluated, b.stats.candidates_evaluated);
}

/// How many of the 48 faces of CubeGrid have a plane within 2 degrees and 2 eps.
int CubeGridFacesFound(const PlaneDetectionResult& r) {
  int faces = 0;
  for (int c = 0; c < 8; ++c) {
    const Vec3 centre(3.0 * (c % 4), 3.0 * (c / 4), 0.2 * c);
    for (int axis = 0; axis < 3; ++axis) {
      for (int side = -1; side <= 1; side += 2) {
        const Vec3 on_face = centre + side * Vec3::Unit(axis);
        const double min_cos = std::cos(2.0 * std::numbers::pi / 180.0);
        bool found = false;
        for (const Plane3& plane : r.planes) {
          found = found || (std::abs(plane.normal[axis]) > min_cos &&
                            std::abs(plane.SignedDistance(on_face)) < 2.0 * r.stats.epsilon);
        }
        faces += found ? 1 : 0;
      }
    }
  }
  return faces;
}

PlaneDetectionOptions GridOptions() {
  PlaneDetectionOptions o;
  o.epsilon = 0.03;
  o.seed = 42;
  return o;
}

TEST(DetectPlanes, SameSeedSameOutputForAnyThreadCount) {
  const linesurf::testing::RealThreadCounts real_threads;
  const Scene scene = CubeGrid();
  // Whole scene; blocks cutting the cubes; one grid block split (octree) down to <= 40 lines;
  // one grid block split because its RANSAC reached max_planes.
  for (const auto& [block_size, max_segments, max_planes] :
       {std::tuple{0.0, 0, 160}, {2.0, 0, 160}, {20.0, 40, 160}, {20.0, 0, 12}}) {
    PlaneDetectionOptions o = GridOptions();
    o.block_size = block_size;
    o.block_max_segments = max_segments;
    o.max_planes = max_planes;
    const PlaneDetectionResult r1 = Detect(scene, o, 1);
    ASSERT_GT(r1.planes.size(), 10u);
    EXPECT_TRUE((max_segments == 0 && max_planes == 160) || r1.stats.blocks > 1);
    for (int threads : linesurf::testing::kThreadCounts) {
      ExpectSameResult(Detect(scene, o, threads), r1);
    }
  }
}

TEST(DetectPlanes, OneBlockReproducesTheWholeSceneRun) {
  const Scene scene = CubeGrid();
  PlaneDetectionOptions one = GridOptions();
  one.block_size = 100.0;  // larger than the scene
  const PlaneDetectionResult r = Detect(scene, one);
  EXPECT_EQ(r.stats.blocks, 1);
  ExpectSameResult(r, Detect(scene, GridOptions()));
}

TEST(DetectPlanes, PerBlockDetectionFindsEveryCubeFaceAndKeepsTheAtMostTwoRule) {
  const Scene scene = CubeGrid();
  PlaneDetectionOptions o = GridOptions();
  o.block_size = 2.5;  // cubes of side 2 on a grid of 3: most are cut, their planes found in pieces
  o.block_halo = 0.3;
  const PlaneDetectionResult r = Detect(scene, o);
  EXPECT_GT(r.stats.blocks, 8);
  EXPECT_GT(r.stats.merges, 0);
  // The memberships and the planes' inlier lists agree, and nobody is on more than 2 planes.
  std::vector<int> count(scene.segments.size(), 0);
  for (std::size_t p = 0; p < r.planes.size(); ++p) {
    EXPECT_GE(r.support[PlaneId(p)].inliers.size(), static_cast<std::size_t>(o.min_support));
    for (const SegmentId s : r.support[PlaneId(p)].inliers) {
      ++count[s.index()];
      EXPECT_TRUE(r.memberships[s].Contains(PlaneId(p)));
    }
  }
  for (std::size_t s = 0; s < count.size(); ++s) {
    EXPECT_LE(count[s], 2);
    EXPECT_EQ(count[s], r.memberships[SegmentId(s)].count);
  }
  EXPECT_EQ(CubeGridFacesFound(r), 48);
}

TEST(DetectPlanes, ABlockThatReachesMaxPlanesIsSplitUntilItsPlanesFit) {
  const Scene scene = CubeGrid();
  PlaneDetectionOptions o = GridOptions();
  o.max_planes = 12;  // the 48 faces need at least 4 blocks
  const PlaneDetectionResult whole = Detect(scene, o);
  EXPECT_EQ(whole.stats.capped_blocks, 1);  // no grid, nothing to split: the cap holds
  EXPECT_EQ(whole.planes.size(), 12u);
  o.block_size = 20.0;  // one grid block holding the whole scene
  const PlaneDetectionResult split = Detect(scene, o);
  EXPECT_GE(split.stats.blocks, 4);
  EXPECT_EQ(split.stats.capped_blocks, 0);
  EXPECT_EQ(CubeGridFacesFound(split), 48);
}

TEST(DetectPlanes, RelativeEpsilonScalesWithTheScene) {
  Scene cube = NoisyCube(0.0, 0, 1);
  for (Segment3& s : cube.segments) {
    s.p1 *= 1000.0;
    s.p2 *= 1000.0;
  }
  PlaneDetectionOptions o = CubeOptions();
  o.relative_epsilon = 0.01;
  const PlaneDetectionResult r = Detect(cube, o);
  EXPECT_NEAR(r.stats.epsilon, 0.01 * 2000.0 * std::sqrt(3.0), 1e-6);
  EXPECT_EQ(r.planes.size(), 6u);
}

TEST(DetectPlanes, RejectsInvalidOptionsAndEmptyInputGivesNoPlanes) {
  PlaneDetectionOptions o;
  o.epsilon = -1.0;
  RunContext ctx;
  const auto bad = DetectPlanes(Scene{}, o, ctx);
  ASSERT_FALSE(bad.has_value());
  EXPECT_EQ(bad.error().code, ErrorCode::kInvalidOptions);
  EXPECT_NE(bad.error().message.find("epsilon"), std::string::npos);
  using Setter = void (*)(PlaneDetectionOptions&);
  const std::vector<std::pair<std::string, Setter>> bad_blocks = {
      {"block_size", [](PlaneDetectionOptions& x) { x.block_size = -1.0; }},
      {"block_size", [](PlaneDetectionOptions& x) { x.block_size = std::nan(""); }},
      {"block_halo", [](PlaneDetectionOptions& x) { x.block_halo = 0.5; }}};
  for (const auto& [field, set] : bad_blocks) {
    PlaneDetectionOptions b;
    set(b);
    const auto r = DetectPlanes(Scene{}, b, ctx);
    ASSERT_FALSE(r.has_value()) << field;
    EXPECT_NE(r.error().message.find(field), std::string::npos) << r.error().message;
  }
  const auto empty = DetectPlanes(Scene{}, PlaneDetectionOptions{}, ctx);
  ASSERT_TRUE(empty.has_value());
  EXPECT_TRUE(empty->planes.empty());
}

TEST(DetectPlanes, WithBlocksMaxPlanesBoundsEachBlockNotTheTotal) {
  PlaneDetectionOptions o = GridOptions();
  o.block_size = 2.5;
  o.block_halo = 0.3;
  o.max_planes = 6;
  const PlaneDetectionResult r = Detect(CubeGrid(), o);
  EXPECT_GT(r.planes.size(), 6u * 2);  // several blocks, up to 6 planes each
}

TEST(DetectPlanes, AbsurdlySmallBlocksAreRefusedWithAClearError) {
  PlaneDetectionOptions o = GridOptions();
  o.block_size = 1e-9;
  RunContext ctx;
  const auto r = DetectPlanes(CubeGrid(), o, ctx);
  ASSERT_FALSE(r.has_value());
  EXPECT_EQ(r.error().code, ErrorCode::kInvalidOptions);
  EXPECT_NE(r.error().message.find("block_size"), std::string::npos) << r.error().message;
}

TEST(DetectPlanes, CancelStopsTheRun) {
  RunContext ctx;
  ctx.is_cancelled = [] { return true; };
  const auto r = DetectPlanes(NoisyCube(0.0, 0, 1), CubeOptions(), ctx);
  ASSERT_FALSE(r.has_value());
  EXPECT_EQ(r.error().code, ErrorCode::kCancelled);
}

}  // namespace
}  // namespace linesurf
