#include "engine/pipeline/mesh_topology.h"

#include "tests/support/box_mesh.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace linesurf::pipeline {
namespace {

using linesurf::testing::Append;
using linesurf::testing::Box;
using linesurf::testing::Cube;

TEST(MeshTopology, CubeIsPairedAndManifold) {
  const MeshTopology t = ComputeMeshTopology(Cube(1.0));
  EXPECT_TRUE(t.paired);
  EXPECT_TRUE(t.IsManifold());
  EXPECT_TRUE(t.consistent);
  EXPECT_EQ(t.num_boundary_edges, 0u);
  EXPECT_EQ(t.num_unpaired_half_edges, 0u);
  EXPECT_EQ(t.num_components, 1u);
  EXPECT_NEAR(t.signed_volume, 8.0, 1e-12);
}

TEST(MeshTopology, OpenBoxHasBoundaryEdgesOnBothCounts) {
  PolygonMesh mesh = Cube(1.0);
  mesh.face_indices.resize(mesh.face_offsets[5]);
  mesh.face_offsets.pop_back();
  const MeshTopology t = ComputeMeshTopology(mesh);
  EXPECT_FALSE(t.paired);
  EXPECT_EQ(t.num_boundary_edges, 4u);
  EXPECT_EQ(t.num_unpaired_half_edges, 4u);
}

TEST(MeshTopology, FlippedFaceIsClosedButNotPaired) {
  PolygonMesh mesh = Cube(1.0);
  std::reverse(mesh.face_indices.begin(), mesh.face_indices.begin() + 4);
  const MeshTopology t = ComputeMeshTopology(mesh);
  EXPECT_EQ(t.num_boundary_edges, 0u);
  EXPECT_FALSE(t.consistent);
  EXPECT_FALSE(t.paired);
  EXPECT_EQ(t.num_unpaired_half_edges, 8u);  // the face's 4 edges and their 4 neighbours
}

TEST(MeshTopology, BoxesSharingAVertexAreNotManifold) {
  // Welded at (1, 1, 1) by index: two fans there, edges still paired.
  PolygonMesh mesh = Append(Box(Vec3(0, 0, 0), Vec3(1, 1, 1)), Box(Vec3(1, 1, 1), Vec3(2, 2, 2)));
  const std::uint32_t a = 7;  // corner (1, 1, 1) of the first box
  const std::uint32_t b = 8;  // corner (1, 1, 1) of the second box
  ASSERT_EQ(mesh.vertices[a], mesh.vertices[b]);
  for (std::uint32_t& v : mesh.face_indices) v = v == b ? a : v;
  const MeshTopology t = ComputeMeshTopology(mesh);
  EXPECT_TRUE(t.paired);
  EXPECT_EQ(t.num_non_manifold_vertices, 1u);
  EXPECT_FALSE(t.IsManifold());
  EXPECT_EQ(t.num_components, 2u);
}

TEST(MeshTopology, ALoneLoopIsItsOwnOpposite) {
  PolygonMesh mesh;
  mesh.vertices = {Vec3::Zero()};
  mesh.AddFace(std::vector<std::uint32_t>{0});
  EXPECT_TRUE(ComputeMeshTopology(mesh).paired);
  mesh.AddFace(std::vector<std::uint32_t>{0});
  EXPECT_EQ(ComputeMeshTopology(mesh).num_unpaired_half_edges, 2u);
}

TEST(MeshTopology, EmptyMeshIsNotPaired) {
  EXPECT_FALSE(ComputeMeshTopology(PolygonMesh{}).paired);
}

}  // namespace
}  // namespace linesurf::pipeline
