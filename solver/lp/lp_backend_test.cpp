#include "solver/lp/lp_backend.h"

#include "solver/lp/backends/cbc/cbc_backend.h"
#include "tests/support/random_energy.h"
#include "tests/support/thread_count.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace linesurf::solver {
namespace {

constexpr double kObjectiveTolerance = 1e-6;
// Exact arithmetic on small sums of given costs.
constexpr double kExactObjectiveTolerance = 1e-9;
// Relative agreement of pdhg (tolerance 1e-4) with Clp's optimum.
constexpr double kPdhgAgreement = 1e-3;

LabelingResult MustSolve(const EnergyInput& e, SolverBackend backend, int threads = 1) {
  LabelingOptions options;
  options.backend = backend;
  RunContext ctx;
  ctx.num_threads = threads;
  auto result = SolveLabeling(e, options, ctx);
  EXPECT_TRUE(result) << (result ? "" : result.error().ToString());
  if (!result) return {};
  return std::move(result).value();
}

// A chain 0-1-...-5: strong evidence for full at cell 1 and 4, pairwise terms between
// neighbours, the ends fixed empty. Min cut: full on 1..4 costs 2 (two cut pairs) and less than
// leaving the evidence empty (3 + 3).
EnergyInput Chain() {
  EnergyInput e;
  e.AddCell(0.0, 0.0, CellFix::kEmpty);
  e.AddCell(3.0, 0.0);
  e.AddCell(0.0, 0.2);
  e.AddCell(0.0, 0.2);
  e.AddCell(3.0, 0.0);
  e.AddCell(0.0, 0.0, CellFix::kEmpty);
  for (std::uint32_t i = 0; i + 1 < 6; ++i) e.AddPair(CellId(i), CellId(i + 1), 1.0);
  return e;
}

class EveryBackend : public ::testing::TestWithParam<SolverBackend> {};

TEST_P(EveryBackend, ChainGivesTheMinCut) {
  const LabelingResult r = MustSolve(Chain(), GetParam());
  EXPECT_EQ(r.labels, (std::vector<std::uint8_t>{0, 1, 1, 1, 1, 0}));
  EXPECT_NEAR(r.labels_objective, 2.4, kExactObjectiveTolerance);
  EXPECT_NEAR(r.relaxed_objective, 2.4, kPdhgAgreement);
}

TEST_P(EveryBackend, FixedCellsAreRespected) {
  EnergyInput e = Chain();
  e.fixed[CellId(2u)] = CellFix::kEmpty;  // evidence says full, boundary says empty
  e.fixed[CellId(0u)] = CellFix::kFull;
  const LabelingResult r = MustSolve(e, GetParam());
  EXPECT_EQ(r.labels[0], 1);
  EXPECT_EQ(r.labels[2], 0);
  EXPECT_EQ(r.labels[5], 0);
  EXPECT_NEAR(r.labels_objective, testing::BruteForceMinimum(e), kExactObjectiveTolerance);
}

INSTANTIATE_TEST_SUITE_P(Solver,
                         EveryBackend,
                         ::testing::Values(SolverBackend::kClp,
                                           SolverBackend::kMaxflow,
                                           SolverBackend::kPdhg,
                                           SolverBackend::kPdhgEnergy,
                                           SolverBackend::kAuto));

class LpBackends : public ::testing::TestWithParam<SolverBackend> {};

TEST_P(LpBackends, StructuralGroupForcesOneCellFull) {
  // Three cells, a slight cost for being full, one structural group over all of them: exactly
  // one must be full; the cheapest is cell 1.
  EnergyInput e;
  e.AddCell(0.0, 0.3);
  e.AddCell(0.0, 0.1);
  e.AddCell(0.0, 0.2);
  const CellId group[] = {CellId(0u), CellId(1u), CellId(2u)};
  e.AddStructuralGroup(group, 1.0);
  const LabelingResult r = MustSolve(e, GetParam());
  EXPECT_EQ(r.labels, (std::vector<std::uint8_t>{0, 1, 0}));
  EXPECT_NEAR(r.labels_objective, 0.1, kExactObjectiveTolerance);
}

TEST_P(LpBackends, ParityTermPrefersAFlatSurface) {
  // Four cells around an edge, nu = (+,-,+,-), cells 0 and 1 fixed full; cell 2 has weak
  // evidence for full (0.4), cell 3 a viewpoint prior (0.5). Full {0,1,2} is a crease (parity
  // 1), full {0,1} is flat (parity 0, pays 0.4), all full is flat (pays 0.5): with an edge
  // weight above the evidence the flat surface {0,1} wins.
  EnergyInput e;
  e.AddCell(0.0, 0.0, CellFix::kFull);
  e.AddCell(0.0, 0.0, CellFix::kFull);
  e.AddCell(0.4, 0.0);
  e.AddCell(0.0, 0.5);
  const CellId cells[] = {CellId(0u), CellId(1u), CellId(2u), CellId(3u)};
  const std::int8_t nu[] = {1, -1, 1, -1};
  e.AddParityGroup(cells, nu, 1.0);
  const LabelingResult flat = MustSolve(e, GetParam());
  EXPECT_EQ(flat.labels, (std::vector<std::uint8_t>{1, 1, 0, 0}));
  EXPECT_NEAR(flat.labels_objective, 0.4, kExactObjectiveTolerance);
  e.parity_weights[0] = 0.1;  // now the evidence wins: crease costs 0.1 < 0.4
  const LabelingResult crease = MustSolve(e, GetParam());
  EXPECT_EQ(crease.labels, (std::vector<std::uint8_t>{1, 1, 1, 0}));
}

TEST_P(LpBackends, MatchClpOnRandomEnergies) {
  int integral = 0;
  for (std::uint64_t seed = 1; seed <= 30; ++seed) {
    testing::RandomEnergySpec spec;
    spec.num_cells = 14;
    spec.num_pairs = 20;
    spec.num_structural = 5;
    spec.num_parity = 5;
    spec.fixed_fraction = 0.15;
    spec.seed = seed;
    const EnergyInput e = testing::RandomEnergy(spec);
    const double best = testing::BruteForceMinimum(e);
    const LabelingResult clp = MustSolve(e, SolverBackend::kClp);
    const LabelingResult other = MustSolve(e, GetParam());
    // The relaxation bounds the integral optimum from below.
    EXPECT_LE(clp.relaxed_objective, best + kObjectiveTolerance);
    EXPECT_NEAR(other.relaxed_objective,
                clp.relaxed_objective,
                kPdhgAgreement * (1.0 + clp.relaxed_objective))
        << "seed " << seed;
    if (clp.fractional_cells == 0) {
      ++integral;
      // An integral LP optimum is an integral optimum; labels must agree where it is unique.
      EXPECT_NEAR(clp.labels_objective, best, kObjectiveTolerance) << "seed " << seed;
      EXPECT_NEAR(other.labels_objective, clp.labels_objective, kObjectiveTolerance)
          << "seed " << seed;
    }
  }
  EXPECT_GT(integral, 5);
}

INSTANTIATE_TEST_SUITE_P(Solver,
                         LpBackends,
                         ::testing::Values(SolverBackend::kClp,
                                           SolverBackend::kPdhg,
                                           SolverBackend::kPdhgEnergy));

TEST(SolveLabeling, MaxflowMatchesClpOnPairwiseEnergies) {
  for (std::uint64_t seed = 1; seed <= 30; ++seed) {
    testing::RandomEnergySpec spec;
    spec.num_cells = 40;
    spec.num_pairs = 80;
    spec.num_structural = 0;
    spec.num_parity = 0;
    spec.seed = seed;
    const EnergyInput e = testing::RandomEnergy(spec);
    const LabelingResult clp = MustSolve(e, SolverBackend::kClp);
    const LabelingResult flow = MustSolve(e, SolverBackend::kMaxflow);
    EXPECT_NEAR(flow.labels_objective, clp.relaxed_objective, kObjectiveTolerance) << seed;
    EXPECT_NEAR(clp.labels_objective, clp.relaxed_objective, kObjectiveTolerance) << seed;
  }
}

TEST(SolveLabeling, MaxflowRefusesHigherOrderTerms) {
  EnergyInput e;
  e.AddCell(0.0, 0.3);
  e.AddCell(0.0, 0.1);
  const CellId group[] = {CellId(0u), CellId(1u)};
  e.AddStructuralGroup(group, 1.0);
  LabelingOptions options;
  options.backend = SolverBackend::kMaxflow;
  const auto result = SolveLabeling(e, options, RunContext{});
  ASSERT_FALSE(result);
  EXPECT_EQ(result.error().code, ErrorCode::kInvalidOptions);
  // With the group's cell fixed full the group vanishes and max-flow is exact again.
  e.fixed[CellId(0u)] = CellFix::kFull;
  EXPECT_TRUE(SolveLabeling(e, options, RunContext{}));
}

TEST(SolveLabeling, AutoPicksMaxflowOnlyWhenExact) {
  EXPECT_EQ(MustSolve(Chain(), SolverBackend::kAuto).backend, SolverBackend::kMaxflow);
  testing::RandomEnergySpec spec;
  EXPECT_EQ(MustSolve(testing::RandomEnergy(spec), SolverBackend::kAuto).backend,
            SolverBackend::kClp);
  LabelingOptions options;
  options.auto_rule.clp_max_columns = 5;
  const auto large = SolveLabeling(testing::RandomEnergy(spec), options, RunContext{});
  ASSERT_TRUE(large);
  EXPECT_EQ(large->backend, SolverBackend::kPdhgEnergy);
}

TEST(SolveLabeling, LocalSearchNeverRaisesTheEnergy) {
  testing::GridEnergySpec spec;
  spec.nx = spec.ny = spec.nz = 8;
  const EnergyInput e = testing::GridEnergy(spec);
  LabelingOptions plain;
  plain.backend = SolverBackend::kClp;
  plain.improve.local_search_passes = 0;
  plain.improve.group_move_passes = 0;
  plain.improve.window_cells = 0;
  const auto rounded = SolveLabeling(e, plain, RunContext{});
  LabelingOptions searched = plain;
  searched.improve.local_search_passes = 10;
  const auto improved = SolveLabeling(e, searched, RunContext{});
  ASSERT_TRUE(rounded && improved);
  EXPECT_EQ(rounded->local_search_flips, 0u);
  EXPECT_DOUBLE_EQ(improved->rounded_objective, rounded->labels_objective);
  EXPECT_LE(improved->labels_objective, rounded->labels_objective);
  EXPECT_GE(improved->labels_objective, improved->relaxed_objective - kExactObjectiveTolerance);
}

TEST(SolveLabeling, RejectsBadOptionsAndInput) {
  LabelingOptions options;
  options.backend = static_cast<SolverBackend>(42);
  EXPECT_EQ(SolveLabeling(Chain(), options, RunContext{}).error().code, ErrorCode::kInvalidOptions);
  options = {};
  options.pdhg.tolerance = 0.0;
  EXPECT_EQ(SolveLabeling(Chain(), options, RunContext{}).error().code, ErrorCode::kInvalidOptions);
  options = {};
  options.pdhg_energy.tolerance = 0.2;
  const auto too_loose = SolveLabeling(Chain(), options, RunContext{});
  ASSERT_FALSE(too_loose);
  EXPECT_NE(too_loose.error().message.find("pdhg_energy_tolerance"), std::string::npos);
  EnergyInput bad = Chain();
  bad.AddPair(CellId(0u), CellId(99u), 1.0);
  EXPECT_EQ(SolveLabeling(bad, LabelingOptions{}, RunContext{}).error().code,
            ErrorCode::kInvalidInput);
}

TEST(SolveLabeling, CancelledRunReturnsCancelled) {
  RunContext ctx;
  ctx.is_cancelled = [] { return true; };
  testing::GridEnergySpec spec;
  spec.nx = spec.ny = spec.nz = 8;
  for (const SolverBackend backend : {SolverBackend::kClp, SolverBackend::kPdhg}) {
    LabelingOptions options;
    options.backend = backend;
    const auto result = SolveLabeling(testing::GridEnergy(spec), options, ctx);
    ASSERT_FALSE(result) << SolverBackendName(backend);
    EXPECT_EQ(result.error().code, ErrorCode::kCancelled) << SolverBackendName(backend);
  }
}

TEST(SolveLabeling, EmptyEnergySolves) {
  const LabelingResult r = MustSolve(EnergyInput{}, SolverBackend::kClp);
  EXPECT_TRUE(r.labels.empty());
  EXPECT_EQ(r.lp_columns, 0u);
}

}  // namespace
}  // namespace linesurf::solver

namespace linesurf::solver {
namespace {

TEST(SolveLabeling, FirstOrderBackendsAreIdenticalForAnyThreadCount) {
  testing::GridEnergySpec spec;
  spec.nx = spec.ny = spec.nz = 14;  // LP of ~16k columns, 2.7k cells: several parallel chunks
  const EnergyInput e = testing::GridEnergy(spec);
  const linesurf::testing::RealThreadCounts real_threads;
  for (const SolverBackend backend : {SolverBackend::kPdhg, SolverBackend::kPdhgEnergy}) {
    const LabelingResult one = MustSolve(e, backend, 1);
    ASSERT_GT(one.lp_columns, 10000u);
    for (int threads : linesurf::testing::kThreadCounts) {
      const LabelingResult many = MustSolve(e, backend, threads);
      EXPECT_EQ(many.labels, one.labels) << SolverBackendName(backend) << " " << threads;
      EXPECT_EQ(many.relaxed, one.relaxed)
          << SolverBackendName(backend) << " " << threads;  // bitwise
      EXPECT_EQ(many.iterations, one.iterations) << SolverBackendName(backend) << " " << threads;
    }
  }
}

TEST(SolveLabeling, FirstOrderBackendsAreCloseToClpOnAGridEnergy) {
  testing::GridEnergySpec spec;
  spec.nx = spec.ny = spec.nz = 10;
  const EnergyInput e = testing::GridEnergy(spec);
  const LabelingResult clp = MustSolve(e, SolverBackend::kClp);
  for (const SolverBackend backend : {SolverBackend::kPdhg, SolverBackend::kPdhgEnergy}) {
    const LabelingResult first_order = MustSolve(e, backend);
    EXPECT_NEAR(first_order.relaxed_objective,
                clp.relaxed_objective,
                kPdhgAgreement * clp.relaxed_objective)
        << SolverBackendName(backend);
    EXPECT_GE(first_order.relaxed_objective, clp.relaxed_objective - kObjectiveTolerance)
        << SolverBackendName(backend);
  }
}

TEST(SolveLabeling, BandIsAnUpperBoundOfTheFullLpAndKeepsFixes) {
  for (std::uint64_t seed = 1; seed <= 10; ++seed) {
    const EnergyInput e = testing::SmallRandomEnergy(seed);
    const LabelingResult clp = MustSolve(e, SolverBackend::kClp);
    const LabelingResult band = MustSolve(e, SolverBackend::kBand);
    EXPECT_EQ(band.backend, SolverBackend::kBand);
    ASSERT_TRUE(band.band_lp_backend.has_value());
    EXPECT_EQ(BackendReportName(band),
              std::string("band+") + SolverBackendName(*band.band_lp_backend));
    EXPECT_GE(band.relaxed_objective, clp.relaxed_objective - kObjectiveTolerance) << seed;
    EXPECT_NEAR(band.labels_objective,
                e.Evaluate(std::span<const std::uint8_t>(band.labels)),
                kObjectiveTolerance);
    for (std::size_t c = 0; c < e.NumCells(); ++c) {
      const CellFix f = e.fixed[CellId(c)];
      if (f != CellFix::kFree) {
        EXPECT_EQ(band.labels[c], f == CellFix::kFull ? 1 : 0);
      }
    }
  }
}

TEST(SolveLabeling, BandOnAGridEnergyIsCloseToTheFullLp) {
  testing::GridEnergySpec spec;
  spec.nx = spec.ny = spec.nz = 10;
  const EnergyInput e = testing::GridEnergy(spec);
  const LabelingResult clp = MustSolve(e, SolverBackend::kClp);
  const LabelingResult band = MustSolve(e, SolverBackend::kBand);
  EXPECT_LT(band.band_lp_columns, clp.lp_columns);
  EXPECT_GE(band.relaxed_objective, clp.relaxed_objective - kObjectiveTolerance);
  // The labels of the band are within 5 % of the energy of the full LP's labels.
  EXPECT_LE(band.labels_objective, 1.05 * clp.labels_objective);
}

}  // namespace
}  // namespace linesurf::solver

namespace linesurf::solver {
namespace {

TEST(SolveLabeling, CbcFindsTheBruteForceOptimum) {
  if (!CbcAvailable()) GTEST_SKIP() << "this build has no Cbc";
  for (std::uint64_t seed = 1; seed <= 30; ++seed) {
    testing::RandomEnergySpec spec;
    spec.num_cells = 14;
    spec.num_pairs = 20;
    spec.num_structural = 5;
    spec.num_parity = 6;
    spec.fixed_fraction = 0.15;
    spec.seed = seed;
    const EnergyInput e = testing::RandomEnergy(spec);
    const double best = testing::BruteForceMinimum(e);
    const LabelingResult cbc = MustSolve(e, SolverBackend::kCbc);
    EXPECT_EQ(cbc.status, "optimal") << seed;
    EXPECT_EQ(cbc.lower_bound_source, "integer optimum") << seed;
    EXPECT_NEAR(cbc.labels_objective, best, kObjectiveTolerance) << seed;
    EXPECT_NEAR(cbc.labels_objective,
                e.Evaluate(std::span<const std::uint8_t>(cbc.labels)),
                kExactObjectiveTolerance);
    EXPECT_NEAR(cbc.lower_bound, best, kObjectiveTolerance) << seed;
    for (std::size_t c = 0; c < e.NumCells(); ++c) {
      const CellFix f = e.fixed[CellId(c)];
      if (f != CellFix::kFree) {
        EXPECT_EQ(cbc.labels[c], f == CellFix::kFull ? 1 : 0);
      }
    }
  }
}

TEST(SolveLabeling, LowerBoundsAreBelowTheIntegralOptimum) {
  for (std::uint64_t seed = 1; seed <= 10; ++seed) {
    testing::RandomEnergySpec spec;
    spec.num_cells = 14;
    spec.num_pairs = 20;
    spec.num_structural = 5;
    spec.num_parity = 6;
    spec.seed = seed;
    const EnergyInput e = testing::RandomEnergy(spec);
    const double best = testing::BruteForceMinimum(e);
    for (const SolverBackend backend : {SolverBackend::kClp, SolverBackend::kBand}) {
      const LabelingResult r = MustSolve(e, backend);
      EXPECT_NE(r.lower_bound_source, "none") << SolverBackendName(backend);
      EXPECT_LE(r.lower_bound, best + kObjectiveTolerance)
          << SolverBackendName(backend) << " seed " << seed;
      EXPECT_GE(r.labels_objective, best - kObjectiveTolerance)
          << SolverBackendName(backend) << " seed " << seed;
    }
  }
}

}  // namespace
}  // namespace linesurf::solver

namespace linesurf::solver {
namespace {

LabelingResult SolveWith(const EnergyInput& e, LabelingOptions options) {
  auto result = SolveLabeling(e, options, RunContext{});
  EXPECT_TRUE(result) << (result ? "" : result.error().ToString());
  return result ? std::move(result).value() : LabelingResult{};
}

// The labelling without its improvement: rounding and single-cell local search only.
LabelingOptions RoundingAndLocalSearch(SolverBackend backend) {
  LabelingOptions o;
  o.backend = backend;
  o.improve.group_move_passes = 0;
  o.improve.window_cells = 0;
  return o;
}

TEST(ImprovedLabelling, NeverWorseThanLocalSearchAndOptimalWhereCbcProvesIt) {
  if (!CbcAvailable()) GTEST_SKIP() << "this build has no Cbc";
  for (std::uint64_t seed = 1; seed <= 10; ++seed) {
    testing::RandomEnergySpec spec;
    spec.num_cells = 40;  // within one window (random energies are hard for Cbc beyond that)
    spec.num_pairs = spec.num_cells * 2;
    spec.num_structural = spec.num_cells / 4;
    spec.num_parity = spec.num_cells / 3;
    spec.seed = seed;
    const EnergyInput e = testing::RandomEnergy(spec);
    for (const SolverBackend backend : {SolverBackend::kClp, SolverBackend::kPdhg}) {
      const LabelingResult before = SolveWith(e, RoundingAndLocalSearch(backend));
      LabelingOptions defaults;
      defaults.backend = backend;
      const LabelingResult after = SolveWith(e, defaults);
      LabelingOptions exact;
      exact.backend = SolverBackend::kCbc;
      const LabelingResult optimum = SolveWith(e, exact);
      ASSERT_EQ(optimum.status, "optimal") << seed;
      EXPECT_LE(after.labels_objective, before.labels_objective + kExactObjectiveTolerance)
          << SolverBackendName(backend) << seed;
      EXPECT_NEAR(after.labels_objective, optimum.labels_objective, kObjectiveTolerance)
          << SolverBackendName(backend) << " seed " << seed;
      if (after.windows > 0) {  // the window held every free cell: the optimum is proven
        EXPECT_EQ(after.lower_bound_source, "integer optimum")
            << SolverBackendName(backend) << " seed " << seed;
      }
    }
  }
}

// 5^3 free cells: several windows of 64.
TEST(ImprovedLabelling, ReachesCbcsOptimumOnASmallGridEnergy) {
  if (!CbcAvailable()) GTEST_SKIP() << "this build has no Cbc";
  testing::GridEnergySpec spec;
  spec.nx = spec.ny = spec.nz = 7;
  const EnergyInput e = testing::GridEnergy(spec);
  LabelingOptions exact;
  exact.backend = SolverBackend::kCbc;
  const LabelingResult optimum = SolveWith(e, exact);
  ASSERT_EQ(optimum.status, "optimal");
  const LabelingResult before = SolveWith(e, RoundingAndLocalSearch(SolverBackend::kClp));
  LabelingOptions defaults;
  defaults.backend = SolverBackend::kClp;
  const LabelingResult after = SolveWith(e, defaults);
  EXPECT_LE(after.labels_objective, before.labels_objective + kExactObjectiveTolerance);
  EXPECT_NEAR(after.labels_objective, optimum.labels_objective, kObjectiveTolerance);
  EXPECT_LE(after.lower_bound, optimum.labels_objective + kObjectiveTolerance);
}

TEST(ImprovedLabelling, IsIdenticalForAnyThreadCount) {
  testing::GridEnergySpec spec;
  spec.nx = spec.ny = spec.nz = 9;
  const EnergyInput e = testing::GridEnergy(spec);
  const LabelingResult one = MustSolve(e, SolverBackend::kClp, 1);
  for (int threads : {2, 3, 8}) {
    const LabelingResult many = MustSolve(e, SolverBackend::kClp, threads);
    EXPECT_EQ(many.labels, one.labels) << threads;
    EXPECT_EQ(many.windows, one.windows) << threads;
  }
}

}  // namespace
}  // namespace linesurf::solver

namespace linesurf::solver {
namespace {

// The first-order backends prove bounds from their dual points: below Clp's LP optimum, and
// within the tolerance of it at the end.
TEST(SolveLabeling, FirstOrderDualBoundsAreValidAndCloseLowerBounds) {
  testing::GridEnergySpec spec;
  spec.nx = spec.ny = spec.nz = 10;
  const EnergyInput e = testing::GridEnergy(spec);
  const LabelingResult clp = MustSolve(e, SolverBackend::kClp);
  const std::pair<SolverBackend, const char*> kSources[] = {
      {SolverBackend::kPdhg, "lp dual bound"}, {SolverBackend::kPdhgEnergy, "energy dual bound"}};
  for (const auto& [backend, source] : kSources) {
    const LabelingResult first_order = MustSolve(e, backend);
    EXPECT_EQ(first_order.lower_bound_source, source);
    EXPECT_LE(first_order.lower_bound, clp.relaxed_objective + kObjectiveTolerance)
        << SolverBackendName(backend);
    EXPECT_GE(first_order.lower_bound, clp.relaxed_objective * (1.0 - kPdhgAgreement))
        << SolverBackendName(backend);
    for (std::uint64_t seed = 1; seed <= 10; ++seed) {
      testing::RandomEnergySpec random;
      random.seed = seed;
      const EnergyInput r = testing::RandomEnergy(random);
      // Without windows: one window holding every cell would prove the (higher) integer optimum.
      const LabelingResult only = SolveWith(r, RoundingAndLocalSearch(backend));
      EXPECT_EQ(only.lower_bound_source, source);
      EXPECT_LE(only.lower_bound,
                MustSolve(r, SolverBackend::kClp).relaxed_objective + kExactObjectiveTolerance)
          << SolverBackendName(backend) << " " << seed;
    }
  }
}

}  // namespace
}  // namespace linesurf::solver
