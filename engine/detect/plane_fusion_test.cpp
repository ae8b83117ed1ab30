#include "engine/detect/plane_fusion.h"

#include <gtest/gtest.h>

#include <cmath>

namespace linesurf::detect {
namespace {

std::vector<SegmentId> Ids(std::initializer_list<int> ids) {
  std::vector<SegmentId> out;
  for (const int i : ids) out.emplace_back(static_cast<std::uint32_t>(i));
  return out;
}

TEST(LimitMemberships, LargerPlanesKeepTheirSegmentsAndSmallLeftoversGo) {
  std::vector<SupportedPlane> planes(4);
  planes[0].inliers = Ids({0, 1, 2, 3});        // 4: visited third; 0 and 1 are taken twice,
                                                // 2 and 3 are too few: the plane goes
  planes[1].inliers = Ids({0, 1, 2, 4, 5, 6});  // 6: visited first, keeps all
  planes[2].inliers = Ids({0, 1, 7, 8, 9});     // 5: visited second, keeps all
  planes[3].inliers = Ids({2, 3, 4});           // 3: 2, 3 and 4 are still free enough
  const std::int64_t dropped = LimitMemberships(10, 3, planes);
  ASSERT_EQ(planes.size(), 3u);
  EXPECT_EQ(planes[0].inliers, Ids({0, 1, 2, 4, 5, 6}));
  EXPECT_EQ(planes[1].inliers, Ids({0, 1, 7, 8, 9}));
  EXPECT_EQ(planes[2].inliers, Ids({2, 3, 4}));
  EXPECT_EQ(dropped, 4);  // plane 0's four memberships
}

/// eps 2 cm, eps_fus 6 cm, theta_fus 0.17 rad, p_fus 0.2.
FusionParameters CentimetreParameters() {
  FusionParameters params;
  params.epsilon = 0.02;
  params.epsilon_fusion = 0.06;
  params.max_angle_rad = 0.17;
  params.min_shared_fraction = 0.2;
  return params;
}

TEST(FusePlanes, PiecesOfOnePlaneMergeOnlyWhenTheyAreWithinTheGap) {
  // Two coplanar pieces of the plane z = 0, 10 apart along x.
  std::vector<Segment3> segments;
  for (int piece = 0; piece < 2; ++piece) {
    for (int i = 0; i < 4; ++i) {
      const double x = 10.0 * piece + 0.5 * i;
      segments.push_back({Vec3(x, 0, 0), Vec3(x + 0.3, 1, 0)});
    }
  }
  auto pieces = [] {
    std::vector<SupportedPlane> planes(2);
    for (int p = 0; p < 2; ++p) {
      planes[p].plane.normal = Vec3::UnitZ();
      planes[p].plane.point = Vec3(10.0 * p, 0, 0);
      planes[p].inliers = Ids({4 * p, 4 * p + 1, 4 * p + 2, 4 * p + 3});
    }
    return planes;
  };
  FusionParameters params = CentimetreParameters();
  std::vector<SupportedPlane> unbounded = pieces();
  EXPECT_EQ(FusePlanes(segments, params, unbounded), 1);
  EXPECT_EQ(unbounded.size(), 1u);
  params.max_gap = 1.0;
  std::vector<SupportedPlane> local = pieces();
  EXPECT_EQ(FusePlanes(segments, params, local), 0);
  EXPECT_EQ(local.size(), 2u);
}

TEST(FusePlanes, PiecesWhoseNormalsLieEitherSideOfADiagonalStillMeet) {
  // Two pieces of the wall x = y (normal (1, -1, 0)), 4 segments each, their normals 0.24 rad
  // and 0.005 rad either side of the wall's: 0.245 rad apart, under max_angle 0.25. The largest
  // component of the first normal is x, of the second y; fusion indexes the planes by that axis,
  // and the first (the one that asks: the lower index) differs from the second's class by 0.34
  // in its components, more than max_angle: a bound of max_angle instead of twice it would skip
  // the pair.
  std::vector<Segment3> segments;
  for (int i = 0; i < 8; ++i) {
    const double t = 0.2 * i;
    segments.push_back({Vec3(t, t, 0), Vec3(t, t, 1)});
  }
  const double wall_normal = std::atan2(-1.0, 1.0);
  std::vector<SupportedPlane> planes(2);
  for (int p = 0; p < 2; ++p) {
    const double a = wall_normal + (p == 0 ? 0.24 : -0.005);
    planes[p].plane.normal = Vec3(std::cos(a), std::sin(a), 0);
    planes[p].plane.point = Vec3(0.7, 0.7, 0.5);
    planes[p].inliers = Ids({4 * p, 4 * p + 1, 4 * p + 2, 4 * p + 3});
  }
  const Vec3 first = planes[0].plane.normal.cwiseAbs();
  const Vec3 second = planes[1].plane.normal.cwiseAbs();
  ASSERT_GT(first.x(), first.y() + 0.3) << "the first normal must lie well inside class x";
  ASSERT_GT(second.y(), second.x()) << "the second normal must lie in class y";
  FusionParameters params = CentimetreParameters();
  params.epsilon = 0.5;  // the tilted pieces still hold each other's segments in their slabs
  params.epsilon_fusion = 1.0;
  params.max_angle_rad = 0.25;
  params.min_shared_fraction = 0.5;
  EXPECT_EQ(FusePlanes(segments, params, planes), 1);
  ASSERT_EQ(planes.size(), 1u);
  EXPECT_EQ(planes[0].inliers.size(), 8u);
}

TEST(FusePlanes, ALargeSupportSharesTheSegmentsInTheOtherPlanesSlabWhereverTheyLie) {
  // A: the ground z = 0 over x in [0, 300], support large enough to be searched through its
  // index. B: a piece of it near x = 0 whose fit tilts: its plane is 0.04 above the ground at
  // x = 0 (its own segments are farther than eps from it) and meets the ground at x = 150, so
  // the shared support is the ground's segments from x = 75 to 225 alone.
  std::vector<Segment3> segments;
  for (int i = 0; i <= 300; ++i) segments.push_back({Vec3(i, 0, 0), Vec3(i + 0.3, 1, 0)});
  for (int i = 0; i < 4; ++i) {
    segments.push_back({Vec3(0.25 * i, 0, 0), Vec3(0.25 * i + 0.3, 1, 0)});
  }
  std::vector<SupportedPlane> planes(2);
  planes[0].plane.normal = Vec3::UnitZ();
  planes[0].plane.point = Vec3::Zero();
  for (int i = 0; i <= 300; ++i) planes[0].inliers.emplace_back(static_cast<std::uint32_t>(i));
  planes[1].plane.normal = Vec3(0.04 / 150.0, 0, 1).normalized();
  planes[1].plane.point = Vec3(0, 0, 0.04);
  planes[1].inliers = Ids({301, 302, 303, 304});
  FusionParameters params = CentimetreParameters();
  EXPECT_EQ(FusePlanes(segments, params, planes), 1);
  ASSERT_EQ(planes.size(), 1u);
  EXPECT_EQ(planes[0].inliers.size(), 305u);
  // Without the band the two share nothing: B moved up by 1 is refused.
  planes.assign(2, SupportedPlane{});
  planes[0].plane.normal = Vec3::UnitZ();
  for (int i = 0; i <= 300; ++i) planes[0].inliers.emplace_back(static_cast<std::uint32_t>(i));
  planes[1].plane.normal = Vec3(0.04 / 150.0, 0, 1).normalized();
  planes[1].plane.point = Vec3(0, 0, 1.04);
  planes[1].inliers = Ids({301, 302, 303, 304});
  EXPECT_EQ(FusePlanes(segments, params, planes), 0);
}

TEST(FusePlanes, ASegmentInSeveralPiecesOfAMergedPlaneCountsOnce) {
  // The ground z = 0 over x in [0, 1000], found twice (two blocks' pieces with the same 1,001
  // segments): the pieces merge first. B: 300 segments at z ~ 0.03 (farther than eps from the
  // ground, within epsilon_fusion) on a plane of slope 0.001 that meets the ground at x = 500.
  // They share the ground's ~40 segments within eps of both planes, each in both pieces of the
  // merged ground: counted once, fewer than 0.2 x 300 = 60 (twice, 80 would merge them); more
  // than 0.1 x 300 = 30.
  std::vector<Segment3> segments;
  for (int i = 0; i <= 1000; ++i) segments.push_back({Vec3(i, 0, 0), Vec3(i + 0.3, 1, 0)});
  const auto on_b = [](double x, double y) { return Vec3(x, y, 0.001 * (x - 500.0)); };
  for (int i = 0; i < 300; ++i) {
    segments.push_back({on_b(530.0 + 0.01 * i, 0), on_b(530.0 + 0.01 * i + 0.3, 1)});
  }
  const auto planes = [] {
    std::vector<SupportedPlane> out(3);
    for (int k = 0; k < 2; ++k) {
      out[k].plane.normal = Vec3::UnitZ();
      for (int i = 0; i <= 1000; ++i) out[k].inliers.emplace_back(static_cast<std::uint32_t>(i));
    }
    out[2].plane = Plane3{Vec3(500, 0, 0), Vec3(-0.001, 0, 1).normalized()};
    for (int i = 0; i < 300; ++i) out[2].inliers.emplace_back(static_cast<std::uint32_t>(1001 + i));
    return out;
  };
  FusionParameters params = CentimetreParameters();
  std::vector<SupportedPlane> refused = planes();
  EXPECT_EQ(FusePlanes(segments, params, refused), 1);
  ASSERT_EQ(refused.size(), 2u);
  EXPECT_EQ(refused[0].inliers.size(), 1001u);
  EXPECT_EQ(refused[1].inliers.size(), 300u);
  params.min_shared_fraction = 0.1;
  std::vector<SupportedPlane> merged = planes();
  EXPECT_EQ(FusePlanes(segments, params, merged), 2);
  ASSERT_EQ(merged.size(), 1u);
  EXPECT_EQ(merged[0].inliers.size(), 1301u);
}

TEST(FusePlanes, HundredsOfPiecesInARowMergeIntoTheirTwoPlanes) {
  // Two parallel rows of 300 touching pieces, on z = 0 and z = 1: 598 merges, enough for the
  // index of near planes to be rebuilt many times; a merged plane must stay findable, both in the
  // list of added planes and after a rebuild.
  constexpr int kPieces = 300;
  std::vector<Segment3> segments;
  std::vector<SupportedPlane> planes;
  for (int row = 0; row < 2; ++row) {
    for (int piece = 0; piece < kPieces; ++piece) {
      SupportedPlane& plane = planes.emplace_back();
      plane.plane = Plane3{Vec3(2.0 * piece, 0, row), Vec3::UnitZ()};
      for (int i = 0; i < 4; ++i) {
        const double x = 2.0 * piece + 0.5 * i;
        plane.inliers.emplace_back(static_cast<std::uint32_t>(segments.size()));
        segments.push_back({Vec3(x, 0, row), Vec3(x + 0.5, 1, row)});
      }
    }
  }
  FusionParameters params = CentimetreParameters();
  params.max_gap = 0.1;
  EXPECT_EQ(FusePlanes(segments, params, planes), 2 * (kPieces - 1));
  ASSERT_EQ(planes.size(), 2u);
  for (const SupportedPlane& plane : planes) {
    EXPECT_EQ(plane.inliers.size(), static_cast<std::size_t>(4 * kPieces));
    EXPECT_NEAR(std::abs(plane.plane.normal.z()), 1.0, 1e-12);
  }
}

}  // namespace
}  // namespace linesurf::detect
