#pragma once
// Runs the built `linesurf` executable from tests, as a user would.

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace linesurf::testing {

struct CliRunResult {
  int exit_code = -1;  ///< -1 when the process did not exit normally
  std::string out;     ///< stdout
  std::string err;     ///< stderr
};

/// The whole content of a file ("" if it cannot be read).
std::string Slurp(const std::filesystem::path& path);
/// `s` in single quotes for the shell.
std::string ShellQuote(const std::string& s);
/// Runs BinDir()/linesurf with `args` (already quoted); stdout and stderr go through files in
/// `scratch_dir`.
CliRunResult RunLinesurf(const std::string& args, const std::filesystem::path& scratch_dir);

/// Fixture of CLI tests: fails when the linesurf executable is missing, and gives each test a
/// fresh scratch directory `dir_`.
class CliTest : public ::testing::Test {
 protected:
  void SetUp() override;
  std::filesystem::path dir_;
};

}  // namespace linesurf::testing
