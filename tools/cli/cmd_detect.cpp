// `linesurf detect INPUT -o OUT.json`: plane detection only (docs/plane_detection.md).

#include "engine/detect/detect_planes.h"
#include "engine/io/read_scene.h"
#include "engine/io/reference_json.h"
#include "engine/pipeline/sanitize_scene.h"
#include "tools/cli/commands.h"
#include "tools/cli/detection_options.h"
#include "tools/cli/output_files.h"

#include <cstdio>
#include <fstream>
#include <iomanip>
#include <limits>
#include <optional>
#include <string>

namespace linesurf::cli {
namespace {

struct DetectArgs {
  std::string input;
  std::string output;
  std::string vg;
  std::string report;
  std::optional<double> relative_epsilon;
  PlaneDetectionOptions options;
};

/// Writes the PolyFit / abspy vertex-group (.vg) subset: points = both endpoints of every segment
/// (segment i -> points 2i, 2i+1), world coordinates, grey colours, normals = the first plane's
/// normal (0 when none); one group (type 0 = plane, parameters a b c d of ax+by+cz+d = 0) per
/// plane listing its inliers' endpoints (a structural segment's endpoints are in both groups).
Status WriteVertexGroups(const Scene& scene, const std::filesystem::path& path) {
  std::ofstream out(path);
  if (!out) return Error{ErrorCode::kInvalidInput, "write_vg", "cannot open " + path.string()};
  out << std::setprecision(std::numeric_limits<double>::max_digits10);
  const std::size_t n = scene.segments.size();
  const Vec3& t = scene.world_from_local.translation;
  out << "num_points: " << 2 * n << "\n";
  for (const Segment3& s : scene.segments) {
    for (const Vec3& p : {s.p1, s.p2}) {
      const Vec3 w = p + t;
      out << w.x() << " " << w.y() << " " << w.z() << "\n";
    }
  }
  out << "num_colors: " << 2 * n << "\n";
  for (std::size_t i = 0; i < 2 * n; ++i) out << "0.5 0.5 0.5\n";
  out << "num_normals: " << 2 * n << "\n";
  for (std::size_t i = 0; i < n; ++i) {
    const PlaneMembership& m = scene.memberships[SegmentId(i)];
    const Vec3 normal = m.count > 0 ? scene.planes[m.planes[0]].normal : Vec3::Zero();
    for (int k = 0; k < 2; ++k) out << normal.x() << " " << normal.y() << " " << normal.z() << "\n";
  }
  std::vector<std::vector<std::size_t>> groups(scene.planes.size());
  for (std::size_t i = 0; i < n; ++i) {
    const PlaneMembership& m = scene.memberships[SegmentId(i)];
    for (std::uint8_t k = 0; k < m.count; ++k) groups[m.planes[k].index()].push_back(i);
  }
  out << "num_groups: " << groups.size() << "\n";
  for (std::size_t g = 0; g < groups.size(); ++g) {
    const Plane3& plane = scene.planes[PlaneId(g)];
    const double d = -plane.normal.dot(plane.point + t);
    out << "group_type: 0\nnum_group_parameters: 4\ngroup_parameters: " << plane.normal.x() << " "
        << plane.normal.y() << " " << plane.normal.z() << " " << d << "\n";
    out << "group_label: plane_" << g << "\ngroup_color: 0.5 0.5 0.5\n";
    out << "group_num_point: " << 2 * groups[g].size() << "\n";
    for (std::size_t k = 0; k < groups[g].size(); ++k) {
      out << (k ? " " : "") << 2 * groups[g][k] << " " << 2 * groups[g][k] + 1;
    }
    out << "\nnum_children: 0\n";
  }
  out.close();
  if (!out) return Error{ErrorCode::kInvalidInput, "write_vg", "cannot write " + path.string()};
  return {};
}

/// Above this many segments, a whole-scene detection gets a hint about per-block detection.
constexpr std::size_t kLargeSceneSegments = 50000;

/// The run report: options, statistics and every plane's inlier count and total length (plane
/// i is plane i of the output JSON).
nlohmann::json DetectReportJson(const CommonOptions& common, const DetectArgs& args,
                                const PlaneDetectionResult& r, std::size_t segments) {
  const PlaneDetectionStats& st = r.stats;
  nlohmann::json j;
  j["input"] = args.input;
  j["output"] = args.output;
  j["options"] = DetectionOptionsJson(args.options);
  j["options"]["threads"] = common.threads;
  j["stats"] = {{"segments", segments},
                {"lines", st.lines},
                {"epsilon", st.epsilon},
                {"blocks", st.blocks},
                {"planes_before_fusion", st.planes_before_fusion},
                {"planes", st.planes_after_fusion},
                {"merges", st.merges},
                {"memberships_dropped", st.memberships_dropped},
                {"segments_with_0_planes", st.num_l0},
                {"segments_with_1_plane", st.num_l1},
                {"segments_with_2_planes", st.num_l2},
                {"candidates_evaluated", st.candidates_evaluated},
                {"failed_draws", st.failed_draws},
                {"seconds", st.seconds},
                {"seconds_fusion", st.seconds_fusion}};
  nlohmann::json planes = nlohmann::json::array();
  for (const PlaneSupport& support : r.support) {
    planes.push_back(
        {{"inlier_count", support.inlier_count}, {"inlier_length", support.inlier_length}});
  }
  j["planes"] = std::move(planes);
  return j;
}

int RunDetect(const CommonOptions& common, DetectArgs& args) {
  OutputFiles files("detect");
  files.AddInput(args.input);
  files.AddOutput("-o", args.output, kJsonExtensions);
  files.AddOutput("--vg", args.vg, {".vg"});
  files.AddOutput("--report", args.report, {});
  if (Status s = files.Prepare(); !s) return ReportError(s.error());
  Expected<io::SceneReadResult> read = io::ReadSceneWithWarnings(args.input, {});
  if (!read) return ReportError(read.error());
  for (const std::string& w : read->warnings) PrintWarning(common, w);
  Scene scene = std::move(read->scene);
  const std::size_t given_planes = scene.planes.size();
  scene.planes.clear();  // detection ignores any given planes
  scene.memberships.clear();
  Expected<pipeline::SanitizeResult> sane = pipeline::SanitizeScene(std::move(scene), {});
  if (!sane) return ReportError(sane.error());
  for (const std::string& w : sane->warnings) PrintWarning(common, w);
  scene = std::move(sane->scene);

  args.options.relative_epsilon = args.relative_epsilon;
  if (args.options.block_size <= 0.0 && scene.segments.size() > kLargeSceneSegments) {
    PrintWarning(common, std::to_string(scene.segments.size()) +
                             " segments detected as one block: this grows faster than linearly; "
                             "--block-size (e.g. the size of one building) keeps it linear");
  }
  RunContext ctx;
  ConfigureRunContext(common, ctx);
  Expected<PlaneDetectionResult> detected = DetectPlanes(scene, args.options, ctx);
  if (!detected) return ReportError(detected.error());
  const PlaneDetectionStats& st = detected->stats;
  if (!args.report.empty()) {
    const nlohmann::json report = DetectReportJson(common, args, *detected, scene.segments.size());
    if (Status s = files.Write(
            args.report, [&](const auto& path) { return WriteReport(path, report, "detect"); });
        !s) {
      return ReportError(s.error());
    }
  }
  scene.planes = std::move(detected->planes);
  scene.memberships = std::move(detected->memberships);

  if (Status s = files.Write(args.output,
                             [&](const auto& path) { return io::WriteReferenceJson(scene, path); });
      !s) {
    return ReportError(s.error());
  }
  if (!args.vg.empty()) {
    if (Status s =
            files.Write(args.vg, [&](const auto& path) { return WriteVertexGroups(scene, path); });
        !s) {
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
                 scene.segments.size(), st.epsilon, args.relative_epsilon ? " (relative)" : "",
                 st.planes_after_fusion, st.planes_before_fusion, st.merges,
                 given_planes ? " (given planes ignored)" : "", static_cast<long long>(st.num_l0),
                 static_cast<long long>(st.num_l1), static_cast<long long>(st.num_l2),
                 static_cast<long long>(st.candidates_evaluated),
                 static_cast<long long>(st.failed_draws), st.seconds, st.seconds_fusion);
  }
  return kExitOk;
}

}  // namespace

Command AddDetectCommand(CLI::App& app, CommonOptions& common) {
  auto args = std::make_shared<DetectArgs>();
  Command cmd;
  cmd.app = app.add_subcommand("detect", "Detect planes in 3D line segments (RANSAC)");
  CLI::App* sub = cmd.app;
  sub->add_option("input", args->input, "Input scene (.json reference, .txt Line3D++, .obj)")
      ->required();
  sub->add_option("-o,--output", args->output, "Output reference JSON with planes and plane_index")
      ->required();
  AddDetectionOptions(*sub, args->options, args->relative_epsilon);
  sub->add_option("--seed", args->options.seed, "Random seed")->capture_default_str();
  sub->add_option("--vg", args->vg, "Also write the planes as PolyFit/abspy vertex groups");
  sub->add_option("--report", args->report,
                  "Write the run report (JSON: options, statistics, inlier count and length of "
                  "every plane) here");
  cmd.run = [&common, args] { return RunDetect(common, *args); };
  return cmd;
}

}  // namespace linesurf::cli
