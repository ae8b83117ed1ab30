#include "engine/pipeline/block_evidence.h"

#include "engine/core/rng.h"
#include "engine/pipeline/block_partition.h"
#include "engine/pipeline/open_seams.h"
#include "engine/pipeline/segment_evidence.h"
#include "partition/arrangement/build_cell_complex.h"
#include "partition/arrangement/cell_geometry.h"
#include "partition/arrangement/cell_locator.h"
#include "tests/support/one_complex_evidence.h"
#include "tests/support/thread_count.h"

#include <Eigen/Geometry>
#include <Eigen/QR>
#include <gtest/gtest.h>

#include <numeric>
#include <vector>

namespace linesurf::pipeline {
namespace {

const Box3 kBox{Vec3(-2.0, -2.0, -2.0), Vec3(2.0, 2.1, 1.9)};

/// Random planes through the box with textural inliers, creases of consecutive planes
/// (structural), segments on no plane, and viewpoints inside and outside the box.
Scene RandomScene(std::uint64_t seed, int num_planes) {
  Rng rng(seed);
  Scene scene;
  const auto random_point = [&](double margin) {
    return Vec3(rng.Uniform(kBox.min.x() + margin, kBox.max.x() - margin),
                rng.Uniform(kBox.min.y() + margin, kBox.max.y() - margin),
                rng.Uniform(kBox.min.z() + margin, kBox.max.z() - margin));
  };
  for (int v = 0; v < 12; ++v) scene.viewpoints.push_back(random_point(0.1));
  scene.viewpoints.push_back(Vec3(5.0, 0.3, 0.2));  // outside the box
  for (int i = 0; i < num_planes; ++i) {
    Plane3 p;
    p.point = random_point(0.5);
    p.normal = Vec3(rng.Uniform(-1, 1), rng.Uniform(-1, 1), rng.Uniform(-1, 1)).normalized();
    scene.planes.push_back(p);
  }
  const auto add = [&](const Vec3& a, const Vec3& b, PlaneMembership m) {
    scene.segments.push_back({a, b});
    std::vector<ViewpointId> views;
    for (int k = 0; k < 3; ++k) {
      views.emplace_back(static_cast<std::size_t>(rng.Uniform(0, 12.999)));
    }
    views.emplace_back(std::size_t{12});
    std::sort(views.begin(), views.end());
    views.erase(std::unique(views.begin(), views.end()), views.end());
    scene.observations.AddRow(views);
    scene.memberships.push_back(m);
  };
  for (int i = 0; i < num_planes; ++i) {
    const Plane3& p = scene.planes[PlaneId(static_cast<std::size_t>(i))];
    for (int k = 0; k < 12; ++k) {
      const Vec3 q = random_point(0.3);
      const Vec3 a = q - p.SignedDistance(q) * p.normal;
      const Vec3 dir = p.normal.cross(Vec3(rng.Uniform(-1, 1), rng.Uniform(-1, 1), 1)).normalized();
      PlaneMembership m;
      m.Add(PlaneId(static_cast<std::size_t>(i)));
      add(a, a + 0.4 * dir, m);
    }
    if (i + 1 < num_planes) {
      const Plane3& p2 = scene.planes[PlaneId(static_cast<std::size_t>(i + 1))];
      const Vec3 u = p.normal.cross(p2.normal).normalized();
      // A point on the crease near the box centre.
      Eigen::Matrix3d m;
      m.row(0) = p.normal.transpose();
      m.row(1) = p2.normal.transpose();
      m.row(2) = u.transpose();
      const Vec3 x =
          m.colPivHouseholderQr().solve(Vec3(p.normal.dot(p.point), p2.normal.dot(p2.point), 0.0));
      if (kBox.Contains(x)) {
        PlaneMembership mm;
        mm.Add(PlaneId(static_cast<std::size_t>(i)));
        mm.Add(PlaneId(static_cast<std::size_t>(i + 1)));
        add(x, x + 0.5 * u, mm);
      }
    }
  }
  for (int k = 0; k < 10; ++k) {
    const Vec3 a = random_point(0.2);
    add(a, a + Vec3(0.2, 0.1, -0.1), PlaneMembership{});
  }
  return scene;
}

EnergyOptions Options() {
  EnergyOptions o;
  o.sigma = 0.25;
  o.weights.visibility = 0.5;
  o.weights.edge = 0.05;
  o.weights.corner = 0.02;
  return o;
}

partition::BlockComplexes Blocks(const Scene& scene,
                                 double block_size,
                                 bool everywhere,
                                 int threads = 1) {
  RunContext ctx;
  ctx.num_threads = threads;
  if (everywhere) {
    const auto grid = partition::BlockGrid::Create(kBox, block_size);
    EXPECT_TRUE(grid);
    std::vector<std::int64_t> all(static_cast<std::size_t>(grid->NumBaseBlocks()));
    std::iota(all.begin(), all.end(), std::int64_t{0});
    auto cx = partition::BuildBlockComplexes(
        *grid,
        scene.planes.raw(),
        partition::RegionsFromBlockLists(std::vector(scene.planes.size(), all)),
        {},
        ctx);
    EXPECT_TRUE(cx) << cx.error().ToString();
    return std::move(cx).value();
  }
  BlockPartitionOptions options;
  options.block_size = block_size;
  auto p = BuildBlockPartition(scene, kBox, options, ctx);
  EXPECT_TRUE(p) << p.error().ToString();
  return std::move(p->complexes);
}

EvidenceResult BlockEnergy(const partition::BlockComplexes& cx,
                           const Scene& scene,
                           int threads = 1) {
  RunContext ctx;
  ctx.num_threads = threads;
  auto r = ComputeBlockEvidence(cx, scene, Options(), BoundaryMode::kExterior, ctx);
  EXPECT_TRUE(r) << r.error().ToString();
  return std::move(r).value();
}

void ExpectSameEnergy(const solver::EnergyInput& a, const solver::EnergyInput& b) {
  EXPECT_EQ(a.cost_if_empty.raw(), b.cost_if_empty.raw());
  EXPECT_EQ(a.cost_if_full.raw(), b.cost_if_full.raw());
  EXPECT_EQ(a.fixed.raw(), b.fixed.raw());
  ASSERT_EQ(a.pairs.size(), b.pairs.size());
  for (std::size_t i = 0; i < a.pairs.size(); ++i) {
    EXPECT_EQ(a.pairs[i].a, b.pairs[i].a);
    EXPECT_EQ(a.pairs[i].b, b.pairs[i].b);
    EXPECT_EQ(a.pairs[i].weight, b.pairs[i].weight);
  }
  EXPECT_EQ(a.structural_offsets, b.structural_offsets);
  EXPECT_EQ(a.structural_cells, b.structural_cells);
  EXPECT_EQ(a.structural_weights, b.structural_weights);
  EXPECT_EQ(a.parity_offsets, b.parity_offsets);
  EXPECT_EQ(a.parity_cells, b.parity_cells);
  EXPECT_EQ(a.parity_signs, b.parity_signs);
  EXPECT_EQ(a.parity_weights, b.parity_weights);
}

/// The energies of the block complexes (every plane in every block) and of the monolithic
/// complex of the same planes.
struct BlocksAndMonolithic {
  partition::BlockComplexes blocks;
  EvidenceResult block_energy;
  CellComplex mono;
  EvidenceResult mono_energy;
};

BlocksAndMonolithic Energies(const Scene& scene, double block_size) {
  BlocksAndMonolithic out;
  out.blocks = Blocks(scene, block_size, true);
  out.block_energy = BlockEnergy(out.blocks, scene);
  auto mono = partition::BuildCellComplex(kBox, scene.planes.raw(), {}, {});
  EXPECT_TRUE(mono);
  if (!mono) return out;
  out.mono = std::move(mono->complex);
  auto m = testing::ComputeOneComplexEvidence(out.mono, scene, Options(), BoundaryMode::kExterior, {});
  EXPECT_TRUE(m) << m.error().ToString();
  if (m) out.mono_energy = std::move(m).value();
  return out;
}

double Sum(const IdVector<CellId, double>& v) {
  return std::accumulate(v.raw().begin(), v.raw().end(), 0.0);
}

TEST(ComputeBlockEvidence, OneBlockIsComputeEvidenceTermForTerm) {
  const Scene scene = RandomScene(3, 7);
  const BlocksAndMonolithic both = Energies(scene, 100.0);
  const partition::BlockComplexes& blocks = both.blocks;
  ASSERT_EQ(blocks.blocks.size(), 1u);
  const EvidenceResult& b = both.block_energy;
  const EvidenceResult* m = &both.mono_energy;
  EXPECT_GT(m->energy.NumPairs(), 0u);
  EXPECT_GT(m->energy.NumStructuralGroups(), 0u);
  EXPECT_GT(m->energy.NumParityGroups(), 0u);
  ExpectSameEnergy(b.energy, m->energy);
  EXPECT_EQ(b.viewpoint_cells.raw(), m->viewpoint_cells.raw());
  EXPECT_EQ(b.stats.walks, m->stats.walks);
  EXPECT_EQ(b.stats.facets_crossed, m->stats.facets_crossed);
}

TEST(ComputeBlockEvidence, SameEnergyForAnyThreadCount) {
  const linesurf::testing::RealThreadCounts real;
  const Scene scene = RandomScene(5, 8);
  const partition::BlockComplexes blocks = Blocks(scene, 1.1, false);
  ASSERT_GT(blocks.blocks.size(), 8u);
  const EvidenceResult one = BlockEnergy(blocks, scene, 1);
  EXPECT_GT(one.energy.NumParityGroups(), 0u);
  for (const int threads : linesurf::testing::kThreadCounts) {
    SCOPED_TRACE(threads);
    ExpectSameEnergy(BlockEnergy(blocks, scene, threads).energy, one.energy);
  }
}

// Two blocks along x, no planes: a ray from a viewpoint in the lower block to a segment in the
// upper one crosses exactly the seam facet between the two cells.
TEST(ComputeBlockEvidence, ARayAcrossASeamCrossesItsSeamFacet) {
  Scene scene;
  scene.viewpoints.push_back(Vec3(-1.5, 0.2, 0.1));
  scene.segments.push_back({Vec3(1.5, 0.0, 0.05), Vec3(1.5, 0.6, 0.05)});
  scene.observations.AddRow(std::vector<ViewpointId>{ViewpointId(std::size_t{0})});
  const auto grid = partition::BlockGrid::Create(kBox, 2.0);  // x faces at -2, 0, 2
  ASSERT_TRUE(grid);
  ASSERT_EQ(grid->dims(), Eigen::Vector3i(2, 3, 2));
  auto cx = partition::BuildBlockComplexes(*grid, {}, partition::RegionsFromBlockLists({}), {}, {});
  ASSERT_TRUE(cx);
  EnergyOptions o = Options();
  o.weights.visibility = 1.0;
  o.sigma = 1.0;
  o.weights.open_seam = 0.0;  // rays only (no plane lies on any seam here)
  auto r = ComputeBlockEvidence(*cx, scene, o, BoundaryMode::kNone, {});
  ASSERT_TRUE(r) << r.error().ToString();
  // Each block is one cell (global id = block index); the viewpoint is in block (0, 1, 1), the
  // segment in block (1, 1, 1): one pair of weight length / sigma = 0.6.
  const CellId from(static_cast<std::size_t>(grid->LinearIndex({0, 1, 1})));
  const CellId to(static_cast<std::size_t>(grid->LinearIndex({1, 1, 1})));
  EXPECT_EQ(r->viewpoint_cells[ViewpointId(std::size_t{0})], from);
  ASSERT_EQ(r->energy.NumPairs(), 1u);
  EXPECT_EQ(r->energy.pairs[0].a, from);
  EXPECT_EQ(r->energy.pairs[0].b, to);
  EXPECT_NEAR(r->energy.pairs[0].weight, 0.6, 1e-9);
}

// Surface on a seam without a plane is priced by area (open_seam_weight / sigma^2); a seam with a
// plane on it is not.
TEST(ComputeBlockEvidence, OpenSeamsArePricedByAreaAndSeamsWithAPlaneAreNot) {
  Scene scene;
  scene.viewpoints.push_back(Vec3(-1.5, 0.2, 0.1));
  scene.segments.push_back({Vec3(1.5, 0.0, 0.05), Vec3(1.5, 0.6, 0.05)});
  scene.observations.AddRow(std::vector<ViewpointId>{ViewpointId(std::size_t{0})});
  Plane3 wall;
  wall.point = Vec3(0.0, 0.0, 0.0);  // x = 0: the x face of the 2.0 grid from -2
  wall.normal = Vec3::UnitX();
  const auto grid = partition::BlockGrid::Create(kBox, 2.0);
  ASSERT_TRUE(grid);
  EnergyOptions o = Options();
  o.weights.visibility = 0.0;
  o.weights.edge = 0.0;
  o.weights.corner = 0.0;
  o.sigma = 0.5;
  o.weights.open_seam = 3.0;
  for (const bool with_wall : {false, true}) {
    SCOPED_TRACE(with_wall);
    std::vector<Plane3> planes;
    std::vector<std::vector<std::int64_t>> regions;
    if (with_wall) {
      planes.push_back(wall);
      std::vector<std::int64_t> all(static_cast<std::size_t>(grid->NumBaseBlocks()));
      std::iota(all.begin(), all.end(), std::int64_t{0});
      regions.push_back(all);
    }
    auto cx = partition::BuildBlockComplexes(
        *grid, planes, partition::RegionsFromBlockLists(regions), {}, {});
    ASSERT_TRUE(cx);
    double open_area = 0.0;
    std::size_t open_facets = 0;
    for (std::size_t f = 0; f < cx->seams.size(); ++f) {
      EXPECT_EQ(SeamCarriesPlane(*cx, f), with_wall && cx->seams[f].axis == 0);
      if (SeamCarriesPlane(*cx, f)) continue;
      for (const partition::SeamFacet& facet : cx->seams[f].facets) {
        open_area += PolygonArea(facet.points);
        ++open_facets;
      }
    }
    auto r = ComputeBlockEvidence(*cx, scene, o, BoundaryMode::kNone, {});
    ASSERT_TRUE(r) << r.error().ToString();
    EXPECT_EQ(r->energy.NumPairs(), open_facets);
    double total = 0.0;
    for (const auto& pair : r->energy.pairs) total += pair.weight;
    EXPECT_NEAR(total, 3.0 * open_area / 0.25, 1e-9);
    EXPECT_GT(open_facets, with_wall ? 10u : 16u);
  }
}

// A ray through a block edge (and one along a block face) walks a chain of neighbours.
TEST(ComputeBlockEvidence, RaysThroughBlockEdgesAndAlongFacesCrossSeams) {
  Scene scene;
  scene.viewpoints.push_back(Vec3(-1.0, -1.0, 0.5));
  // Through the block edge x = 0, y = 0 (at z = 0.5), and along the face x = 0.
  scene.segments.push_back({Vec3(1.0, 1.0, 0.5), Vec3(1.0, 1.0, 0.6)});
  scene.segments.push_back({Vec3(0.0, 1.5, 0.5), Vec3(0.0, 1.5, 0.6)});
  for (int i = 0; i < 2; ++i) {
    scene.observations.AddRow(std::vector<ViewpointId>{ViewpointId(std::size_t{0})});
  }
  const auto grid = partition::BlockGrid::Create(Box3{Vec3(-2, -2, -2), Vec3(2, 2, 2)}, 2.0);
  ASSERT_TRUE(grid);
  auto cx = partition::BuildBlockComplexes(*grid, {}, partition::RegionsFromBlockLists({}), {}, {});
  ASSERT_TRUE(cx);
  EnergyOptions o = Options();
  o.sigma = 1.0;
  o.max_samples_per_segment = 1;
  o.weights.open_seam = 0.0;  // rays only
  auto r = ComputeBlockEvidence(*cx, scene, o, BoundaryMode::kNone, {});
  ASSERT_TRUE(r) << r.error().ToString();
  // First ray: (0,0,1) -> (1,0,1) -> (1,1,1) (x first on the tie); second ray ends on the face
  // x = 0, which its tie (towards the viewpoint, -x) puts in block (0,1,1): (0,0,1) -> (0,1,1).
  const auto id = [&](int x, int y) {
    return CellId(static_cast<std::size_t>(grid->LinearIndex({x, y, 1})));
  };
  std::vector<std::pair<CellId, CellId>> pairs;
  for (const auto& p : r->energy.pairs) pairs.emplace_back(p.a, p.b);
  std::sort(pairs.begin(), pairs.end());
  std::vector<std::pair<CellId, CellId>> expected{
      {id(0, 0), id(1, 0)}, {id(0, 0), id(0, 1)}, {id(1, 0), id(1, 1)}};
  std::sort(expected.begin(), expected.end());
  EXPECT_EQ(pairs, expected);
}

// Every plane reaching every block: the blocks refine the monolithic complex by their faces, so
// the evidence totals agree, and any labelling of the monolithic cells (carried to the block
// cells) has the same energy in both.
TEST(ComputeBlockEvidence, BlocksRefiningTheMonolithicComplexGiveItsEnergy) {
  const Scene scene = RandomScene(11, 6);
  const BlocksAndMonolithic both = Energies(scene, 1.3);
  const partition::BlockComplexes& blocks = both.blocks;
  ASSERT_GT(blocks.blocks.size(), 20u);
  const EvidenceResult& b = both.block_energy;
  const EvidenceResult* m = &both.mono_energy;
  EXPECT_NEAR(Sum(b.energy.cost_if_empty), Sum(m->energy.cost_if_empty), 1e-9);
  EXPECT_NEAR(Sum(b.energy.cost_if_full), Sum(m->energy.cost_if_full), 1e-9);
  EXPECT_NEAR(
      std::accumulate(b.energy.structural_weights.begin(), b.energy.structural_weights.end(), 0.0),
      std::accumulate(
          m->energy.structural_weights.begin(), m->energy.structural_weights.end(), 0.0),
      1e-9);
  EXPECT_EQ(b.stats.walks, m->stats.walks);
  EXPECT_EQ(b.stats.samples, m->stats.samples);
  // Visibility on the input planes (pairs inside one block): every ray crosses each plane at
  // the same points in both.
  const std::vector<std::size_t> offsets = partition::GlobalCellOffsets(blocks);
  const auto block_of = [&](CellId c) {
    return std::upper_bound(offsets.begin(), offsets.end(), c.index()) - offsets.begin();
  };
  double inside = 0.0;
  for (const auto& p : b.energy.pairs) inside += block_of(p.a) == block_of(p.b) ? p.weight : 0.0;
  double mono_total = 0.0;
  for (const auto& p : m->energy.pairs) mono_total += p.weight;
  EXPECT_NEAR(inside, mono_total, 1e-6 * mono_total);

  // Labellings of the monolithic cells, carried to the block cells by their centroids.
  const partition::CellLocator locator(both.mono);
  std::vector<CellId> mono_of(b.energy.NumCells());
  for (std::size_t k = 0; k < blocks.blocks.size(); ++k) {
    const CellComplex& c = blocks.blocks[k].complex;
    for (std::size_t i = 0; i < c.NumCells(); ++i) {
      mono_of[offsets[k] + i] = locator.Locate(partition::CellCentroid(c, CellId(i)));
    }
  }
  Rng rng(4);
  for (int trial = 0; trial < 20; ++trial) {
    std::vector<std::uint8_t> xm(m->energy.NumCells());
    for (std::size_t i = 0; i < xm.size(); ++i) {
      const solver::CellFix fix = m->energy.fixed[CellId(i)];
      xm[i] = fix == solver::CellFix::kFree ? (rng.Uniform(0, 1) < 0.5 ? 1 : 0)
                                            : (fix == solver::CellFix::kFull ? 1 : 0);
    }
    std::vector<std::uint8_t> xb(b.energy.NumCells());
    for (std::size_t i = 0; i < xb.size(); ++i) xb[i] = xm[mono_of[i].index()];
    const double em = m->energy.Evaluate(xm);
    EXPECT_NEAR(b.energy.Evaluate(xb), em, 1e-6 * em) << "trial " << trial;
  }
}

// A wall lying on a block face is not a plane of any block; its segments' evidence falls on the
// cells on both sides of the face, as the monolithic complex puts it on the cells of its plane.
TEST(ComputeBlockEvidence, PlanesOnBlockFacesKeepTheirEvidence) {
  Scene scene = RandomScene(8, 2);
  Plane3 wall;
  wall.point = Vec3(0.0, 0.0, 0.0);  // x = 0: a face of the 1.0 grid from -2
  wall.normal = Vec3::UnitX();
  const PlaneId id = scene.planes.NextId();
  scene.planes.push_back(wall);
  Rng rng(9);
  for (int k = 0; k < 15; ++k) {
    const Vec3 a(0.0, rng.Uniform(-1.5, 1.5), rng.Uniform(-1.5, 1.5));
    scene.segments.push_back({a, a + Vec3(0.0, 0.3, 0.1)});
    scene.observations.AddRow(
        std::vector<ViewpointId>{ViewpointId(std::size_t{0}), ViewpointId(std::size_t{1})});
    PlaneMembership m;
    m.Add(id);
    scene.memberships.push_back(m);
  }
  const BlocksAndMonolithic both = Energies(scene, 1.0);
  const partition::BlockComplexes& blocks = both.blocks;
  EXPECT_GT(blocks.stats.planes_on_faces, 0u);
  const EvidenceResult& b = both.block_energy;
  const EvidenceResult* m = &both.mono_energy;
  EXPECT_NEAR(Sum(b.energy.cost_if_empty), Sum(m->energy.cost_if_empty), 1e-9);
  EXPECT_GT(Sum(b.energy.cost_if_empty), 0.0);
}

}  // namespace
}  // namespace linesurf::pipeline
