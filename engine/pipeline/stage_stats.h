#pragma once
// The public numbers of each stage (linesurf/stats.h) from that stage's own result: one function
// per stage struct, the one place where the pipeline fills it (docs/design/options_and_reports.md,
// "Stats layout and versions").

#include "linesurf/options.h"
#include "linesurf/stats.h"

#include "engine/core/polygon_mesh.h"
#include "engine/core/scene.h"
#include "engine/pipeline/block_partition.h"
#include "engine/pipeline/evidence.h"
#include "engine/pipeline/detect_scene_planes.h"
#include "engine/pipeline/extract_block_surface.h"
#include "engine/pipeline/judge_result.h"
#include "engine/pipeline/mesh_topology.h"
#include "engine/pipeline/pinch_repair.h"
#include "engine/pipeline/sanitize_scene.h"
#include "engine/pipeline/surface_quality.h"
#include "solver/lp/lp_backend.h"

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace linesurf::pipeline {

/// The segments sanitation read, and what the sanitised scene (with its planes) holds.
/// The frame of the run, in the input's axes.
[[nodiscard]] FrameStats MakeFrameStats(const DataFrame& frame);

[[nodiscard]] InputStats MakeInputStats(const SanitizeStats& sanitation, const Scene& scene);

/// Detected planes: the planes and memberships of the detected scene, its capped blocks, cube
/// side and eps.
[[nodiscard]] DetectionStats MakeDetectionStats(const DetectedScene& detected);
/// Given planes: those of the sanitised `scene` and the eps ResolveEpsilon chose for it.
[[nodiscard]] DetectionStats MakeDetectionStats(const Scene& scene, EpsilonEstimate epsilon);

/// The partition of a scene with `scene_planes` planes, built with `options`: its blocks, the
/// size rule's figures (when it chose the size) and the complexes' sizes summed over the blocks.
[[nodiscard]] ComplexStats MakeComplexStats(const BlockPartition& partition,
                                            const BlockPartitionOptions& options,
                                            std::size_t scene_planes);

/// The resolved boundary condition, and the decision's reason when the mode was automatic.
[[nodiscard]] SceneModeStats MakeSceneModeStats(const ResultFacts& facts);

/// The energy's terms and the scale and crease weight the evidence used.
[[nodiscard]] EnergyStats MakeEnergyStats(const EvidenceResult& evidence);

/// The LP's size, the backend, its status and objectives, and the cells labelled full.
[[nodiscard]] LabelingStats MakeLabelingStats(const solver::LabelingResult& labeling);

/// The surface returned (`mesh`, its topology by vertex index), the extraction's split vertices (of the
/// labels' surface, before fragments are removed) and what the pinch repair changed.
[[nodiscard]] SurfaceStats MakeSurfaceStats(const PolygonMesh& mesh,
                                            const MeshTopology& topology,
                                            const ExtractStats& extraction,
                                            const PinchRepairStats& repair);

/// The floating fragments RemoveFloatingFragments dropped.
[[nodiscard]] FragmentStats MakeFragmentStats(const FragmentRemoval& removal);

/// Measured figures.
[[nodiscard]] QualityStats MakeQualityStats(SurfaceQuality figures);

/// The stages' wall times in run order, their sum, and the process's peak memory now.
[[nodiscard]] ResourceStats MakeResourceStats(
    std::vector<std::pair<std::string, double>> stage_seconds);

}  // namespace linesurf::pipeline
