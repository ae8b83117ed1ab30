// `linesurf reconstruct INPUT -o MESH.{ply,obj,off,city.json,city.jsonl,ifc}`: the whole method
// (docs/design/reconstruction.md).

#include "linesurf/linesurf.h"

#include "tools/cli/commands.h"
#include "tools/cli/option_registry.h"
#include "tools/cli/output_files.h"
#include "tools/cli/scene_input.h"
#include "tools/cli/surface_quality_summary.h"

#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

namespace linesurf::cli {
namespace {

/// The command's own options, beside the library's, in the report's output_options.
const std::vector<std::string> kOutputOptionKeys = {"ascii", "cityjson", "crs"};

struct ReconstructArgs {
  SceneInputArgs source;
  std::string output;
  std::string report;
  std::string work_dir;
  bool ascii = false;
  bool cityjson = false;
  GeoreferenceOptions georeference;
  ReconstructOptions options;
  std::unique_ptr<OptionRegistry> registry;  ///< flags, --config and the report's options
};

/// The library's report (report.h) with the paths read and written and the command's own
/// output options.
nlohmann::ordered_json CliReportJson(const ReconstructArgs& args, const ReconstructResult& r) {
  nlohmann::ordered_json j;
  j["input"] = args.source.input;
  j["output"] = args.output;
  j["output_options"] = args.registry->Effective(kOutputOptionKeys);
  j.update(nlohmann::ordered_json::parse(ReportJson(r, args.options)));
  return j;
}

int RunReconstruct(const CommonOptions& common, ReconstructArgs& args) {
  args.options.num_threads = common.threads;
  if (Status s = args.registry->ApplyConfig(); !s) return ReportError(s.error());
  if (Status s = args.options.Validate(); !s) return ReportError(s.error());
  if (Status s = args.georeference.Validate(); !s) return ReportError(s.error());
  OutputFiles files("reconstruct");
  args.source.AddInputsTo(files);
  const bool sequence = IsCityJsonSeqPath(args.output);
  const bool ifc = IsIfcPath(args.output);
  const bool cityjson = !sequence && !ifc && (args.cityjson || IsCityJsonPath(args.output));
  files.AddOutput("-o", args.output,
                  cityjson || sequence || ifc ? std::vector<std::string>{} : kMeshExtensions);
  files.AddOutput("--report", args.report, {});
  if (Status s = files.Prepare(); !s) return ReportError(s.error());
  Expected<ReadSceneResult> read = ReadScene(args.source.input, args.source.Options());
  if (!read) return ReportError(read.error());
  for (const std::string& w : read->warnings) PrintWarning(common, w);

  std::optional<ReconstructResult> result;
  std::size_t failed_units = 0;
  if (args.work_dir.empty()) {
    Expected<ReconstructResult> run =
        Reconstruct(read->scene.View(), args.options, CliRunControl(common));
    if (!run) return ReportError(run.error(), args.source.input);
    result = std::move(*run);
  } else {
    Expected<WorkStep> step = ReconstructInWorkDirectory(read->scene.View(), args.options,
                                                         args.work_dir, CliRunControl(common));
    if (!step) return ReportError(step.error(), args.source.input);
    if (!common.quiet) {
      std::fprintf(stderr, "reconstruct: %zu work units, %zu already done, %zu pending\n",
                   step->units, step->reused, step->pending.size());
    }
    if (!step->pending.empty()) {
      for (const std::string& id : step->pending) std::printf("%s\n", id.c_str());
      return kExitUnitsPending;
    }
    failed_units = step->failed.size();
    result = std::move(*step->result);
  }
  for (const std::string& w : result->warnings) PrintWarning(common, w);
  MeshWriteOptions write;
  write.ascii = args.ascii;  // faces are already triangles when --triangulate was given
  // The format follows the destination's name: the staged file keeps only its last extension.
  auto write_surface = [&](const std::filesystem::path& path) {
    GeoreferenceOptions geo = args.georeference;
    geo.up = result->stats.frame.up;  // roof, wall and ground by the data's up
    if (sequence) return WriteCityJsonSeq(path.string(), result->mesh, result->planes, geo);
    if (cityjson) return WriteCityJson(path.string(), result->mesh, result->planes, geo);
    if (ifc) return WriteIfc(path.string(), result->mesh, result->planes, geo);
    return WriteMesh(path.string(), result->mesh, write);
  };
  if (Status s = files.Write(args.output, write_surface); !s) return ReportError(s.error());
  if (!args.report.empty()) {
    const nlohmann::ordered_json report = CliReportJson(args, *result);
    if (Status s =
            files.Write(args.report,
                        [&](const auto& path) { return WriteReport(path, report, "reconstruct"); });
        !s) {
      return ReportError(s.error());
    }
  }
  if (Status s = files.Commit(); !s) return ReportError(s.error());
  const ReconstructStats& s = result->stats;
  if (!common.quiet) {
    std::fprintf(stderr,
                 "reconstruct: %zu segments, %zu planes, %s scene; %zu cells, LP %zu x %zu (%s, "
                 "%s); mesh %zu vertices, %zu faces, %s, %s; %.2f s\n",
                 s.inputs.segments,
                 s.detection.planes,
                 s.scene.scene_mode.c_str(),
                 s.complex.cells,
                 s.labeling.lp_variables,
                 s.labeling.lp_constraints,
                 s.labeling.solver_backend.c_str(),
                 s.labeling.solver_status.c_str(),
                 s.surface.mesh_vertices,
                 s.surface.mesh_faces,
                 s.surface.mesh_closed ? "closed" : "NOT closed",
                 s.surface.mesh_manifold ? "2-manifold" : "NOT 2-manifold",
                 s.resources.total_seconds);
    std::fprintf(stderr,
                 "reconstruct: eps %.6g (%s)\n",
                 s.detection.epsilon.epsilon,
                 s.detection.epsilon.source.c_str());
    if (s.fragments.removed_fragments > 0) {
      std::fprintf(stderr,
                   "reconstruct: removed %zu floating fragments (volume %.6g, %zu supported "
                   "segments)\n",
                   s.fragments.removed_fragments,
                   s.fragments.removed_fragment_volume,
                   s.fragments.removed_fragment_segments);
    }
    if (s.quality.measured) {
      std::fputs(SurfaceQualitySummary(s.quality, "reconstruct: ").c_str(), stderr);
    }
  }
  return failed_units > 0 ? kExitPartial : kExitOk;
}

}  // namespace

Command AddReconstructCommand(CLI::App& app, CommonOptions& common) {
  auto args = std::make_shared<ReconstructArgs>();
  Command cmd;
  cmd.app = app.add_subcommand(
      "reconstruct", "Reconstruct a closed piecewise-planar mesh from 3D line segments");
  CLI::App* sub = cmd.app;
  AddSceneInputOptions(*sub, args->source);
  sub->add_option("-o,--output", args->output, "Output mesh (.ply, .obj or .off)")->required();
  sub->add_option("--report", args->report, "Write the run report (JSON) here");
  sub->add_option("--work-dir", args->work_dir,
                  "Run per-block detection as work units in this directory: exit 6 and print "
                  "the pending units (run them with `linesurf work-unit`, then this command "
                  "again), or finish the run (exit 7 when some unit failed)");
  OptionRegistry& r = *(args->registry = std::make_unique<OptionRegistry>(*sub));
  r.AddOptions(args->options, {"num_threads"});  // num_threads: the global -j
  r.AddFlag("ascii", args->ascii, "ASCII PLY");
  r.AddFlag("cityjson", args->cityjson,
            "Write CityJSON whatever the output extension (one Building per connected part; "
            ".city.jsonl names write CityJSONSeq)");
  r.Add("crs", args->georeference.crs,
        "CityJSON and IFC: the coordinates' reference system, EPSG:CODE");
  cmd.run = [&common, args] { return RunReconstruct(common, *args); };
  return cmd;
}

}  // namespace linesurf::cli
