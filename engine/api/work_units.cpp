// The work-directory entry points (linesurf/work_units.h): the run's detection through
// pipeline::DetectionWorkUnits, one unit through pipeline::RunDetectionUnit.

#include "linesurf/work_units.h"

#include "engine/api/host_context.h"
#include "engine/api/options_conversion.h"
#include "engine/api/options_json.h"
#include "engine/api/result_conversion.h"
#include "engine/api/scene_conversion.h"
#include "engine/core/exception.h"
#include "engine/core/parallel.h"
#include "engine/pipeline/detection_work_units.h"
#include "engine/pipeline/reconstruct.h"

#include <utility>

namespace linesurf {
inline namespace v3 {
namespace {

constexpr const char* kWorkUnitStage = "work_unit";

WorkUnitInfo ToPublic(const pipeline::WorkUnitEntry& unit) {
  return WorkUnitInfo{.id = unit.id,
                      .status = pipeline::WorkUnitStatusName(unit.status),
                      .reason = unit.reason,
                      .seconds = unit.seconds};
}

/// The detection options a unit runs with: those of the run's options, as Reconstruct converts
/// them.
PlaneDetectionOptions UnitDetectionOptions(const std::string& options_json) {
  return api::ToEngineOptions(api::ReadOptionsJson<ReconstructOptions>(options_json,
                                                                       kWorkUnitStage))
      .planes;
}

}  // namespace

Expected<WorkStep> ReconstructInWorkDirectory(const InputScene& scene,
                                              const ReconstructOptions& options,
                                              const std::string& work_dir,
                                              const RunControl& control) noexcept {
  return CatchAll("reconstruct", [&]() -> WorkStep {
    if (Status s = options.Validate(); !s) throw LinesurfException(s.error());
    const Scene engine_scene = ValueOrThrow(api::ToEngineScene(scene));
    const api::HostContext host(control, options.num_threads);
    // The thread count changes no result: the units' inputs (and hashes) do not carry it.
    ReconstructOptions unit_options = options;
    unit_options.num_threads = 0;
    pipeline::DetectionWorkUnits units(work_dir, api::OptionsJson(unit_options).dump());
    Expected<pipeline::ReconstructResult> run = pipeline::Reconstruct(
        engine_scene, api::ToEngineOptions(options), host.Context(), &units);
    WorkStep step;
    step.units = units.Units().size();
    step.reused = units.Reused();
    step.pending = units.Pending();
    for (const pipeline::WorkUnitEntry& unit : units.Units()) {
      if (unit.status == pipeline::WorkUnitStatus::kFailed) step.failed.push_back(ToPublic(unit));
    }
    // A run stopped to wait for its units reports kCancelled; a host's cancel stays one.
    if (!step.pending.empty() && !host.Context().ShouldStop()) return step;
    if (!run) throw LinesurfException(run.error());
    if (step.units > 0) units.WriteManifest();
    step.result = api::ToPublicResult(*run);
    std::vector<std::string> warnings;
    for (const WorkUnitInfo& unit : step.failed) {
      warnings.push_back("work unit " + unit.id + " failed, its block gave no planes: " +
                         unit.reason);
    }
    step.result->warnings.insert(step.result->warnings.begin(), warnings.begin(), warnings.end());
    return step;
  });
}

Expected<WorkUnitInfo> RunWorkUnit(const std::string& work_dir,
                                   const std::string& unit,
                                   int num_threads,
                                   const RunControl& control) noexcept {
  return CatchAll(kWorkUnitStage, [&]() -> WorkUnitInfo {
    LINESURF_THROW_IF(num_threads < 0, kInvalidOptions, kWorkUnitStage,
                      "num_threads must be >= 0");
    const api::HostContext host(control, num_threads);
    return RunInArena(host.Context(), [&] {
      return ToPublic(
          pipeline::RunDetectionUnit(work_dir, unit, UnitDetectionOptions, host.Context()));
    });
  });
}

}  // namespace v3
}  // namespace linesurf
