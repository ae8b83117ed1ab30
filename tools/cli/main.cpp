// linesurf command line: a thin layer over the library stages.

#include <vector>

#include "tools/cli/commands.h"

int main(int argc, char** argv) {
  using namespace linesurf::cli;
  CLI::App app{"linesurf: piecewise-planar building surfaces from 3D line segments"};
  app.require_subcommand(1);
  CommonOptions common;
  app.add_flag("-q,--quiet", common.quiet, "No progress or warnings on stderr");
  app.add_option("-j,--threads", common.threads, "Worker threads (0 = all cores)")
      ->check(CLI::NonNegativeNumber);

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
  // Later subcommands register here (one cmd_<name>.cpp each).

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return CheckStandardOutput(code == 0 ? kExitOk : kExitUsage);
  }
  for (const Command& cmd : commands) {
    if (cmd.app->parsed()) return CheckStandardOutput(GuardedRun(cmd.run));
  }
  return kExitUsage;
}
