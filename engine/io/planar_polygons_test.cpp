#include "engine/io/planar_polygons.h"

#include "engine/core/vector_area.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace linesurf::io {
namespace {

/// Unit squares of the grid cells `cells` ((i, j): [i, i+1] x [j, j+1], z = 0) on the vertex
/// grid (n+1) x (n+1), counter-clockwise about +z.
PolygonMesh GridSquares(int n, const std::vector<std::pair<int, int>>& cells) {
  PolygonMesh mesh;
  for (int j = 0; j <= n; ++j) {
    for (int i = 0; i <= n; ++i) mesh.vertices.emplace_back(i, j, 0.0);
  }
  auto id = [n](int i, int j) { return static_cast<std::uint32_t>(j * (n + 1) + i); };
  for (const auto& [i, j] : cells) {
    const std::uint32_t face[] = {id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)};
    mesh.AddFace(face);
  }
  return mesh;
}

std::vector<std::uint32_t> AllFaces(const PolygonMesh& mesh) {
  std::vector<std::uint32_t> faces(mesh.NumFaces());
  for (std::uint32_t f = 0; f < faces.size(); ++f) faces[f] = f;
  return faces;
}

double SignedArea(const PolygonMesh& mesh, const std::vector<std::uint32_t>& ring) {
  return 0.5 * TwiceVectorArea(mesh.vertices, ring).z();
}

TEST(PlanarPolygons, NeighboursBecomeOnePolygonKeepingCollinearCorners) {
  const PolygonMesh mesh = GridSquares(2, {{0, 0}, {1, 0}});
  const auto polygons = JoinIntoPlanarPolygons(mesh, AllFaces(mesh), Vec3::UnitZ());
  ASSERT_EQ(polygons.size(), 1u);
  ASSERT_EQ(polygons[0].rings.size(), 1u);
  // The shared edge's ends stay: the faces of other planes may use them.
  EXPECT_EQ(polygons[0].rings[0].size(), 6u);
  EXPECT_DOUBLE_EQ(SignedArea(mesh, polygons[0].rings[0]), 2.0);
}

TEST(PlanarPolygons, ARingOfSquaresHasAHole) {
  std::vector<std::pair<int, int>> cells;
  for (int j = 0; j < 3; ++j) {
    for (int i = 0; i < 3; ++i) {
      if (i != 1 || j != 1) cells.emplace_back(i, j);
    }
  }
  const PolygonMesh mesh = GridSquares(3, cells);
  const auto polygons = JoinIntoPlanarPolygons(mesh, AllFaces(mesh), Vec3::UnitZ());
  ASSERT_EQ(polygons.size(), 1u);
  ASSERT_EQ(polygons[0].rings.size(), 2u);
  EXPECT_EQ(polygons[0].rings[0].size(), 12u);
  EXPECT_DOUBLE_EQ(SignedArea(mesh, polygons[0].rings[0]), 9.0);
  EXPECT_EQ(polygons[0].rings[1].size(), 4u);
  EXPECT_DOUBLE_EQ(SignedArea(mesh, polygons[0].rings[1]), -1.0);  // clockwise
  // No ring passes a vertex twice.
  for (const auto& ring : polygons[0].rings) {
    auto sorted = ring;
    std::sort(sorted.begin(), sorted.end());
    EXPECT_EQ(std::adjacent_find(sorted.begin(), sorted.end()), sorted.end());
  }
}

TEST(PlanarPolygons, InteriorVerticesAreDropped) {
  const PolygonMesh mesh = GridSquares(2, {{0, 0}, {1, 0}, {0, 1}, {1, 1}});
  const auto polygons = JoinIntoPlanarPolygons(mesh, AllFaces(mesh), Vec3::UnitZ());
  ASSERT_EQ(polygons.size(), 1u);
  ASSERT_EQ(polygons[0].rings.size(), 1u);
  const auto& ring = polygons[0].rings[0];
  EXPECT_EQ(ring.size(), 8u);
  EXPECT_EQ(std::count(ring.begin(), ring.end(), 4u), 0);  // the centre (1, 1)
}

TEST(PlanarPolygons, CornersTouchingAtAPointStayApart) {
  // (0,0) and (1,1) meet at vertex (1,1) only: no edge joins them.
  const PolygonMesh apart = GridSquares(2, {{0, 0}, {1, 1}});
  const auto two = JoinIntoPlanarPolygons(apart, AllFaces(apart), Vec3::UnitZ());
  ASSERT_EQ(two.size(), 2u);
  EXPECT_EQ(two[0].rings[0].size(), 4u);
  EXPECT_EQ(two[1].rings[0].size(), 4u);
}

TEST(PlanarPolygons, HoleTouchingTheOuterRingAtAVertex) {
  // A U of five squares whose arms end at one shared vertex: the enclosed square is a hole
  // that meets the outer ring at that vertex; neither ring passes a vertex twice.
  //   row 2: (0,2) (1,2)        the hole is (1,1); the arms (0,2)-(1,2) and (2,1) meet at
  //   row 1: (0,1)       (2,1)  vertex (2,2)
  //   row 0: (0,0) (1,0) (2,0)
  const PolygonMesh mesh = GridSquares(3, {{0, 0}, {1, 0}, {2, 0}, {0, 1}, {2, 1}, {0, 2}, {1, 2}});
  const auto polygons = JoinIntoPlanarPolygons(mesh, AllFaces(mesh), Vec3::UnitZ());
  ASSERT_EQ(polygons.size(), 1u);
  ASSERT_EQ(polygons[0].rings.size(), 2u);
  EXPECT_DOUBLE_EQ(SignedArea(mesh, polygons[0].rings[0]), 8.0);
  EXPECT_DOUBLE_EQ(SignedArea(mesh, polygons[0].rings[1]), -1.0);
}

TEST(PlanarPolygons, ReversedNormalFrameIsHandled) {
  // Faces counter-clockwise about -z (seen from below) joined with the normal -z.
  PolygonMesh mesh = GridSquares(2, {{0, 0}, {1, 0}});
  for (std::size_t f = 0; f < mesh.NumFaces(); ++f) {
    std::reverse(mesh.face_indices.begin() + mesh.face_offsets[f],
                 mesh.face_indices.begin() + mesh.face_offsets[f + 1]);
  }
  const auto polygons = JoinIntoPlanarPolygons(mesh, AllFaces(mesh), -Vec3::UnitZ());
  ASSERT_EQ(polygons.size(), 1u);
  ASSERT_EQ(polygons[0].rings.size(), 1u);
  EXPECT_DOUBLE_EQ(SignedArea(mesh, polygons[0].rings[0]), -2.0);
}

}  // namespace
}  // namespace linesurf::io
