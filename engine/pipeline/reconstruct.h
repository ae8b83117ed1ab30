#pragma once
/// @file reconstruct.h
/// @brief The whole method, one path for every scene: sanitise -> planes (detected or given) ->
/// box -> block partition (one block or several) -> evidence -> LP labelling -> surface. See
/// docs/design/reconstruction.md and docs/design/block_engine.md.

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "engine/core/polygon_mesh.h"
#include "engine/core/run_context.h"
#include "engine/core/scene.h"
#include "engine/detect/detect_planes.h"
#include "engine/pipeline/block_partition.h"
#include "engine/pipeline/evidence.h"
#include "engine/pipeline/judge_result.h"
#include "engine/pipeline/sanitize_scene.h"
#include "engine/pipeline/surface_quality.h"
#include "linesurf/error.h"
#include "linesurf/options.h"
#include "linesurf/result.h"
#include "partition/arrangement/build_cell_complex.h"
#include "solver/lp/lp_backend.h"

#include <optional>

namespace linesurf::pipeline {

/// Boundary condition of the scene (see DecideSceneMode for kAuto): the public enum.
using SceneMode = ::linesurf::SceneMode;

/// How an options struct spells the block fields, for the messages of ValidateOneBlockSize
/// (the engine's spelling by default; the facade passes its own).
struct BlockFieldNames {
  const char* block_size = "blocks.block_size";            ///< the partition's block side
  const char* detection_block_size = "planes.block_size";  ///< per-block detection's cube side
};

/// The rule tying the partition's block side to the one-block partition, for every options
/// layer: a block side (0 = automatic) is given only to a partition of several blocks, since one
/// block is the whole box; per-block detection has its own cube side, which the message points
/// to.
[[nodiscard]] Status ValidateOneBlockSize(bool one_block,
                                          double block_size,
                                          const BlockFieldNames& names = {});

/// The rule for merging coplanar faces, for every options layer: merged faces may be
/// non-convex, so not with triangulate.
[[nodiscard]] Status ValidateMergeCoplanar(bool merge_coplanar, bool triangulate);

struct ReconstructOptions {
  SanitizeOptions sanitize;
  /// Plane detection (ignored with use_given_planes). Its seed is replaced by `seed`.
  PlaneDetectionOptions planes;
  /// Use the scene's planes and memberships instead of detecting planes (fails when the scene
  /// has none).
  bool use_given_planes = false;
  EnergyOptions energy;
  solver::LabelingOptions solver;
  partition::CellComplexOptions complex;
  /// Block size (0 = the size rule) or one block, size rule and support margin of the
  /// partition; its `complex` is replaced by `complex` above. A block size with one block is an
  /// error (kInvalidOptions). Detection does not use it: its blocks are planes.block_size, or
  /// with planes.block_size 0 those that `detection_blocks` picks (blocks as small as the partition's miss planes: on synth house at
  /// 3 m blocks detection found 4 planes of 10 and the solid closed on block faces).
  BlockPartitionOptions blocks;
  /// planes.block_size 0: the detection cube side, by segments alone (the whole
  /// scene when it fits one block). 4,000 segments keep a block's planes under max_planes'
  /// default of 160 on the synthetic cities (about 8 planes per 270 segments).
  partition::BlockSizeRule detection_blocks = {
      .ladder = partition::BlockSizeLadder::kHalvingsOfTheExtent,
      .target_segments_per_block = 4000.0,
      .target_planes_per_block = 1e9,
      .min_block_lengths = 8.0};
  SceneMode scene_mode = SceneMode::kAuto;
  /// The box is the bounding box of the segments and viewpoints grown on each side by this
  /// fraction of its extent along that axis (an axis under 1 % of the largest extent counts as
  /// that thick: SceneBox). Range (0, 10]. Default 0.05, as the reference, so viewpoints lie in
  /// bounded cells.
  double box_margin = 0.05;
  /// Measure the surface against the segments (surface_quality.h) and report it in
  /// RunStats::quality. Default true.
  bool measure_quality = true;
  SurfaceQualityOptions quality;
  /// Drop the surface's floating fragments (solid components holding fewer than
  /// quality.min_lines_per_component supported lines, RemoveFloatingFragments) when another
  /// component holds more; RunStats::fragments counts them. Default true: pieces behind
  /// one or two lines (clutter, vegetation) are not the building (docs/design/reconstruction.md).
  bool remove_floating_fragments = true;
  /// Repair the surface's pinches (pinch_repair.h, at most kPinchRepairRounds extractions more).
  bool repair_pinches = true;
  /// Triangulate the output faces (default: convex polygons).
  bool triangulate = false;
  /// Neighbouring faces of one plane with one outward side (split by block faces
  /// or by planes without surface there) become one polygon (ExtractOptions::merge_coplanar),
  /// which may be non-convex; not with triangulate.
  /// Default false: the blocks' facets.
  bool merge_coplanar = false;
  /// Worker threads: 0 = automatic, 1 = serial. Results do not depend on it.
  int num_threads = 0;
  /// Seed of every random stream (plane detection); same input + options + seed => same mesh.
  std::uint64_t seed = 0;

  /// Names the first offending field (including the nested options).
  [[nodiscard]] Status Validate() const;
};

/// Numbers of a run (docs/design/reconstruction.md lists the report keys): the public struct.
using RunStats = ::linesurf::ReconstructStats;

struct ReconstructResult {
  /// The surface in world coordinates, faces oriented from full to empty space.
  PolygonMesh mesh;
  /// The planes used (world coordinates).
  IdVector<PlaneId, Plane3> planes;
  /// Each sanitised segment's memberships (into `planes`), and its id in the input scene.
  IdVector<SegmentId, PlaneMembership> memberships;
  IdVector<SegmentId, SegmentId> input_segment;
  RunStats stats;
  /// Sanitation, detection, complex and evidence warnings, one sentence each.
  std::vector<std::string> warnings;
  Rigid3 world_from_local;
};

/// What a reconstruction computes before the evidence: the sanitised scene (local frame) with
/// its planes, the block partition of the box, and the resolved boundary condition. It does not
/// depend on the energy weights, so one preparation serves several solves.
struct PreparedReconstruction {
  Scene scene;
  /// Per segment of `scene`, its id in the input scene.
  IdVector<SegmentId, SegmentId> input_segment;
  /// The block partition of the box and its complexes (one block or several).
  BlockPartition blocks;
  /// What the result checks (JudgeResult) need from the preparation; `interior` is the
  /// resolved boundary condition.
  ResultFacts facts;
  /// Filled up to the scene mode: inputs, detection, complex, scene, and the stage times of
  /// sanitize, detect, complex and scene_mode (resources.stage_seconds).
  RunStats stats;
  std::vector<std::string> warnings;
};

/// @brief The stages up to the cell complex (sanitise, planes, box, complex, scene mode).
/// `runner`, when given, runs the per-block RANSAC of detection (detect/detection_run.h).
/// @return kInvalidOptions, kInvalidInput, kDegenerate, kResourceExhausted, kCancelled.
[[nodiscard]] Expected<PreparedReconstruction> PrepareReconstruction(
    const Scene& scene,
    const ReconstructOptions& options,
    const RunContext& ctx,
    detect::DetectionRunner* runner = nullptr) noexcept;

/// @brief The stages from the evidence on (evidence, LP labelling, surface) with the energy,
/// solver and output options of `options`; the preparation's own options are not consulted.
/// Solving a preparation with the options it was prepared with gives exactly Reconstruct's
/// result.
/// @return kInvalidOptions, kSolverFailed, kResourceExhausted, kCancelled.
[[nodiscard]] Expected<ReconstructResult> SolvePrepared(const PreparedReconstruction& prepared,
                                                        const ReconstructOptions& options,
                                                        const RunContext& ctx) noexcept;

/// @brief Reconstructs the surface of `scene` (world coordinates): PrepareReconstruction, then
/// SolvePrepared.
/// @return the stage's error: kInvalidOptions, kInvalidInput (nothing usable, no given planes),
/// kDegenerate, kSolverFailed, kResourceExhausted, kCancelled. Never throws.
/// Deterministic: same scene, options and seed give the same mesh for every num_threads, and
/// for any `runner` (PrepareReconstruction).
[[nodiscard]] Expected<ReconstructResult> Reconstruct(
    const Scene& scene,
    const ReconstructOptions& options,
    const RunContext& ctx,
    detect::DetectionRunner* runner = nullptr) noexcept;

}  // namespace linesurf::pipeline
