// `linesurf reconstruct INPUT -o MESH.{ply,obj,off,city.json,city.jsonl,ifc}`: the whole method
// (docs/reconstruction.md).

#include "linesurf/linesurf.h"

#include "tools/cli/commands.h"
#include "tools/cli/detection_options.h"
#include "tools/cli/mesh_validity_json.h"
#include "tools/cli/option_checks.h"
#include "tools/cli/output_files.h"
#include "tools/cli/scene_input.h"
#include "tools/cli/surface_quality_json.h"

#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

namespace linesurf::cli {
namespace {

struct ReconstructArgs {
  SceneInputArgs source;
  std::string output;
  std::string report;
  bool ascii = false;
  bool cityjson = false;
  GeoreferenceOptions georeference;
  ReconstructOptions options;
  std::unique_ptr<OptionRegistry> registry;  ///< flags, --config and the report's options
};

nlohmann::json ReportJson(const ReconstructArgs& args, const ReconstructResult& r) {
  const ReconstructStats& s = r.stats;
  nlohmann::json j;
  j["input"] = args.source.input;
  j["output"] = args.output;
  j["options"] = args.registry->Effective();
  j["options"]["threads"] = args.options.num_threads;
  nlohmann::json stages = nlohmann::json::object();
  for (const auto& [name, seconds] : s.stage_seconds) stages[name] = seconds;
  j["stage_seconds"] = stages;
  j["total_seconds"] = s.total_seconds;
  j["counts"] = {{"input_segments", s.input_segments},
                 {"segments", s.segments},
                 {"viewpoints", s.viewpoints},
                 {"observations", s.observations},
                 {"planes", s.planes},
                 {"capped_blocks", s.capped_blocks},
                 {"segments_with_0_planes", s.segments_with_planes[0]},
                 {"segments_with_1_plane", s.segments_with_planes[1]},
                 {"segments_with_2_planes", s.segments_with_planes[2]},
                 {"planes_in_complex", s.planes_in_complex},
                 {"blocks", s.blocks},
                 {"seam_facets", s.seam_facets},
                 {"crowded_split_faces", s.crowded_split_faces},
                 {"crowded_blocks", s.crowded_blocks},
                 {"cells", s.cells},
                 {"facets", s.facets},
                 {"edges", s.edges},
                 {"vertices", s.vertices},
                 {"pair_terms", s.pair_terms},
                 {"structural_groups", s.structural_groups},
                 {"parity_groups", s.parity_groups},
                 {"fixed_cells", s.fixed_cells},
                 {"full_cells", s.full_cells},
                 {"lp_variables", s.lp_variables},
                 {"lp_constraints", s.lp_constraints},
                 {"lp_nonzeros", s.lp_nonzeros}};
  j["engine"] = s.engine;
  j["block_size"] = s.block_size;
  j["block_size_rule"] = {{"automatic", s.block_size_automatic},
                          {"mean_segments_per_block", s.mean_segments_per_block},
                          {"mean_planes_per_block", s.mean_planes_per_block},
                          {"at_floor", s.block_size_at_floor}};
  j["detection_block_size"] = s.detection_block_size;
  j["scene_mode"] = s.scene_mode;
  j["scene_mode_reason"] = s.scene_mode_reason;
  j["sigma"] = s.sigma;
  j["crease_weight"] = s.crease_weight;
  j["epsilon"] = EpsilonJson(s.epsilon);
  if (s.quality_measured) j["quality"] = SurfaceQualityJson(s.quality);
  // A lower bound of -infinity (none known) and its gap are null.
  const bool bounded = std::isfinite(s.lower_bound);
  j["solver"] = {{"backend", s.solver_backend},
                 {"method", s.labeling_method},
                 {"status", s.solver_status},
                 {"objective", s.objective},
                 {"rounded_objective", s.rounded_objective},
                 {"relaxed_objective", s.relaxed_objective},
                 {"lower_bound", bounded ? nlohmann::json(s.lower_bound) : nlohmann::json()},
                 {"lower_bound_source", s.lower_bound_source},
                 {"gap", bounded ? nlohmann::json(s.objective - s.lower_bound) : nlohmann::json()},
                 {"fractional_cells", s.fractional_cells}};
  j["mesh"] = {{"vertices", s.mesh_vertices},
               {"faces", s.mesh_faces},
               {"closed", s.mesh_closed},
               {"manifold", s.mesh_manifold},
               {"volume", s.mesh_volume},
               {"split_vertices", s.split_vertices},
               {"removed_fragments", s.removed_fragments},
               {"removed_fragment_volume", s.removed_fragment_volume},
               {"removed_fragment_segments", s.removed_fragment_segments}};
  if (Expected<MeshValidity> validity = CheckMesh(r.mesh)) {
    j["validity"] = MeshValidityJson(*validity);
  }
  j["peak_memory_bytes"] = s.peak_memory_bytes;
  j["warnings"] = r.warnings;
  return j;
}

int RunReconstruct(const CommonOptions& common, ReconstructArgs& args) {
  if (Status s = args.registry->ApplyConfig(); !s) return ReportError(s.error());
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

  args.options.num_threads = common.threads;
  Expected<ReconstructResult> result =
      Reconstruct(read->scene.View(), args.options, CliRunControl(common));
  if (!result) return ReportError(result.error(), args.source.input);
  for (const std::string& w : result->warnings) PrintWarning(common, w);
  MeshWriteOptions write;
  write.ascii = args.ascii;  // faces are already triangles when --triangulate was given
  // The format follows the destination's name: the staged file keeps only its last extension.
  auto write_surface = [&](const std::filesystem::path& path) {
    const GeoreferenceOptions& geo = args.georeference;
    if (sequence) return WriteCityJsonSeq(path.string(), result->mesh, result->planes, geo);
    if (cityjson) return WriteCityJson(path.string(), result->mesh, result->planes, geo);
    if (ifc) return WriteIfc(path.string(), result->mesh, result->planes, geo);
    return WriteMesh(path.string(), result->mesh, write);
  };
  if (Status s = files.Write(args.output, write_surface); !s) return ReportError(s.error());
  if (!args.report.empty()) {
    const nlohmann::json report = ReportJson(args, *result);
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
                 s.segments, s.planes, s.scene_mode.c_str(), s.cells, s.lp_variables,
                 s.lp_constraints, s.solver_backend.c_str(), s.solver_status.c_str(),
                 s.mesh_vertices, s.mesh_faces, s.mesh_closed ? "closed" : "NOT closed",
                 s.mesh_manifold ? "2-manifold" : "NOT 2-manifold", s.total_seconds);
    std::fprintf(stderr, "reconstruct: eps %.6g (%s)\n", s.epsilon.epsilon,
                 s.epsilon.source.c_str());
    if (s.removed_fragments > 0) {
      std::fprintf(stderr,
                   "reconstruct: removed %zu floating fragments (volume %.6g, %zu supported "
                   "segments)\n",
                   s.removed_fragments,
                   s.removed_fragment_volume,
                   s.removed_fragment_segments);
    }
    if (s.quality_measured) {
      std::fputs(SurfaceQualitySummary(s.quality, "reconstruct: ").c_str(), stderr);
    }
  }
  return kExitOk;
}

}  // namespace

Command AddReconstructCommand(CLI::App& app, CommonOptions& common) {
  auto args = std::make_shared<ReconstructArgs>();
  ReconstructOptions& o = args->options;
  EnergyWeights& w = o.weights;
  Command cmd;
  cmd.app = app.add_subcommand(
      "reconstruct", "Reconstruct a closed piecewise-planar mesh from 3D line segments");
  CLI::App* sub = cmd.app;
  AddSceneInputOptions(*sub, args->source);
  sub->add_option("-o,--output", args->output, "Output mesh (.ply, .obj or .off)")->required();
  sub->add_option("--report", args->report, "Write the run report (JSON) here");
  OptionRegistry& r = *(args->registry = std::make_unique<OptionRegistry>(*sub));
  r.AddChoice("planes",
              o.planes,
              {{"detect", PlaneSource::kDetect}, {"given", PlaneSource::kGiven}},
              "Planes: detect them, or use the input's");
  r.AddChoice("scene",
              o.scene_mode,
              {{"exterior", SceneMode::kExterior},
               {"interior", SceneMode::kInterior},
               {"auto", SceneMode::kAuto}},
              "Boundary: box cells empty (exterior), full (interior), or decided");
  r.Add("w-textural", w.textural, "Textural weight");
  r.Add("w-structural", w.structural, "Structural weight");
  r.Add(
      "w-crease", w.crease, "Crease weight (default: 0.2 in interior scenes, 0 in exterior ones)");
  r.Add("w-visibility", w.visibility, "Visibility weight");
  r.Add("w-edge", w.edge, "Edge regularisation weight");
  r.Add("w-corner", w.corner, "Corner regularisation weight");
  r.Add("w-area", w.area, "Area weight");
  r.Add("w-open-seam",
        w.open_seam,
        "Block engine: weight of surface on block faces that carry no plane, per area / sigma^2");
  r.Add("w-prior", w.viewpoint_prior, "Viewpoint prior weight");
  r.Add("sigma", o.sigma, "Scale sigma, scene units (default: median length)");
  r.Add("samples-per-sigma", o.samples_per_sigma, "Samples per sigma of segment");
  r.AddFlag("structural-as-textural",
            o.structural_as_textural,
            "Ablation: structural segments count as two textural ones");
  r.AddChoice("solver",
              o.solver.backend,
              {{"auto", SolverBackend::kAuto},
               {"clp", SolverBackend::kClp},
               {"maxflow", SolverBackend::kMaxflow},
               {"pdhg", SolverBackend::kPdhg},
               {"band", SolverBackend::kBand},
               {"cbc", SolverBackend::kCbc},
               {"clp-barrier", SolverBackend::kClpBarrier},
               {"blocks", SolverBackend::kBlocks},
               {"pdhg-energy", SolverBackend::kPdhgEnergy}},
              "Labelling backend (auto: by model size)");
  r.Add("time-limit", o.solver.time_limit_seconds, "Solver time limit, s (0 = none)");
  r.AddChoice("engine",
              o.engine,
              {{"monolithic", ComplexEngine::kMonolithic}, {"blocks", ComplexEngine::kBlocks}},
              "Cell complex: one arrangement of the scene box, or per-block arrangements "
              "(blocks of --block-size, automatic when 0)");
  r.Add("block-size",
        o.block_size,
        "Block engine: side of the base blocks, scene units (0 = automatic; --engine blocks "
        "only)")
      ->check(AtLeast(0.0));
  r.Add("block-margin",
        o.block_margin,
        "Blocks a plane's support region is dilated by, fractions allowed (--engine blocks)")
      ->check(Between(0.0, 64.0));
  r.Add("box-margin", o.box_margin, "Box margin, fraction of the extent per side");
  r.Add("seed", o.seed, "Random seed");
  r.AddFlag("ascii", args->ascii, "ASCII PLY");
  r.AddFlag("cityjson", args->cityjson,
            "Write CityJSON whatever the output extension (one Building per connected part; "
            ".city.jsonl names write CityJSONSeq)");
  r.Add("crs", args->georeference.crs,
        "CityJSON and IFC: the coordinates' reference system, EPSG:CODE");
  r.AddFlag("triangulate", o.triangulate, "Triangles instead of convex polygons");
  r.AddFlag(
      "merge-coplanar",
      o.merge_coplanar,
      "Blocks engine: neighbouring faces of one plane (split by block faces or by planes "
      "without surface there) become one polygon (may be non-convex; not with --triangulate)");
  r.AddFlag("quality",
            o.measure_quality,
            "Figures without ground truth in the report (data fit, visibility, components; "
            "--quality=false skips them)");
  r.AddFlag("remove-fragments",
            o.remove_floating_fragments,
            "Drop floating fragments: components holding fewer supported lines than 3 "
            "(--remove-fragments=false keeps them)");
  RegisterDetectionOptions(r, o.detection, "detect-");
  cmd.run = [&common, args] { return RunReconstruct(common, *args); };
  return cmd;
}

}  // namespace linesurf::cli
