// `linesurf convert INPUT -o OUTPUT`: any input scene format to reference JSON.

#include "linesurf/linesurf.h"

#include "tools/cli/commands.h"
#include "tools/cli/output_files.h"
#include "tools/cli/scene_input.h"

#include <iostream>
#include <string>

namespace linesurf::cli {
namespace {

struct ConvertArgs {
  SceneInputArgs scene;
  std::string output;
  bool sanitize = false;
};

}  // namespace

Command AddConvertCommand(CLI::App& app, CommonOptions& common) {
  auto args = std::make_shared<ConvertArgs>();
  Command cmd;
  cmd.app = app.add_subcommand(
      "convert",
      "Convert a scene (reference JSON, Line3D++ .txt + NVM/COLMAP, OBJ lines) to reference JSON, "
      "keeping every value");
  AddSceneInputOptions(*cmd.app, args->scene);
  cmd.app->add_option("-o,--output", args->output, "Output reference JSON file (.json)")
      ->required();
  cmd.app->add_flag("--sanitize", args->sanitize,
                    "Drop/fix bad elements first (as before a reconstruction); default: convert "
                    "values exactly as read");
  cmd.run = [args, &common]() -> int {
    OutputFiles files("convert");
    args->scene.AddInputsTo(files);
    files.AddOutput("-o", args->output, kJsonExtensions);
    if (Status s = files.Prepare(); !s) return ReportError(s.error());
    Expected<ReadSceneResult> read = ReadScene(args->scene.input, args->scene.Options());
    if (!read) return ReportError(read.error());
    for (const std::string& w : read->warnings) {
      PrintWarning(common, args->scene.input + ": " + w);
    }
    SceneData scene = std::move(read->scene);
    if (args->sanitize) {
      Expected<SanitizedScene> sanitized = SanitizeScene(scene);
      if (!sanitized) return ReportError(sanitized.error(), args->scene.input);
      for (const std::string& w : sanitized->warnings) PrintWarning(common, "sanitation: " + w);
      scene = std::move(sanitized->scene);
    }
    const Status written = files.Write(
        args->output, [&](const auto& path) { return WriteScene(path.string(), scene); });
    if (!written) return ReportError(written.error());
    if (Status s = files.Commit(); !s) return ReportError(s.error());
    if (!common.quiet) {
      std::cerr << "linesurf: wrote " << args->output << " (" << scene.segments.size()
                << " segments, " << scene.viewpoints.size() << " viewpoints, "
                << scene.planes.size() << " planes)\n";
    }
    return kExitOk;
  };
  return cmd;
}

}  // namespace linesurf::cli
