#include "engine/pipeline/pinch_repair.h"

#include "engine/pipeline/mesh_validity.h"
#include "partition/arrangement/cell_locator.h"
#include "partition/voxel/block_grid.h"
#include "partition/voxel/plane_support.h"

#include <gtest/gtest.h>

#include <vector>

namespace linesurf::pipeline {
namespace {

/// The box [0,3]^2 x [0,1] cut by x = 1, x = 2, y = 1, y = 2 into 3 x 3 unit columns, as one
/// block; the cell of column (i, j).
struct Columns {
  partition::BlockComplexes complexes;
  CellId Cell(int i, int j) const {
    const partition::CellLocator locator(complexes.blocks[0].complex);
    return locator.Locate(Vec3(i + 0.5, j + 0.5, 0.5), {}, CellId::Invalid());
  }
};

Columns MakeColumns() {
  const Box3 box{Vec3(0, 0, 0), Vec3(3, 3, 1)};
  const std::vector<Plane3> planes{{Vec3(1, 0, 0), Vec3::UnitX()},
                                   {Vec3(2, 0, 0), Vec3::UnitX()},
                                   {Vec3(0, 1, 0), Vec3::UnitY()},
                                   {Vec3(0, 2, 0), Vec3::UnitY()}};
  const partition::BlockGrid grid = partition::BlockGrid::Create(box, 3.0).value();
  Columns out;
  out.complexes =
      partition::BuildBlockComplexes(
          grid, planes, partition::RegionsFromBlockLists({{0}, {0}, {0}, {0}}), {}, RunContext{})
          .value();
  return out;
}

// Two full columns that meet only along their shared vertical edge (diagonal neighbours): the
// surface splits that edge's vertices; the repair fills the cheaper of the two empty columns
// beside the edge, and the surface is one valid solid.
TEST(PinchRepair, FillsTheCheaperCellWherePartsMeetAlongAnEdge) {
  const Columns c = MakeColumns();
  const std::size_t n = c.complexes.blocks[0].complex.NumCells();
  ASSERT_EQ(n, 9u);
  solver::EnergyInput energy;
  energy.ResizeCells(n);
  const CellId a = c.Cell(0, 0), b = c.Cell(1, 1), cheap = c.Cell(1, 0), dear = c.Cell(0, 1);
  energy.cost_if_full[cheap] = 1.0;
  energy.cost_if_full[dear] = 5.0;
  energy.cost_if_empty[a] = energy.cost_if_empty[b] = 10.0;  // carving costs more than filling
  std::vector<std::uint8_t> labels(n, 0);
  labels[a.index()] = labels[b.index()] = 1;

  std::vector<std::uint8_t> unrepaired = labels;
  const auto split = ExtractWithoutPinches(c.complexes, energy, {}, 0, unrepaired, {});
  ASSERT_TRUE(split) << split.error().ToString();
  EXPECT_GT(split->stats.split_points, 0u);
  EXPECT_EQ(split->stats.flipped_cells, 0u);
  EXPECT_GT(CheckMeshValidity(split->surface.mesh)->num_coincident_vertices, 0u);

  const auto repaired =
      ExtractWithoutPinches(c.complexes, energy, {}, kPinchRepairRounds, labels, {});
  ASSERT_TRUE(repaired) << repaired.error().ToString();
  EXPECT_EQ(repaired->stats.split_points, 0u);
  EXPECT_EQ(repaired->stats.flipped_cells, 1u);
  EXPECT_EQ(labels[cheap.index()], 1);
  EXPECT_EQ(labels[dear.index()], 0);
  EXPECT_DOUBLE_EQ(repaired->stats.energy_increase, 1.0);
  const MeshValidity v = CheckMeshValidity(repaired->surface.mesh).value();
  EXPECT_TRUE(v.closed && v.two_manifold && v.oriented);
  EXPECT_EQ(v.num_coincident_vertices, 0u);
  EXPECT_EQ(v.num_touching_triangle_pairs, 0u);
}

// A fixed cell keeps its label: with both empty neighbours fixed, the repair carves one of the
// two full columns instead.
TEST(PinchRepair, NeverChangesAFixedCell) {
  const Columns c = MakeColumns();
  const std::size_t n = c.complexes.blocks[0].complex.NumCells();
  solver::EnergyInput energy;
  energy.ResizeCells(n);
  const CellId a = c.Cell(0, 0), b = c.Cell(1, 1);
  energy.fixed[c.Cell(1, 0)] = solver::CellFix::kEmpty;
  energy.fixed[c.Cell(0, 1)] = solver::CellFix::kEmpty;
  energy.cost_if_empty[a] = 2.0;
  energy.cost_if_empty[b] = 3.0;
  std::vector<std::uint8_t> labels(n, 0);
  labels[a.index()] = labels[b.index()] = 1;
  const auto repaired =
      ExtractWithoutPinches(c.complexes, energy, {}, kPinchRepairRounds, labels, {});
  ASSERT_TRUE(repaired) << repaired.error().ToString();
  EXPECT_EQ(repaired->stats.split_points, 0u);
  EXPECT_EQ(labels[c.Cell(1, 0).index()], 0);
  EXPECT_EQ(labels[c.Cell(0, 1).index()], 0);
  EXPECT_EQ(labels[a.index()], 0);  // the cheaper one to carve
  EXPECT_EQ(labels[b.index()], 1);
}

}  // namespace
}  // namespace linesurf::pipeline
