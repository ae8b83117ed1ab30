#include "partition/arrangement/block_complexes.h"

#include "engine/core/rng.h"
#include "partition/arrangement/cell_geometry.h"
#include "tests/support/thread_count.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace linesurf::partition {
namespace {

BlockGrid MakeGrid(const Box3& box, double size) {
  return std::move(BlockGrid::Create(box, size)).value();
}

Plane3 MakePlane(const Vec3& point, const Vec3& normal) { return {point, normal.normalized()}; }

std::vector<std::int64_t> AllBlocks(const BlockGrid& grid) {
  std::vector<std::int64_t> all(static_cast<std::size_t>(grid.NumBaseBlocks()));
  for (std::size_t i = 0; i < all.size(); ++i) all[i] = static_cast<std::int64_t>(i);
  return all;
}

BlockComplexes Build(const BlockGrid& grid,
                     const std::vector<Plane3>& planes,
                     std::vector<std::vector<std::int64_t>> regions,
                     int threads = 1) {
  RunContext ctx;
  ctx.num_threads = threads;
  Expected<BlockComplexes> cx =
      BuildBlockComplexes(grid, planes, RegionsFromBlockLists(std::move(regions)), {}, ctx);
  EXPECT_TRUE(cx) << cx.error().ToString();
  return std::move(cx).value();
}

void ExpectValid(const BlockComplexes& cx) {
  const Status ok = ValidateBlockComplexes(cx);
  EXPECT_TRUE(ok) << ok.error().ToString();
}

std::vector<Plane3> RandomPlanes(int n, const Box3& box, std::uint64_t seed) {
  Rng rng(seed);
  std::vector<Plane3> planes;
  for (int i = 0; i < n; ++i) {
    const Vec3 p(rng.Uniform(box.min.x(), box.max.x()),
                 rng.Uniform(box.min.y(), box.max.y()),
                 rng.Uniform(box.min.z(), box.max.z()));
    planes.push_back(
        MakePlane(p, Vec3(rng.Uniform(-1, 1), rng.Uniform(-1, 1), rng.Uniform(-1, 1))));
  }
  return planes;
}

TEST(BuildBlockComplexes, OneBlockIsTheMonolithicComplex) {
  const Box3 box = Box3{Vec3(-1.1, -0.9, -1), Vec3(1, 1.2, 0.8)};
  const BlockGrid grid = MakeGrid(box, 10.0);
  const std::vector<Plane3> planes = RandomPlanes(12, box, 1);
  const BlockComplexes cx = Build(grid, planes, std::vector(planes.size(), AllBlocks(grid)));
  ExpectValid(cx);
  ASSERT_EQ(cx.blocks.size(), 1u);
  EXPECT_TRUE(cx.seams.empty());
  const auto mono = BuildCellComplex(box, planes, {}, {});
  ASSERT_TRUE(mono);
  const CellComplex& a = cx.blocks[0].complex;
  const CellComplex& b = mono->complex;
  EXPECT_EQ(a.NumCells(), b.NumCells());
  EXPECT_EQ(a.NumFacets(), b.NumFacets());
  EXPECT_EQ(a.vertex_points.raw(), b.vertex_points.raw());
  EXPECT_EQ(a.facet_vertices.items(), b.facet_vertices.items());
  for (const FacetKind kind : cx.blocks[0].facet_kind.raw()) {
    EXPECT_NE(kind, FacetKind::kSeam);
  }
}

// Every plane reaches every block: the blocks cut the full arrangement, the overlay of each
// face pairs identical subdivisions.
TEST(BuildBlockComplexes, RandomPlanesEverywhereAreValidAndConforming) {
  const Box3 box = Box3{Vec3(-1, -1, -1), Vec3(1, 1, 1)};
  const BlockGrid grid = MakeGrid(box, 0.7);  // 3 x 3 x 3, the last ones clipped
  const std::vector<Plane3> planes = RandomPlanes(10, box, 2);
  const BlockComplexes cx = Build(grid, planes, std::vector(planes.size(), AllBlocks(grid)));
  ExpectValid(cx);
  EXPECT_EQ(cx.blocks.size(), 27u);
  EXPECT_EQ(cx.seams.size(), 54u);
  // With the same planes on both sides, each face's facets match one to one.
  for (const SeamFace& face : cx.seams) {
    std::size_t lower = 0;
    const CellComplex& c = cx.blocks[face.lower_block].complex;
    for (std::size_t f = 0; f < c.NumFacets(); ++f) {
      lower += c.facet_plane[FacetId(f)].index() == static_cast<std::size_t>(3 + face.axis);
    }
    EXPECT_EQ(face.facets.size(), lower);
  }
}

TEST(GlobalCellOffsets, NumberTheCellsOfEveryBlockContiguouslyInBlockOrder) {
  const Box3 box = Box3{Vec3(-1, -1, -1), Vec3(1, 1, 1)};
  const BlockGrid grid = MakeGrid(box, 0.7);
  const std::vector<Plane3> planes = RandomPlanes(6, box, 5);
  const BlockComplexes cx = Build(grid, planes, std::vector(planes.size(), AllBlocks(grid)));
  const std::vector<std::size_t> offsets = GlobalCellOffsets(cx);
  ASSERT_EQ(offsets.size(), cx.blocks.size() + 1);
  EXPECT_EQ(offsets.front(), 0u);
  for (std::size_t b = 0; b < cx.blocks.size(); ++b) {
    EXPECT_EQ(offsets[b + 1] - offsets[b], cx.blocks[b].complex.NumCells()) << "block " << b;
  }
  EXPECT_EQ(offsets.back(), cx.stats.cells);
}

// Random regions: neighbouring blocks are cut by different planes, so the overlay must intersect
// different subdivisions of each face.
TEST(BuildBlockComplexes, DifferentPlanesOnTheTwoSidesOfSeamsAreOverlaidExactly) {
  const Box3 box = Box3{Vec3(-1, -1, -1), Vec3(1, 1, 1)};
  const BlockGrid grid = MakeGrid(box, 0.5);  // 4 x 4 x 4
  for (std::uint64_t seed = 3; seed < 6; ++seed) {
    const std::vector<Plane3> planes = RandomPlanes(14, box, seed);
    Rng rng(seed);
    std::vector<std::vector<std::int64_t>> regions(planes.size());
    for (auto& region : regions) {
      for (const std::int64_t b : AllBlocks(grid)) {
        if (rng.Uniform() < 0.5) region.push_back(b);
      }
    }
    const BlockComplexes cx = Build(grid, planes, regions);
    ExpectValid(cx);
    std::size_t different = 0;
    for (const SeamFace& face : cx.seams) {
      different += face.facets.size() > 1 ? 1 : 0;
    }
    EXPECT_GT(different, cx.seams.size() / 2);
    EXPECT_GT(cx.stats.seam_facets, cx.stats.seam_faces);
  }
}

// Degenerate input: planes on block faces (kept, recorded on both sides), through block edges
// and corners, duplicates, and many planes through one line crossing a seam.
TEST(BuildBlockComplexes, PlanesOnFacesEdgesAndCornersOfBlocks) {
  const Box3 box = Box3{Vec3(0, 0, 0), Vec3(4, 4, 4)};
  const BlockGrid grid = MakeGrid(box, 1.0);
  // Small integer normals, not normalised, so that the coincidences are exact.
  std::vector<Plane3> planes = {
      {Vec3(2, 0, 0), Vec3(1, 0, 0)},   // on the faces x = 2
      {Vec3(0, 1, 0), Vec3(0, -1, 0)},  // on y = 1, opposite orientation
      {Vec3(2, 2, 0), Vec3(1, 1, 0)},   // through block edges: x + y = 4
      {Vec3(1, 1, 1), Vec3(1, 1, 1)},   // through block corners: x + y + z = 3
      {Vec3(2, 0, 0), Vec3(2, 0, 0)},   // the first again, scaled
      {Vec3(1.5, 1.5, 0.5), Vec3(1, -1, 0)},
      MakePlane(Vec3(1, 1, 1), Vec3(1, 1, 1)),  // normalised: misses the corners by rounding
  };
  for (int k = -2; k <= 3; ++k) {  // a pencil through the line x = 2.5, z = 2 on the faces z = 2
    planes.push_back({Vec3(2.5, 0, 2), Vec3(1, 0, k)});
  }
  const BlockComplexes cx = Build(grid, planes, std::vector(planes.size(), AllBlocks(grid)));
  ExpectValid(cx);
  // x = 2 lies on the faces between x-blocks 1 and 2 (16 + 16 block faces), y = 1 between 0
  // and 1 (16 + 16).
  EXPECT_EQ(cx.stats.planes_on_faces, 64u);
  const BlockComplex& left = cx.blocks[static_cast<std::size_t>(grid.LinearIndex({1, 2, 2}))];
  const BlockComplex& right = cx.blocks[static_cast<std::size_t>(grid.LinearIndex({2, 2, 2}))];
  EXPECT_EQ(left.face_planes[3], PlaneId(0u));   // its xmax face
  EXPECT_EQ(right.face_planes[0], PlaneId(0u));  // its xmin face
}

TEST(BuildBlockComplexes, SameComplexesForAnyThreadCount) {
  const testing::RealThreadCounts real_threads;
  const Box3 box = Box3{Vec3(-1, -1, -1), Vec3(1, 1, 1)};
  const BlockGrid grid = MakeGrid(box, 0.5);
  const std::vector<Plane3> planes = RandomPlanes(12, box, 9);
  Rng rng(9);
  std::vector<std::vector<std::int64_t>> regions(planes.size());
  for (auto& region : regions) {
    for (const std::int64_t b : AllBlocks(grid)) {
      if (rng.Uniform() < 0.6) region.push_back(b);
    }
  }
  const BlockComplexes one = Build(grid, planes, regions, 1);
  for (const int threads : testing::kThreadCounts) {
    const BlockComplexes other = Build(grid, planes, regions, threads);
    ASSERT_EQ(one.seams.size(), other.seams.size());
    for (std::size_t s = 0; s < one.seams.size(); ++s) {
      ASSERT_EQ(one.seams[s].facets.size(), other.seams[s].facets.size());
      for (std::size_t i = 0; i < one.seams[s].facets.size(); ++i) {
        EXPECT_EQ(one.seams[s].facets[i].vertices, other.seams[s].facets[i].vertices);
        EXPECT_EQ(one.seams[s].facets[i].points, other.seams[s].facets[i].points);
      }
    }
    for (std::size_t b = 0; b < one.blocks.size(); ++b) {
      EXPECT_EQ(one.blocks[b].complex.vertex_points.raw(),
                other.blocks[b].complex.vertex_points.raw());
    }
  }
}

TEST(ValidateBlockComplexes, CatchesABrokenOverlay) {
  const Box3 box = Box3{Vec3(-1, -1, -1), Vec3(1, 1, 1)};
  const BlockGrid grid = MakeGrid(box, 1.0);
  const std::vector<Plane3> planes = RandomPlanes(6, box, 4);
  BlockComplexes cx = Build(grid, planes, std::vector(planes.size(), AllBlocks(grid)));
  ExpectValid(cx);
  SeamFace* face = nullptr;
  for (SeamFace& f : cx.seams) {
    if (f.facets.size() > 1) face = &f;
  }
  ASSERT_NE(face, nullptr);
  BlockComplexes missing = cx;
  for (SeamFace& f : missing.seams) {
    if (f.lower_block == face->lower_block && f.axis == face->axis) f.facets.pop_back();
  }
  EXPECT_FALSE(ValidateBlockComplexes(missing));
  BlockComplexes swapped = cx;
  for (SeamFace& f : swapped.seams) {
    if (f.lower_block == face->lower_block && f.axis == face->axis) {
      std::swap(f.facets[0].upper_cell, f.facets[1].upper_cell);
    }
  }
  const bool same_cells = face->facets[0].upper_cell == face->facets[1].upper_cell;
  EXPECT_EQ(static_cast<bool>(ValidateBlockComplexes(swapped)), same_cells);
}

}  // namespace
}  // namespace linesurf::partition
