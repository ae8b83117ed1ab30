#include "partition/arrangement/seam_regularisation.h"

#include "partition/arrangement/cell_geometry.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <numeric>

namespace linesurf::partition {
namespace {

// Two blocks [0,1] x [0,1]^2 and [1,2] x [0,1]^2 (the scene box [0,2] x [0,1]^2).
BlockComplexes TwoBlocks(const std::vector<Plane3>& planes,
                         std::vector<std::vector<std::int64_t>> regions) {
  const auto grid = BlockGrid::Create(Box3{Vec3(0, 0, 0), Vec3(2, 1, 1)}, 1.0);
  EXPECT_TRUE(grid);
  auto cx = BuildBlockComplexes(*grid, planes, RegionsFromBlockLists(std::move(regions)), {}, {});
  EXPECT_TRUE(cx) << cx.error().ToString();
  return std::move(cx).value();
}

SeamRegularisation Seams(const BlockComplexes& cx) {
  auto r = ComputeSeamRegularisation(cx, {});
  EXPECT_TRUE(r) << r.error().ToString();
  return std::move(r).value();
}

int Parity(const SeamParityGroup& g, const std::vector<std::uint8_t>& label_of_cell) {
  int sum = 0;
  for (std::size_t i = 0; i < g.cells.size(); ++i) {
    sum += g.signs[i] * label_of_cell[g.cells[i].block * 2 + g.cells[i].cell.index()];
  }
  return std::abs(sum);
}

/// The cell of block b on the side `above` of the plane z = 0.3 + 0.4 x (by centroid).
CellId CellAbove(const BlockComplexes& cx, std::uint32_t b, bool above) {
  const CellComplex& c = cx.blocks[b].complex;
  for (std::size_t i = 0; i < c.NumCells(); ++i) {
    const Vec3 m = CellCentroid(c, CellId(i));
    if ((m.z() > 0.3 + 0.4 * m.x()) == above) return CellId(i);
  }
  return CellId();
}

const Plane3 kInclined{Vec3(0.0, 0.0, 0.3), Vec3(-0.4, 0.0, 1.0).normalized()};

// The plane reaches the lower block only: on the face x = 1 its trace (z = 0.7, the whole
// width) has three cells around it, and the term must be 1 exactly when the surface bends there,
// for all 8 labellings.
TEST(ComputeSeamRegularisation, TEdgeIsThePairwiseTermOfTheSplitSide) {
  const BlockComplexes cx = TwoBlocks({kInclined}, {{0}});
  ASSERT_EQ(cx.blocks[0].complex.NumCells(), 2u);
  ASSERT_EQ(cx.blocks[1].complex.NumCells(), 1u);
  const SeamRegularisation seams = Seams(cx);
  ASSERT_EQ(seams.edges.size(), 1u);
  EXPECT_EQ(seams.edges_with_dropped_cells, 1u);
  const SeamParityGroup& g = seams.edges[0];
  EXPECT_NEAR(g.length, 1.0, 1e-12);
  const CellId a1 = CellAbove(cx, 0, true);
  const CellId a2 = CellAbove(cx, 0, false);
  for (int bits = 0; bits < 8; ++bits) {
    const std::uint8_t x1 = bits & 1, x2 = (bits >> 1) & 1, xb = (bits >> 2) & 1;
    std::vector<std::uint8_t> labels(4, 0);
    labels[a1.index()] = x1;
    labels[a2.index()] = x2;
    labels[2] = xb;
    // Surface facets at the edge: the inclined one (a1|a2) and the two halves of the face
    // (a1|b, a2|b), which are coplanar: it bends exactly when the inclined facet is on it.
    const bool bends = x1 != x2;
    EXPECT_EQ(Parity(g, labels), bends ? 1 : 0) << "labelling " << bits;
  }
  EXPECT_TRUE(seams.vertices.empty());  // the trace ends on the scene box
}

// The plane reaches both blocks: four cells around its trace, the parity term of a crossing.
TEST(ComputeSeamRegularisation, PlaneOnBothSidesIsAParityCrossing) {
  const BlockComplexes cx = TwoBlocks({kInclined}, {{0, 1}});
  const SeamRegularisation seams = Seams(cx);
  ASSERT_EQ(seams.edges.size(), 1u);
  EXPECT_EQ(seams.edges_with_dropped_cells, 0u);
  const SeamParityGroup& g = seams.edges[0];
  ASSERT_EQ(g.cells.size(), 4u);
  const CellId a1 = CellAbove(cx, 0, true), a2 = CellAbove(cx, 0, false);
  const CellId b1 = CellAbove(cx, 1, true), b2 = CellAbove(cx, 1, false);
  for (int bits = 0; bits < 16; ++bits) {
    std::vector<std::uint8_t> labels(4, 0);
    labels[a1.index()] = bits & 1;
    labels[a2.index()] = (bits >> 1) & 1;
    labels[2 + b1.index()] = (bits >> 2) & 1;
    labels[2 + b2.index()] = (bits >> 3) & 1;
    const bool pa = labels[a1.index()] != labels[a2.index()];
    const bool pb = labels[2 + b1.index()] != labels[2 + b2.index()];
    const bool f1 = labels[a1.index()] != labels[2 + b1.index()];
    const bool f2 = labels[a2.index()] != labels[2 + b2.index()];
    const int facets = pa + pb + f1 + f2;
    // Flat: the plane on both sides, or the face on both sides; four facets: a checkerboard.
    const int expected = facets == 4 ? 2 : (facets == 0 || (pa && pb) || (f1 && f2)) ? 0 : 1;
    EXPECT_EQ(Parity(g, labels), expected) << "labelling " << bits;
  }
}

// A grid of 2 x 2 x 2 blocks without planes: the block edges through the centre are crossings
// of two faces (four cells) and the centre is a corner of eight cells, all with alternating
// signs.
TEST(ComputeSeamRegularisation, BlockEdgesAndCornersOfAnEmptyGrid) {
  const auto grid = BlockGrid::Create(Box3{Vec3(0, 0, 0), Vec3(2, 2, 2)}, 1.0);
  ASSERT_TRUE(grid);
  auto cx = BuildBlockComplexes(*grid, {}, RegionsFromBlockLists({}), {}, {});
  ASSERT_TRUE(cx);
  const SeamRegularisation seams = Seams(*cx);
  // Three interior block-edge lines, each split at the centre into two pieces of length 1.
  ASSERT_EQ(seams.edges.size(), 6u);
  for (const SeamParityGroup& g : seams.edges) {
    EXPECT_NEAR(g.length, 1.0, 1e-12);
    EXPECT_EQ(g.cells.size(), 4u);
    EXPECT_EQ(std::accumulate(g.signs.begin(), g.signs.end(), 0), 0);
  }
  ASSERT_EQ(seams.vertices.size(), 1u);
  const SeamParityGroup& v = seams.vertices[0];
  ASSERT_EQ(v.cells.size(), 8u);
  for (std::size_t i = 0; i < 8; ++i) {
    const Eigen::Vector3i b = grid->BaseFromLinear(v.cells[i].block);
    EXPECT_EQ(v.signs[i], (b.sum() % 2 == 0) ? v.signs[0] : -v.signs[0]);
  }
}

}  // namespace
}  // namespace linesurf::partition
