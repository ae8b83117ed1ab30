#include "partition/mesh/triangle_tree.h"

#include "engine/core/exception.h"

#include <gtest/gtest.h>

namespace linesurf::partition {
namespace {

/// The unit square z = 0 as one quad, plus a degenerate (collinear) triangle as face 1.
PolygonMesh SquareAndSliver() {
  PolygonMesh m;
  m.vertices = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {2, 0, 0}, {3, 0, 0}, {4, 0, 0}};
  const std::uint32_t quad[] = {0, 1, 2, 3};
  const std::uint32_t sliver[] = {4, 5, 6};
  m.AddFace(quad);
  m.AddFace(sliver);
  return m;
}

TEST(TriangleTree, FansFacesAndSkipsDegenerateTriangles) {
  const TriangleTree tree(SquareAndSliver(), "test", "square");
  ASSERT_EQ(tree.NumTriangles(), 2u);
  EXPECT_EQ(tree.FaceOf(0), 0u);
  EXPECT_EQ(tree.FaceOf(1), 0u);
  EXPECT_DOUBLE_EQ(tree.Area(0) + tree.Area(1), 1.0);
  EXPECT_EQ(tree.Corners(1)[2], Vec3(0, 1, 0));
}

TEST(TriangleTree, NearestPointDistanceAndSegmentHits) {
  const TriangleTree tree(SquareAndSliver(), "test", "square");
  const TriangleTree::Nearest n = tree.Closest({0.25, 0.5, 2.0});
  EXPECT_NEAR(n.squared_distance, 4.0, 1e-12);
  EXPECT_NEAR((n.point - Vec3(0.25, 0.5, 0.0)).norm(), 0.0, 1e-12);
  EXPECT_EQ(tree.FaceOf(n.triangle), 0u);
  EXPECT_NEAR(tree.SquaredDistance({2.0, 0.5, 0.0}), 1.0, 1e-12);
  EXPECT_TRUE(tree.Intersects({0.5, 0.2, -1.0}, {0.5, 0.2, 1.0}));
  EXPECT_FALSE(tree.Intersects({0.5, 0.2, 0.5}, {0.5, 0.2, 1.0}));
  std::vector<std::uint32_t> hits{7};
  tree.IntersectedTriangles({0.5, 0.2, -1.0}, {0.5, 0.2, 1.0}, hits);
  ASSERT_EQ(hits.size(), 1u);
  EXPECT_EQ(tree.FaceOf(hits[0]), 0u);
  tree.IntersectedTriangles({5.0, 5.0, -1.0}, {5.0, 5.0, 1.0}, hits);
  EXPECT_TRUE(hits.empty());
}

TEST(TriangleTree, BadIndicesAndEmptyMeshesAreInvalidInput) {
  PolygonMesh bad = SquareAndSliver();
  bad.face_indices[2] = 99;
  try {
    const TriangleTree tree(bad, "test", "result");
    FAIL() << "no error";
  } catch (const LinesurfException& e) {
    EXPECT_EQ(e.error().code, ErrorCode::kInvalidInput);
    EXPECT_NE(e.error().message.find("result mesh: face 0 refers to vertex 99"), std::string::npos);
  }
  PolygonMesh sliver;
  sliver.vertices = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}};
  const std::uint32_t face[] = {0, 1, 2};
  sliver.AddFace(face);
  EXPECT_THROW(TriangleTree(sliver, "test", "sliver"), LinesurfException);
}

}  // namespace
}  // namespace linesurf::partition
