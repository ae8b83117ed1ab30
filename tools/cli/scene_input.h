#pragma once
// The scene input arguments shared by every subcommand that reads a scene (info, convert, detect,
// reconstruct, render --lines): the scene file plus --nvm / --colmap for the formats whose
// observations are camera ids (Line3D++ and LIMAP .txt).

#include "linesurf/options.h"

#include "tools/cli/output_files.h"

#include <string>

#include <CLI/CLI.hpp>

namespace linesurf::cli {

struct SceneInputArgs {
  std::string input;
  std::string nvm;
  std::string colmap;

  /// The facade's read options (format from the file name and content).
  [[nodiscard]] linesurf::ReadOptions Options() const {
    linesurf::ReadOptions options;
    options.nvm = nvm;
    options.colmap = colmap;
    return options;
  }
  /// The scene file and camera model as inputs of `files` (checked to exist, never overwritten).
  void AddInputsTo(OutputFiles& files) const {
    files.AddInput(input);
    files.AddInput(nvm);
    files.AddInput(colmap);
  }
};

/// What a scene file may be, for the help texts.
inline constexpr const char* kSceneFileHelp =
    "Scene file: .json (reference JSON), .txt (Line3D++, or LIMAP alltracks.txt), .obj (v/l "
    "lines)";

/// Adds --nvm and --colmap (mutually exclusive) to `app`.
inline void AddCameraModelOptions(CLI::App& app, SceneInputArgs& args) {
  auto* nvm = app.add_option("--nvm", args.nvm,
                             "Line3D++/LIMAP input: VisualSfM .nvm with the camera centres");
  app.add_option("--colmap", args.colmap,
                 "Line3D++/LIMAP input: COLMAP model directory, text or binary (images.txt or "
                 "images.bin)")
      ->excludes(nvm);
}

/// Adds INPUT (required), --nvm and --colmap to `app`.
inline void AddSceneInputOptions(CLI::App& app, SceneInputArgs& args) {
  app.add_option("INPUT", args.input, kSceneFileHelp)->required();
  AddCameraModelOptions(app, args);
}

}  // namespace linesurf::cli
