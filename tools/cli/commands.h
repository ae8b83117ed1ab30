#pragma once
// Registration functions of the subcommands, one per cmd_<name>.cpp.

#include "tools/cli/cli_support.h"

namespace linesurf::cli {

Command AddVersionCommand(CLI::App& app, CommonOptions& common);
Command AddInfoCommand(CLI::App& app, CommonOptions& common);
Command AddConvertCommand(CLI::App& app, CommonOptions& common);
Command AddSynthCommand(CLI::App& app, CommonOptions& common);
Command AddEvaluateCommand(CLI::App& app, CommonOptions& common);
Command AddRenderCommand(CLI::App& app, CommonOptions& common);
Command AddArrangeCommand(CLI::App& app, CommonOptions& common);
Command AddDetectCommand(CLI::App& app, CommonOptions& common);
Command AddReconstructCommand(CLI::App& app, CommonOptions& common);
Command AddOptionsCommand(CLI::App& app, CommonOptions& common);
Command AddWorkUnitCommand(CLI::App& app, CommonOptions& common);

}  // namespace linesurf::cli
