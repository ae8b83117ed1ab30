#include "tests/support/one_complex_surface.h"

#include "engine/core/rng.h"
#include "tests/support/grid_complex.h"
#include "engine/pipeline/mesh_topology.h"

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace linesurf::pipeline {
namespace {

using testing::ExtractResult;
using testing::GridComplexForTest;

std::vector<std::uint8_t> Labels(const GridComplexForTest& g,
                                 const std::vector<std::array<int, 3>>& full) {
  std::vector<std::uint8_t> labels(g.complex().NumCells(), 0);
  for (const auto& c : full) labels[g.Cell(c[0], c[1], c[2]).index()] = 1;
  return labels;
}

ExtractResult Extract(const GridComplexForTest& g,
                      const std::vector<std::uint8_t>& labels,
                      ExtractOptions options = {}) {
  auto result = testing::ExtractOneComplexSurface(g.complex(), labels, options);
  EXPECT_TRUE(result.has_value()) << (result ? "" : result.error().ToString());
  return result ? std::move(result.value()) : ExtractResult{};
}

void ExpectClosedManifold(const PolygonMesh& mesh, double volume) {
  const MeshTopology t = ComputeMeshTopology(mesh);
  EXPECT_TRUE(t.paired) << t.num_unpaired_half_edges << " bad edges";
  EXPECT_TRUE(t.IsManifold()) << t.num_non_manifold_vertices << " non-manifold vertices";
  EXPECT_NEAR(t.signed_volume, volume, 1e-9);
}

TEST(OneComplexSurface, SingleCellIsAnOutwardCube) {
  const GridComplexForTest g(3, 3, 3);
  const ExtractResult r = Extract(g, Labels(g, {{1, 1, 1}}));
  EXPECT_EQ(r.mesh.NumFaces(), 6u);
  EXPECT_EQ(r.mesh.vertices.size(), 8u);
  EXPECT_EQ(r.stats.split_vertices, 0u);
  ExpectClosedManifold(r.mesh, 1.0);
}

TEST(OneComplexSurface, CellsTouchingAlongAnEdgeAreSplit) {
  const GridComplexForTest g(4, 4, 3);
  const ExtractResult r = Extract(g, Labels(g, {{1, 1, 1}, {2, 2, 1}}));
  EXPECT_EQ(r.mesh.NumFaces(), 12u);
  EXPECT_EQ(r.mesh.vertices.size(), 16u);
  EXPECT_EQ(r.stats.split_vertices, 2u);
  EXPECT_EQ(r.stats.non_manifold_edges, 1u);
  ExpectClosedManifold(r.mesh, 2.0);
}

TEST(OneComplexSurface, CellsTouchingAtAVertexAreSplit) {
  const GridComplexForTest g(4, 4, 4);
  const ExtractResult r = Extract(g, Labels(g, {{1, 1, 1}, {2, 2, 2}}));
  EXPECT_EQ(r.mesh.vertices.size(), 16u);
  EXPECT_EQ(r.stats.split_vertices, 1u);
  ExpectClosedManifold(r.mesh, 2.0);
}

TEST(OneComplexSurface, PinchedEdgeInsideOneUmbrellaIsCut) {
  // A and B meet only along the edge x = y = 2, z in [1, 2], but are joined below it through
  // three cells of the layer z = 0, so one umbrella at (2, 2, 1) passes twice through that edge.
  const GridComplexForTest g(4, 4, 3);
  const ExtractResult r =
      Extract(g, Labels(g, {{1, 1, 1}, {2, 2, 1}, {1, 1, 0}, {1, 2, 0}, {2, 2, 0}}));
  ExpectClosedManifold(r.mesh, 5.0);
}

TEST(OneComplexSurface, EdgeShrinkingToOneUmbrellaAtBothEndsGetsAMidpoint) {
  // As above, with a second bridge above the edge: both ends of the edge keep one umbrella, so
  // each of the two face pairs along it gets its own midpoint vertex (both: a midpoint in one
  // pair only would lie on the straight edge of the other pair's faces, a T-junction).
  const GridComplexForTest g(4, 4, 5);
  const ExtractResult r = Extract(g,
                                  Labels(g,
                                         {{1, 1, 2},
                                          {2, 2, 2},
                                          {1, 1, 1},
                                          {1, 2, 1},
                                          {2, 2, 1},
                                          {1, 1, 3},
                                          {1, 2, 3},
                                          {2, 2, 3}}));
  EXPECT_EQ(r.stats.non_manifold_edges, 1u);
  EXPECT_EQ(r.stats.split_vertices, 2u);
  const std::size_t n = r.vertex_source.size();
  ASSERT_GE(n, 2u);
  EXPECT_FALSE(r.vertex_source[n - 1].IsValid());
  EXPECT_FALSE(r.vertex_source[n - 2].IsValid());
  EXPECT_EQ(r.mesh.vertices[n - 1], r.mesh.vertices[n - 2]);
  // Each midpoint is a corner of the two faces of its pair.
  for (const std::size_t v : {n - 2, n - 1}) {
    std::size_t uses = 0;
    for (const std::uint32_t i : r.mesh.face_indices) uses += i == v ? 1 : 0;
    EXPECT_EQ(uses, 2u);
  }
  ExpectClosedManifold(r.mesh, 8.0);
}

TEST(OneComplexSurface, RandomLabelsGiveClosedManifolds) {
  const GridComplexForTest g(6, 5, 5);
  for (std::uint64_t trial = 0; trial < 40; ++trial) {
    Rng rng(MixSeed(trial, RngStage::kEvidence, 7));
    std::vector<std::uint8_t> labels(g.complex().NumCells(), 0);
    double volume = 0.0;
    for (int k = 0; k < 5; ++k) {
      for (int j = 0; j < 5; ++j) {
        for (int i = 0; i < 6; ++i) {
          if (g.OnBox(i, j, k) && trial % 2 == 0) continue;  // odd trials touch the box too
          const bool full = rng.Uniform() < 0.5;
          labels[g.Cell(i, j, k).index()] = full ? 1 : 0;
          volume += full ? 1.0 : 0.0;
        }
      }
    }
    const ExtractResult r = Extract(g, labels);
    ExpectClosedManifold(r.mesh, volume);
    ExtractOptions tri;
    tri.triangulate = true;
    const ExtractResult t = Extract(g, labels, tri);
    for (std::size_t f = 0; f < t.mesh.NumFaces(); ++f) ASSERT_EQ(t.mesh.Face(f).size(), 3u);
    ExpectClosedManifold(t.mesh, volume);
  }
}

TEST(OneComplexSurface, CheckerboardIsClosedAndManifold) {
  const GridComplexForTest g(6, 6, 6);
  std::vector<std::uint8_t> labels(g.complex().NumCells(), 0);
  double volume = 0.0;
  for (int k = 1; k < 5; ++k) {
    for (int j = 1; j < 5; ++j) {
      for (int i = 1; i < 5; ++i) {
        if ((i + j + k) % 2 != 0) continue;
        labels[g.Cell(i, j, k).index()] = 1;
        volume += 1.0;
      }
    }
  }
  const ExtractResult r = Extract(g, labels);
  EXPECT_GT(r.stats.split_vertices, 0u);
  ExpectClosedManifold(r.mesh, volume);
}

TEST(OneComplexSurface, InteriorSceneFacesPointIntoTheEmptyRoom) {
  const GridComplexForTest g(3, 3, 3);
  std::vector<std::uint8_t> labels(g.complex().NumCells(), 1);
  labels[g.Cell(1, 1, 1).index()] = 0;
  ExtractOptions options;
  options.outside_full = true;
  const ExtractResult r = Extract(g, labels, options);
  EXPECT_EQ(r.mesh.NumFaces(), 6u);
  ExpectClosedManifold(r.mesh, -1.0);
}

TEST(OneComplexSurface, FullCellsOnTheBoxCloseAgainstTheBox) {
  const GridComplexForTest g(2, 2, 2);
  std::vector<std::uint8_t> labels(g.complex().NumCells(), 1);
  const ExtractResult r = Extract(g, labels);
  EXPECT_EQ(r.mesh.NumFaces(), 24u);
  ExpectClosedManifold(r.mesh, 8.0);
}

TEST(OneComplexSurface, TriangulatedFacesAreNotDegenerate) {
  const GridComplexForTest g(4, 3, 3);
  ExtractOptions tri;
  tri.triangulate = true;
  const ExtractResult r = Extract(g, Labels(g, {{1, 1, 1}, {2, 1, 1}}), tri);
  ExpectClosedManifold(r.mesh, 2.0);
  for (std::size_t f = 0; f < r.mesh.NumFaces(); ++f) {
    const auto face = r.mesh.Face(f);
    const Vec3 n = (r.mesh.vertices[face[1]] - r.mesh.vertices[face[0]])
                       .cross(r.mesh.vertices[face[2]] - r.mesh.vertices[face[0]]);
    EXPECT_GT(n.norm(), 1e-12);
  }
}

TEST(OneComplexSurface, RejectsWrongLabelCount) {
  const GridComplexForTest g(2, 2, 2);
  const std::vector<std::uint8_t> labels(3, 0);
  const auto r = testing::ExtractOneComplexSurface(g.complex(), labels, {});
  ASSERT_FALSE(r.has_value());
  EXPECT_EQ(r.error().code, ErrorCode::kInvalidInput);
}

}  // namespace
}  // namespace linesurf::pipeline
