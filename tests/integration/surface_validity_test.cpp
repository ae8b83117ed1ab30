// Reconstructions with default options that `linesurf evaluate` itself
// reports closed, 2-manifold and not self-intersecting: the `self-intersecting-floor` reproducer
// (../shared/data/repro) and `linesurf synth floor` seeds 1-20.

#include "tests/support/cli_runner.h"
#include "tests/support/test_paths.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

namespace linesurf {
namespace {

using testing::CliRunResult;
using testing::RunLinesurf;
using testing::ShellQuote;

class SurfaceValidity : public testing::CliTest {
 protected:
  /// Reconstructs `input` with defaults and checks the topology that `evaluate` reports.
  void ExpectValidSurface(const std::filesystem::path& input) {
    const std::filesystem::path mesh = dir_ / "mesh.ply";
    CliRunResult r =
        RunLinesurf("-q reconstruct " + ShellQuote(input) + " -o " + ShellQuote(mesh), dir_);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    // The mesh is its own ground truth: only the topology is of interest here.
    r = RunLinesurf(
        "-q evaluate " + ShellQuote(mesh) + " " + ShellQuote(mesh) + " --samples 1000 --json -",
        dir_);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const nlohmann::json topology = nlohmann::json::parse(r.out).at("topology");
    EXPECT_TRUE(topology.at("closed").get<bool>()) << topology.dump();
    EXPECT_TRUE(topology.at("two_manifold").get<bool>()) << topology.dump();
    EXPECT_FALSE(topology.at("self_intersecting").get<bool>()) << topology.dump();
  }
};

TEST_F(SurfaceValidity, SelfIntersectingFloorReproducer) {
  const auto shared = testing::SharedDir();
  const std::filesystem::path input =
      shared ? *shared / "data/repro/self-intersecting-floor/lines.json" : "";
  if (!shared || !std::filesystem::exists(input)) {
    GTEST_SKIP() << "../shared/data/repro/self-intersecting-floor is absent: reproducer skipped";
  }
  ExpectValidSurface(input);
}

class SynthFloorSurface : public SurfaceValidity, public ::testing::WithParamInterface<int> {};

TEST_P(SynthFloorSurface, IsClosedManifoldAndNotSelfIntersecting) {
  const std::filesystem::path scene = dir_ / "floor";
  const CliRunResult r = RunLinesurf(
      "-q synth floor --seed " + std::to_string(GetParam()) + " -o " + ShellQuote(scene), dir_);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  ExpectValidSurface(scene / "lines.json");
}

INSTANTIATE_TEST_SUITE_P(Seeds1To20, SynthFloorSurface, ::testing::Range(1, 21));

}  // namespace
}  // namespace linesurf
