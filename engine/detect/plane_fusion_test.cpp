#include "engine/detect/plane_fusion.h"

#include "engine/core/endpoint_box.h"
#include "engine/core/rng.h"
#include "engine/detect/segment_geometry.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <set>
#include <tuple>

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

std::vector<SegmentId> UnionOf(const std::vector<SegmentId>& a, const std::vector<SegmentId>& b) {
  std::vector<SegmentId> out;
  std::set_union(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(out));
  return out;
}

/// FusePlanes as its header defines it, with no index: every pair of live planes is a candidate.
/// A pair merges when its inlier boxes are within max_gap on every axis, its angle is under
/// theta_fus, at least p_fus of the smaller support (and one segment) of the union lies within eps
/// of both planes, and every inlier of the union lies within eps_fus of the refit (hinted by the
/// earlier parent's normal); smallest (angle, earlier, later) first. A merged plane is numbered
/// after all others and takes the earlier parent's output position.
int FuseEveryPair(std::span<const Segment3> segments,
                  const FusionParameters& params,
                  std::vector<SupportedPlane>& planes) {
  struct Node {
    SupportedPlane data;
    Box3 box;
    std::size_t key;
    bool alive = true;
  };
  std::vector<Node> nodes;
  for (std::size_t i = 0; i < planes.size(); ++i) {
    nodes.push_back({planes[i], EndpointBox(segments, planes[i].inliers), i});
  }
  const auto within = [&](SegmentId s, const Plane3& plane, double tolerance) {
    return SegmentPlaneDistance(segments[s.index()], plane, params.distance) <= tolerance;
  };
  std::set<std::tuple<double, std::size_t, std::size_t>> pending;
  const auto consider = [&](std::size_t i, std::size_t j) {
    const Node& a = nodes[i];
    const Node& b = nodes[j];
    const double gap = (a.box.min - b.box.max).cwiseMax(b.box.min - a.box.max).maxCoeff();
    const double angle =
        std::acos(std::min(1.0, std::abs(a.data.plane.normal.dot(b.data.plane.normal))));
    if (gap > params.max_gap || angle >= params.max_angle_rad) return;
    const std::vector<SegmentId> both = UnionOf(a.data.inliers, b.data.inliers);
    const auto shared = std::count_if(both.begin(), both.end(), [&](SegmentId s) {
      return within(s, a.data.plane, params.epsilon) && within(s, b.data.plane, params.epsilon);
    });
    const std::size_t smaller = std::min(a.data.inliers.size(), b.data.inliers.size());
    if (static_cast<double>(shared) >=
        std::max(1.0, params.min_shared_fraction * static_cast<double>(smaller))) {
      pending.emplace(angle, i, j);
    }
  };
  for (std::size_t j = 0; j < nodes.size(); ++j) {
    for (std::size_t i = 0; i < j; ++i) consider(i, j);
  }
  int merges = 0;
  while (!pending.empty()) {
    const auto [angle, i, j] = *pending.begin();
    pending.erase(pending.begin());
    if (!nodes[i].alive || !nodes[j].alive) continue;
    std::vector<SegmentId> merged = UnionOf(nodes[i].data.inliers, nodes[j].data.inliers);
    const Plane3 plane = FitPlane(segments, merged, nodes[i].data.plane.normal);
    if (!std::all_of(merged.begin(), merged.end(), [&](SegmentId s) {
          return within(s, plane, params.epsilon_fusion);
        })) {
      continue;
    }
    nodes[i].alive = false;
    nodes[j].alive = false;
    const std::size_t key = std::min(nodes[i].key, nodes[j].key);
    const Box3 box = EndpointBox(segments, merged);
    nodes.push_back({SupportedPlane{plane, std::move(merged)}, box, key});
    ++merges;
    for (std::size_t k = 0; k + 1 < nodes.size(); ++k) {
      if (nodes[k].alive) consider(k, nodes.size() - 1);
    }
  }
  std::erase_if(nodes, [](const Node& node) { return !node.alive; });
  std::sort(nodes.begin(), nodes.end(), [](const Node& a, const Node& b) { return a.key < b.key; });
  planes.clear();
  for (Node& node : nodes) planes.push_back(std::move(node.data));
  return merges;
}

/// The ids as numbers, which gtest prints readably.
std::vector<std::size_t> Indices(const std::vector<SegmentId>& ids) {
  std::vector<std::size_t> out;
  for (const SegmentId s : ids) out.push_back(s.index());
  return out;
}

struct FusionScene {
  std::vector<Segment3> segments;
  std::vector<SupportedPlane> planes;
};

/// `normal` turned by `angle` toward a random direction across it.
Vec3 Tilted(const Vec3& normal, double angle, Rng& rng) {
  const Vec3 random(rng.Normal(), rng.Normal(), rng.Normal());
  return std::cos(angle) * normal + std::sin(angle) * normal.cross(random).normalized();
}

/// Pieces of 9 base planes with random normals, as per-block detection leaves them, in random
/// order. Each base plane is cut by a 6 x 7 grid of its own whose rows and columns lie 0 to 3
/// apart (pieces meet at gaps on both sides of max_gap). A piece holds 4 to 10 segments on the
/// base plane (3 mm noise) under a plane of random sign tilted up to 0.02 rad from it; one piece
/// in five is a 30 cm patch whose plane, fitted to a few short segments, tilts up to 0.15 rad
/// and may still merge; one in ten is found twice (the same segments under another tilt). Every
/// third base plane lies 2 to 30 cm beside the previous one and up to 0.1 rad from it: pieces
/// close in angle but offset, of which some merge and some are too thick.
FusionScene RandomPieces(std::uint64_t seed) {
  Rng rng(seed);
  FusionScene scene;
  Plane3 base;
  for (int b = 0; b < 9; ++b) {
    if (b % 3 == 1) {
      base.normal = Tilted(base.normal, rng.Uniform(0.0, 0.1), rng);
      base.point += rng.Uniform(0.02, 0.3) * base.normal;
    } else {
      base.normal = Tilted(Vec3::UnitZ(), std::acos(rng.Uniform(-1.0, 1.0)), rng);
      base.point = Vec3(rng.Uniform(-20, 20), rng.Uniform(-20, 20), rng.Uniform(-20, 20));
    }
    const Vec3 u = base.normal.unitOrthogonal();
    const Vec3 v = base.normal.cross(u);
    // Lines of the grid: pieces 0.5 to 1.5 wide, then a gap of up to 3.
    const auto grid_lines = [&](int n) {
      std::vector<double> lines{0.0};
      for (int i = 0; i < 2 * n - 1; ++i) {
        lines.push_back(lines.back() +
                        (i % 2 == 0 ? rng.Uniform(0.5, 1.5) : rng.Uniform(0.0, 3.0)));
      }
      return lines;
    };
    const std::vector<double> rows = grid_lines(6);
    const std::vector<double> columns = grid_lines(7);
    for (std::size_t r = 0; r < rows.size(); r += 2) {
      for (std::size_t c = 0; c < columns.size(); c += 2) {
        const bool patch = rng.Uniform() < 0.2;
        const double row_end = patch ? rows[r] + 0.3 : rows[r + 1];
        const double column_end = patch ? columns[c] + 0.3 : columns[c + 1];
        const auto on_piece = [&] {
          return base.point + rng.Uniform(rows[r], row_end) * u +
                 rng.Uniform(columns[c], column_end) * v + 0.003 * rng.Normal() * base.normal;
        };
        SupportedPlane piece;
        const int count = 4 + static_cast<int>(rng.Below(7));
        for (int i = 0; i < count; ++i) {
          piece.inliers.emplace_back(static_cast<std::uint32_t>(scene.segments.size()));
          scene.segments.push_back({on_piece(), on_piece()});
        }
        for (int copy = 0; copy < (rng.Uniform() < 0.1 ? 2 : 1); ++copy) {
          const double sign = rng.Uniform() < 0.5 ? -1.0 : 1.0;
          const double tilt = rng.Uniform(0.0, patch ? 0.15 : 0.02);
          piece.plane.normal = sign * Tilted(base.normal, tilt, rng);
          piece.plane.point =
              base.point + 0.5 * (rows[r] + row_end) * u + 0.5 * (columns[c] + column_end) * v;
          scene.planes.push_back(piece);
        }
      }
    }
  }
  for (std::size_t i = scene.planes.size(); i > 1; --i) {
    std::swap(scene.planes[i - 1], scene.planes[rng.Below(i)]);
  }
  return scene;
}

TEST(FusePlanes, MergesAsTheGreedyPassOverEveryPair) {
  // Each scene has ~415 pieces and 2,650 segments. Even seeds bound the gap (0.5 to 1.4: 130 to
  // 330 merges, thousands of pairs refused for their gap), odd ones do not (about 405 merges, to
  // the base planes or nearly). Either way the index of near planes is rebuilt several times (once
  // per ~35 merges) and merged supports grow past the size searched through their pieces; some
  // pairs share too little, some merges are too thick.
  for (std::uint64_t seed = 0; seed < 40; ++seed) {
    SCOPED_TRACE(seed);
    const FusionScene scene = RandomPieces(seed);
    FusionParameters params = CentimetreParameters();
    if (seed % 2 == 0) params.max_gap = 0.5 + 0.05 * static_cast<double>(seed % 20);
    params.distance = seed % 4 < 2 ? SegmentDistance::kMeanEndpoint : SegmentDistance::kMaxEndpoint;
    std::vector<SupportedPlane> fused = scene.planes;
    std::vector<SupportedPlane> expected = scene.planes;
    const int merges = FuseEveryPair(scene.segments, params, expected);
    ASSERT_GT(merges, 100) << "too few merges to rebuild the index";
    ASSERT_EQ(FusePlanes(scene.segments, params, fused), merges);
    ASSERT_EQ(fused.size(), expected.size());
    // Equal, not near: both refit the same inliers with the same hint.
    for (std::size_t p = 0; p < fused.size(); ++p) {
      ASSERT_EQ(Indices(fused[p].inliers), Indices(expected[p].inliers)) << "plane " << p;
      ASSERT_EQ(fused[p].plane.normal, expected[p].plane.normal) << "plane " << p;
      ASSERT_EQ(fused[p].plane.point, expected[p].plane.point) << "plane " << p;
    }
  }
}

}  // namespace
}  // namespace linesurf::detect
