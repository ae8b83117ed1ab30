// `linesurf work-unit --work-dir DIR UNIT...`: runs work units of a run over a work directory
// (`reconstruct --work-dir`, docs/user/distributed.md), one after the other.

#include "linesurf/linesurf.h"

#include "tools/cli/commands.h"

#include <cstdio>
#include <memory>
#include <string>
#include <vector>

namespace linesurf::cli {
namespace {

struct WorkUnitArgs {
  std::string work_dir;
  std::vector<std::string> units;
};

int RunWorkUnits(const CommonOptions& common, const WorkUnitArgs& args) {
  int code = kExitOk;
  for (const std::string& id : args.units) {
    Expected<WorkUnitInfo> unit = RunWorkUnit(args.work_dir, id, common.threads,
                                              CliRunControl(common));
    if (!unit) return ReportError(unit.error());
    if (unit->status == "failed") {
      PrintWarning(common, "work unit " + id + " failed: " + unit->reason);
      code = kExitPartial;
    } else if (!common.quiet) {
      std::fprintf(stderr, "work-unit: %s done in %.2f s\n", id.c_str(), unit->seconds);
    }
  }
  return code;
}

}  // namespace

Command AddWorkUnitCommand(CLI::App& app, CommonOptions& common) {
  auto args = std::make_shared<WorkUnitArgs>();
  Command cmd;
  cmd.app = app.add_subcommand(
      "work-unit", "Run work units of `reconstruct --work-dir` (exit 7 when one failed)");
  cmd.app->add_option("--work-dir", args->work_dir, "The run's work directory")->required();
  cmd.app->add_option("units", args->units, "Unit ids, as `reconstruct --work-dir` prints them")
      ->required();
  cmd.run = [&common, args] { return RunWorkUnits(common, *args); };
  return cmd;
}

}  // namespace linesurf::cli
