#pragma once
// Runs the built `linesurf` executable from tests, as a user would.

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

}  // namespace linesurf::testing
