// OutputFiles: a run writes all of its outputs or none, even when a rename fails at the end,
// and takes back the directories it created.

#include "tools/cli/output_files.h"

#include "tests/support/cli_runner.h"
#include "tests/support/test_paths.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <string>
#include <vector>

namespace linesurf::cli {
namespace {
namespace fs = std::filesystem;

Status WriteText(const fs::path& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
  return {};
}

/// Two outputs written and staged; then a directory appears at the second one's path, so its
/// rename fails after the first one's succeeded.
Status CommitWithTheSecondRenameFailing(const fs::path& dir) {
  OutputFiles files("test");
  files.AddOutput("-o", dir / "mesh.ply", kMeshExtensions);
  files.AddOutput("--report", dir / "report.json", kJsonExtensions);
  EXPECT_TRUE(files.Prepare());
  EXPECT_TRUE(files.Write(dir / "mesh.ply", [](const fs::path& p) { return WriteText(p, "new"); }));
  EXPECT_TRUE(
      files.Write(dir / "report.json", [](const fs::path& p) { return WriteText(p, "new"); }));
  fs::create_directory(dir / "report.json");
  return files.Commit();
}

std::vector<std::string> Entries(const fs::path& dir) {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(dir)) names.push_back(entry.path().filename());
  std::sort(names.begin(), names.end());
  return names;
}

TEST(OutputFiles, AFailedRenameTakesBackTheOutputsAlreadyInPlace) {
  const fs::path dir = testing::FreshTempDir();
  const Status s = CommitWithTheSecondRenameFailing(dir);
  ASSERT_FALSE(s);
  EXPECT_EQ(s.error().code, ErrorCode::kInvalidInput);
  EXPECT_NE(s.error().message.find("report.json: --report"), std::string::npos)
      << s.error().message;
  // Nothing of the run is left: no mesh, no staged or kept file; the directory is not ours.
  EXPECT_EQ(Entries(dir), std::vector<std::string>{"report.json"});
}

TEST(OutputFiles, AFailedRenameRestoresTheFileAnOutputReplaced) {
  const fs::path dir = testing::FreshTempDir();
  std::ofstream(dir / "mesh.ply") << "older";
  ASSERT_FALSE(CommitWithTheSecondRenameFailing(dir));
  EXPECT_EQ(testing::Slurp(dir / "mesh.ply"), "older");
  EXPECT_EQ(Entries(dir), (std::vector<std::string>{"mesh.ply", "report.json"}));
}

TEST(OutputFiles, ACommitReplacesOlderFilesAndLeavesNothingElse) {
  const fs::path dir = testing::FreshTempDir();
  std::ofstream(dir / "mesh.ply") << "older";
  {
    OutputFiles files("test");
    files.AddOutput("-o", dir / "mesh.ply", kMeshExtensions);
    files.AddOutput("--report", dir / "report.json", kJsonExtensions);
    ASSERT_TRUE(files.Prepare());
    for (const char* name : {"mesh.ply", "report.json"}) {
      ASSERT_TRUE(files.Write(dir / name, [](const fs::path& p) { return WriteText(p, "new"); }));
    }
    ASSERT_TRUE(files.Commit());
  }
  EXPECT_EQ(testing::Slurp(dir / "mesh.ply"), "new");
  EXPECT_EQ(testing::Slurp(dir / "report.json"), "new");
  EXPECT_EQ(Entries(dir), (std::vector<std::string>{"mesh.ply", "report.json"}));
}

TEST(OutputFiles, DirectoriesItCreatedAreRemovedWhenTheRunFails) {
  const fs::path dir = testing::FreshTempDir();
  fs::create_directory(dir / "existing");
  {
    OutputFiles files("test");
    ASSERT_TRUE(files.CreateDirectories("-o", dir / "existing" / "new" / "deeper"));
    files.AddOutput("-o", dir / "existing" / "new" / "deeper" / "lines.json", kJsonExtensions);
    ASSERT_TRUE(files.Prepare());
    EXPECT_TRUE(fs::is_directory(dir / "existing" / "new" / "deeper"));
  }  // no Commit: the run failed
  EXPECT_TRUE(fs::is_directory(dir / "existing"));
  EXPECT_TRUE(fs::is_empty(dir / "existing"));
}

TEST(OutputFiles, DirectoriesItCreatedStayAfterACommit) {
  const fs::path dir = testing::FreshTempDir();
  {
    OutputFiles files("test");
    ASSERT_TRUE(files.CreateDirectories("-o", dir / "new"));
    files.AddOutput("-o", dir / "new" / "lines.json", kJsonExtensions);
    ASSERT_TRUE(files.Prepare());
    ASSERT_TRUE(files.Write(dir / "new" / "lines.json",
                            [](const fs::path& p) { return WriteText(p, "{}"); }));
    ASSERT_TRUE(files.Commit());
  }
  EXPECT_EQ(testing::Slurp(dir / "new" / "lines.json"), "{}");
}

TEST(OutputFiles, CreateDirectoriesRefusesAFile) {
  const fs::path dir = testing::FreshTempDir();
  std::ofstream(dir / "taken") << "x";
  OutputFiles files("test");
  const Status s = files.CreateDirectories("-o", dir / "taken");
  ASSERT_FALSE(s);
  EXPECT_EQ(s.error().code, ErrorCode::kInvalidOptions);
  EXPECT_NE(s.error().message.find("taken: -o"), std::string::npos) << s.error().message;
}

}  // namespace
}  // namespace linesurf::cli
