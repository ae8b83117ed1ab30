#include <iostream>

#include "tools/cli/commands.h"

namespace linesurf::cli {

Command AddVersionCommand(CLI::App& app, CommonOptions& /*common*/) {
  Command cmd;
  cmd.app = app.add_subcommand("version", "Print the linesurf version");
  cmd.run = [] {
    std::cout << "linesurf " << LINESURF_VERSION << "\n";
    return kExitOk;
  };
  return cmd;
}

}  // namespace linesurf::cli
