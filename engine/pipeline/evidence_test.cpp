#include "engine/pipeline/evidence.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "tests/support/grid_complex.h"
#include "tests/support/one_complex_evidence.h"
#include "tests/support/thread_count.h"

namespace linesurf::pipeline {
namespace {

using testing::GridComplexForTest;

/// A scene with one segment, its planes and one viewpoint.
Scene OneSegmentScene(const Segment3& segment, const std::vector<Plane3>& planes,
                      const Vec3& viewpoint) {
  Scene scene;
  scene.segments.push_back(segment);
  scene.viewpoints.push_back(viewpoint);
  scene.observations.AddRow(std::vector<ViewpointId>{ViewpointId(std::size_t{0})});
  PlaneMembership m;
  for (const Plane3& p : planes) {
    m.Add(scene.planes.NextId());
    scene.planes.push_back(p);
  }
  scene.memberships.push_back(m);
  return scene;
}

EnergyOptions UnitOptions() {
  EnergyOptions o;
  o.sigma = 1.0;
  o.weights.visibility = 1.0;
  o.weights.edge = 0.0;
  o.weights.corner = 0.0;
  return o;
}

EvidenceResult Compute(const GridComplexForTest& g, const Scene& scene, const EnergyOptions& o,
                       int threads = 1) {
  RunContext ctx;
  ctx.num_threads = threads;
  auto r = testing::ComputeOneComplexEvidence(g.complex(), scene, o, BoundaryMode::kNone, ctx);
  EXPECT_TRUE(r.has_value()) << (r ? "" : r.error().ToString());
  return r ? std::move(r.value()) : EvidenceResult{};
}

double PairWeight(const solver::EnergyInput& e, CellId a, CellId b) {
  double w = 0.0;
  for (const auto& p : e.pairs) {
    if ((p.a == a && p.b == b) || (p.a == b && p.b == a)) w += p.weight;
  }
  return w;
}

TEST(OneComplexEvidence, TexturalSegmentPenalisesTheCellBehindIt) {
  const GridComplexForTest g(4, 4, 4);
  const Scene scene = OneSegmentScene({Vec3(2, 1.2, 1.5), Vec3(2, 1.8, 1.5)},
                                      {Plane3{Vec3(2, 0, 0), Vec3::UnitX()}}, Vec3(0.5, 1.5, 1.5));
  const EvidenceResult r = Compute(g, scene, UnitOptions());
  const solver::EnergyInput& e = r.energy;
  ASSERT_EQ(e.NumCells(), g.complex().NumCells());
  EXPECT_NEAR(e.cost_if_empty[g.Cell(2, 1, 1)], 0.6, 1e-6);
  double total = 0.0;
  for (const double c : e.cost_if_empty) total += c;
  EXPECT_NEAR(total, 0.6, 1e-6);
  // The sight rays cross x = 1 only; the facet the segment lies on (x = 2) is exempt.
  EXPECT_NEAR(PairWeight(e, g.Cell(0, 1, 1), g.Cell(1, 1, 1)), 0.6, 1e-6);
  EXPECT_EQ(e.NumPairs(), 1u);
  // Prior: one observation from the viewpoint's cell.
  EXPECT_NEAR(e.cost_if_full[g.Cell(0, 1, 1)], 1.0, 1e-12);
  EXPECT_EQ(r.stats.segments_with_planes[1], 1u);
}

TEST(OneComplexEvidence, ViewpointOnTheOtherSideFlipsTheBehindCell) {
  const GridComplexForTest g(4, 4, 4);
  const Scene scene = OneSegmentScene({Vec3(2, 1.2, 1.5), Vec3(2, 1.8, 1.5)},
                                      {Plane3{Vec3(2, 0, 0), Vec3::UnitX()}}, Vec3(3.5, 1.5, 1.5));
  const EvidenceResult r = Compute(g, scene, UnitOptions());
  EXPECT_NEAR(r.energy.cost_if_empty[g.Cell(1, 1, 1)], 0.6, 1e-6);
  EXPECT_NEAR(PairWeight(r.energy, g.Cell(3, 1, 1), g.Cell(2, 1, 1)), 0.6, 1e-6);
}

TEST(OneComplexEvidence, StructuralSegmentGroupsTheCellsNotFacingTheView) {
  const GridComplexForTest g(4, 4, 4);
  const Scene scene = OneSegmentScene(
      {Vec3(2, 2, 1.2), Vec3(2, 2, 1.8)},
      {Plane3{Vec3(2, 0, 0), Vec3::UnitX()}, Plane3{Vec3(0, 2, 0), Vec3::UnitY()}},
      Vec3(0.5, 0.5, 1.5));
  const EvidenceResult r = Compute(g, scene, UnitOptions());
  const solver::EnergyInput& e = r.energy;
  ASSERT_EQ(e.NumStructuralGroups(), 1u);
  std::vector<CellId> group(e.StructuralGroup(0).begin(), e.StructuralGroup(0).end());
  std::vector<CellId> expected{g.Cell(2, 1, 1), g.Cell(1, 2, 1), g.Cell(2, 2, 1)};
  std::sort(expected.begin(), expected.end());
  EXPECT_EQ(group, expected);
  EXPECT_NEAR(e.structural_weights[0], 0.6, 1e-6);
  // No single cell is penalised for being empty.
  for (const double c : e.cost_if_empty) EXPECT_EQ(c, 0.0);
  // The ablation turns it into two textural segments instead.
  EnergyOptions ablation = UnitOptions();
  ablation.structural_as_textural = true;
  const EvidenceResult a = Compute(g, scene, ablation);
  EXPECT_EQ(a.energy.NumStructuralGroups(), 0u);
  double total = 0.0;
  for (const double c : a.energy.cost_if_empty) total += c;
  EXPECT_NEAR(total, 1.2, 1e-6);
}

TEST(OneComplexEvidence, CreaseTermChargesOnlyTheFlatLabellingsThroughTheSegment) {
  const GridComplexForTest g(4, 4, 4);
  const Scene scene =
      OneSegmentScene({Vec3(2, 2, 1.2), Vec3(2, 2, 1.8)},
                      {Plane3{Vec3(2, 0, 0), Vec3::UnitX()}, Plane3{Vec3(0, 2, 0), Vec3::UnitY()}},
                      Vec3(0.5, 0.5, 1.5));
  EnergyOptions with = UnitOptions();
  with.weights.crease = 0.5;
  EnergyOptions without = UnitOptions();
  without.weights.crease = 0.0;
  const EvidenceResult r = Compute(g, scene, with);
  const EvidenceResult paper = Compute(g, scene, without);
  EXPECT_EQ(r.stats.crease_weight, 0.5);
  // Across x = 2, across y = 2, across both; the cell facing the view (1, 1, 1) stays empty.
  const CellId a = g.Cell(2, 1, 1), b = g.Cell(1, 2, 1), d = g.Cell(2, 2, 1);
  for (int code = 0; code < 8; ++code) {
    std::vector<std::uint8_t> labels(g.complex().NumCells(), 0);
    const int xa = code & 1, xb = (code >> 1) & 1, xd = (code >> 2) & 1;
    labels[a.index()] = xa;
    labels[b.index()] = xb;
    labels[d.index()] = xd;
    const bool flat = xd == 1 && xa != xb;  // the surface is x = 2 or y = 2 through the crease
    const double extra = r.energy.Evaluate(std::span<const std::uint8_t>(labels)) -
                         paper.energy.Evaluate(std::span<const std::uint8_t>(labels));
    EXPECT_NEAR(extra, flat ? 0.5 * 0.6 : 0.0, 1e-6) << "labels (a, b, d) " << xa << xb << xd;
  }
}

TEST(OneComplexEvidence, CreaseWeightDefaultsByTheBoundary) {
  EnergyOptions o;
  EXPECT_EQ(CreaseWeight(o, BoundaryMode::kInterior), kInteriorCreaseWeight);
  EXPECT_EQ(CreaseWeight(o, BoundaryMode::kExterior), 0.0);
  EXPECT_EQ(CreaseWeight(o, BoundaryMode::kNone), 0.0);
  o.weights.crease = 0.7;
  EXPECT_EQ(CreaseWeight(o, BoundaryMode::kExterior), 0.7);
  o.weights.crease = -1.0;
  EXPECT_FALSE(o.Validate());
}

TEST(OneComplexEvidence, SegmentsWithoutPlanesStillGiveVisibility) {
  const GridComplexForTest g(4, 4, 4);
  const Scene scene =
      OneSegmentScene({Vec3(2.5, 1.2, 1.5), Vec3(2.5, 1.8, 1.5)}, {}, Vec3(0.5, 1.5, 1.5));
  const EvidenceResult r = Compute(g, scene, UnitOptions());
  EXPECT_EQ(r.energy.NumStructuralGroups(), 0u);
  EXPECT_NEAR(PairWeight(r.energy, g.Cell(0, 1, 1), g.Cell(1, 1, 1)), 0.6, 1e-6);
  EXPECT_NEAR(PairWeight(r.energy, g.Cell(1, 1, 1), g.Cell(2, 1, 1)), 0.6, 1e-6);
  EXPECT_EQ(r.stats.segments_with_planes[0], 1u);
}

TEST(OneComplexEvidence, RegularisationAndBoundary) {
  const GridComplexForTest g(3, 3, 3);
  Scene scene;
  scene.observations.Clear();
  EnergyOptions o = UnitOptions();
  o.weights.edge = 0.5;
  o.weights.corner = 0.25;
  RunContext ctx;
  auto r = testing::ComputeOneComplexEvidence(g.complex(), scene, o, BoundaryMode::kExterior, ctx);
  ASSERT_TRUE(r.has_value()) << r.error().ToString();
  // Interior edges of a 3x3x3 grid: 3 axes x 3 segments x 2x2 lines = 36; interior vertices: 8.
  EXPECT_EQ(r->energy.NumParityGroups(), 36u + 8u);
  EXPECT_EQ(r->energy.ParityGroup(0).size(), 4u);
  EXPECT_EQ(r->energy.ParityGroup(36).size(), 8u);
  EXPECT_DOUBLE_EQ(r->energy.parity_weights[0], 0.5);
  EXPECT_DOUBLE_EQ(r->energy.parity_weights[36], 0.25);
  // Every cell but the centre touches the box.
  EXPECT_EQ(r->stats.fixed_cells, 26u);
  EXPECT_EQ(r->energy.fixed[g.Cell(1, 1, 1)], solver::CellFix::kFree);
  EXPECT_EQ(r->energy.fixed[g.Cell(0, 1, 1)], solver::CellFix::kEmpty);
  EXPECT_TRUE(r->energy.Validate().has_value());
}

TEST(OneComplexEvidence, IdenticalForAnyThreadCount) {
  const GridComplexForTest g(6, 6, 6);
  Scene scene;
  for (int i = 0; i < 300; ++i) {
    const double t = 0.37 * i;
    const Vec3 a(1.0 + std::fmod(t, 4.0), 1.0 + std::fmod(1.7 * t, 4.0), 3.0);
    scene.segments.push_back({a, a + Vec3(0.3, 0.2, 0.0)});
    scene.observations.AddRow(std::vector<ViewpointId>{ViewpointId(std::size_t(i % 3))});
    PlaneMembership m;
    m.Add(PlaneId(std::size_t{0}));
    scene.memberships.push_back(m);
  }
  scene.planes.push_back(Plane3{Vec3(0, 0, 3), Vec3::UnitZ()});
  scene.viewpoints.push_back(Vec3(0.5, 0.5, 5.5));
  scene.viewpoints.push_back(Vec3(5.5, 0.5, 5.5));
  scene.viewpoints.push_back(Vec3(3.1, 3.2, 0.5));
  EnergyOptions o;
  o.sigma = 0.1;
  const linesurf::testing::RealThreadCounts real_threads;
  const EvidenceResult one = Compute(g, scene, o, 1);
  for (const int threads : linesurf::testing::kThreadCounts) {
    const EvidenceResult many = Compute(g, scene, o, threads);
    EXPECT_EQ(one.energy.cost_if_empty.raw(), many.energy.cost_if_empty.raw());
    EXPECT_EQ(one.energy.cost_if_full.raw(), many.energy.cost_if_full.raw());
    ASSERT_EQ(one.energy.NumPairs(), many.energy.NumPairs());
    for (std::size_t i = 0; i < one.energy.NumPairs(); ++i) {
      EXPECT_EQ(one.energy.pairs[i].a, many.energy.pairs[i].a);
      EXPECT_EQ(one.energy.pairs[i].weight, many.energy.pairs[i].weight);
    }
  }
}

TEST(EnergyOptions, ValidateNamesTheBadField) {
  EnergyOptions o;
  o.weights.visibility = -1.0;
  const Status s = o.Validate();
  ASSERT_FALSE(s.has_value());
  EXPECT_NE(s.error().message.find("weights.visibility"), std::string::npos);
  o = EnergyOptions{};
  o.sigma = 0.0;
  EXPECT_FALSE(o.Validate().has_value());
  EXPECT_TRUE(EnergyOptions{}.Validate().has_value());
}

}  // namespace
}  // namespace linesurf::pipeline
