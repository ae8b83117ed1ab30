#pragma once
// Runs the built `linesurf` executable (BinDir()/linesurf) as a user would, for CLI tests.

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "tests/support/test_paths.h"

namespace linesurf::testing {

struct CliRun {
  int exit_code = -1;  ///< -1 when the process did not exit normally
  std::string out;     ///< stdout
  std::string err;     ///< stderr
};

/// The whole file as bytes ("" when absent).
inline std::string ReadFileBytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

/// Single-quotes `s` for /bin/sh (paths of the test temp dirs hold no quotes).
inline std::string ShellQuote(const std::string& s) { return "'" + s + "'"; }

/// Runs `linesurf <args>` (args already quoted) capturing stdout/stderr in files under `dir`.
inline CliRun RunLinesurf(const std::string& args, const std::filesystem::path& dir) {
  const auto exe = BinDir() / "linesurf";
  const auto out = dir / "stdout.txt";
  const auto err = dir / "stderr.txt";
  const std::string command = ShellQuote(exe.string()) + " " + args + " > " +
                              ShellQuote(out.string()) + " 2> " + ShellQuote(err.string());
  const int status = std::system(command.c_str());
  CliRun run;
  run.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  run.out = ReadFileBytes(out);
  run.err = ReadFileBytes(err);
  return run;
}

}  // namespace linesurf::testing
