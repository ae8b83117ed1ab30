// Runs every hostile case against the built `linesurf` executable and checks the contract:
// exit code, a message naming the file and the place, no partial output, inputs untouched.
// Run the executable directly (build/bin/linesurf_test_robustness) to get the table of cases by
// kind and verdict printed at the end (docs/user/errors.md).

#include "tests/robustness/hostile_cases.h"
#include "tests/support/cli_runner.h"
#include "tests/support/test_paths.h"

#include <gtest/gtest.h>

#include <cctype>
#include <cstdlib>
#include <map>
#include <ostream>
#include <set>
#include <string>

#include <sys/wait.h>

namespace linesurf::robustness {
namespace {
namespace fs = std::filesystem;

/// Every regular file under `dir` with its content, and every directory (its name ending in
/// '/', empty content).
std::map<std::string, std::string> Snapshot(const fs::path& dir) {
  std::map<std::string, std::string> files;
  for (const auto& entry : fs::recursive_directory_iterator(dir)) {
    const std::string name = fs::relative(entry.path(), dir).string();
    if (entry.is_regular_file()) files[name] = testing::Slurp(entry.path());
    if (entry.is_directory()) files[name + "/"] = "";
  }
  return files;
}

struct CaseRun {
  int exit_code = -1;  ///< -1: killed by a signal (or not run)
  int signal = 0;
  std::string err;
};

/// The shell command of a case's run of `linesurf` with stdout to `out` and stderr to `err`.
std::string CaseCommand(const HostileCase& c, const fs::path& out, const fs::path& err) {
  const std::string run = testing::ShellQuote((testing::BinDir() / "linesurf").string()) + " " +
                          c.args + " > " + testing::ShellQuote(out.string()) + " 2> " +
                          testing::ShellQuote(err.string());
  const std::string before = c.before.empty() ? "" : c.before + "; ";
  if (c.during.empty()) return before + run;
  // Wait (at most 60 s) for the stage's progress line, act, and give linesurf's exit status.
  return before + "{ " + run + " & pid=$!; i=0; while [ $i -lt 3000 ] && kill -0 $pid 2>/dev/null" +
         " && ! grep -qF " + testing::ShellQuote(c.during_when) + " " +
         testing::ShellQuote(err.string()) + "; do i=$((i+1)); sleep 0.02; done; " + c.during +
         "; wait $pid; }";
}

CaseRun RunCase(const HostileCase& c, const fs::path& dir, const fs::path& io_dir) {
  const fs::path out = c.stdout_to.empty() ? io_dir / "stdout.txt" : fs::path(c.stdout_to);
  const fs::path err = io_dir / "stderr.txt";
  const std::string command =
      "cd " + testing::ShellQuote(dir.string()) + " && " + CaseCommand(c, out, err);
  const int status = std::system(command.c_str());
  CaseRun run;
  // The shell reports a child killed by signal s as exit 128 + s.
  if (WIFEXITED(status) && WEXITSTATUS(status) < 128) run.exit_code = WEXITSTATUS(status);
  if (WIFEXITED(status) && WEXITSTATUS(status) >= 128) run.signal = WEXITSTATUS(status) - 128;
  if (WIFSIGNALED(status)) run.signal = WTERMSIG(status);
  run.err = testing::Slurp(err);
  return run;
}

/// True when `text` holds more than 20 digits in a row (a double printed with %f or to_string).
bool HasLongDigitRun(const std::string& text) {
  int run = 0;
  for (const char ch : text) {
    run = std::isdigit(static_cast<unsigned char>(ch)) != 0 ? run + 1 : 0;
    if (run > 20) return true;
  }
  return false;
}

/// Verdict counts by kind, printed after all cases ran in this process.
std::map<std::string, std::map<int, int>>& Tally() {
  static std::map<std::string, std::map<int, int>> tally;
  return tally;
}
std::map<std::string, int>& Failures() {
  static std::map<std::string, int> failures;
  return failures;
}

class Robustness : public ::testing::TestWithParam<HostileCase> {};

}  // namespace

/// gtest prints a case by its name (test names and CTest stay readable).
void PrintTo(const HostileCase& c, std::ostream* os) { *os << c.name; }

namespace {

TEST_P(Robustness, KeepsTheContract) {
  const HostileCase& c = GetParam();
  ASSERT_TRUE(fs::exists(testing::BinDir() / "linesurf")) << "linesurf not built";
  const fs::path root = testing::FreshTempDir();
  const fs::path dir = root / "case";
  const fs::path io_dir = root / "io";
  fs::create_directories(dir);
  fs::create_directories(io_dir);
  c.make(dir);
  const auto before = Snapshot(dir);

  const CaseRun run = RunCase(c, dir, io_dir);
  const auto after = Snapshot(dir);
  RecordVerdict(c.kind, c.exit_code);

  EXPECT_EQ(run.signal, 0) << "killed by signal " << run.signal << "\n" << run.err;
  EXPECT_EQ(run.exit_code, c.exit_code) << c.args << "\n" << run.err;
  if (c.exit_code != 0) {
    EXPECT_NE(run.err.find("linesurf: error: "), std::string::npos) << run.err;
  }
  EXPECT_FALSE(HasLongDigitRun(run.err)) << "a number printed with too many digits:\n" << run.err;
  for (const std::string& part : c.message) {
    EXPECT_NE(run.err.find(part), std::string::npos) << "stderr lacks '" << part << "':\n"
                                                     << run.err;
  }
  // Inputs are never modified or removed.
  for (const auto& [name, content] : before) {
    const auto now = after.find(name);
    ASSERT_NE(now, after.end()) << name << " was removed";
    EXPECT_TRUE(now->second == content) << name << " was modified";
  }
  // A failed run writes nothing, not even a directory; a successful one exactly the files it
  // names (and the directories they need).
  std::set<std::string> created;
  for (const auto& [name, content] : after) {
    const bool directory = name.back() == '/';
    if (!before.count(name) && !(directory && run.exit_code == 0)) created.insert(name);
  }
  const std::set<std::string> expected =
      run.exit_code == 0 ? std::set<std::string>(c.outputs.begin(), c.outputs.end())
                         : std::set<std::string>{};
  EXPECT_EQ(created, expected) << run.err;
}

std::string CaseName(const ::testing::TestParamInfo<HostileCase>& info) { return info.param.name; }

INSTANTIATE_TEST_SUITE_P(Cli, Robustness, ::testing::ValuesIn(AllHostileCases()), CaseName);

/// Prints the table of cases by kind and expected exit code (the verdict the contract gives).
class TallyPrinter : public ::testing::EmptyTestEventListener {
  void OnTestEnd(const ::testing::TestInfo& info) override {
    if (info.result()->Failed()) ++Failures()[info.name()];
  }
  void OnTestProgramEnd(const ::testing::UnitTest& /*unit*/) override {
    if (Tally().empty()) return;
    const int codes[] = {0, 2, 3, 4, 5, 70};
    std::printf("\n| kind | cases | exit 0 | exit 2 | exit 3 | exit 4 | exit 5 | exit 70 |\n");
    std::printf("|---|---|---|---|---|---|---|---|\n");
    std::map<int, int> totals;
    int all = 0;
    for (const auto& [kind, by_code] : Tally()) {
      int n = 0;
      for (const auto& [code, count] : by_code) n += count, totals[code] += count;
      all += n;
      std::printf("| %s | %d |", kind.c_str(), n);
      for (int code : codes) std::printf(" %d |", by_code.count(code) ? by_code.at(code) : 0);
      std::printf("\n");
    }
    std::printf("| all | %d |", all);
    for (int code : codes) std::printf(" %d |", totals[code]);
    std::printf("\n\n%d of %d cases keep the contract (%d failed)\n",
                all - static_cast<int>(Failures().size()),
                all,
                static_cast<int>(Failures().size()));
  }
};

const bool kTallyInstalled = [] {
  ::testing::UnitTest::GetInstance()->listeners().Append(new TallyPrinter);
  return true;
}();

}  // namespace

void RecordVerdict(const std::string& kind, int exit_code) { ++Tally()[kind][exit_code]; }

std::vector<HostileCase> AllHostileCases() {
  std::vector<HostileCase> all;
  for (auto generator : {InputCases, OptionCases, OutputPathCases, SignalCases}) {
    for (HostileCase& c : generator()) all.push_back(std::move(c));
  }
  return all;
}

}  // namespace linesurf::robustness
