#include "tests/support/cli_runner.h"

#include <sys/wait.h>

#include <cstdlib>
#include <fstream>
#include <sstream>

#include "tests/support/test_paths.h"

namespace linesurf::testing {

std::string Slurp(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

std::string ShellQuote(const std::string& s) { return "'" + s + "'"; }

CliRunResult RunLinesurf(const std::string& args, const std::filesystem::path& scratch_dir) {
  const auto exe = BinDir() / "linesurf";
  const auto out = scratch_dir / "stdout.txt";
  const auto err = scratch_dir / "stderr.txt";
  const std::string command = ShellQuote(exe.string()) + " " + args + " > " +
                              ShellQuote(out.string()) + " 2> " + ShellQuote(err.string());
  const int status = std::system(command.c_str());
  CliRunResult result;
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  result.out = Slurp(out);
  result.err = Slurp(err);
  return result;
}

void CliTest::SetUp() {
  if (!std::filesystem::exists(BinDir() / "linesurf")) {
    GTEST_FAIL() << "linesurf executable not found in " << BinDir();
  }
  dir_ = FreshTempDir();
}

}  // namespace linesurf::testing
