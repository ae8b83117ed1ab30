#pragma once
// One hostile case of the robustness suite: inputs it generates, the command it runs, and the
// contract the run must keep (docs/user/errors.md).

#include "linesurf/error.h"

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace linesurf::robustness {

struct HostileCase {
  using Maker = std::function<void(const std::filesystem::path& dir)>;
  std::string kind;  ///< malformed file, degenerate geometry, extreme coordinates, ...
  std::string name;  ///< unique, [A-Za-z0-9_]
  /// Writes the case's inputs into the (empty) directory it gets.
  Maker make;
  /// Arguments of `linesurf`, run with the case's directory as working directory.
  std::string args;
  int exit_code = 0;
  /// Strings stderr must contain (the file, the place); failed runs must also start their error
  /// line with "linesurf: error: ".
  std::vector<std::string> message;
  /// Files (relative to the directory) a successful run must create; a failed run creates none.
  std::vector<std::string> outputs;
  /// Where stdout goes ("" = a capture file; e.g. "/dev/full").
  std::string stdout_to;
  /// Shell commands run before `linesurf` in its shell (e.g. `ulimit -f 0`: every write fails).
  std::string before = {};
  /// Shell commands run while `linesurf` runs (its process id in $pid) as soon as stderr shows
  /// `during_when`, a progress line of the stage to disturb (e.g. `kill -INT $pid`).
  std::string during = {};
  std::string during_when = {};
};

/// Counts one case of `kind` whose contract is `exit_code` (for the library API: the exit code
/// the CLI gives its ErrorCode) in the table printed at the end of the run.
void RecordVerdict(const std::string& kind, int exit_code);
/// The exit code the CLI gives `code` (tools/cli/cli_support.cpp), for the table of verdicts.
int ExitCodeOf(ErrorCode code);

/// Helpers the generators share.
void WriteFile(const std::filesystem::path& path, const std::string& content);
/// A small valid scene: the synthetic cube (12 edges, viewpoints), as reference JSON.
std::string CubeSceneJson();
/// A closed unit cube mesh as ASCII OFF, its vertices scaled by `scale`.
std::string CubeOff(double scale = 1.0);

}  // namespace linesurf::robustness
