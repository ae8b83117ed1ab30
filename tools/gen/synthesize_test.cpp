#include "tools/gen/synthesize.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <set>
#include <string>

#include <gtest/gtest.h>

#include <numbers>

#include <Eigen/Geometry>

#include "tests/support/mesh_checks.h"
#include "tools/gen/synthetic_meta.h"

namespace linesurf::synth {
namespace {

SyntheticScene Make(const SynthSpec& spec) {
  Expected<SyntheticScene> scene = Synthesize(spec);
  EXPECT_TRUE(scene.has_value()) << (scene ? "" : scene.error().ToString());
  return std::move(scene).value();
}

void Append(std::string& out, const void* data, std::size_t n) {
  out.append(static_cast<const char*>(data), n);
}
void AppendVec(std::string& out, const Vec3& v) { Append(out, v.data(), 3 * sizeof(double)); }

/// Every value of the scene, byte for byte.
std::string Serialize(const SyntheticScene& s) {
  std::string out;
  for (const Segment3& seg : s.scene.segments) {
    AppendVec(out, seg.p1);
    AppendVec(out, seg.p2);
  }
  for (const Vec3& v : s.scene.viewpoints) AppendVec(out, v);
  for (ViewpointId v : s.scene.observations.items()) out += std::to_string(v.value()) + ",";
  for (std::uint32_t o : s.scene.observations.offsets()) out += std::to_string(o) + ";";
  for (const PlaneMembership& m : s.scene.memberships) {
    out += std::to_string(m.count) + ":" + std::to_string(m.planes[0].value()) + ":" +
           std::to_string(m.planes[1].value()) + ";";
  }
  for (const Plane3& p : s.true_planes) {
    AppendVec(out, p.point);
    AppendVec(out, p.normal);
  }
  for (SegmentKind k : s.kinds) out += SegmentKindName(k);
  for (const Vec3& v : s.ground_truth.vertices) AppendVec(out, v);
  for (std::uint32_t i : s.ground_truth.face_indices) out += std::to_string(i) + ",";
  for (std::uint32_t i : s.ground_truth.face_offsets) out += std::to_string(i) + ";";
  return out;
}

/// Fails when a sample of the sight ray from each listed viewpoint to the segment's midpoint is
/// strictly inside the convex solid bounded by the true planes (cube, house).
void ExpectSightRaysOutsideConvexSolid(const SyntheticScene& s) {
  constexpr double kInsideMargin = 1e-6;
  constexpr int kSamples = 200;
  for (std::size_t i = 0; i < s.scene.segments.size(); ++i) {
    if (s.kinds[i] == SegmentKind::kOutlier) continue;
    const Vec3 mid = s.scene.segments[SegmentId(i)].Midpoint();
    for (ViewpointId v : s.scene.observations[SegmentId(i)]) {
      const Vec3& eye = s.scene.viewpoints[v];
      for (int k = 0; k < kSamples; ++k) {
        const Vec3 p = eye + (mid - eye) * (0.99 * k / kSamples);
        bool inside = true;
        for (const Plane3& plane : s.true_planes) {
          inside = inside && plane.SignedDistance(p) < -kInsideMargin;
        }
        ASSERT_FALSE(inside) << "segment " << i << " seen through the solid from viewpoint "
                             << v.value();
      }
    }
  }
}

TEST(Synthesize, RejectsBadSpecs) {
  SynthSpec spec;
  spec.family = "castle";
  EXPECT_EQ(Synthesize(spec).error().code, ErrorCode::kInvalidOptions);
  spec = SynthSpec{};
  spec.noise_sigma = -1.0;
  EXPECT_EQ(Synthesize(spec).error().code, ErrorCode::kInvalidOptions);
  spec = SynthSpec{};
  spec.outlier_fraction = 1.0;
  EXPECT_EQ(Synthesize(spec).error().code, ErrorCode::kInvalidOptions);
  spec = SynthSpec{};
  spec.max_views = 0;
  EXPECT_EQ(Synthesize(spec).error().code, ErrorCode::kInvalidOptions);
}

TEST(Synthesize, CubeWithoutNoiseIsItsTwelveEdges) {
  const SyntheticScene s = Make(SynthSpec{});
  ASSERT_EQ(s.scene.segments.size(), 12u);
  ASSERT_EQ(s.true_planes.size(), 6u);
  std::set<std::array<long, 6>> edges;
  for (std::size_t i = 0; i < 12; ++i) {
    const Segment3& seg = s.scene.segments[SegmentId(i)];
    EXPECT_EQ(s.kinds[i], SegmentKind::kStructural);
    EXPECT_EQ(s.scene.memberships[SegmentId(i)].count, 2);
    EXPECT_NEAR(seg.Length(), 2.0, 1e-12);
    // Both endpoints are cube corners.
    for (const Vec3& p : {seg.p1, seg.p2}) {
      for (int a = 0; a < 3; ++a) EXPECT_NEAR(std::abs(p[a]), 1.0, 1e-12);
    }
    // The segment lies on both of its planes.
    for (std::uint8_t k = 0; k < 2; ++k) {
      const Plane3& plane = s.true_planes[s.scene.memberships[SegmentId(i)].planes[k].index()];
      EXPECT_NEAR(plane.SignedDistance(seg.p1), 0.0, 1e-12);
      EXPECT_NEAR(plane.SignedDistance(seg.p2), 0.0, 1e-12);
    }
    std::array<long, 6> key{};
    for (int a = 0; a < 3; ++a) {
      key[a] = std::lround(std::min(seg.p1[a], seg.p2[a]));
      key[3 + a] = std::lround(std::max(seg.p1[a], seg.p2[a]));
    }
    edges.insert(key);
    EXPECT_GE(s.scene.observations[SegmentId(i)].size(), 1u);
    EXPECT_LE(s.scene.observations[SegmentId(i)].size(), 8u);
  }
  EXPECT_EQ(edges.size(), 12u);
  EXPECT_EQ(s.num_hidden_dropped, 0u);
}

TEST(Synthesize, CubeGroundTruthIsAClosedOutwardSolidOfVolumeEight) {
  const SyntheticScene s = Make(SynthSpec{});
  const testing::MeshCheckReport r = testing::CheckMesh(s.ground_truth);
  EXPECT_TRUE(r.two_manifold);
  EXPECT_TRUE(r.closed);
  EXPECT_TRUE(r.outward_oriented);
  EXPECT_NEAR(r.volume, 8.0, 1e-9);
  EXPECT_NEAR(s.ground_truth_volume, 8.0, 1e-12);
}

TEST(Synthesize, CubeViewsAreOcclusionCorrect) {
  const SyntheticScene s = Make(SynthSpec{});
  ExpectSightRaysOutsideConvexSolid(s);
  // An edge is never seen by a viewpoint behind both of its faces.
  for (std::size_t i = 0; i < s.scene.segments.size(); ++i) {
    const Vec3 mid = s.scene.segments[SegmentId(i)].Midpoint();
    const PlaneMembership& m = s.scene.memberships[SegmentId(i)];
    for (ViewpointId v : s.scene.observations[SegmentId(i)]) {
      const Vec3& eye = s.scene.viewpoints[v];
      const Vec3 n0 = s.true_planes[m.planes[0].index()].normal;
      const Vec3 n1 = s.true_planes[m.planes[1].index()].normal;
      // Cube planes are outward: normal . midpoint > 0 on the cube.
      const double s0 = (n0.dot(mid) > 0 ? 1 : -1) * n0.dot(eye - mid);
      const double s1 = (n1.dot(mid) > 0 ? 1 : -1) * n1.dot(eye - mid);
      EXPECT_TRUE(s0 > 0 || s1 > 0) << "edge " << i << " seen from behind by " << v.value();
    }
  }
}

TEST(Synthesize, CubeNoiseAndOutliers) {
  SynthSpec spec;
  spec.seed = 3;
  spec.noise_sigma = 0.2;
  spec.noise_model = NoiseModel::kUniformBall;
  spec.outlier_count = 20;
  const SyntheticScene s = Make(spec);
  ASSERT_EQ(s.scene.segments.size(), 32u);
  int outliers = 0;
  for (std::size_t i = 0; i < s.scene.segments.size(); ++i) {
    const Segment3& seg = s.scene.segments[SegmentId(i)];
    if (s.kinds[i] == SegmentKind::kOutlier) {
      ++outliers;
      EXPECT_LE(seg.p1.norm(), 2.0);
      EXPECT_LE(seg.p2.norm(), 2.0);
      EXPECT_EQ(s.scene.memberships[SegmentId(i)].count, 0);
    } else {
      // Endpoints moved by at most the noise radius from a cube corner.
      for (const Vec3& p : {seg.p1, seg.p2}) {
        const Vec3 corner(p.x() > 0 ? 1 : -1, p.y() > 0 ? 1 : -1, p.z() > 0 ? 1 : -1);
        EXPECT_LE((p - corner).norm(), 0.2 + 1e-12);
      }
    }
    EXPECT_GE(s.scene.observations[SegmentId(i)].size(), 1u);
  }
  EXPECT_EQ(outliers, 20);
}

TEST(Synthesize, OutlierFractionGivesThatShareOfSegments) {
  SynthSpec spec;
  spec.family = "house";
  spec.outlier_fraction = 0.2;
  const SyntheticScene s = Make(spec);
  std::size_t outliers = 0;
  for (SegmentKind k : s.kinds) outliers += k == SegmentKind::kOutlier ? 1 : 0;
  EXPECT_NEAR(static_cast<double>(outliers) / static_cast<double>(s.kinds.size()), 0.2, 0.01);
}

TEST(Synthesize, SameSeedGivesIdenticalBytesOtherSeedDiffers) {
  for (const char* family : {"cube", "house", "lshape", "room", "floor", "city"}) {
    SynthSpec spec;
    spec.family = family;
    spec.seed = 11;
    spec.noise_sigma = 0.01;
    spec.outlier_fraction = 0.05;
    spec.size = 9;
    const std::string a = Serialize(Make(spec));
    const std::string b = Serialize(Make(spec));
    EXPECT_EQ(a, b) << family;
    spec.seed = 12;
    EXPECT_NE(a, Serialize(Make(spec))) << family;
  }
}

void ExpectValidSolid(const SyntheticScene& s, std::size_t components) {
  const testing::MeshCheckReport r = testing::CheckMesh(s.ground_truth);
  EXPECT_TRUE(r.two_manifold) << s.spec.family;
  EXPECT_TRUE(r.closed) << s.spec.family;
  EXPECT_TRUE(r.outward_oriented) << s.spec.family;
  EXPECT_EQ(r.num_components, components) << s.spec.family;
  EXPECT_NEAR(r.volume, s.ground_truth_volume, 1e-9 * s.ground_truth_volume) << s.spec.family;
}

/// Every non-outlier segment lies on its true planes (before noise) and has 1..max_views views.
void ExpectSegmentsOnTheirPlanes(const SyntheticScene& s) {
  for (std::size_t i = 0; i < s.scene.segments.size(); ++i) {
    const auto views = s.scene.observations[SegmentId(i)];
    EXPECT_GE(views.size(), 1u);
    EXPECT_LE(views.size(), static_cast<std::size_t>(s.spec.max_views));
    const PlaneMembership& m = s.scene.memberships[SegmentId(i)];
    EXPECT_EQ(m.count, s.kinds[i] == SegmentKind::kStructural ? 2 : s.kinds[i] == SegmentKind::kTextural ? 1 : 0);
    const Segment3& seg = s.scene.segments[SegmentId(i)];
    for (std::uint8_t k = 0; k < m.count; ++k) {
      const Plane3& plane = s.true_planes[m.planes[k].index()];
      EXPECT_NEAR(plane.SignedDistance(seg.p1), 0.0, 1e-9);
      EXPECT_NEAR(plane.SignedDistance(seg.p2), 0.0, 1e-9);
    }
  }
}

SynthSpec Family(const char* family, int size = 0) {
  SynthSpec spec;
  spec.family = family;
  spec.size = size;
  return spec;
}

TEST(Synthesize, HouseIsAClosedGableSolidWithVisibleLines) {
  const SyntheticScene s = Make(Family("house"));
  ExpectValidSolid(s, 1);
  EXPECT_NEAR(s.ground_truth_volume, 600.0, 1e-9);
  EXPECT_EQ(s.true_planes.size(), 7u);
  EXPECT_FALSE(s.interior);
  ExpectSegmentsOnTheirPlanes(s);
  std::size_t structural = 0, textural = 0;
  for (SegmentKind k : s.kinds) {
    structural += k == SegmentKind::kStructural ? 1 : 0;
    textural += k == SegmentKind::kTextural ? 1 : 0;
  }
  // 15 sharp edges, cut into up to 3 pieces; windows, door, bands and tiles as texture.
  EXPECT_GE(structural, 15u);
  EXPECT_GE(textural, 40u);
}

TEST(Synthesize, HouseViewsAreOcclusionCorrect) {
  const SyntheticScene s = Make(Family("house"));
  ExpectSightRaysOutsideConvexSolid(s);
  // Texture on the north wall (y = 4) is never seen from behind the house (y < -4).
  std::size_t north = 0;
  for (std::size_t i = 0; i < s.scene.segments.size(); ++i) {
    const Segment3& seg = s.scene.segments[SegmentId(i)];
    if (s.kinds[i] != SegmentKind::kTextural || std::abs(seg.p1.y() - 4.0) > 1e-9 ||
        std::abs(seg.p2.y() - 4.0) > 1e-9) {
      continue;
    }
    ++north;
    for (ViewpointId v : s.scene.observations[SegmentId(i)]) {
      EXPECT_GT(s.scene.viewpoints[v].y(), 4.0) << "north-wall segment " << i;
    }
  }
  EXPECT_GT(north, 10u);
}

/// The room's matter, as documented in docs/user/synthetic.md (independent of the generator).
bool InRoomMatter(const Vec3& p) {
  const auto in = [&](Vec3 lo, Vec3 hi) {
    return (p.array() > lo.array()).all() && (p.array() < hi.array()).all();
  };
  bool table = in({2.0, 2.0, 0.70}, {3.6, 3.0, 0.78});
  for (double x : {2.05, 3.47}) {
    for (double y : {2.05, 2.87}) table = table || in({x, y, 0}, {x + 0.08, y + 0.08, 0.70});
  }
  const bool cavity = in({0, 0, 0}, {6, 5, 2.8}) || in({1.0, -0.2, 0}, {1.9, 0, 2.1}) ||
                      in({6, 1.5, 0.9}, {6.2, 3.5, 2.1}) || in({3.5, 5, 1}, {5, 5.2, 2});
  return table || (in({-0.3, -0.3, -0.3}, {6.3, 5.3, 3.1}) && !cavity);
}

TEST(Synthesize, RoomIsAShellWithATableSeenFromInside) {
  const SyntheticScene s = Make(Family("room"));
  ExpectValidSolid(s, 2);  // outer surface + inner surface (room, niches and table)
  const double expected = 6.6 * 5.6 * 3.4 - 6 * 5 * 2.8 - 0.9 * 0.2 * 2.1 - 0.2 * 2.0 * 1.2 -
                          1.5 * 0.2 * 1.0 + 1.6 * 1.0 * 0.08 + 4 * 0.08 * 0.08 * 0.70;
  EXPECT_NEAR(s.ground_truth_volume, expected, 1e-9);
  EXPECT_TRUE(s.interior);
  ExpectSegmentsOnTheirPlanes(s);
  for (const Vec3& v : s.scene.viewpoints) EXPECT_FALSE(InRoomMatter(v));
  // Sight rays never cross the matter (walls, table).
  std::size_t rays = 0;
  for (std::size_t i = 0; i < s.scene.segments.size(); ++i) {
    const Vec3 mid = s.scene.segments[SegmentId(i)].Midpoint();
    for (ViewpointId v : s.scene.observations[SegmentId(i)]) {
      const Vec3& eye = s.scene.viewpoints[v];
      for (int k = 0; k < 200; ++k) {
        ASSERT_FALSE(InRoomMatter(eye + (mid - eye) * (0.99 * k / 200)))
            << "segment " << i << " seen through matter from " << v.value();
      }
      ++rays;
    }
  }
  EXPECT_GT(rays, 100u);
  // Legs stand on the floor: some structural segments lie on the floor plane z = 0 at the legs.
  std::size_t leg_feet = 0;
  for (std::size_t i = 0; i < s.scene.segments.size(); ++i) {
    const Segment3& seg = s.scene.segments[SegmentId(i)];
    if (s.kinds[i] == SegmentKind::kStructural && std::abs(seg.p1.z()) < 1e-9 &&
        std::abs(seg.p2.z()) < 1e-9 && seg.p1.x() > 2.0 && seg.p1.x() < 3.6 &&
        seg.p1.y() > 2.0 && seg.p1.y() < 3.0) {
      ++leg_feet;
    }
  }
  EXPECT_GT(leg_feet, 0u);
}

TEST(Synthesize, CityIsClosedBuildingsWithStreetViews) {
  const SyntheticScene s = Make(Family("city", 25));
  ExpectValidSolid(s, 25);
  ExpectSegmentsOnTheirPlanes(s);
  EXPECT_GT(s.scene.segments.size(), 25u * 40u);
}

TEST(Synthesize, CitySightRaysNeverCrossABuilding) {
  const SyntheticScene s = Make(Family("city", 16));
  // Samples of every sight ray (eye to midpoint and to both ends), tested against the ground
  // truth with CGAL (independent of the generator's own ray/triangle tests).
  constexpr int kSamples = 40;
  std::vector<Vec3> samples;
  std::vector<std::size_t> owner;
  for (std::size_t i = 0; i < s.scene.segments.size(); ++i) {
    if (s.kinds[i] == SegmentKind::kOutlier) continue;
    const Segment3& seg = s.scene.segments[SegmentId(i)];
    for (ViewpointId v : s.scene.observations[SegmentId(i)]) {
      const Vec3& eye = s.scene.viewpoints[v];
      const std::array<Vec3, 3> targets = {seg.Midpoint(), Vec3(seg.p1 + 0.02 * (seg.p2 - seg.p1)),
                                            Vec3(seg.p1 + 0.98 * (seg.p2 - seg.p1))};
      for (const Vec3& target : targets) {
        for (int k = 0; k < kSamples; ++k) {
          samples.push_back(eye + (target - eye) * (0.995 * k / kSamples));
          owner.push_back(i);
        }
      }
    }
  }
  const std::vector<bool> inside = testing::PointsStrictlyInside(s.ground_truth, samples);
  ASSERT_EQ(inside.size(), samples.size());
  std::size_t crossing = 0;
  for (std::size_t k = 0; k < inside.size(); ++k) {
    if (inside[k]) {
      ++crossing;
      ADD_FAILURE() << "segment " << owner[k] << " seen through a building";
      if (crossing > 5) break;
    }
  }
  EXPECT_GT(samples.size(), 10000u);
}

TEST(Synthesize, CityOfAThousandBuildingsGenerates) {
  const SyntheticScene s = Make(Family("city", 1000));
  EXPECT_EQ(testing::CheckMesh(s.ground_truth).num_components, 1000u);
  EXPECT_GT(s.scene.segments.size(), 50000u);
  EXPECT_EQ(s.kinds.size(), s.scene.segments.size());
}

TEST(Synthesize, OffsetShiftsEverythingInXY) {
  SynthSpec spec = Family("house");
  const SyntheticScene a = Make(spec);
  spec.offset = 1e6;
  const SyntheticScene b = Make(spec);
  ASSERT_EQ(a.scene.segments.size(), b.scene.segments.size());
  const Vec3 shift(1e6, 1e6, 0);
  for (std::size_t i = 0; i < a.scene.segments.size(); ++i) {
    EXPECT_NEAR((b.scene.segments[SegmentId(i)].p1 - a.scene.segments[SegmentId(i)].p1 - shift).norm(), 0.0, 1e-6);
  }
  for (std::size_t p = 0; p < a.true_planes.size(); ++p) {
    EXPECT_NEAR(b.true_planes[p].SignedDistance(a.true_planes[p].point + shift), 0.0, 1e-6);
  }
  EXPECT_TRUE(testing::IsClosed(b.ground_truth));
}

TEST(Synthesize, ScaleAndRotationMoveEverythingAsOneSimilarity) {
  SynthSpec spec = Family("house");
  spec.noise_sigma = 0.01;
  spec.outlier_fraction = 0.05;
  const SyntheticScene a = Make(spec);
  spec.scale = 37.1;
  spec.rotation_axis = {1.0, 2.0, 3.0};
  spec.rotation_degrees = 70.0;
  const SyntheticScene b = Make(spec);
  const Eigen::Matrix3d r =
      Eigen::AngleAxisd(70.0 * std::numbers::pi / 180.0, Vec3(1, 2, 3).normalized())
          .toRotationMatrix();
  const auto move = [&](const Vec3& p) -> Vec3 { return r * (37.1 * p); };
  // The same segments, noise and views, moved: the random streams do not see the frame.
  ASSERT_EQ(a.scene.segments.size(), b.scene.segments.size());
  for (std::size_t i = 0; i < a.scene.segments.size(); ++i) {
    EXPECT_NEAR((b.scene.segments[SegmentId(i)].p1 - move(a.scene.segments[SegmentId(i)].p1)).norm(),
                0.0, 1e-9);
    EXPECT_NEAR((b.scene.segments[SegmentId(i)].p2 - move(a.scene.segments[SegmentId(i)].p2)).norm(),
                0.0, 1e-9);
  }
  EXPECT_EQ(a.scene.observations.offsets(), b.scene.observations.offsets());
  ASSERT_EQ(a.true_planes.size(), b.true_planes.size());
  for (std::size_t p = 0; p < a.true_planes.size(); ++p) {
    EXPECT_NEAR((b.true_planes[p].normal - r * a.true_planes[p].normal).norm(), 0.0, 1e-12);
    EXPECT_NEAR(b.true_planes[p].SignedDistance(move(a.true_planes[p].point)), 0.0, 1e-9);
  }
  const testing::MeshCheckReport ra = testing::CheckMesh(a.ground_truth);
  const testing::MeshCheckReport rb = testing::CheckMesh(b.ground_truth);
  EXPECT_TRUE(rb.outward_oriented);
  EXPECT_NEAR(rb.volume / ra.volume, 37.1 * 37.1 * 37.1, 1e-6);
  EXPECT_NEAR(b.ground_truth_volume / a.ground_truth_volume, 37.1 * 37.1 * 37.1, 1e-9);
  const std::array<double, 3> up = UpDirection(spec);
  EXPECT_NEAR((Vec3(up[0], up[1], up[2]) - r * Vec3::UnitZ()).norm(), 0.0, 1e-15);
  const std::string meta = SyntheticMetaJson(b);
  EXPECT_NE(meta.find("\"scale\": 37.1"), std::string::npos);
  EXPECT_NE(meta.find("\"up\""), std::string::npos);

  SynthSpec bad = Family("house");
  bad.scale = 0.0;
  EXPECT_EQ(Synthesize(bad).error().code, ErrorCode::kInvalidOptions);
  bad = Family("house");
  bad.rotation_axis = {0.0, 0.0, 0.0};
  bad.rotation_degrees = 10.0;
  EXPECT_EQ(Synthesize(bad).error().code, ErrorCode::kInvalidOptions);
}

TEST(Synthesize, MetaJsonIsDeterministicAndListsEverySegment) {
  SynthSpec spec = Family("room");
  spec.outlier_fraction = 0.05;
  const SyntheticScene s = Make(spec);
  const std::string meta = SyntheticMetaJson(s);
  EXPECT_EQ(meta, SyntheticMetaJson(Make(spec)));
  std::size_t kinds = 0;
  for (std::size_t pos = meta.find("\"kind\""); pos != std::string::npos; pos = meta.find("\"kind\"", pos + 1)) ++kinds;
  EXPECT_EQ(kinds, s.scene.segments.size());
  EXPECT_NE(meta.find("\"family\": \"room\""), std::string::npos);
}

}  // namespace
}  // namespace linesurf::synth

namespace linesurf::synth {
namespace {

TEST(Synthesize, LShapeIsAClosedPrismWithVisibleLines) {
  const SyntheticScene s = Make(Family("lshape"));
  ExpectValidSolid(s, 1);
  EXPECT_NEAR(s.ground_truth_volume, 1099.0, 1e-9);
  EXPECT_EQ(s.true_planes.size(), 8u);
  ExpectSegmentsOnTheirPlanes(s);
  // The reflex corner's vertical edge is a sharp edge too.
  EXPECT_GE(std::count(s.kinds.begin(), s.kinds.end(), SegmentKind::kStructural), 18);
}

TEST(Synthesize, FloorIsAShellOfThreeRoomsSeenFromInside) {
  const SyntheticScene s = Make(Family("floor"));
  ExpectValidSolid(s, 2);  // outer surface + the rooms' inner surface (joined by the doors)
  const double expected = 10.6 * 8.6 * 3.4 - 4 * 8 * 2.8 - 5.85 * 4 * 2.8 - 5.85 * 3.85 * 2.8 -
                          3 * 0.15 * 1.0 * 2.1 - 0.2 * 2.0 * 1.2 - 2.5 * 0.2 * 1.0 -
                          0.2 * 1.5 * 1.0;
  EXPECT_NEAR(s.ground_truth_volume, expected, 1e-9);
  EXPECT_TRUE(s.interior);
  ExpectSegmentsOnTheirPlanes(s);
  // Every room is seen: some segment with a view from each room's first viewpoint (ids 0, 6, 12).
  for (std::uint32_t first : {0u, 6u, 12u}) {
    bool seen = false;
    for (ViewpointId v : s.scene.observations.items()) seen = seen || v.value() == first;
    EXPECT_TRUE(seen) << "viewpoint " << first;
  }
}

TEST(Synthesize, ResidualSplitGivesOneSubSegmentPerObservationOnItsLine) {
  SynthSpec spec = Family("house");
  spec.noise_sigma = 0.01;
  spec.outlier_fraction = 0.05;
  const SyntheticScene whole = Make(spec);
  spec.residual_split = true;
  const SyntheticScene split = Make(spec);
  ASSERT_EQ(split.scene.NumSegments(), whole.scene.observations.NumItems());
  std::size_t k = 0;
  for (std::size_t i = 0; i < whole.scene.NumSegments(); ++i) {
    const Segment3& parent = whole.scene.segments[SegmentId(i)];
    const Vec3 dir = (parent.p2 - parent.p1).normalized();
    for (ViewpointId v : whole.scene.observations[SegmentId(i)]) {
      const SegmentId s(k++);
      ASSERT_EQ(split.scene.observations[s].size(), 1u);
      EXPECT_EQ(split.scene.observations[s][0], v);
      EXPECT_EQ(split.kinds[s.index()], whole.kinds[i]);
      EXPECT_EQ(split.scene.memberships[s].count, whole.scene.memberships[SegmentId(i)].count);
      const Segment3& part = split.scene.segments[s];
      for (const Vec3& p : {part.p1, part.p2}) {  // on the parent, inside it, shrunk
        const double t = (p - parent.p1).dot(dir);
        EXPECT_LT(((p - parent.p1) - t * dir).norm(), 1e-9);
        EXPECT_GT(t, 0.0);
        EXPECT_LT(t, parent.Length());
      }
      EXPECT_LE(part.Length(), 0.95 * parent.Length() + 1e-12);
      EXPECT_GE(part.Length(), 0.95 * (1.0 - 2.0 * spec.max_view_trim) * parent.Length() - 1e-12);
    }
  }
}

TEST(Synthesize, Line3DppLikeModelsKeepTheSceneValid) {
  SynthSpec spec = Family("house");
  spec.noise_sigma = 0.02;
  spec.noise_model = NoiseModel::kDepth;
  spec.outlier_model = OutlierModel::kNear;
  spec.outlier_fraction = 0.07;
  const SyntheticScene s = Make(spec);
  std::size_t outliers = 0;
  for (std::size_t i = 0; i < s.scene.NumSegments(); ++i) {
    if (s.kinds[i] != SegmentKind::kOutlier) continue;
    ++outliers;
    EXPECT_FALSE(s.scene.observations[SegmentId(i)].empty());
    EXPECT_EQ(s.scene.memberships[SegmentId(i)].count, 0);
  }
  EXPECT_NEAR(static_cast<double>(outliers) / s.scene.NumSegments(), 0.07, 0.01);
  // Near outliers stay near the house (within its box grown by the largest shift and length).
  for (std::size_t i = 0; i < s.scene.NumSegments(); ++i) {
    const Vec3 m = s.scene.segments[SegmentId(i)].Midpoint();
    EXPECT_LT(std::abs(m.x()), 7.0);
    EXPECT_LT(std::abs(m.y()), 6.0);
  }
  EXPECT_EQ(Serialize(s), Serialize(Make(spec)));
}

}  // namespace
}  // namespace linesurf::synth
