// Runs `linesurf synth` as a user would: byte-identical files for the same seed (any thread
// count), different files for another seed, files that read back into a valid scene and mesh.

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "linesurf/linesurf.h"
#include "tests/support/cli_runner.h"
#include "tests/support/test_paths.h"

namespace linesurf {
namespace {

using testing::ShellQuote;
using testing::Slurp;

/// Runs build/bin/linesurf with `args`; returns the exit code (stderr in dir/stderr.txt).
int RunLinesurf(const std::string& args, const std::filesystem::path& dir) {
  return testing::RunLinesurf(args, dir).exit_code;
}

class CliSynth : public testing::CliTest {};

TEST_F(CliSynth, SameSeedGivesByteIdenticalFilesForAnyThreadCount) {
  const std::string spec = "synth house --seed 5 --noise 0.01 --outliers 0.05 -o ";
  ASSERT_EQ(RunLinesurf("-j 1 " + spec + ShellQuote((dir_ / "a").string()), dir_), 0)
      << Slurp(dir_ / "stderr.txt");
  ASSERT_EQ(RunLinesurf("-j 2 " + spec + ShellQuote((dir_ / "b").string()), dir_), 0)
      << Slurp(dir_ / "stderr.txt");
  ASSERT_EQ(RunLinesurf("synth house --seed 6 --noise 0.01 --outliers 0.05 -o " +
                            ShellQuote((dir_ / "c").string()),
                        dir_),
            0);
  for (const char* file : {"lines.json", "ground_truth.ply", "meta.json"}) {
    const std::string a = Slurp(dir_ / "a" / file);
    EXPECT_FALSE(a.empty()) << file;
    EXPECT_EQ(a, Slurp(dir_ / "b" / file)) << file;
  }
  EXPECT_NE(Slurp(dir_ / "a" / "lines.json"), Slurp(dir_ / "c" / "lines.json"));
  EXPECT_NE(Slurp(dir_ / "a" / "meta.json"), Slurp(dir_ / "c" / "meta.json"));
}

// The bundled example was made by this command (docs/examples/house/README.md). Any compiler
// must give the same bytes: C++ leaves the order of function arguments unspecified, and a draw
// per argument (`Vec3(rng.Uniform(), rng.Uniform(), rng.Uniform())`) once made clang's scenes
// differ from g++'s.
TEST_F(CliSynth, TheExampleCommandWritesTheBundledExampleOnAnyCompiler) {
  ASSERT_EQ(RunLinesurf(
                "synth house --seed 1 --noise 0.01 --outliers 0.05 -o " + ShellQuote(dir_.string()),
                dir_),
            0)
      << Slurp(dir_ / "stderr.txt");
  const std::filesystem::path example = testing::SourceDir() / "docs" / "examples" / "house";
  for (const char* file : {"lines.json", "ground_truth.ply", "meta.json"}) {
    const std::string bundled = Slurp(example / file);
    ASSERT_FALSE(bundled.empty()) << example / file;
    EXPECT_TRUE(Slurp(dir_ / file) == bundled) << file << " differs from " << example / file;
  }
}

TEST_F(CliSynth, FilesReadBackIntoASceneWithTruePlanesAndAClosedMesh) {
  ASSERT_EQ(RunLinesurf("synth cube --seed 1 -o " + ShellQuote(dir_.string()), dir_), 0)
      << Slurp(dir_ / "stderr.txt");
  Expected<ReadSceneResult> read = ReadScene((dir_ / "lines.json").string());
  ASSERT_TRUE(read.has_value()) << read.error().ToString();
  const SceneData& scene = read->scene;
  EXPECT_EQ(scene.segments.size(), 12u);
  EXPECT_EQ(scene.planes.size(), 6u);
  ASSERT_TRUE(scene.has_memberships);
  std::vector<int> planes_per_segment(scene.segments.size(), 0);
  for (const Membership& m : scene.memberships) ++planes_per_segment.at(m.segment);
  for (int count : planes_per_segment) EXPECT_EQ(count, 2);
  Expected<Mesh> mesh = ReadMesh((dir_ / "ground_truth.ply").string());
  ASSERT_TRUE(mesh.has_value()) << mesh.error().ToString();
  Expected<MeshValidity> validity = CheckMesh(*mesh);
  ASSERT_TRUE(validity.has_value()) << validity.error().ToString();
  EXPECT_TRUE(validity->closed);
  EXPECT_TRUE(validity->two_manifold);
  EXPECT_TRUE(validity->outward);
  EXPECT_NEAR(validity->signed_volume, 8.0, 1e-9);
  const std::string meta = Slurp(dir_ / "meta.json");
  EXPECT_NE(meta.find("\"family\": \"cube\""), std::string::npos);
  EXPECT_NE(meta.find("\"structural\": 12"), std::string::npos) << meta.substr(0, 800);
}

TEST_F(CliSynth, BadOptionsExitWithUsageCode) {
  EXPECT_EQ(RunLinesurf("synth castle -o " + ShellQuote(dir_.string()), dir_), 2);
  EXPECT_EQ(RunLinesurf("synth city --size -3 -o " + ShellQuote(dir_.string()), dir_), 2);
  EXPECT_EQ(RunLinesurf("synth cube --outliers 0.95 -o " + ShellQuote(dir_.string()), dir_), 2);
  EXPECT_EQ(RunLinesurf("synth cube", dir_), 2);  // no -o
}

}  // namespace
}  // namespace linesurf
