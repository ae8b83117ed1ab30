#include "solver/lp/labeling_backends.h"

#include "engine/core/exception.h"
#include "solver/lp/backends/cbc/cbc_backend.h"
#include "solver/lp/lp_backend.h"
#include "tests/support/random_energy.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace linesurf::solver {
namespace {

// Exact arithmetic on small sums of given costs.
constexpr double kBoundTolerance = 1e-6;

std::vector<SolverBackend> EveryEnumerator() {
  std::vector<SolverBackend> all;
  for (int i = 0; i < OptionEnum<SolverBackend>::kCount; ++i) {
    all.push_back(static_cast<SolverBackend>(i));
  }
  return all;
}

// A small energy with structural and parity terms, small enough for the brute-force minimum.
EnergyInput MixedEnergy() {
  return testing::RandomEnergy({.num_cells = 14,
                                .num_pairs = 20,
                                .num_structural = 5,
                                .num_parity = 6,
                                .fixed_fraction = 0.15,
                                .parity_constants = false,
                                .seed = 7});
}

Expected<LabelingResult> SolveBy(const EnergyInput& e, SolverBackend backend) {
  LabelingOptions options;
  options.backend = backend;
  return SolveLabeling(e, options, RunContext{});
}

TEST(LabelingBackends, EveryEnumeratorHasOneEntry) {
  EXPECT_EQ(LabelingBackends().size(), EveryEnumerator().size());
  for (const SolverBackend backend : EveryEnumerator()) {
    const LabelingBackend* entry = FindBackend(backend);
    ASSERT_NE(entry, nullptr) << SolverBackendName(backend);
    EXPECT_EQ(entry->backend, backend);
    EXPECT_EQ(&LookupBackend(backend), entry);
  }
  EXPECT_EQ(FindBackend(static_cast<SolverBackend>(42)), nullptr);
  EXPECT_THROW(static_cast<void>(LookupBackend(static_cast<SolverBackend>(42))), LinesurfException);
}

TEST(LabelingBackends, CapabilitiesAndStrategiesAgree) {
  for (const LabelingBackend& b : LabelingBackends()) {
    SCOPED_TRACE(SolverBackendName(b.backend));
    const BackendCapabilities& can = b.capabilities;
    EXPECT_TRUE(!can.integral || can.exact);  // an integral solve proves its optimum
    EXPECT_TRUE(!can.needs_partition || can.takes_partition);
    EXPECT_EQ(b.strategy == BackendStrategy::kSolve, b.solve != nullptr);
    EXPECT_EQ(b.strategy == BackendStrategy::kRule, b.backend == SolverBackend::kAuto);
    ASSERT_NE(b.availability.in_this_build, nullptr);
    // A backend every build has needs no hint; an optional one says how to get it.
    EXPECT_EQ(std::string(b.availability.missing_hint).empty(),
              b.availability.in_this_build ==
                  LookupBackend(SolverBackend::kClp).availability.in_this_build);
  }
  EXPECT_EQ(LookupBackend(SolverBackend::kCbc).availability.in_this_build(), CbcAvailable());
}

TEST(LabelingBackends, ValidateAcceptsExactlyTheTable) {
  LabelingOptions options;
  options.backend = static_cast<SolverBackend>(42);
  const Status unknown = options.Validate();
  ASSERT_FALSE(unknown);
  EXPECT_EQ(unknown.error().message,
            "backend: value 42 is not one of auto, clp, clp-barrier, maxflow, pdhg, pdhg-energy, "
            "band, blocks, cbc");
  for (const LabelingBackend& b : LabelingBackends()) {
    options.backend = b.backend;
    EXPECT_EQ(options.Validate().has_value(), b.availability.in_this_build())
        << SolverBackendName(b.backend);
  }
}

TEST(LabelingBackends, BlocksTakeThePerBlockBackendsOfThisBuild) {
  for (const LabelingBackend& b : LabelingBackends()) {
    BlocksOptions blocks;
    blocks.backend = b.backend;
    const Status s = blocks.Validate();
    EXPECT_EQ(s.has_value(), b.capabilities.per_block && b.availability.in_this_build())
        << SolverBackendName(b.backend);
    if (!b.capabilities.per_block) {
      ASSERT_FALSE(s);
      EXPECT_EQ(s.error().message,
                "block_backend: '" + std::string(SolverBackendName(b.backend)) +
                    "' is not one of auto, clp, pdhg, pdhg-energy, cbc");
    }
  }
}

TEST(LabelingBackends, CbcIsRefusedWhereTheBuildHasNone) {
  if (CbcAvailable()) GTEST_SKIP() << "this build has Cbc";
  LabelingOptions options;
  options.backend = SolverBackend::kCbc;
  const Status s = options.Validate();
  ASSERT_FALSE(s);
  EXPECT_EQ(s.error().message,
            "backend: 'cbc' is not in this build (install coinor-libcbc-dev and reconfigure)");
}

TEST(LabelingBackends, AutoRule) {
  const AutoRuleOptions rule;  // clp up to 10,000 columns, blocks above 20,000,000, band never
  const auto resolve = [&rule](bool higher_order, std::size_t columns, std::size_t blocks) {
    return ResolveBackend(
        SolverBackend::kAuto,
        AutoRuleInput{
            .higher_order_terms = higher_order, .lp_columns = columns, .num_blocks = blocks},
        rule);
  };
  EXPECT_EQ(resolve(false, 100000000, 10), SolverBackend::kMaxflow);
  EXPECT_EQ(resolve(true, 10000, 0), SolverBackend::kClp);
  EXPECT_EQ(resolve(true, 10001, 0), SolverBackend::kPdhgEnergy);
  EXPECT_EQ(resolve(true, 20000001, 1), SolverBackend::kPdhgEnergy);
  EXPECT_EQ(resolve(true, 20000001, 2), SolverBackend::kBlocks);
  AutoRuleOptions band = rule;
  band.band_min_columns = 50;
  EXPECT_EQ(
      ResolveBackend(SolverBackend::kAuto,
                     AutoRuleInput{.higher_order_terms = true, .lp_columns = 51, .num_blocks = 0},
                     band),
      SolverBackend::kBand);
  for (const SolverBackend backend : EveryEnumerator()) {
    if (backend == SolverBackend::kAuto) continue;
    EXPECT_EQ(ResolveBackend(backend, AutoRuleInput{}, rule), backend);
  }
}

TEST(LabelingBackends, PairwiseOnlyBackendsRefuseHigherOrderTerms) {
  const EnergyInput e = MixedEnergy();
  for (const LabelingBackend& b : LabelingBackends()) {
    if (!b.capabilities.pairwise_only) continue;
    const auto r = SolveBy(e, b.backend);
    ASSERT_FALSE(r) << SolverBackendName(b.backend);
    EXPECT_EQ(r.error().code, ErrorCode::kInvalidOptions);
  }
}

TEST(LabelingBackends, BackendsThatNeedAPartitionRefuseToRunWithout) {
  for (const LabelingBackend& b : LabelingBackends()) {
    if (!b.capabilities.needs_partition) continue;
    const auto r = SolveBy(MixedEnergy(), b.backend);
    ASSERT_FALSE(r) << SolverBackendName(b.backend);
    EXPECT_EQ(r.error().code, ErrorCode::kInvalidOptions);
    EXPECT_EQ(r.error().message,
              "backend '" + std::string(SolverBackendName(b.backend)) +
                  "' needs a partition of the cells into blocks");
  }
}

// Every backend this build has that runs without a partition: its labels are no better than the
// optimum, its bound no higher; an exact backend's bound is at least the LP optimum's (Clp) and
// an integral one solves the integer program: no fractional cells, no windows.
TEST(LabelingBackends, EveryBackendBoundsTheOptimumAsItsCapabilitiesSay) {
  const EnergyInput e = MixedEnergy();
  const double best = testing::BruteForceMinimum(e);
  const auto clp = SolveBy(e, SolverBackend::kClp);
  ASSERT_TRUE(clp);
  for (const LabelingBackend& b : LabelingBackends()) {
    const BackendCapabilities& can = b.capabilities;
    if (!b.availability.in_this_build() || can.needs_partition || can.pairwise_only) continue;
    SCOPED_TRACE(SolverBackendName(b.backend));
    const auto r = SolveBy(e, b.backend);
    ASSERT_TRUE(r) << r.error().ToString();
    EXPECT_NE(r->backend, SolverBackend::kAuto);
    EXPECT_GE(r->labels_objective, best - kBoundTolerance);
    EXPECT_LE(r->lower_bound, best + kBoundTolerance);
    EXPECT_NE(r->lower_bound_source, "none");
    if (can.exact) {
      EXPECT_GE(r->lower_bound, clp->relaxed_objective - kBoundTolerance);
    }
    if (can.integral) {
      EXPECT_EQ(r->fractional_cells, 0u);
      EXPECT_EQ(r->windows, 0u);
      EXPECT_NE(r->method.find("integer program"), std::string::npos) << r->method;
    }
  }
}

TEST(LabelingBackends, ReportNamesTheBandsLpBackend) {
  LabelingResult r;
  r.backend = SolverBackend::kPdhgEnergy;
  EXPECT_EQ(BackendReportName(r), "pdhg-energy");
  r.backend = SolverBackend::kBand;
  r.band_lp_backend = SolverBackend::kClp;
  EXPECT_EQ(BackendReportName(r), "band+clp");
}

}  // namespace
}  // namespace linesurf::solver
