// `linesurf synth FAMILY --seed S [--size N] [--noise SIGMA] [--outliers FRACTION] -o DIR`:
// a seeded synthetic scene with ground truth (docs/user/synthetic.md).

#include "tools/cli/commands.h"
#include "tools/cli/option_checks.h"
#include "tools/cli/output_files.h"
#include "tools/gen/synthetic_files.h"

#include <filesystem>
#include <iostream>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace linesurf::cli {
namespace {

struct SynthArgs {
  synth::SynthSpec spec;
  std::string noise_model = "gaussian";
  std::string outlier_model = "uniform";
  int outlier_count = -1;
  int max_pieces = 0;
  double max_trim = -1.0;
  std::vector<double> rotate;
  std::string out_dir;
};

int RunSynth(const SynthArgs& args, const CommonOptions& common) {
  synth::SynthSpec spec = args.spec;
  static const std::map<std::string, synth::NoiseModel> kNoise{
      {"gaussian", synth::NoiseModel::kGaussian},
      {"ball", synth::NoiseModel::kUniformBall},
      {"depth", synth::NoiseModel::kDepth}};
  spec.noise_model = kNoise.at(args.noise_model);
  spec.outlier_model =
      args.outlier_model == "near" ? synth::OutlierModel::kNear : synth::OutlierModel::kUniform;
  if (args.outlier_count >= 0) spec.outlier_count = args.outlier_count;
  if (args.max_pieces > 0) spec.max_pieces = args.max_pieces;
  if (args.max_trim >= 0.0) spec.max_trim = args.max_trim;
  if (!args.rotate.empty()) {
    spec.rotation_axis = {args.rotate[0], args.rotate[1], args.rotate[2]};
    spec.rotation_degrees = args.rotate[3];
  }
  if (Status valid = spec.Validate(); !valid) return ReportError(valid.error());

  const std::filesystem::path dir(args.out_dir);
  OutputFiles files("synth");
  // Removed again unless every file is written: a failed run leaves nothing.
  if (Status s = files.CreateDirectories("-o", dir); !s) return ReportError(s.error());
  files.AddOutput("-o", dir / "lines.json", kJsonExtensions);
  files.AddOutput("-o", dir / "ground_truth.ply", kMeshExtensions);
  files.AddOutput("-o", dir / "meta.json", kJsonExtensions);
  if (Status s = files.Prepare(); !s) return ReportError(s.error());

  Expected<synth::SyntheticFiles> scene = synth::SyntheticFiles::Generate(spec, common.threads);
  if (!scene) return ReportError(scene.error());
  if (Status s = files.Write(dir / "lines.json",
                             [&](const auto& p) { return scene->WriteLines(p); });
      !s) {
    return ReportError(s.error());
  }
  if (Status s = files.Write(dir / "ground_truth.ply",
                             [&](const auto& p) { return scene->WriteGroundTruth(p); });
      !s) {
    return ReportError(s.error());
  }
  if (Status s =
          files.Write(dir / "meta.json", [&](const auto& p) { return scene->WriteMeta(p); });
      !s) {
    return ReportError(s.error());
  }
  if (Status s = files.Commit(); !s) return ReportError(s.error());
  if (!common.quiet) {
    const synth::SyntheticSummary n = scene->Summary();
    std::cerr << "synth " << spec.family << " seed " << spec.seed << ": " << n.segments
              << " segments (" << n.structural << " structural, " << n.textural << " textural, "
              << n.outliers << " outliers), " << n.viewpoints << " viewpoints, " << n.true_planes
              << " true planes, ground truth " << n.ground_truth_faces << " faces -> "
              << (dir / "lines.json").string() << ", " << (dir / "ground_truth.ply").string()
              << ", " << (dir / "meta.json").string() << "\n";
  }
  return kExitOk;
}

}  // namespace

Command AddSynthCommand(CLI::App& app, CommonOptions& common) {
  auto args = std::make_shared<SynthArgs>();
  Command cmd;
  cmd.app = app.add_subcommand(
      "synth", "Generate a seeded synthetic scene with ground truth: DIR/lines.json (reference "
               "JSON, plane_index = true planes), DIR/ground_truth.ply, DIR/meta.json");
  cmd.app->add_option("family", args->spec.family, "Scene family")
      ->required()
      ->check(CLI::IsMember({"cube", "house", "lshape", "room", "floor", "city"}));
  cmd.app->add_option("--seed", args->spec.seed, "Random seed (same seed => identical files)")
      ->default_val(0);
  cmd.app->add_option("--size", args->spec.size, "city: number of buildings (0 = 16)")
      ->default_val(0)
      ->check(Between(0, 100000));
  cmd.app->add_option("--noise", args->spec.noise_sigma,
                      "Endpoint noise in metres (Gaussian sigma, or ball radius with "
                      "--noise-model ball)")
      ->default_val(0.0)
      ->check(Between(0.0, 10.0));
  cmd.app
      ->add_option("--noise-model", args->noise_model,
                   "gaussian, ball (uniform in a ball) or depth (Line3D++-like: twice the spread "
                   "along the viewing direction)")
      ->default_val("gaussian")
      ->check(CLI::IsMember({"gaussian", "ball", "depth"}));
  cmd.app
      ->add_option("--outlier-model", args->outlier_model,
                   "uniform (in the scene box) or near (Line3D++-like false matches: moved copies "
                   "of seen pieces)")
      ->default_val("uniform")
      ->check(CLI::IsMember({"uniform", "near"}));
  cmd.app->add_option("--outliers", args->spec.outlier_fraction,
                      "Fraction of output segments that are outliers, 0..0.9")
      ->default_val(0.0)
      ->check(Between(0.0, 0.9));
  cmd.app->add_option("--outlier-count", args->outlier_count,
                      "Exact number of outliers (overrides --outliers)")
      ->check(Between(0, 1000000));
  cmd.app->add_option("--max-pieces", args->max_pieces,
                      "Cut each true line into 1..N pieces (default: cube 1, others 3)")
      ->check(Between(1, 16));
  cmd.app->add_option("--max-trim", args->max_trim,
                      "Trim up to this fraction of each piece at each end (default: cube 0, "
                      "others 0.1)")
      ->check(Between(0.0, 0.4));
  cmd.app->add_option("--max-views", args->spec.max_views,
                      "Views per segment: nearest viewpoints that see it, at most N")
      ->default_val(8)
      ->check(Between(1, 64));
  cmd.app->add_option("--scale", args->spec.scale,
                      "Output units per metre (100: centimetres): everything scaled about the "
                      "origin, noise included")
      ->default_val(1.0)
      ->check(Between(1e-3, 1e3));
  cmd.app->add_option("--rotate", args->rotate,
                      "AX,AY,AZ,DEGREES: everything turned about the origin around that axis, "
                      "after --scale (an up axis other than z; meta.json gives the up)")
      ->delimiter(',')
      ->expected(4);
  cmd.app->add_option("--offset", args->spec.offset,
                      "Added to x and y of everything after --scale and --rotate, output units "
                      "(georeferenced-like coordinates)")
      ->default_val(0.0);
  cmd.app->add_flag("--residual-split", args->spec.residual_split,
                    "One sub-segment per observation with that one view, shrunk by 5 % (as the "
                    "reference's converter made Andalusian)");
  cmd.app->add_option("--max-view-trim", args->spec.max_view_trim,
                      "Residual split: share of a segment a camera may miss at each end")
      ->default_val(0.25)
      ->check(Between(0.0, 0.45));
  cmd.app->add_option("-o,--output", args->out_dir, "Output directory (created if needed)")
      ->required();
  cmd.run = [args, &common] { return RunSynth(*args, common); };
  return cmd;
}

}  // namespace linesurf::cli
