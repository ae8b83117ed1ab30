#include "tests/support/test_paths.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

#include <unistd.h>

namespace linesurf::testing {

std::optional<std::filesystem::path> SharedDir() {
  const char* dir = std::getenv("LINESURF_SHARED_DIR");
  if (dir == nullptr || !std::filesystem::is_directory(dir)) return std::nullopt;
  return std::filesystem::path(dir);
}

std::optional<std::filesystem::path> AndalusianInput() {
  const auto shared = SharedDir();
  if (!shared) return std::nullopt;
  auto path = *shared / "data" / "andalusian" / "input_lines_from_residuals.json";
  if (!std::filesystem::exists(path)) return std::nullopt;
  return path;
}

std::filesystem::path SourceDir() {
  const char* dir = std::getenv("LINESURF_SOURCE_DIR");
  return dir != nullptr ? std::filesystem::path(dir) : std::filesystem::current_path();
}

std::filesystem::path ExampleHouseInput() {
  return SourceDir() / "docs" / "examples" / "house" / "lines.json";
}

std::filesystem::path BinDir() {
  const char* dir = std::getenv("LINESURF_BIN_DIR");
  if (dir != nullptr) return std::filesystem::path(dir);
  // Test executables are built into the same bin/ directory as linesurf.
  std::error_code ec;
  const auto self = std::filesystem::read_symlink("/proc/self/exe", ec);
  return ec ? std::filesystem::current_path() : self.parent_path();
}

namespace {

std::filesystem::path TempDirOf(const ::testing::TestInfo* info) {
  // The process id keeps suites run at the same time (two worktrees, two build directories)
  // out of each other's directories.
  std::string name = "linesurf_test_" + std::to_string(::getpid());
  if (info != nullptr) name += std::string("_") + info->test_suite_name() + "_" + info->name();
  for (char& c : name) {
    if (c == '/') c = '_';
  }
  return std::filesystem::temp_directory_path() / name;
}

}  // namespace

std::filesystem::path FreshTempDir() {
  auto dir = TempDirOf(::testing::UnitTest::GetInstance()->current_test_info());
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

void RemoveTempDirOfPassedTest(const ::testing::TestInfo& test) {
  if (!test.result()->Passed()) return;
  std::error_code ignored;  // nothing to remove is the common case
  std::filesystem::remove_all(TempDirOf(&test), ignored);
}

}  // namespace linesurf::testing
