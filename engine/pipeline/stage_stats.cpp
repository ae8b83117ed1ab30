#include "engine/pipeline/stage_stats.h"

#include "engine/pipeline/stage_timer.h"

#include <algorithm>
#include <array>
#include <cstdint>

namespace linesurf::pipeline {
namespace {

/// Segments on 0, 1 and 2 planes.
std::array<std::size_t, 3> SegmentsWithPlanes(const Scene& scene) {
  std::array<std::size_t, 3> counts{};
  if (!scene.HasMemberships()) {
    counts[0] = scene.NumSegments();
    return counts;
  }
  for (const PlaneMembership& m : scene.memberships) ++counts[std::min<std::size_t>(m.count, 2)];
  return counts;
}

}  // namespace

FrameStats MakeFrameStats(const DataFrame& frame) {
  FrameStats s;
  s.aligned = frame.found;
  for (int axis = 0; axis < 3; ++axis) {
    for (int k = 0; k < 3; ++k) s.axes[axis][k] = frame.axes(k, axis);
  }
  for (int k = 0; k < 3; ++k) s.up[k] = frame.up[k];
  s.up_evidence = UpEvidenceName(frame.up_evidence);
  s.up_sign = frame.up_sign_reason;
  s.axis_share = frame.axis_share;
  return s;
}

InputStats MakeInputStats(const SanitizeStats& sanitation, const Scene& scene) {
  return {.input_segments = sanitation.input_segments,
          .segments = scene.NumSegments(),
          .viewpoints = scene.viewpoints.size(),
          .observations = scene.observations.NumItems()};
}

DetectionStats MakeDetectionStats(const DetectedScene& detected) {
  return {.planes = detected.scene.planes.size(),
          .capped_blocks = static_cast<std::size_t>(detected.detection_stats.capped_blocks),
          .segments_with_planes = SegmentsWithPlanes(detected.scene),
          .detection_block_size = detected.detection_block_size,
          .epsilon = detected.detection_stats.epsilon_estimate};
}

DetectionStats MakeDetectionStats(const Scene& scene, EpsilonEstimate epsilon) {
  return {.planes = scene.planes.size(),
          .capped_blocks = 0,
          .segments_with_planes = SegmentsWithPlanes(scene),
          .detection_block_size = 0.0,
          .epsilon = std::move(epsilon)};
}

ComplexStats MakeComplexStats(const BlockPartition& partition,
                              const BlockPartitionOptions& options,
                              std::size_t scene_planes) {
  const BlockPartitionStats& ps = partition.stats;
  const partition::BlockComplexes& bc = partition.complexes;
  ComplexStats out;
  out.planes_in_complex = scene_planes - ps.planes_without_inliers;
  out.blocks = bc.blocks.size();
  out.seam_facets = bc.stats.seam_facets;
  out.crowded_split_faces = ps.crowded_split_faces;
  out.crowded_blocks = ps.crowded_blocks_left;
  for (const partition::BlockComplex& b : bc.blocks) {
    out.cells += b.complex.NumCells();
    out.facets += b.complex.NumFacets();
    out.edges += b.complex.NumEdges();
    out.vertices += b.complex.NumVertices();
  }
  // One engine underneath; the report names the partition the options asked for.
  out.engine =
      ComplexEngineName(options.one_block ? ComplexEngine::kMonolithic : ComplexEngine::kBlocks);
  out.block_size = ps.block_size;
  out.block_size_automatic = ps.automatic_size;
  if (ps.automatic_size) {
    out.mean_segments_per_block = ps.size_choice.mean_segments_per_block;
    out.mean_planes_per_block = ps.size_choice.mean_planes_per_block;
    out.block_size_at_floor = ps.size_choice.limited_by_length;
  }
  return out;
}

SceneModeStats MakeSceneModeStats(const ResultFacts& facts) {
  return {.scene_mode = facts.interior ? "interior" : "exterior",
          .scene_mode_reason = facts.auto_mode ? facts.decision.reason : std::string()};
}

EnergyStats MakeEnergyStats(const EvidenceResult& evidence) {
  return {.pair_terms = evidence.energy.NumPairs(),
          .structural_groups = evidence.energy.NumStructuralGroups(),
          .parity_groups = evidence.energy.NumParityGroups(),
          .fixed_cells = evidence.stats.fixed_cells,
          .sigma = evidence.stats.sigma,
          .crease_weight = evidence.stats.crease_weight};
}

LabelingStats MakeLabelingStats(const solver::LabelingResult& labeling) {
  return {.full_cells = static_cast<std::size_t>(
              std::count(labeling.labels.begin(), labeling.labels.end(), std::uint8_t{1})),
          .lp_variables = labeling.lp_columns,
          .lp_constraints = labeling.lp_rows,
          .lp_nonzeros = labeling.lp_nonzeros,
          .solver_backend = solver::BackendReportName(labeling),
          .labeling_method = labeling.method,
          .solver_status = labeling.status,
          .objective = labeling.labels_objective,
          .rounded_objective = labeling.rounded_objective,
          .relaxed_objective = labeling.relaxed_objective,
          .lower_bound = labeling.lower_bound,
          .lower_bound_source = labeling.lower_bound_source,
          .fractional_cells = labeling.fractional_cells};
}

SurfaceStats MakeSurfaceStats(const PolygonMesh& mesh,
                              const MeshTopology& topology,
                              const ExtractStats& extraction,
                              const PinchRepairStats& repair) {
  return {.mesh_vertices = mesh.vertices.size(),
          .mesh_faces = mesh.NumFaces(),
          .mesh_closed = topology.paired,
          .mesh_manifold = topology.IsManifold(),
          .mesh_volume = topology.signed_volume,
          .split_vertices = extraction.split_vertices,
          .pinch_cells_relabelled = repair.flipped_cells,
          .split_points = repair.split_points,
          .pinch_energy_increase = repair.energy_increase};
}

FragmentStats MakeFragmentStats(const FragmentRemoval& removal) {
  return {.removed_fragments = removal.removed_components,
          .removed_fragment_volume = removal.removed_volume,
          .removed_fragment_segments = removal.removed_supported_segments};
}

QualityStats MakeQualityStats(SurfaceQuality figures) {
  return QualityStats{std::move(figures), true};
}

ResourceStats MakeResourceStats(std::vector<std::pair<std::string, double>> stage_seconds) {
  double total = 0.0;
  for (const auto& stage : stage_seconds) total += stage.second;
  return {.stage_seconds = std::move(stage_seconds),
          .total_seconds = total,
          .peak_memory_bytes = PeakRssBytes()};
}

}  // namespace linesurf::pipeline
