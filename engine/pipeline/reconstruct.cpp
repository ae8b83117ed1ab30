#include "engine/pipeline/reconstruct.h"

#include "linesurf/option_schema.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "engine/core/exception.h"
#include "engine/detect/estimate_epsilon.h"
#include "engine/pipeline/block_evidence.h"
#include "engine/pipeline/decide_scene_mode.h"
#include "engine/pipeline/detect_scene_planes.h"
#include "engine/pipeline/extract_block_surface.h"
#include "engine/pipeline/judge_result.h"
#include "engine/pipeline/mesh_topology.h"
#include "engine/pipeline/mesh_validity.h"
#include "engine/pipeline/open_seams.h"
#include "engine/pipeline/pinch_repair.h"
#include "engine/pipeline/scene_box.h"
#include "engine/pipeline/stage_stats.h"
#include "engine/pipeline/stage_timer.h"
#include "solver/lp/labeling_backends.h"

namespace linesurf::pipeline {
namespace {

constexpr const char* kReconstructStage = "reconstruct";

/// Observing viewpoints whose cell is labelled full (inside the solid: against the evidence).
void CountViewpointsInFullCells(const Scene& scene, const IdVector<ViewpointId, CellId>& cells,
                                std::span<const std::uint8_t> labels, ResultFacts& facts) {
  std::vector<std::uint8_t> observing(scene.viewpoints.size(), 0);
  for (const ViewpointId v : scene.observations.items()) observing[v.index()] = 1;
  for (std::size_t v = 0; v < observing.size(); ++v) {
    if (observing[v] == 0) continue;
    ++facts.observing_viewpoints;
    const CellId c = cells[ViewpointId(v)];
    if (c.IsValid() && labels[c.index()] != 0) ++facts.viewpoints_in_full_cells;
  }
}

/// The partition of the cells that the per-block solve ("blocks", picked by "auto" for large
/// LPs) works on: the partition's own blocks. Empty when no backend that uses it can run.
std::vector<std::uint32_t> SolveBlocks(const PreparedReconstruction& prepared,
                                       const solver::LabelingOptions& options) {
  if (!solver::LookupBackend(options.backend).capabilities.takes_partition) return {};
  return partition::BlockOfEachCell(prepared.blocks.complexes);
}

/// The callbacks of `ctx` with the thread count of `options`: one context for every stage.
void ConfigureStageContext(const ReconstructOptions& options, const RunContext& ctx,
                           RunContext& stage_ctx) {
  stage_ctx.num_threads = options.num_threads != 0 ? options.num_threads : ctx.num_threads;
  stage_ctx.is_cancelled = [&ctx] { return ctx.ShouldStop(); };
  stage_ctx.on_progress = [&ctx](const Progress& p) {
    ctx.ReportProgress(p.stage, p.stage_fraction);
  };
  stage_ctx.log = ctx.log;
}

/// The sanitised scene with its planes (given or detected), and what the planes stage tells
/// the report and the result checks.
struct ScenePlanes {
  Scene scene;
  IdVector<SegmentId, SegmentId> input_segment;
  std::vector<std::string> warnings;
  SanitizeStats sanitation;
  DataFrame frame;
  DetectionStats detection;
  std::string plane_cap_warning;   ///< "" unless a detection block stopped at max_planes
  double detection_epsilon = 0.0;  ///< eps used by detection (0: given planes)
};

/// Sanitises the scene and keeps its own planes and memberships (stages "sanitize", "detect").
ScenePlanes GivenPlanes(const Scene& input,
                        const ReconstructOptions& options,
                        const RunContext& ctx,
                        StageTimer& timer) {
  timer.Start("sanitize");
  LINESURF_THROW_IF(input.planes.empty() || !input.HasMemberships(),
                    kInvalidInput,
                    kReconstructStage,
                    "use_given_planes: the scene has no planes or plane memberships");
  SanitizeResult sane = ValueOrThrow(SanitizeScene(input, options.sanitize));
  ctx.ThrowIfCancelled(kReconstructStage);
  timer.Start("detect");  // nothing to detect: the report lists the same stages either way
  ScenePlanes out;
  out.detection = MakeDetectionStats(
      sane.scene, ValueOrThrow(ResolveEpsilon(sane.scene, options.planes, ctx)));
  out.scene = std::move(sane.scene);
  out.input_segment = std::move(sane.input_segment);
  out.warnings = std::move(sane.warnings);
  out.sanitation = sane.stats;
  out.frame = std::move(sane.frame);
  return out;
}

/// Sanitises the scene and detects its planes (stages "sanitize", "detect").
ScenePlanes DetectedPlanes(const Scene& input,
                           const ReconstructOptions& options,
                           const RunContext& ctx,
                           StageTimer& timer,
                           detect::DetectionRunner* runner) {
  PlaneDetectionOptions detect = options.planes;
  detect.seed = options.seed;
  DetectedScene detected = ValueOrThrow(SanitizeAndDetectPlanes(
      input, options.sanitize, detect, ctx, &timer, &options.detection_blocks, runner));
  ScenePlanes out;
  out.detection = MakeDetectionStats(detected);
  out.plane_cap_warning = PlaneCapWarning(detected.detection_stats, detect.max_planes);
  out.detection_epsilon = detected.detection_stats.epsilon;
  out.scene = std::move(detected.scene);
  out.input_segment = std::move(detected.input_segment);
  out.warnings = std::move(detected.warnings);
  out.sanitation = detected.sanitize_stats;
  out.frame = std::move(detected.frame);
  return out;
}

/// The warning for blocks still crowded with planes when the cuts stopped ("" when none is).
std::string CrowdedBlocksWarning(const BlockPartitionStats& stats,
                                 const BlockPartitionOptions& options) {
  if (stats.crowded_blocks_left == 0) return {};
  std::ostringstream w;
  w << stats.crowded_blocks_left << " block(s) still reached by more than "
    << options.crowded_planes_per_block
    << " planes when the crowded-block cuts stopped (cut depth or block budget reached): "
       "their complexes take most of the time and memory; a smaller --block-size splits "
       "them";
  return w.str();
}

}  // namespace

Status ValidateOneBlockSize(bool one_block, double block_size, const BlockFieldNames& names) {
  if (!one_block || block_size == 0.0) return {};
  return Error{ErrorCode::kInvalidOptions,
               "reconstruct_options",
               std::string(names.block_size) +
                   " applies to the blocks engine only (per-block detection: " +
                   names.detection_block_size + ")"};
}

Status ValidateMergeCoplanar(bool merge_coplanar, bool triangulate) {
  if (!merge_coplanar || !triangulate) return {};
  return Error{ErrorCode::kInvalidOptions,
               "reconstruct_options",
               "merge_coplanar gives non-convex faces: not with triangulate"};
}

Status ReconstructOptions::Validate() const {
  if (Status s = sanitize.Validate(); !s) return s;
  if (!use_given_planes) {
    if (Status s = planes.Validate(); !s) return s;
  }
  if (Status s = energy.Validate(); !s) return s;
  if (Status s = solver.Validate(); !s) return s;
  if (Status s = complex.Validate(); !s) return s;
  if (Status s = blocks.Validate(); !s) return s;
  if (Status s = detection_blocks.Validate(); !s) return s;
  if (Status s = ValidateOneBlockSize(blocks.one_block, blocks.block_size); !s) return s;
  if (Status s = ValidateMergeCoplanar(merge_coplanar, triangulate); !s) return s;
  if (Status s = ValidateOptionValues(quality); !s) return s;
  if (!(box_margin > 0.0 && box_margin <= 10.0)) {
    return Error{ErrorCode::kInvalidOptions, "reconstruct_options",
                 "box_margin must be in (0, 10]"};
  }
  if (num_threads < 0) {
    return Error{ErrorCode::kInvalidOptions, "reconstruct_options", "num_threads must be >= 0"};
  }
  return {};
}

Expected<PreparedReconstruction> PrepareReconstruction(const Scene& input,
                                                       const ReconstructOptions& options,
                                                       const RunContext& ctx,
                                                       detect::DetectionRunner* runner) noexcept {
  return CatchAll(kReconstructStage, [&]() -> PreparedReconstruction {
    if (Status s = options.Validate(); !s) throw LinesurfException(s.error());
    RunContext stage_ctx;
    ConfigureStageContext(options, ctx, stage_ctx);

    PreparedReconstruction prepared;
    RunStats& stats = prepared.stats;
    ResultFacts& facts = prepared.facts;
    StageTimer timer;

    ScenePlanes planes = options.use_given_planes
                             ? GivenPlanes(input, options, stage_ctx, timer)
                             : DetectedPlanes(input, options, stage_ctx, timer, runner);
    Scene& scene = planes.scene;
    prepared.input_segment = std::move(planes.input_segment);
    prepared.warnings = std::move(planes.warnings);
    stats.detection = std::move(planes.detection);
    facts.viewpoints_dropped = planes.sanitation.dropped_bad_viewpoints;
    facts.plane_cap_warning = std::move(planes.plane_cap_warning);
    facts.detection_epsilon = planes.detection_epsilon;
    LINESURF_THROW_IF(scene.planes.empty(),
                      kDegenerate,
                      kReconstructStage,
                      "no plane: nothing to reconstruct from");
    const Box3 box = SceneBox(scene, options.box_margin);
    // The derived option bounds, before the complex (ComputeBlockEvidence checks them again).
    if (Status scale = CheckEnergyScale(scene, box, options.energy); !scale) {
      throw LinesurfException(scale.error());
    }

    timer.Start("complex");
    BlockPartitionOptions partition_options = options.blocks;
    partition_options.complex = options.complex;
    prepared.blocks = ValueOrThrow(BuildBlockPartition(scene, box, partition_options, stage_ctx));
    const partition::BlockComplexes& bc = prepared.blocks.complexes;
    prepared.warnings.insert(prepared.warnings.end(), bc.warnings.begin(), bc.warnings.end());
    stats.complex = MakeComplexStats(prepared.blocks, options.blocks, scene.planes.size());
    if (std::string crowded = CrowdedBlocksWarning(prepared.blocks.stats, options.blocks);
        !crowded.empty()) {
      prepared.warnings.push_back(std::move(crowded));
    }
    timer.Stop();

    // Decided in every mode: a given mode that contradicts the evidence is warned about.
    timer.Start("scene_mode");
    facts.decision = DecideSceneMode(scene, {}, stage_ctx);
    timer.Stop();
    facts.auto_mode = options.scene_mode == SceneMode::kAuto;
    facts.interior =
        facts.auto_mode ? facts.decision.interior : options.scene_mode == SceneMode::kInterior;
    stats.scene = MakeSceneModeStats(facts);
    if (facts.interior) OrientUpInside(scene, planes.frame);
    stats.frame = MakeFrameStats(planes.frame);

    facts.planes = scene.planes.size();
    facts.planes_in_complex = stats.complex.planes_in_complex;
    facts.cells = stats.complex.cells;
    facts.scene_diagonal = box.Extent().norm();
    stats.inputs = MakeInputStats(planes.sanitation, scene);
    stats.resources.stage_seconds = timer.Stages();
    prepared.scene = std::move(scene);
    return prepared;
  });
}

namespace {

/// The surface between the labels' full and empty cells, with the cheapest pinches relabelled
/// when `options` asks (`labels` changes with them).
PinchRepair ExtractLabelledSurface(const PreparedReconstruction& prepared,
                                   const EvidenceResult& evidence,
                                   const ReconstructOptions& options,
                                   std::vector<std::uint8_t>& labels,
                                   const RunContext& ctx) {
  ExtractOptions extract;
  extract.outside_full = prepared.facts.interior;
  extract.triangulate = options.triangulate;
  extract.merge_coplanar = options.merge_coplanar;
  return ValueOrThrow(ExtractWithoutPinches(prepared.blocks.complexes,
                                            evidence.energy,
                                            extract,
                                            options.repair_pinches ? kPinchRepairRounds : 0,
                                            labels,
                                            ctx));
}

/// Completes `facts` with the labels, the evidence and the surface, judges the result (throws
/// on an unusable one) and appends the judgement's warnings.
void JudgeSurface(const Scene& scene,
                  const EvidenceResult& evidence,
                  const std::vector<std::uint8_t>& labels,
                  const EnergyOptions& e,
                  ResultFacts& facts,
                  ReconstructResult& result) {
  facts.full_cells =
      static_cast<std::size_t>(std::count(labels.begin(), labels.end(), std::uint8_t{1}));
  CountViewpointsInFullCells(scene, evidence.viewpoint_cells, labels, facts);
  facts.has_data_weight = e.weights.textural > 0.0 || e.weights.structural > 0.0 ||
                          e.weights.visibility > 0.0 || e.weights.viewpoint_prior > 0.0;
  facts.sigma = evidence.stats.sigma;
  facts.samples = evidence.stats.samples;
  facts.grazing_samples = evidence.stats.grazing_samples;
  facts.mesh_faces = result.mesh.NumFaces();
  ResultJudgement judgement = JudgeResult(facts);
  if (judgement.error) throw LinesurfException(*judgement.error);
  result.warnings.insert(result.warnings.end(), judgement.warnings.begin(),
                         judgement.warnings.end());
}

/// On a surface the judgement accepted (not empty, not inverted; the pieces left are closed):
/// drops floating fragments and measures the figures without ground truth, as `options` asks.
/// The removal measures the surface it returns: those are the final figures.
void RemoveFragmentsAndMeasure(const Scene& scene,
                               const ReconstructOptions& options,
                               const RunContext& ctx,
                               StageTimer& timer,
                               MeshTopology& topology,
                               ReconstructResult& result) {
  RunStats& stats = result.stats;
  const double epsilon = stats.detection.epsilon.epsilon;
  std::optional<SurfaceQuality> measured;
  if (options.remove_floating_fragments) {
    timer.Start("fragments");
    FragmentRemoval kept = ValueOrThrow(
        RemoveFloatingFragments(result.mesh, scene, epsilon, options.quality, ctx));
    if (kept.removed_components > 0) {
      result.mesh = std::move(kept.mesh);
      topology = ComputeMeshTopology(result.mesh);
    }
    stats.fragments = MakeFragmentStats(kept);
    measured = std::move(kept.quality);
    timer.Stop();
  }
  // Figures without ground truth, in the local frame, on a surface the judgement accepted.
  if (options.measure_quality) {
    timer.Start("quality");
    stats.quality = MakeQualityStats(
        measured ? std::move(*measured)
                 : ValueOrThrow(
                       MeasureSurfaceQuality(result.mesh, scene, epsilon, options.quality, ctx)));
    timer.Stop();
  }
}

/// The mesh to world coordinates, as written: never returned broken; what only a solid must not
/// have is said.
void CheckWorldSurface(const Scene& scene, StageTimer& timer, ReconstructResult& result) {
  for (Vec3& p : result.mesh.vertices) p = scene.world_from_local.Apply(p);
  timer.Start("validity");
  const MeshValidity validity = ValueOrThrow(CheckMeshValidity(result.mesh));
  if (Status refused = RefuseBrokenSurface(validity); !refused) {
    throw LinesurfException(refused.error());
  }
  for (std::string& w : SolidValidityWarnings(validity)) result.warnings.push_back(std::move(w));
  timer.Stop();
}

}  // namespace

Expected<ReconstructResult> SolvePrepared(const PreparedReconstruction& prepared,
                                          const ReconstructOptions& options,
                                          const RunContext& ctx) noexcept {
  return CatchAll(kReconstructStage, [&]() -> ReconstructResult {
    if (Status s = options.Validate(); !s) throw LinesurfException(s.error());
    RunContext stage_ctx;
    ConfigureStageContext(options, ctx, stage_ctx);
    const Scene& scene = prepared.scene;
    const bool interior = prepared.facts.interior;

    ReconstructResult result;
    result.stats = prepared.stats;
    result.warnings = prepared.warnings;
    result.world_from_local = scene.world_from_local;
    RunStats& stats = result.stats;
    ResultFacts facts = prepared.facts;
    StageTimer timer;

    timer.Start("evidence");
    const BoundaryMode boundary = interior ? BoundaryMode::kInterior : BoundaryMode::kExterior;
    EvidenceResult evidence = ValueOrThrow(ComputeBlockEvidence(
        prepared.blocks.complexes, scene, options.energy, boundary, stage_ctx));
    result.warnings.insert(result.warnings.end(), evidence.warnings.begin(),
                           evidence.warnings.end());
    stats.energy = MakeEnergyStats(evidence);

    timer.Start("solve");
    const std::vector<std::uint32_t> block_of_cell = SolveBlocks(prepared, options.solver);
    const solver::LabelingResult labeling = ValueOrThrow(
        solver::SolveLabeling(evidence.energy, block_of_cell, options.solver, stage_ctx));
    std::vector<std::uint8_t> labels = labeling.labels;
    stats.labeling = MakeLabelingStats(labeling);

    timer.Start("extract");
    PinchRepair repaired = ExtractLabelledSurface(prepared, evidence, options, labels, stage_ctx);
    BlockExtractResult& surface = repaired.surface;
    const OpenSeamSurface open =
        MeasureOpenSeamSurface(prepared.blocks.complexes, surface.mesh, surface.face_facet);
    facts.open_seam_area = open.area;
    facts.open_seam_faces = open.faces;
    facts.mesh_area = open.total_area;
    result.mesh = std::move(surface.mesh);
    MeshTopology topology = ComputeMeshTopology(result.mesh);
    timer.Stop();

    facts.topology = topology;
    JudgeSurface(scene, evidence, labels, options.energy, facts, result);
    RemoveFragmentsAndMeasure(scene, options, stage_ctx, timer, topology, result);
    CheckWorldSurface(scene, timer, result);

    // Planes back to world coordinates.
    result.planes = scene.planes;
    for (Plane3& p : result.planes) {
      p.point = scene.world_from_local.Apply(p.point);
      p.normal = scene.world_from_local.Rotate(p.normal);
    }
    result.memberships = scene.memberships;
    result.input_segment = prepared.input_segment;

    stats.surface = MakeSurfaceStats(result.mesh, topology, surface.stats, repaired.stats);
    std::vector<std::pair<std::string, double>> stages = prepared.stats.resources.stage_seconds;
    stages.insert(stages.end(), timer.Stages().begin(), timer.Stages().end());
    stats.resources = MakeResourceStats(std::move(stages));
    return result;
  });
}

Expected<ReconstructResult> Reconstruct(const Scene& input,
                                        const ReconstructOptions& options,
                                        const RunContext& ctx,
                                        detect::DetectionRunner* runner) noexcept {
  Expected<PreparedReconstruction> prepared = PrepareReconstruction(input, options, ctx, runner);
  if (!prepared) return prepared.error();
  return SolvePrepared(*prepared, options, ctx);
}

}  // namespace linesurf::pipeline
