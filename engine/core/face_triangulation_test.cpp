#include "engine/core/face_triangulation.h"

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>

namespace linesurf {
namespace {

using Triangles = std::vector<std::array<std::uint32_t, 3>>;

double SignedArea(const std::vector<Vec3>& v, const Triangles& triangles, const Vec3& normal) {
  double area = 0.0;
  for (const auto& t : triangles)
    area += 0.5 * (v[t[1]] - v[t[0]]).cross(v[t[2]] - v[t[0]]).dot(normal);
  return area;
}

std::vector<std::uint32_t> Ring(std::size_t n) {
  std::vector<std::uint32_t> ring(n);
  std::iota(ring.begin(), ring.end(), 0u);
  return ring;
}

TEST(FaceTriangles, AConvexFaceWithAStraightCornerIsTheFanOfItsFirstCorner) {
  const std::vector<Vec3> v{{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {2, 1, 0}, {0, 1, 0}};
  const Triangles t = FaceTriangles(v, Ring(5));
  EXPECT_EQ(t, (Triangles{{0, 1, 2}, {0, 2, 3}, {0, 3, 4}}));
}

TEST(FaceTriangles, AnLShapedFaceIsCoveredByTrianglesInsideIt) {
  // The L of a wall merged across a seam, in the plane x = 5, counter-clockwise about +x:
  // (y, z) = (0,0) (2,0) (2,1) (1,1) (1,2) (0,2); the corner (1,1) is reflex. Its fan from
  // (0,0) would cover the notch (1..2, 1..2) and count area 3.5 for 3.
  const std::vector<Vec3> v{{5, 0, 0}, {5, 2, 0}, {5, 2, 1}, {5, 1, 1}, {5, 1, 2}, {5, 0, 2}};
  const Triangles t = FaceTriangles(v, Ring(6));
  ASSERT_EQ(t.size(), 4u);
  EXPECT_NEAR(SignedArea(v, t, Vec3::UnitX()), 3.0, 1e-12);
  for (const auto& tri : t) {
    // Every triangle is counter-clockwise and its centroid lies outside the notch.
    EXPECT_GE(0.5 * (v[tri[1]] - v[tri[0]]).cross(v[tri[2]] - v[tri[0]]).dot(Vec3::UnitX()), 0.0);
    const Vec3 c = (v[tri[0]] + v[tri[1]] + v[tri[2]]) / 3.0;
    EXPECT_FALSE(c.y() > 1.0 && c.z() > 1.0) << c.transpose();
  }
}

TEST(FaceTriangles, StraightCornersOfANonConvexFaceStayCornersOfTheTriangles) {
  // A U with corners on its straight sides: every corner is used, so a triangulated surface
  // has no T-junction where a neighbouring face ends on a side.
  const std::vector<Vec3> v{{0, 0, 0},
                            {1.5, 0, 0},
                            {3, 0, 0},
                            {3, 2, 0},
                            {2, 2, 0},
                            {2, 1, 0},
                            {1, 1, 0},
                            {1, 2, 0},
                            {0, 2, 0},
                            {0, 1, 0}};
  const Triangles t = FaceTriangles(v, Ring(10));
  ASSERT_EQ(t.size(), 8u);
  EXPECT_NEAR(SignedArea(v, t, Vec3::UnitZ()), 5.0, 1e-12);
  std::vector<bool> used(v.size(), false);
  for (const auto& tri : t) {
    for (const std::uint32_t i : tri) used[i] = true;
  }
  EXPECT_EQ(std::count(used.begin(), used.end(), true), 10);
}

TEST(FaceTriangles, FewerThanThreeCornersGiveNoTriangle) {
  const std::vector<Vec3> v{{0, 0, 0}, {1, 0, 0}};
  EXPECT_TRUE(FaceTriangles(v, Ring(2)).empty());
}

}  // namespace
}  // namespace linesurf
