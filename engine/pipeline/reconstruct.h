#pragma once
/// @file reconstruct.h
/// @brief The whole method on one box (DESIGN 2): sanitise -> planes (detected or given) -> box
/// -> cell complex -> evidence -> LP labelling -> surface. See docs/reconstruction.md.
///
/// Every stage works on one box with no global state, so the block engine (DESIGN 3) can call
/// the per-box stages (BuildCellComplex, ComputeEvidence, SolveLabeling, ExtractSurface) itself.

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "engine/core/polygon_mesh.h"
#include "engine/core/run_context.h"
#include "engine/core/scene.h"
#include "engine/detect/detect_planes.h"
#include "engine/pipeline/compute_evidence.h"
#include "engine/pipeline/sanitize_scene.h"
#include "engine/pipeline/surface_quality.h"
#include "linesurf/error.h"
#include "partition/arrangement/build_cell_complex.h"
#include "solver/lp/lp_backend.h"

namespace linesurf::pipeline {

/// Boundary condition of the scene (see DecideSceneMode for kAuto).
enum class SceneMode {
  kExterior,  ///< an object seen from outside: cells on the box are empty
  kInterior,  ///< a room seen from inside: cells on the box are full
  kAuto,      ///< decided from the viewpoints and planes (decide_scene_mode.h)
};

/// "exterior", "interior" or "auto".
const char* SceneModeName(SceneMode mode) noexcept;

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
  SceneMode scene_mode = SceneMode::kAuto;
  /// The box is the bounding box of the segments and viewpoints grown on each side by this
  /// fraction of its extent along that axis (at least this fraction of its diagonal). Range
  /// (0, 10]. Default 0.05, as the reference, so viewpoints lie in bounded cells.
  double box_margin = 0.05;
  /// Measure the surface against the segments (surface_quality.h) and report it in
  /// RunStats::quality. Default true.
  bool measure_quality = true;
  SurfaceQualityOptions quality;
  /// Triangulate the output faces (default: convex polygons).
  bool triangulate = false;
  /// Worker threads: 0 = automatic, 1 = serial. Results do not depend on it.
  int num_threads = 0;
  /// Seed of every random stream (plane detection); same input + options + seed => same mesh.
  std::uint64_t seed = 0;

  /// Names the first offending field (including the nested options).
  [[nodiscard]] Status Validate() const;
};

/// Numbers of a run (docs/reconstruction.md lists the report keys).
struct RunStats {
  /// (stage, wall seconds) in run order: sanitize, detect, complex, evidence, solve, extract.
  std::vector<std::pair<std::string, double>> stage_seconds;
  double total_seconds = 0.0;
  std::size_t input_segments = 0;
  std::size_t segments = 0;  ///< after sanitation
  std::size_t viewpoints = 0;
  std::size_t observations = 0;
  std::size_t planes = 0;
  std::size_t capped_blocks = 0;  ///< detection blocks that stopped at max_planes
  /// The eps of detection (or, with given planes, of the quality figures) and how it was chosen.
  EpsilonEstimate epsilon;
  std::size_t segments_with_planes[3] = {0, 0, 0};  ///< on 0, 1, 2 planes
  std::size_t planes_in_complex = 0;                ///< planes that split the box
  std::size_t cells = 0;
  std::size_t facets = 0;
  std::size_t edges = 0;
  std::size_t vertices = 0;
  std::string scene_mode;         ///< "exterior" or "interior" (resolved)
  std::string scene_mode_reason;  ///< why, for kAuto
  double sigma = 0.0;
  std::size_t pair_terms = 0;
  std::size_t structural_groups = 0;
  std::size_t parity_groups = 0;
  std::size_t fixed_cells = 0;
  std::size_t lp_variables = 0;    ///< LP columns after fixed cells are substituted
  std::size_t lp_constraints = 0;  ///< LP rows
  std::size_t lp_nonzeros = 0;
  std::string solver_backend;
  std::string solver_status;
  double objective = 0.0;          ///< energy of the labels (after rounding and improvement)
  double relaxed_objective = 0.0;  ///< energy of the relaxed solution (LP optimum for clp)
  double rounded_objective = 0.0;  ///< energy of the labels right after rounding
  /// Best proven lower bound on the integral optimum (-inf: none) and what proves it
  /// (solver::LabelingResult::lower_bound_source).
  double lower_bound = 0.0;
  std::string lower_bound_source;
  std::string labeling_method;  ///< solver::LabelingResult::method
  std::size_t fractional_cells = 0;
  std::size_t full_cells = 0;
  std::size_t mesh_vertices = 0;
  std::size_t mesh_faces = 0;
  bool mesh_closed = false;
  bool mesh_manifold = false;
  double mesh_volume = 0.0;  ///< signed, positive when outward (exterior)
  std::size_t split_vertices = 0;
  /// Figures without ground truth (local frame; valid when quality_measured).
  SurfaceQuality quality;
  bool quality_measured = false;
  std::size_t peak_memory_bytes = 0;  ///< process peak RSS at the end of the run
};

struct ReconstructResult {
  /// The surface in world coordinates, faces oriented from full to empty space.
  PolygonMesh mesh;
  /// The planes used (world coordinates), and each sanitised segment's memberships.
  IdVector<PlaneId, Plane3> planes;
  RunStats stats;
  /// Sanitation, detection, complex and evidence warnings, one sentence each.
  std::vector<std::string> warnings;
  Rigid3 world_from_local;
};

/// @brief Reconstructs the surface of `scene` (world coordinates).
/// @return the stage's error: kInvalidOptions, kInvalidInput (nothing usable, no given planes),
/// kDegenerate, kSolverFailed, kResourceExhausted, kCancelled. Never throws.
/// Deterministic: same scene, options and seed give the same mesh for every num_threads.
[[nodiscard]] Expected<ReconstructResult> Reconstruct(const Scene& scene,
                                                      const ReconstructOptions& options,
                                                      const RunContext& ctx) noexcept;

}  // namespace linesurf::pipeline
