// FreshTempDir: one directory per test and process, so suites run at the same time from two
// build directories do not remove each other's files.

#include "tests/support/test_paths.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include <sys/wait.h>
#include <unistd.h>

namespace linesurf::testing {
namespace {

TEST(FreshTempDir, IsNotSharedWithTheSameTestInAnotherProcess) {
  const std::filesystem::path dir = FreshTempDir();
  std::ofstream(dir / "mine.txt") << "kept";
  const pid_t child = ::fork();
  ASSERT_NE(child, -1);
  if (child == 0) {
    // The same test of another suite run: its directory must be another one.
    const std::filesystem::path other = FreshTempDir();
    std::ofstream(other / "theirs.txt") << "written by the other run";
    const bool distinct = other != dir;
    if (distinct) std::filesystem::remove_all(other);
    ::_exit(distinct ? 0 : 1);
  }
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << "the other process got " << dir;
  EXPECT_TRUE(std::filesystem::exists(dir / "mine.txt"));
  EXPECT_FALSE(std::filesystem::exists(dir / "theirs.txt"));
}

TEST(FreshTempDir, IsEmptiedWhenAskedForAgainInTheSameTest) {
  const std::filesystem::path dir = FreshTempDir();
  std::ofstream(dir / "old.txt") << "old";
  EXPECT_EQ(FreshTempDir(), dir);
  EXPECT_TRUE(std::filesystem::is_empty(dir));
}

}  // namespace
}  // namespace linesurf::testing
