#pragma once
// Shared plumbing of the linesurf subcommands: exit codes, error printing, progress on stderr.

#include "linesurf/error.h"
#include "linesurf/options.h"
#include "linesurf/run_control.h"

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

namespace linesurf::cli {

/// Exit codes are contract (documented in docs/user/cli.md).
enum ExitCode : int {
  kExitOk = 0,
  kExitUsage = 2,
  kExitInvalidInput = 3,
  kExitFailed = 4,
  kExitCancelled = 5,
  kExitUnitsPending = 6,  ///< reconstruct --work-dir: work units to run, then call again
  kExitPartial = 7,       ///< work units failed on their own input: the result lacks their planes
  kExitInternal = 70,
};

/// Options every subcommand shares.
struct CommonOptions {
  bool quiet = false;
  int threads = 0;
};

/// A subcommand: its CLI11 app and the function that runs it after parsing.
struct Command {
  CLI::App* app = nullptr;
  std::function<int()> run;
};

/// Maps a library error to the CLI exit code.
int ExitCodeFor(ErrorCode code);
/// Prints "linesurf: error: <message>" to stderr and returns the exit code for `error`.
int ReportError(const Error& error);
/// ReportError for an error of a stage that worked on the content of `file` (sanitation,
/// detection, reconstruction, evaluation): the message names the file when it does not yet.
int ReportError(const Error& error, const std::filesystem::path& file);
/// Callbacks of a run: progress to stderr (unless quiet), cancel when SIGINT/SIGTERM arrives.
RunControl CliRunControl(const CommonOptions& common);
/// Prints a warning line to stderr unless quiet.
void PrintWarning(const CommonOptions& common, const std::string& message);
/// Writes a run report (`--report`) as indented JSON; a file that cannot be written is an
/// invalid-input error of `stage` naming it.
Status WriteReport(const std::filesystem::path& path,
                   const nlohmann::ordered_json& report,
                   const std::string& stage);
/// Flushes stdout; when anything printed there was lost (e.g. a full device), reports it and
/// turns a successful `code` into kExitInvalidInput, so a lost output is never exit 0.
int CheckStandardOutput(int code);
/// Runs `fn`, turning any escaping exception into an error message and exit code.
int GuardedRun(const std::function<int()>& fn);

}  // namespace linesurf::cli
