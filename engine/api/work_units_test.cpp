// Tests of a reconstruction through a work directory (linesurf/work_units.h): the units run in
// any order give Reconstruct's mesh, a second run reuses them, changed options plan new ones, a
// damaged unit input fails that unit alone.

#include "linesurf/linesurf.h"

#include "tests/support/test_paths.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace linesurf {
namespace {

/// The bundled house on small detection blocks with few planes each: 23 units, then the
/// children of the 6 that reach the cap (a second round).
ReconstructOptions SmallDetectionBlocks() {
  ReconstructOptions options;
  options.detection.block_size = 4.0;
  options.detection.max_planes = 5;
  return options;
}

ReadSceneResult House() {
  Expected<ReadSceneResult> read = ReadScene(testing::ExampleHouseInput().string());
  EXPECT_TRUE(read) << read.error().message;
  return read ? std::move(read.value()) : ReadSceneResult{};
}

/// Calls ReconstructInWorkDirectory until it finishes, running the pending units of each call
/// last to first; `rounds` gets the number of units of each call that had some pending.
WorkStep RunThroughDirectory(const ReadSceneResult& scene,
                             const ReconstructOptions& options,
                             const std::filesystem::path& dir,
                             std::vector<std::size_t>* rounds = nullptr) {
  for (int call = 0; call < 10; ++call) {
    Expected<WorkStep> step = ReconstructInWorkDirectory(scene.scene.View(), options, dir.string());
    EXPECT_TRUE(step) << step.error().message;
    if (!step || step->result) return step ? std::move(*step) : WorkStep{};
    if (rounds != nullptr) rounds->push_back(step->pending.size());
    for (auto it = step->pending.rbegin(); it != step->pending.rend(); ++it) {
      Expected<WorkUnitInfo> unit = RunWorkUnit(dir.string(), *it, 1);
      EXPECT_TRUE(unit) << unit.error().message;
    }
  }
  ADD_FAILURE() << "the run did not finish in 10 calls";
  return {};
}

void ExpectSameMesh(const Mesh& a, const Mesh& b) {
  EXPECT_EQ(a.vertices, b.vertices);
  EXPECT_EQ(a.face_offsets, b.face_offsets);
  EXPECT_EQ(a.face_indices, b.face_indices);
}

TEST(WorkUnits, UnitsRunInAnyOrderGiveReconstructsMesh) {
  const ReadSceneResult house = House();
  const ReconstructOptions options = SmallDetectionBlocks();
  Expected<ReconstructResult> reference = Reconstruct(house.scene.View(), options);
  ASSERT_TRUE(reference) << reference.error().message;
  std::vector<std::size_t> rounds;
  const WorkStep step = RunThroughDirectory(house, options, testing::FreshTempDir(), &rounds);
  ASSERT_TRUE(step.result);
  ASSERT_EQ(rounds.size(), 2u) << "the options must give a round of children";
  EXPECT_GT(rounds[0], 10u);
  EXPECT_EQ(step.units, rounds[0] + rounds[1]);
  EXPECT_TRUE(step.failed.empty());
  ExpectSameMesh(step.result->mesh, reference->mesh);
  EXPECT_EQ(step.result->stats.detection.planes, reference->stats.detection.planes);
}

TEST(WorkUnits, ASecondRunReusesEveryUnitAndChangedOptionsPlanNewOnes) {
  const ReadSceneResult house = House();
  ReconstructOptions options = SmallDetectionBlocks();
  const std::filesystem::path dir = testing::FreshTempDir();
  const WorkStep first = RunThroughDirectory(house, options, dir);
  ASSERT_TRUE(first.result);
  Expected<WorkStep> again = ReconstructInWorkDirectory(house.scene.View(), options, dir.string());
  ASSERT_TRUE(again) << again.error().message;
  ASSERT_TRUE(again->result) << "a finished directory runs no unit again";
  EXPECT_EQ(again->reused, first.units);
  ExpectSameMesh(again->result->mesh, first.result->mesh);
  options.num_threads = 1;  // changes no result: the units stay valid
  Expected<WorkStep> one_thread =
      ReconstructInWorkDirectory(house.scene.View(), options, dir.string());
  ASSERT_TRUE(one_thread && one_thread->result);
  options.seed = 7;
  Expected<WorkStep> reseeded =
      ReconstructInWorkDirectory(house.scene.View(), options, dir.string());
  ASSERT_TRUE(reseeded) << reseeded.error().message;
  EXPECT_FALSE(reseeded->result);
  EXPECT_EQ(reseeded->reused, 0u);
  EXPECT_FALSE(reseeded->pending.empty());
}

TEST(WorkUnits, ADamagedUnitInputFailsThatUnitAndTheRunEndsPartial) {
  const ReadSceneResult house = House();
  const ReconstructOptions options = SmallDetectionBlocks();
  const std::filesystem::path dir = testing::FreshTempDir();
  Expected<WorkStep> first = ReconstructInWorkDirectory(house.scene.View(), options, dir.string());
  ASSERT_TRUE(first && !first->pending.empty());
  const std::string damaged = first->pending.front();
  std::ofstream(dir / "units" / (damaged + ".input.json")) << "{\"segments\": [1, 2";
  Expected<WorkUnitInfo> unit = RunWorkUnit(dir.string(), damaged, 1);
  ASSERT_TRUE(unit) << unit.error().message;
  EXPECT_EQ(unit->status, "failed");
  EXPECT_NE(unit->reason.find(damaged + ".input.json"), std::string::npos) << unit->reason;
  const WorkStep done = RunThroughDirectory(house, options, dir);
  ASSERT_TRUE(done.result);
  ASSERT_EQ(done.failed.size(), 1u);
  EXPECT_EQ(done.failed[0].id, damaged);
  ASSERT_FALSE(done.result->warnings.empty());
  EXPECT_NE(done.result->warnings[0].find(damaged), std::string::npos)
      << done.result->warnings[0];
}

TEST(WorkUnits, AUnitTheManifestDoesNotListIsAnError) {
  const std::filesystem::path dir = testing::FreshTempDir();
  Expected<WorkUnitInfo> none = RunWorkUnit(dir.string(), "detect-L0-0_0_0", 1);
  ASSERT_FALSE(none);
  EXPECT_EQ(none.error().code, ErrorCode::kInvalidInput);
  EXPECT_NE(none.error().message.find("manifest.json"), std::string::npos)
      << none.error().message;
  const ReadSceneResult house = House();
  ASSERT_TRUE(ReconstructInWorkDirectory(house.scene.View(), SmallDetectionBlocks(),
                                         dir.string()));
  Expected<WorkUnitInfo> unknown = RunWorkUnit(dir.string(), "detect-L9-9_9_9", 1);
  ASSERT_FALSE(unknown);
  EXPECT_NE(unknown.error().message.find("detect-L9-9_9_9"), std::string::npos)
      << unknown.error().message;
}

TEST(WorkUnits, AWorkDirectoryThatCannotBeMadeIsInvalidInput) {
  const std::filesystem::path file = testing::FreshTempDir() / "a-file";
  std::ofstream(file) << "not a directory";
  const ReadSceneResult house = House();
  Expected<WorkStep> step = ReconstructInWorkDirectory(house.scene.View(), SmallDetectionBlocks(),
                                                       (file / "run").string());
  ASSERT_FALSE(step);
  EXPECT_EQ(step.error().code, ErrorCode::kInvalidInput);
  EXPECT_NE(step.error().message.find("a-file"), std::string::npos) << step.error().message;
}

}  // namespace
}  // namespace linesurf
