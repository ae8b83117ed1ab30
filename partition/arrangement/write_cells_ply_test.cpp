#include "partition/arrangement/write_cells_ply.h"

#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "partition/arrangement/build_cell_complex.h"
#include "tests/support/test_paths.h"

namespace linesurf::partition {
namespace {

TEST(WriteCellsPly, WritesOnePolyhedronPerCell) {
  Box3 box;
  box.min = Vec3(0, 0, 0);
  box.max = Vec3(2, 1, 1);
  Plane3 plane;
  plane.point = Vec3(1, 0.5, 0.5);
  plane.normal = Vec3(1, 0.2, 0).normalized();
  const std::vector<Plane3> planes{plane};
  auto r = BuildCellComplex(box, planes, {}, RunContext{});
  ASSERT_TRUE(r.has_value());
  ASSERT_EQ(r->complex.NumCells(), 2u);
  const auto path = testing::FreshTempDir() / "cells.ply";
  ASSERT_TRUE(WriteCellsPly(r->complex, path).has_value());
  std::ifstream in(path, std::ios::binary);
  std::string line, header;
  while (std::getline(in, line) && line != "end_header") header += line + "\n";
  // The cut crosses the four faces parallel to x: both halves are hexahedra (8 corners, 6 faces).
  std::size_t vertices = 0, faces = 0;
  for (std::size_t c = 0; c < 2; ++c) faces += r->complex.cell_facets[CellId(c)].size();
  vertices = 16;  // each half of the box is a hexahedron with 8 corners
  EXPECT_NE(header.find("element vertex " + std::to_string(vertices)), std::string::npos) << header;
  EXPECT_NE(header.find("element face " + std::to_string(faces)), std::string::npos) << header;
  CellsPlyOptions bad;
  bad.shrink = 0;
  EXPECT_FALSE(WriteCellsPly(r->complex, path, bad).has_value());
}

}  // namespace
}  // namespace linesurf::partition
