#pragma once
// Locations handed to tests by CTest (never baked into the code).

#include <filesystem>
#include <optional>

namespace testing {
class TestInfo;
}  // namespace testing

namespace linesurf::testing {

/// ../shared beside the repository (LINESURF_SHARED_DIR), if present.
std::optional<std::filesystem::path> SharedDir();
/// The Andalusian input JSON, if ../shared is present.
std::optional<std::filesystem::path> AndalusianInput();
/// The repository's source directory (LINESURF_SOURCE_DIR, set by CTest).
std::filesystem::path SourceDir();
/// docs/examples/house/lines.json, the bundled example scene.
std::filesystem::path ExampleHouseInput();
/// The directory holding the built linesurf executable (LINESURF_BIN_DIR, else the directory
/// of the running test executable: both are built into bin/).
std::filesystem::path BinDir();
/// A fresh, empty temporary directory unique to the running test and process
/// (<tmp>/linesurf_test_<pid>_<suite>_<test>); calling it again in the same test empties it.
std::filesystem::path FreshTempDir();
/// Removes the FreshTempDir() of a test that passed (test_main.cpp, after every test); a failed
/// test's directory is kept to look at.
void RemoveTempDirOfPassedTest(const ::testing::TestInfo& test);

}  // namespace linesurf::testing

/// Skips the current test with a clear message when the Andalusian data is absent.
#define LINESURF_REQUIRE_ANDALUSIAN(path_var)                                                    \
  const auto path_var##_opt = ::linesurf::testing::AndalusianInput();                            \
  if (!path_var##_opt) GTEST_SKIP() << "../shared/data/andalusian is absent: real-data test skipped"; \
  const std::filesystem::path path_var = *path_var##_opt
