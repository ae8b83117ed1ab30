#pragma once
// Per-block plane detection as work units in a work directory (docs/user/distributed.md): a
// DetectionRunner that, instead of running a round's RANSAC, takes each run's result from the
// directory when it is there and otherwise writes the run's input there as a unit for another
// process to run (RunDetectionUnit), then stops the run until the units are done. A unit's
// result is RunDetectionBlock's on the same lines, options, eps and stream: a run through the
// directory gives the bytes of a run in one process.
//
// Layout: <dir>/manifest.json (every unit met so far: id, status, input hash, files) and
// <dir>/units/<id>.input.json, <id>.result.json; ids name the detection block ("detect-L0-3_1_0":
// level, then x_y_z of its key). Files are written atomically.

#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "engine/core/run_context.h"
#include "engine/detect/detection_run.h"

namespace linesurf::pipeline {

enum class WorkUnitStatus { kPending, kDone, kFailed };

/// "pending", "done" or "failed": the manifest's and the facade's spelling.
[[nodiscard]] const char* WorkUnitStatusName(WorkUnitStatus status);

/// A unit as the manifest lists it.
struct WorkUnitEntry {
  std::string id;
  std::string stage;  ///< "detect"
  WorkUnitStatus status = WorkUnitStatus::kPending;
  std::string input_hash;  ///< FNV-1a 64 of the input file's bytes, 16 hex digits
  std::string reason;      ///< why a failed unit failed
  double seconds = 0.0;    ///< the unit's own run time (done units)
};

/// The run's side of the work directory: a DetectionRunner for DetectPlanes.
class DetectionWorkUnits final : public detect::DetectionRunner {
 public:
  /// `options_json`: the run's options as the units read them (engine/api/options_json.h).
  DetectionWorkUnits(std::filesystem::path work_dir, std::string options_json);

  /// Throws kCancelled ("work units pending") when some run of the round has no result yet,
  /// after writing their inputs and the manifest. A failed unit's block gives no planes.
  std::vector<detect::DetectionRunOutcome> RunRound(
      std::span<const Segment3> lines,
      std::span<const detect::DetectionRunRequest> round,
      const PlaneDetectionOptions& options,
      double epsilon,
      const RunContext& ctx) override;

  /// Every unit met so far, in the order of the runs.
  [[nodiscard]] const std::vector<WorkUnitEntry>& Units() const { return units_; }
  /// Units the run waits for (empty once every round had its results).
  [[nodiscard]] std::vector<std::string> Pending() const;
  /// Units whose result was read from the directory.
  [[nodiscard]] std::size_t Reused() const { return reused_; }

  /// Writes <dir>/manifest.json (atomically).
  void WriteManifest() const;

 private:
  std::filesystem::path work_dir_;
  std::string options_json_;
  std::vector<WorkUnitEntry> units_;
  std::size_t reused_ = 0;
};

/// The unit's reading of the run's options (its input's "options" text) into detection options:
/// the facade's conversion of its public options.
using DetectionOptionsReader = PlaneDetectionOptions (*)(const std::string& options_json);

/// Runs unit `id` of `work_dir` (its input as the manifest lists it) and writes its result
/// atomically: the planes, or, when the input cannot be read or is not the one planned (its hash
/// differs), a failed result naming the reason; a unit that is not in the manifest or is
/// cancelled writes nothing and throws (kInvalidInput, kCancelled).
/// @return the unit's entry as its result records it.
WorkUnitEntry RunDetectionUnit(const std::filesystem::path& work_dir,
                               const std::string& id,
                               DetectionOptionsReader read_options,
                               const RunContext& ctx);

}  // namespace linesurf::pipeline
