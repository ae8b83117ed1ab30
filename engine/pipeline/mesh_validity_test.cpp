#include "engine/pipeline/mesh_validity.h"

#include "tests/support/box_mesh.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace linesurf {
namespace {

using testing::Append;
using testing::Box;
using testing::Cube;
using testing::Weld;

TEST(MeshValidity, CubeIsValid) {
  const auto v = CheckMeshValidity(Cube(1.0));
  ASSERT_TRUE(v);
  EXPECT_TRUE(v->IsValid());
  EXPECT_TRUE(RefuseBrokenSurface(*v));
  EXPECT_TRUE(SolidValidityWarnings(*v).empty());
}

TEST(MeshValidity, FlippedFaceIsNotOriented) {
  PolygonMesh mesh = Cube(1.0);
  std::reverse(mesh.face_indices.begin(), mesh.face_indices.begin() + 4);
  const auto topo = CheckMeshValidity(mesh);
  ASSERT_TRUE(topo);
  EXPECT_TRUE(topo->closed);
  EXPECT_FALSE(topo->oriented);
  EXPECT_FALSE(topo->outward);
}

TEST(MeshValidity, InsideOutCubeIsNotOutward) {
  PolygonMesh mesh = Cube(1.0);
  for (std::size_t f = 0; f < mesh.NumFaces(); ++f) {
    std::reverse(mesh.face_indices.begin() + mesh.face_offsets[f],
                 mesh.face_indices.begin() + mesh.face_offsets[f + 1]);
  }
  const auto topo = CheckMeshValidity(mesh);
  ASSERT_TRUE(topo);
  EXPECT_TRUE(topo->closed && topo->oriented);
  EXPECT_FALSE(topo->outward);
  EXPECT_NEAR(topo->signed_volume, -8.0, 1e-9);
}

TEST(MeshValidity, OverlappingCubesSelfIntersect) {
  const auto topo = CheckMeshValidity(Append(Cube(1.0), Box(Vec3(0.5, 0.5, 0.5), Vec3(2, 2, 2))));
  ASSERT_TRUE(topo);
  EXPECT_TRUE(topo->self_intersecting);
  EXPECT_EQ(topo->num_components, 2U);
  const auto apart = CheckMeshValidity(Append(Cube(1.0), Box(Vec3(2, 2, 2), Vec3(3, 3, 3))));
  ASSERT_TRUE(apart);
  EXPECT_FALSE(apart->self_intersecting);
  EXPECT_TRUE(apart->two_manifold);
  EXPECT_EQ(apart->num_components, 2U);
}

TEST(MeshValidity, CubesSharingAnEdgeAreNotManifold) {
  // Two unit boxes touching along the edge x = y = 1, sharing its two vertices.
  const PolygonMesh touching = Append(Box(Vec3(0, 0, 0), Vec3(1, 1, 1)), Box(Vec3(1, 1, 0), Vec3(2, 2, 1)));
  const auto topo = CheckMeshValidity(Weld(touching));
  ASSERT_TRUE(topo);
  EXPECT_FALSE(topo->two_manifold);
  EXPECT_FALSE(topo->closed);
  EXPECT_EQ(topo->num_non_manifold_edges, 1U);
  EXPECT_EQ(topo->num_components, 1U);
  EXPECT_FALSE(topo->self_intersecting);
  // With the edge's vertices split into copies (as linesurf's extraction does), the mesh is a
  // closed 2-manifold whose two parts touch: not counted as self-intersecting.
  const auto split = CheckMeshValidity(touching);
  ASSERT_TRUE(split);
  EXPECT_TRUE(split->two_manifold && split->closed && split->outward);
  EXPECT_EQ(split->num_coincident_vertices, 2U);
  EXPECT_FALSE(split->self_intersecting);
  EXPECT_EQ(split->num_components, 2U);
}

TEST(MeshValidity, BadIndexIsInvalidInput) {
  PolygonMesh mesh = Cube(1.0);
  mesh.face_indices[3] = 99;
  const auto topo = CheckMeshValidity(mesh);
  ASSERT_FALSE(topo);
  EXPECT_EQ(topo.error().code, ErrorCode::kInvalidInput);
}

TEST(MeshValidity, DegenerateFaceIsCountedAndRefused) {
  PolygonMesh mesh = Cube(1.0);
  const std::uint32_t sliver[] = {0, 1, 0};
  mesh.AddFace(sliver);
  const auto v = CheckMeshValidity(mesh);
  ASSERT_TRUE(v);
  EXPECT_EQ(v->num_degenerate_faces, 1u);
  EXPECT_FALSE(v->IsValid());
  const Status refused = RefuseBrokenSurface(*v);
  ASSERT_FALSE(refused);
  EXPECT_NE(refused.error().message.find("1 degenerate faces"), std::string::npos);
}

TEST(MeshValidity, ZeroAreaFaceIsCountedAndWarned) {
  // A cube whose bottom face has a collinear copy of its edge as a face of its own: three
  // distinct vertices on one line.
  PolygonMesh mesh = Cube(1.0);
  mesh.vertices.push_back(Vec3(0.0, -1.0, -1.0));  // on the edge between vertices 0 and 1
  const std::uint32_t flat[] = {0, 8, 1};
  mesh.AddFace(flat);
  const auto v = CheckMeshValidity(mesh);
  ASSERT_TRUE(v);
  EXPECT_EQ(v->num_zero_area_faces, 1u);
  EXPECT_FALSE(v->IsValid());
  const auto warnings = SolidValidityWarnings(*v);
  ASSERT_FALSE(warnings.empty());
  EXPECT_NE(warnings.back().find("zero area"), std::string::npos);
}

TEST(MeshValidity, NonPlanarFaceIsCountedAndRefused) {
  PolygonMesh mesh = Cube(1.0);
  mesh.vertices[3].z() += 0.01;  // one corner of the bottom quad lifted by 1 cm
  const auto v = CheckMeshValidity(mesh);
  ASSERT_TRUE(v);
  EXPECT_GE(v->num_non_planar_faces, 1u);
  EXPECT_FALSE(RefuseBrokenSurface(*v));
}

TEST(MeshValidity, OpenAndMisorientedSurfacesAreRefused) {
  PolygonMesh open = Cube(1.0);
  open.face_offsets.pop_back();
  open.face_indices.resize(open.face_offsets.back());
  const auto v = CheckMeshValidity(open);
  ASSERT_TRUE(v);
  EXPECT_EQ(v->num_boundary_edges, 4u);
  const Status refused = RefuseBrokenSurface(*v);
  ASSERT_FALSE(refused);
  EXPECT_EQ(refused.error().code, ErrorCode::kDegenerate);
  EXPECT_NE(refused.error().message.find("4 boundary edges"), std::string::npos);
  PolygonMesh flipped = Cube(1.0);
  std::reverse(flipped.face_indices.begin(), flipped.face_indices.begin() + 4);
  const auto w = CheckMeshValidity(flipped);
  ASSERT_TRUE(w);
  EXPECT_NE(RefuseBrokenSurface(*w).error().message.find("not consistently oriented"),
            std::string::npos);
}

TEST(MeshValidity, IntersectingPartsAreRefusedTouchingOnesWarned) {
  const auto crossing =
      CheckMeshValidity(Append(Cube(1.0), Box(Vec3(0.5, 0.5, 0.5), Vec3(2, 2, 2))));
  ASSERT_TRUE(crossing);
  EXPECT_GT(crossing->num_intersecting_triangle_pairs, 0u);
  EXPECT_FALSE(RefuseBrokenSurface(*crossing));
  // Two boxes touching at the corner (1, 1, 1) with their own copies of it.
  const auto touching =
      CheckMeshValidity(Append(Box(Vec3(0, 0, 0), Vec3(1, 1, 1)), Box(Vec3(1, 1, 1), Vec3(2, 2, 2))));
  ASSERT_TRUE(touching);
  EXPECT_EQ(touching->num_coincident_vertices, 1u);
  EXPECT_GT(touching->num_touching_triangle_pairs, 0u);
  EXPECT_EQ(touching->num_intersecting_triangle_pairs, 0u);
  EXPECT_TRUE(RefuseBrokenSurface(*touching));
  EXPECT_FALSE(touching->IsValid());
  EXPECT_EQ(SolidValidityWarnings(*touching).size(), 2u);
}

}  // namespace
}  // namespace linesurf
