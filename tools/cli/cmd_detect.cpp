// `linesurf detect INPUT -o OUT.json`: plane detection only (docs/design/plane_detection.md).

#include "linesurf/linesurf.h"

#include "tools/cli/commands.h"
#include "tools/cli/option_registry.h"
#include "tools/cli/output_files.h"
#include "tools/cli/scene_input.h"

#include <cstdio>
#include <memory>
#include <string>

namespace linesurf::cli {
namespace {

struct DetectArgs {
  SceneInputArgs source;
  std::string output;
  std::string vg;
  std::string report;
  DetectOptions options;
  std::unique_ptr<OptionRegistry> registry;  ///< flags, --config and the report's options
};

/// Above this many segments, a whole-scene detection gets a hint about per-block detection.
constexpr std::size_t kLargeSceneSegments = 50000;

/// The library's report (report.h) with the paths read and written.
nlohmann::ordered_json CliReportJson(const DetectArgs& args, const DetectedScene& r) {
  nlohmann::ordered_json j;
  j["input"] = args.source.input;
  j["output"] = args.output;
  j.update(nlohmann::ordered_json::parse(ReportJson(r.detection, args.options)));
  return j;
}

int RunDetect(const CommonOptions& common, DetectArgs& args) {
  args.options.num_threads = common.threads;
  if (Status s = args.registry->ApplyConfig(); !s) return ReportError(s.error());
  if (Status s = args.options.Validate(); !s) return ReportError(s.error());
  OutputFiles files("detect");
  args.source.AddInputsTo(files);
  files.AddOutput("-o", args.output, kJsonExtensions);
  files.AddOutput("--vg", args.vg, {".vg"});
  files.AddOutput("--report", args.report, {});
  if (Status s = files.Prepare(); !s) return ReportError(s.error());
  Expected<ReadSceneResult> read = ReadScene(args.source.input, args.source.Options());
  if (!read) return ReportError(read.error());
  for (const std::string& w : read->warnings) PrintWarning(common, w);
  const std::size_t input_segments = read->scene.segments.size();
  if (args.options.detection.block_size <= 0.0 && input_segments > kLargeSceneSegments) {
    PrintWarning(common, std::to_string(input_segments) +
                             " segments detected as one block: this grows faster than linearly; "
                             "--detect-block-size (e.g. the size of one building) keeps it linear");
  }
  Expected<DetectedScene> detected =
      DetectScenePlanes(read->scene, args.options, CliRunControl(common));
  if (!detected) return ReportError(detected.error(), args.source.input);
  for (const std::string& w : detected->detection.warnings) PrintWarning(common, w);
  const SceneData& scene = detected->scene;
  const DetectStats& st = detected->detection.stats;
  const std::size_t given_planes = detected->given_planes;
  if (!args.report.empty()) {
    const nlohmann::ordered_json report = CliReportJson(args, *detected);
    if (Status s = files.Write(
            args.report, [&](const auto& path) { return WriteReport(path, report, "detect"); });
        !s) {
      return ReportError(s.error());
    }
  }
  if (Status s = files.Write(args.output,
                             [&](const auto& path) { return WriteScene(path.string(), scene); });
      !s) {
    return ReportError(s.error());
  }
  if (!args.vg.empty()) {
    auto write_vg = [&](const auto& path) { return WriteVertexGroups(path.string(), scene); };
    if (Status s = files.Write(args.vg, write_vg); !s) {
      return ReportError(s.error());
    }
  }
  if (Status s = files.Commit(); !s) return ReportError(s.error());
  if (!common.quiet) {
    if (st.lines < static_cast<std::int64_t>(scene.segments.size())) {
      std::fprintf(stderr, "detect: collinear parts merged: %lld distinct lines detected on\n",
                   static_cast<long long>(st.lines));
    }
    if (st.blocks > 1) {
      std::fprintf(stderr, "detect: %lld blocks; %lld memberships dropped by the at-most-2 rule\n",
                   static_cast<long long>(st.blocks),
                   static_cast<long long>(st.memberships_dropped));
    }
    std::fprintf(stderr,
                 "detect: %zu segments, eps %.6g%s; %d planes (%d before fusion, %d merges)%s\n"
                 "detect: segments on 0/1/2 planes: %lld / %lld / %lld; %lld candidates, %lld "
                 "failed draws; %.3f s (fusion %.3f s)\n",
                 scene.segments.size(),
                 st.epsilon,
                 (" (" + st.epsilon_estimate.source + ")").c_str(),
                 st.planes,
                 st.planes_before_fusion,
                 st.merges,
                 given_planes ? " (given planes ignored)" : "",
                 static_cast<long long>(st.segments_with_0_planes),
                 static_cast<long long>(st.segments_with_1_plane),
                 static_cast<long long>(st.segments_with_2_planes),
                 static_cast<long long>(st.candidates_evaluated),
                 static_cast<long long>(st.failed_draws),
                 st.seconds,
                 st.seconds_fusion);
  }
  return kExitOk;
}

}  // namespace

Command AddDetectCommand(CLI::App& app, CommonOptions& common) {
  auto args = std::make_shared<DetectArgs>();
  Command cmd;
  cmd.app = app.add_subcommand("detect", "Detect planes in 3D line segments (RANSAC)");
  CLI::App* sub = cmd.app;
  AddSceneInputOptions(*sub, args->source);
  sub->add_option("-o,--output", args->output, "Output reference JSON with planes and plane_index")
      ->required();
  args->registry = std::make_unique<OptionRegistry>(*sub);
  args->registry->AddOptions(args->options, {"num_threads"});  // num_threads: the global -j
  sub->add_option("--vg", args->vg, "Also write the planes as PolyFit/abspy vertex groups");
  sub->add_option("--report", args->report,
                  "Write the run report (JSON: options, statistics, inlier count and length of "
                  "every plane) here");
  cmd.run = [&common, args] { return RunDetect(common, *args); };
  return cmd;
}

}  // namespace linesurf::cli
