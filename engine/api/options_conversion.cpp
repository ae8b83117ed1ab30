#include "engine/api/options_conversion.h"

namespace linesurf::api {

PlaneDetectionOptions ToEngineOptions(const DetectionParameters& detection, std::uint64_t seed) {
  PlaneDetectionOptions o;
  static_cast<DetectionParameters&>(o) = detection;
  o.seed = seed;
  return o;
}

pipeline::ReconstructOptions ToEngineOptions(const ReconstructOptions& options) {
  pipeline::ReconstructOptions o;
  o.planes = ToEngineOptions(options.detection, options.seed);
  o.use_given_planes = options.plane_source == PlaneSource::kGiven;
  o.energy.weights = options.weights;
  o.energy.sigma = options.sigma;
  o.energy.samples_per_sigma = options.samples_per_sigma;
  o.energy.structural_as_textural = options.structural_as_textural;
  o.solver.backend = options.solver.backend;
  o.solver.time_limit_seconds = options.solver.time_limit_seconds;
  o.scene_mode = options.scene_mode;
  o.blocks.one_block = options.engine == ComplexEngine::kMonolithic;
  o.blocks.block_size = options.block_size;
  o.blocks.support.margin_blocks = options.block_margin;
  o.box_margin = options.box_margin;
  o.measure_quality = options.measure_quality;
  o.remove_floating_fragments = options.remove_floating_fragments;
  o.repair_pinches = options.repair_pinches;
  o.quality = options.quality;
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

}  // namespace linesurf::api
