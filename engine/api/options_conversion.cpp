#include "engine/api/options_conversion.h"

#include "partition/voxel/plane_support.h"

#include <cmath>
#include <string>
#include <string_view>
#include <utility>

namespace linesurf::api {
namespace {

constexpr const char* kOptionsConversionStage = "options";

Status Bad(const std::string& field, const std::string& why) {
  return Error{ErrorCode::kInvalidOptions, kOptionsConversionStage, field + " " + why};
}

/// The engine's own check of the detection fields, named as the facade's.
Status ValidateDetection(const DetectionParameters& detection) {
  const Status s = ToEngineOptions(detection, 0).Validate();
  if (s) return s;
  return Error{
      ErrorCode::kInvalidOptions, kOptionsConversionStage, "detection: " + s.error().message};
}

/// The engine's own check of the block margin (partition::PlaneSupportOptions), named as the
/// facade's.
Status ValidateBlockMargin(double block_margin) {
  partition::PlaneSupportOptions o;
  o.margin_blocks = block_margin;
  const Status s = o.Validate();
  if (s) return s;
  return Error{
      ErrorCode::kInvalidOptions, kOptionsConversionStage, "block_margin: " + s.error().message};
}

pipeline::Engine ToEngine(ComplexEngine engine) {
  return engine == ComplexEngine::kBlocks ? pipeline::Engine::kBlocks
                                          : pipeline::Engine::kMonolithic;
}

/// The engine's own checks of the block fields (pipeline::ValidateBlockSize, the block side
/// against the engine, the block margin), named as the facade's.
Status ValidateBlocks(ComplexEngine engine, double block_size, double block_margin) {
  Status s = pipeline::ValidateBlockSize(block_size);
  if (s) {
    s = pipeline::ValidateEngineBlockSize(
        ToEngine(engine),
        block_size,
        {.block_size = "block_size", .detection_block_size = "detection.block_size"});
  }
  if (!s) return Error{ErrorCode::kInvalidOptions, kOptionsConversionStage, s.error().message};
  return ValidateBlockMargin(block_margin);
}

Status ValidateMergeCoplanar(ComplexEngine engine, bool merge_coplanar, bool triangulate) {
  const Status s = pipeline::ValidateMergeCoplanar(ToEngine(engine), merge_coplanar, triangulate);
  if (!s) return Error{ErrorCode::kInvalidOptions, kOptionsConversionStage, s.error().message};
  return {};
}

/// The engine's own check of the quality fields, named as the facade's.
Status ValidateQuality(const QualityOptions& quality) {
  pipeline::SurfaceQualityOptions o;
  SetEngineQuality(quality, o);
  const Status s = o.Validate();
  if (s) return s;
  return Error{ErrorCode::kInvalidOptions, kOptionsConversionStage, "quality." + s.error().message};
}

}  // namespace

void SetEngineQuality(const QualityOptions& quality, pipeline::SurfaceQualityOptions& engine) {
  engine.fit_factor = quality.fit_factor;
  engine.samples_per_segment = quality.samples_per_segment;
  engine.min_lines_per_component = quality.min_lines_per_component;
}

PlaneDetectionOptions ToEngineOptions(const DetectionParameters& detection, std::uint64_t seed) {
  PlaneDetectionOptions o;
  o.epsilon = detection.epsilon;
  o.epsilon_over_noise = detection.epsilon_over_noise;
  o.relative_epsilon = detection.relative_epsilon;
  o.epsilon_fusion_factor = detection.epsilon_fusion_factor;
  o.theta_fusion_deg = detection.theta_fusion_deg;
  o.p_fusion = detection.p_fusion;
  o.iterations = detection.iterations;
  o.max_planes = detection.max_planes;
  o.min_support = detection.min_support;
  o.support_gap = detection.support_gap;
  o.collinear_tolerance = detection.collinear_tolerance;
  o.block_size = detection.block_size;
  o.block_halo = detection.block_halo;
  o.block_max_segments = detection.block_max_segments;
  o.seed = seed;
  return o;
}

void SetEngineWeights(const EnergyWeights& weights, pipeline::EnergyOptions& energy) {
  energy.textural_weight = weights.textural;
  energy.structural_weight = weights.structural;
  energy.crease_weight = weights.crease;
  energy.visibility_weight = weights.visibility;
  energy.edge_weight = weights.edge;
  energy.corner_weight = weights.corner;
  energy.area_weight = weights.area;
  energy.viewpoint_prior_weight = weights.viewpoint_prior;
  energy.open_seam_weight = weights.open_seam;
}

pipeline::ReconstructOptions ToEngineOptions(const ReconstructOptions& options) {
  pipeline::ReconstructOptions o;
  o.planes = ToEngineOptions(options.detection, options.seed);
  o.use_given_planes = options.planes == PlaneSource::kGiven;
  SetEngineWeights(options.weights, o.energy);
  o.energy.sigma = options.sigma;
  o.energy.samples_per_sigma = options.samples_per_sigma;
  o.energy.structural_as_textural = options.structural_as_textural;
  o.solver.backend = SolverBackendName(options.solver.backend);
  o.solver.time_limit_seconds = options.solver.time_limit_seconds;
  o.scene_mode = options.scene_mode;
  o.engine = ToEngine(options.engine);
  o.blocks.block_size = options.block_size;
  o.blocks.support.margin_blocks = options.block_margin;
  o.box_margin = options.box_margin;
  o.measure_quality = options.measure_quality;
  o.remove_floating_fragments = options.remove_floating_fragments;
  SetEngineQuality(options.quality, o.quality);
  o.triangulate = options.triangulate;
  o.merge_coplanar = options.merge_coplanar;
  o.num_threads = options.num_threads;
  o.seed = options.seed;
  return o;
}

io::SceneReadOptions ToEngineOptions(const ReadOptions& options) {
  io::SceneReadOptions o;
  switch (options.format) {
    case SceneFormat::kAuto:
      o.format = io::SceneFormat::kAuto;
      break;
    case SceneFormat::kReferenceJson:
      o.format = io::SceneFormat::kReferenceJson;
      break;
    case SceneFormat::kLine3dpp:
      o.format = io::SceneFormat::kLine3dpp;
      break;
    case SceneFormat::kObjLines:
      o.format = io::SceneFormat::kObjLines;
      break;
    case SceneFormat::kLimapTracks:
      o.format = io::SceneFormat::kLimapTracks;
      break;
  }
  o.nvm = options.nvm;
  o.colmap = options.colmap;
  return o;
}

io::MeshWriteOptions ToEngineOptions(const MeshWriteOptions& options) {
  io::MeshWriteOptions o;
  o.ascii = options.ascii;
  o.triangulate = options.triangulate;
  return o;
}

Status ValidateWeights(const EnergyWeights& weights) {
  // The engine's rule (EnergyOptions::Validate, the one the CLI applies), named as the facade's.
  pipeline::EnergyOptions energy;
  SetEngineWeights(weights, energy);
  const Status s = energy.Validate();
  if (s) return s;
  const std::pair<std::string_view, const char*> names[] = {
      {"textural_weight", "weights.textural"},
      {"structural_weight", "weights.structural"},
      {"crease_weight", "weights.crease"},
      {"visibility_weight", "weights.visibility"},
      {"edge_weight", "weights.edge"},
      {"corner_weight", "weights.corner"},
      {"area_weight", "weights.area"},
      {"viewpoint_prior_weight", "weights.viewpoint_prior"},
      {"open_seam_weight", "weights.open_seam"}};
  const std::string& message = s.error().message;
  for (const auto& [engine_name, name] : names) {
    // The engine's name stays in brackets: the CLI's messages (docs/user/errors.md) name it.
    if (message.rfind(std::string(engine_name) + " ", 0) == 0) {
      return Bad(std::string(name) + " (" + std::string(engine_name) + ")",
                 message.substr(engine_name.size() + 1));
    }
  }
  return Error{ErrorCode::kInvalidOptions, kOptionsConversionStage, "weights: " + message};
}

namespace {

Status ValidateThreads(int num_threads) {
  if (num_threads >= 0 && num_threads <= kMaxThreads) return {};
  return Bad("num_threads", "must be in [0, " + std::to_string(kMaxThreads) + "]");
}

}  // namespace

}  // namespace linesurf::api

namespace linesurf {
inline namespace v1 {

Status DetectOptions::Validate() const noexcept {
  if (Status s = api::ValidateDetection(detection); !s) return s;
  if (Status s = api::ValidateThreads(num_threads); !s) return s;
  return {};
}

Status ReconstructOptions::Validate() const noexcept {
  using api::Bad;
  if (!PlaneSourceName(planes)[0]) return Bad("planes", "is not a PlaneSource");
  if (planes == PlaneSource::kDetect) {
    if (Status s = api::ValidateDetection(detection); !s) return s;
  }
  if (!SceneModeName(scene_mode)[0]) return Bad("scene_mode", "is not a SceneMode");
  if (Status s = api::ValidateWeights(weights); !s) return s;
  if (sigma && !(std::isfinite(*sigma) && *sigma > 0.0)) return Bad("sigma", "must be > 0");
  if (!(samples_per_sigma > 0.0 && samples_per_sigma <= 1000.0)) {
    return Bad("samples_per_sigma", "must be in (0, 1000]");
  }
  if (!SolverBackendName(solver.backend)[0]) return Bad("solver.backend", "is not a SolverBackend");
  if (!(std::isfinite(solver.time_limit_seconds) && solver.time_limit_seconds >= 0.0)) {
    return Bad("solver.time_limit_seconds", "must be finite and >= 0");
  }
  if (!ComplexEngineName(engine)[0]) return Bad("engine", "is not a ComplexEngine");
  if (Status s = api::ValidateBlocks(engine, block_size, block_margin); !s) return s;
  if (Status s = api::ValidateMergeCoplanar(engine, merge_coplanar, triangulate); !s) return s;
  if (!(box_margin > 0.0 && box_margin <= 10.0)) return Bad("box_margin", "must be in (0, 10]");
  if (Status s = api::ValidateQuality(quality); !s) return s;
  if (Status s = api::ValidateThreads(num_threads); !s) return s;
  return {};
}

}  // namespace v1
}  // namespace linesurf
