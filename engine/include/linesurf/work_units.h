#pragma once
/// @file work_units.h
/// @brief A reconstruction whose per-block plane detection runs as work units in a work
/// directory, so that any engine (a Dask worker, an MPI rank, a Slurm array task, a plain loop)
/// can run them in other processes or on other machines sharing the directory
/// (docs/user/distributed.md).
///
/// ReconstructInWorkDirectory runs the method as Reconstruct does, but takes the RANSAC of each
/// detection block from the work directory: when some are missing it writes their inputs and
/// the manifest and returns them as pending; RunWorkUnit runs one; calling
/// ReconstructInWorkDirectory again goes on. With every unit done it returns Reconstruct's result
/// for the same scene and options, byte for byte, whoever ran the units and in whatever order.
/// Results are kept: a second run over the same directory reuses every unit whose input (lines,
/// options, eps, random stream) is unchanged.

#include "linesurf/error.h"
#include "linesurf/export.h"
#include "linesurf/options.h"
#include "linesurf/result.h"
#include "linesurf/run_control.h"
#include "linesurf/types.h"

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace linesurf {
inline namespace v3 {

/// One work unit: a detection block's RANSAC.
struct WorkUnitInfo {
  std::string id;      ///< "detect-L<level>-<x>_<y>_<z>": the detection block's key
  std::string status;  ///< "pending", "done" or "failed"
  /// Why a failed unit failed (its input unreadable or not the one planned), naming the file.
  std::string reason;
  double seconds = 0.0;  ///< the unit's run time, when done
};

/// Where a run over a work directory stands.
struct WorkStep {
  /// Units to run (RunWorkUnit) before calling again, in run order; empty when `result` is set.
  std::vector<std::string> pending;
  /// Units that failed on their own input: their blocks gave no planes, so the result is
  /// partial (a warning names each).
  std::vector<WorkUnitInfo> failed;
  std::size_t units = 0;   ///< units met so far
  std::size_t reused = 0;  ///< units whose results were in the directory when this call began
  std::optional<ReconstructResult> result;  ///< set once no unit is pending
};

/// @brief One call of a run over `work_dir` (created when missing): see the file comment.
/// @return the errors of Reconstruct; kInvalidInput when the directory cannot be written.
[[nodiscard]] LINESURF_API Expected<WorkStep> ReconstructInWorkDirectory(
    const InputScene& scene,
    const ReconstructOptions& options,
    const std::string& work_dir,
    const RunControl& control = {}) noexcept;

/// @brief Runs work unit `unit` of `work_dir` on `num_threads` threads (0 = all cores) and
/// writes its result (atomically). A unit whose input cannot be read or is not the one the
/// manifest planned gets a failed result naming the reason (returned, not an error).
/// @return kInvalidInput (no manifest, or no such unit in it), kCancelled (nothing written),
/// kResourceExhausted, kInternal.
[[nodiscard]] LINESURF_API Expected<WorkUnitInfo> RunWorkUnit(
    const std::string& work_dir,
    const std::string& unit,
    int num_threads = 0,
    const RunControl& control = {}) noexcept;

}  // namespace v3
}  // namespace linesurf
