#pragma once
// The scene input arguments shared by subcommands that read a scene (info, convert, ...):
// INPUT plus --nvm / --colmap for Line3D++ inputs.

#include <string>

#include <CLI/CLI.hpp>

#include "engine/io/read_scene.h"

namespace linesurf::cli {

struct SceneInputArgs {
  std::string input;
  std::string nvm;
  std::string colmap;

  [[nodiscard]] io::SceneReadOptions ReadOptions() const {
    io::SceneReadOptions options;
    options.nvm = nvm;
    options.colmap = colmap;
    return options;
  }
};

/// Adds INPUT (required), --nvm and --colmap (mutually exclusive) to `app`.
inline void AddSceneInputOptions(CLI::App& app, SceneInputArgs& args) {
  app.add_option("INPUT", args.input,
                 "Scene file: .json (reference JSON), .txt (Line3D++), .obj (v/l lines)")
      ->required();
  auto* nvm = app.add_option("--nvm", args.nvm, "Line3D++ input: VisualSfM .nvm with the cameras");
  app.add_option("--colmap", args.colmap, "Line3D++ input: COLMAP text model directory (images.txt)")
      ->excludes(nvm);
}

}  // namespace linesurf::cli
