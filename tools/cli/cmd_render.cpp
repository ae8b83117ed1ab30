// `linesurf render`: PNG pictures of segments (coloured by plane membership) and/or a mesh.

#include "linesurf/linesurf.h"

#include "tools/cli/commands.h"
#include "tools/cli/output_files.h"
#include "tools/cli/scene_input.h"
#include "tools/render/render_image.h"
#include "tools/render/write_png.h"

#include <cstdio>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace linesurf::cli {
namespace {

struct RenderArgs {
  SceneInputArgs lines;
  std::string mesh_path;
  std::string output_path;
  std::string size = "800x600";
  std::vector<double> camera;
  RenderOptions options;
};

int Run(const RenderArgs& args_in) {
  RenderArgs args = args_in;
  if (args.lines.input.empty() && args.mesh_path.empty()) {
    return ReportError(Error{ErrorCode::kInvalidOptions, "render", "give --lines, --mesh or both"});
  }
  int width = 0;
  int height = 0;
  char tail = 0;
  if (std::sscanf(args.size.c_str(), "%dx%d%c", &width, &height, &tail) != 2) {
    return ReportError(Error{ErrorCode::kInvalidOptions, "render",
                             "--size must look like 800x600, got '" + args.size + "'"});
  }
  args.options.width = width;
  args.options.height = height;
  if (!args.camera.empty()) {
    args.options.camera = Camera{{args.camera[0], args.camera[1], args.camera[2]},
                                 {args.camera[3], args.camera[4], args.camera[5]}};
  }
  if (auto valid = args.options.Validate(); !valid) return ReportError(valid.error());
  OutputFiles files("render");
  args.lines.AddInputsTo(files);
  files.AddInput(args.mesh_path);
  files.AddOutput("-o", args.output_path, {".png"});
  if (Status s = files.Prepare(); !s) return ReportError(s.error());
  std::optional<SceneData> scene;
  if (!args.lines.input.empty()) {
    Expected<ReadSceneResult> read = ReadScene(args.lines.input, args.lines.Options());
    if (!read) return ReportError(read.error());
    scene = std::move(read->scene);
  }
  std::optional<Mesh> mesh;
  if (!args.mesh_path.empty()) {
    Expected<Mesh> read = ReadMesh(args.mesh_path);
    if (!read) return ReportError(read.error());
    mesh = std::move(*read);
  }
  auto image = RenderImage(scene ? &*scene : nullptr, mesh ? &*mesh : nullptr, args.options);
  if (!image) return ReportError(image.error());
  if (Status written =
          files.Write(args.output_path, [&](const auto& path) { return WritePng(*image, path); });
      !written) {
    return ReportError(written.error());
  }
  if (Status s = files.Commit(); !s) return ReportError(s.error());
  return kExitOk;
}

}  // namespace

Command AddRenderCommand(CLI::App& app, CommonOptions& /*common*/) {
  auto args = std::make_shared<RenderArgs>();
  Command cmd;
  cmd.app = app.add_subcommand(
      "render",
      "Write a PNG of segments (grey: no plane, blue: textural, red: structural) and/or a mesh "
      "(flat-shaded, outlined facets); side by side when both are given");
  cmd.app->add_option("--lines", args->lines.input, kSceneFileHelp);
  AddCameraModelOptions(*cmd.app, args->lines);
  cmd.app->add_option("--mesh", args->mesh_path, "Mesh (.ply, .obj, .off)");
  cmd.app->add_option("-o,--output", args->output_path, "Output PNG")->required();
  cmd.app->add_option("--view", args->options.view, "iso, iso-back, front, back, left, right or top")
      ->capture_default_str();
  cmd.app->add_option("--camera", args->camera, "ex,ey,ez,tx,ty,tz: eye and target (replaces --view)")
      ->delimiter(',')
      ->expected(6);
  cmd.app->add_option("--size", args->size, "Image size WxH in pixels (both panels together)")
      ->capture_default_str();
  cmd.app->add_option("--line-width", args->options.line_width, "Segment width in pixels")
      ->capture_default_str();
  cmd.app->add_option("--supersample", args->options.supersample, "Anti-aliasing samples per axis (1-4)")
      ->capture_default_str();
  cmd.run = [args] { return Run(*args); };
  return cmd;
}

}  // namespace linesurf::cli
