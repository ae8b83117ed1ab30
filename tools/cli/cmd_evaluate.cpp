// `linesurf evaluate RESULT [GT] [--lines INPUT]`: precision/completeness against a ground-truth
// mesh and topology; figures without ground truth against the input segments.

#include "linesurf/linesurf.h"

#include "tools/cli/cli_support.h"
#include "tools/cli/commands.h"
#include "tools/cli/option_checks.h"
#include "tools/cli/output_files.h"
#include "tools/cli/surface_quality_summary.h"

#include <chrono>
#include <cstdio>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace linesurf::cli {
namespace {

struct EvaluateArgs {
  std::string result_path;
  std::string gt_path;
  std::string visible_from;
  std::string json_path;
  std::string lines_path;
  std::optional<double> epsilon;  // of the figures against the lines; unset: estimated
  EvaluationOptions options;
};

/// Figures without ground truth of `mesh` against the segments of `args.lines_path`: its planes
/// and memberships, or detected ones when it has none.
Expected<SurfaceQuality> QualityAgainstLines(const CommonOptions& common,
                                             const EvaluateArgs& args,
                                             const Mesh& mesh) {
  Expected<ReadSceneResult> read = ReadScene(args.lines_path);
  if (!read) return read.error();
  for (const std::string& w : read->warnings) PrintWarning(common, w);
  DetectOptions detect;
  detect.detection.epsilon = args.epsilon;
  detect.num_threads = common.threads;
  return MeasureSurfaceQuality(mesh, read->scene, detect, CliRunControl(common));
}

nlohmann::json StatsJson(const DistanceStats& s) {
  return {{"count", s.count}, {"mean", s.mean}, {"median", s.median}, {"p95", s.p95}, {"max", s.max}};
}

nlohmann::json ToJson(const EvaluateArgs& args, const EvaluationResult& r) {
  return {{"result", args.result_path},
          {"ground_truth", args.gt_path},
          {"visible_from", args.visible_from.empty() ? nlohmann::json() : nlohmann::json(args.visible_from)},
          {"samples_per_mesh", args.options.samples_per_mesh},
          {"seed", args.options.seed},
          {"thresholds", r.thresholds},
          {"precision", r.precision},
          {"completeness", r.completeness},
          {"result_to_gt", StatsJson(r.result_to_gt)},
          {"gt_to_result", StatsJson(r.gt_to_result)},
          {"num_gt_samples", r.num_gt_samples},
          {"num_visible_gt_samples", r.num_visible_gt_samples},
          {"result_area", r.result_area},
          {"gt_area", r.gt_area},
          {"topology", nlohmann::json::parse(ReportJson(r.topology))}};
}

void PrintTable(const EvaluateArgs& args, const EvaluationResult& r) {
  std::printf("result        %s\nground truth  %s\n", args.result_path.c_str(), args.gt_path.c_str());
  std::printf("samples       %zu per mesh (seed %llu)", args.options.samples_per_mesh,
              static_cast<unsigned long long>(args.options.seed));
  if (!args.visible_from.empty()) {
    std::printf("; completeness over %zu ground-truth samples seen from %s", r.num_visible_gt_samples,
                args.visible_from.c_str());
  }
  std::printf("\n\n  threshold   precision   completeness\n");
  for (std::size_t i = 0; i < r.thresholds.size(); ++i) {
    std::printf("  %9.4g   %8.2f %%   %10.2f %%\n", r.thresholds[i], 100.0 * r.precision[i],
                100.0 * r.completeness[i]);
  }
  std::printf("\n  distance            mean      median         p95         max\n");
  const auto row = [](const char* name, const DistanceStats& s) {
    std::printf("  %-14s %9.4g   %9.4g   %9.4g   %9.4g\n", name, s.mean, s.median, s.p95, s.max);
  };
  row("result -> GT", r.result_to_gt);
  row("GT -> result", r.gt_to_result);
  const MeshValidity& t = r.topology;
  const auto yes = [](bool b) { return b ? "yes" : "no"; };
  std::printf("\nresult mesh: %zu faces, %zu vertices (%zu at the position of another), %zu component(s),\n"
              "  area %.6g, signed volume %.6g\n",
              t.num_faces, t.num_vertices, t.num_coincident_vertices, t.num_components, r.result_area,
              t.signed_volume);
  std::printf("  closed %s (%zu boundary edges), 2-manifold %s (%zu non-manifold edges, %zu vertices),\n"
              "  oriented %s, outward %s, self-intersecting %s\n",
              yes(t.closed), t.num_boundary_edges, yes(t.two_manifold), t.num_non_manifold_edges,
              t.num_non_manifold_vertices, yes(t.oriented), yes(t.outward), yes(t.self_intersecting));
}

int Run(const CommonOptions& common, const EvaluateArgs& args) {
  if (auto valid = args.options.Validate(); !valid) return ReportError(valid.error());
  if (args.gt_path.empty() && args.lines_path.empty()) {
    std::fprintf(stderr,
                 "linesurf: error: evaluate needs a ground-truth mesh GT, --lines, or both\n");
    return kExitUsage;
  }
  OutputFiles files("evaluate");
  files.AddInput(args.result_path);
  files.AddInput(args.gt_path);
  files.AddInput(args.visible_from);
  files.AddInput(args.lines_path);
  const bool json_file = !args.json_path.empty() && args.json_path != "-";
  if (json_file) files.AddOutput("--json", args.json_path, {});
  if (Status s = files.Prepare(); !s) return ReportError(s.error());
  const auto start = std::chrono::steady_clock::now();
  Expected<Mesh> result_mesh = ReadMesh(args.result_path);
  if (!result_mesh) return ReportError(result_mesh.error());
  nlohmann::json json = {{"result", args.result_path}};
  const bool table = args.json_path != "-";
  if (!args.gt_path.empty()) {
    Expected<Mesh> gt_mesh = ReadMesh(args.gt_path);
    if (!gt_mesh) return ReportError(gt_mesh.error());
    std::vector<Vector3> viewpoints;
    if (!args.visible_from.empty()) {
      Expected<ReadSceneResult> scene = ReadScene(args.visible_from);
      if (!scene) return ReportError(scene.error());
      viewpoints = std::move(scene->scene.viewpoints);
      if (viewpoints.empty()) {
        return ReportError(Error{ErrorCode::kInvalidInput, "evaluate",
                                 args.visible_from + " holds no viewpoints"});
      }
    }
    EvaluationOptions options = args.options;
    options.num_threads = common.threads;
    Expected<EvaluationResult> result =
        EvaluateMesh(*result_mesh, *gt_mesh, options, viewpoints, CliRunControl(common));
    if (!result) {  // the library says "ground truth mesh: ..." or speaks of the result
      const bool of_gt = result.error().message.rfind("ground truth", 0) == 0;
      return ReportError(result.error(), of_gt ? args.gt_path : args.result_path);
    }
    if (table) PrintTable(args, *result);
    json = ToJson(args, *result);
  }
  if (!args.lines_path.empty()) {
    Expected<SurfaceQuality> quality = QualityAgainstLines(common, args, *result_mesh);
    if (!quality) return ReportError(quality.error());
    if (table) {
      std::printf("%s\nagainst the segments of %s (eps %.6g):\n%s",
                  args.gt_path.empty() ? "" : "\n", args.lines_path.c_str(), quality->epsilon,
                  SurfaceQualitySummary(*quality, "  ").c_str());
    }
    json["lines"] = args.lines_path;
    json["quality"] = nlohmann::json::parse(ReportJson(*quality));
  }
  json["seconds"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (args.json_path == "-") std::cout << json.dump(2) << "\n";
  if (json_file) {
    if (Status s = files.Write(
            args.json_path, [&](const auto& path) { return WriteReport(path, json, "evaluate"); });
        !s) {
      return ReportError(s.error());
    }
    if (Status s = files.Commit(); !s) return ReportError(s.error());
  }
  return kExitOk;
}

}  // namespace

Command AddEvaluateCommand(CLI::App& app, CommonOptions& common) {
  auto args = std::make_shared<EvaluateArgs>();
  Command cmd;
  cmd.app = app.add_subcommand(
      "evaluate",
      "Compare a mesh with a ground-truth mesh: precision (share of result samples near the ground "
      "truth), completeness (share of ground-truth samples near the result), distances and "
      "topology checks; or, with --lines, with its input segments (no ground truth needed)");
  cmd.app->add_option("RESULT", args->result_path, "Reconstructed mesh (.ply, .obj, .off)")
      ->required();
  cmd.app->add_option(
      "GT", args->gt_path, "Ground-truth mesh (.ply, .obj, .off); optional with --lines");
  cmd.app->add_option("--lines",
                      args->lines_path,
                      "Input segments (any scene format): figures without ground truth (data fit, "
                      "visibility consistency, components, floating fragments, planes on no face), "
                      "with the input's planes or, when it has none, detected ones");
  cmd.app
      ->add_option("--epsilon",
                   args->epsilon,
                   "eps of the figures, scene units (unset: auto, estimated from the data)")
      ->check(Above(0.0));
  cmd.app->add_option(
      "--visible-from",
      args->visible_from,
      "Reference JSON whose viewpoints restrict completeness to the ground truth they see");
  cmd.app->add_option("--thresholds", args->options.thresholds, "Distance thresholds, increasing")
      ->delimiter(',')
      ->capture_default_str();
  cmd.app->add_option("--samples", args->options.samples_per_mesh, "Samples per mesh")
      ->capture_default_str();
  cmd.app->add_option("--seed", args->options.seed, "Seed of the samples")->capture_default_str();
  cmd.app->add_option("--json", args->json_path,
                      "Write the numbers as JSON to this file ('-': to stdout instead of the table)");
  cmd.run = [&common, args] { return Run(common, *args); };
  return cmd;
}

}  // namespace linesurf::cli
