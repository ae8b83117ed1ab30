// linesurf command line: a thin layer over the library stages.

#include <tbb/global_control.h>

#include <iostream>
#include <optional>
#include <vector>

#include "tools/cli/commands.h"
#include "tools/cli/option_checks.h"

int main(int argc, char** argv) {
  using namespace linesurf::cli;
  CLI::App app{"linesurf: piecewise-planar building surfaces from 3D line segments"};
  app.require_subcommand(1);
  CommonOptions common;
  app.add_flag("-q,--quiet", common.quiet, "No progress or warnings on stderr");
  app.add_option("-j,--threads", common.threads, "Worker threads (0 = all cores)")
      ->check(Between(0, linesurf::kMaxThreads));

  std::vector<Command> commands;
  commands.push_back(AddVersionCommand(app, common));
  commands.push_back(AddInfoCommand(app, common));
  commands.push_back(AddConvertCommand(app, common));
  commands.push_back(AddSynthCommand(app, common));
  commands.push_back(AddEvaluateCommand(app, common));
  commands.push_back(AddRenderCommand(app, common));
  commands.push_back(AddArrangeCommand(app, common));
  commands.push_back(AddDetectCommand(app, common));
  commands.push_back(AddReconstructCommand(app, common));
  commands.push_back(AddOptionsCommand(app, common));
  commands.push_back(AddWorkUnitCommand(app, common));
  // Later subcommands register here (one cmd_<name>.cpp each).
  AddTypeChecks(app);

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return CheckStandardOutput(app.exit(e));  // --help
    std::string where;
    for (const Command& cmd : commands) {
      if (cmd.app->parsed()) where = cmd.app->get_name() + ": ";
    }
    std::string what = e.what();
    if (where.empty()) {  // CLI11 says "A subcommand is required" for a misspelt one
      for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg == "-j" || arg == "--threads") ++i;
        if (arg.empty() || arg[0] == '-' || arg == "-j" || arg == "--threads") continue;
        what = "unknown subcommand '" + arg + "'";
        break;
      }
    }
    std::cerr << "linesurf: error: " << where << what << "\n"
              << "Run with --help for more information.\n";
    return kExitUsage;
  }
  // The CLI owns the process's thread pool: -j N above the core count oversubscribes on
  // purpose (the library's arenas never exceed this limit, engine/core/parallel.h).
  std::optional<tbb::global_control> workers;
  if (common.threads > 0) {
    workers.emplace(tbb::global_control::max_allowed_parallelism,
                    static_cast<std::size_t>(common.threads));
  }
  for (const Command& cmd : commands) {
    if (cmd.app->parsed()) return CheckStandardOutput(GuardedRun(cmd.run));
  }
  return kExitUsage;
}
