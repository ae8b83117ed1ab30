#pragma once
/// @file result.h
/// @brief Results of the facade calls: they own their data and carry their numbers (stats) and
/// warnings ("412 segments dropped: zero or near-zero length"). World coordinates.

#include "linesurf/export.h"
#include "linesurf/types.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace linesurf {
inline namespace v1 {

/// Numbers of a reconstruction (docs/reconstruction.md explains each). The engine fills this
/// very struct (pipeline::RunStats), so no number is lost on the way out.
struct ReconstructStats {
  /// (stage, wall seconds) in run order: sanitize, detect, complex, evidence, solve, extract.
  /// After Reconstruction::Solve: the preparation's stages (as measured by Prepare), then this
  /// solve's.
  std::vector<std::pair<std::string, double>> stage_seconds;
  double total_seconds = 0.0;
  std::size_t input_segments = 0;
  std::size_t segments = 0;  ///< after sanitation
  std::size_t viewpoints = 0;
  std::size_t observations = 0;
  std::size_t planes = 0;
  std::size_t capped_blocks = 0;  ///< detection blocks that stopped at max_planes
  std::array<std::size_t, 3> segments_with_planes{};  ///< on 0, 1, 2 planes
  std::size_t planes_in_complex = 0;                  ///< planes that split the box
  std::size_t cells = 0;
  std::size_t facets = 0;
  std::size_t edges = 0;
  std::size_t vertices = 0;
  std::string scene_mode;         ///< "exterior" or "interior" (resolved)
  std::string scene_mode_reason;  ///< why, for SceneMode::kAuto
  double sigma = 0.0;             ///< the scale used
  std::size_t pair_terms = 0;
  std::size_t structural_groups = 0;
  std::size_t parity_groups = 0;
  std::size_t fixed_cells = 0;
  std::size_t lp_variables = 0;  ///< LP columns after fixed cells are substituted
  std::size_t lp_constraints = 0;
  std::size_t lp_nonzeros = 0;
  std::string solver_backend;  ///< the backend that ran ("auto" resolved)
  std::string solver_status;
  double objective = 0.0;          ///< energy of the labels (after rounding and improvement)
  double relaxed_objective = 0.0;  ///< energy of the relaxed solution (LP optimum for clp)
  double rounded_objective = 0.0;  ///< energy of the labels right after rounding
  /// Best proven lower bound on the integral optimum (-inf: none) and what proves it.
  double lower_bound = 0.0;
  std::string lower_bound_source;
  std::string labeling_method;  ///< how the labels were obtained (solver's method)
  std::size_t fractional_cells = 0;
  std::size_t full_cells = 0;
  std::size_t mesh_vertices = 0;
  std::size_t mesh_faces = 0;
  bool mesh_closed = false;
  bool mesh_manifold = false;
  double mesh_volume = 0.0;  ///< signed; positive for an exterior solid
  std::size_t split_vertices = 0;
  std::size_t peak_memory_bytes = 0;  ///< process peak RSS at the end of the run
};

/// Result of Reconstruct and Reconstruction::Solve.
struct ReconstructResult {
  /// The closed, 2-manifold surface, faces oriented from full to empty space.
  Mesh mesh;
  /// The planes used (detected or the given ones that survived sanitation).
  std::vector<Plane> planes;
  /// Plane memberships: `segment` indexes the INPUT segments, `plane` indexes `planes`; sorted by
  /// segment, then plane. Segments dropped by sanitation have none.
  std::vector<Membership> memberships;
  ReconstructStats stats;
  /// Sanitation, detection, complex and evidence warnings, one sentence each.
  std::vector<std::string> warnings;
};

/// Support of one detected plane.
struct PlaneSupportInfo {
  std::uint32_t inlier_count = 0;
  double inlier_length = 0.0;  ///< total length of the inlier segments
};

/// Numbers of a plane detection.
struct DetectStats {
  std::size_t input_segments = 0;
  std::size_t segments = 0;  ///< after sanitation
  std::int64_t lines = 0;    ///< distinct lines (collinear parts merged)
  double epsilon = 0.0;      ///< the eps used
  std::int64_t blocks = 0;
  std::int32_t planes_before_fusion = 0;
  std::int32_t planes = 0;
  std::int32_t merges = 0;
  std::int64_t memberships_dropped = 0;  ///< by the at-most-2 rule across blocks
  std::int64_t segments_with_0_planes = 0;
  std::int64_t segments_with_1_plane = 0;
  std::int64_t segments_with_2_planes = 0;
  std::int64_t candidates_evaluated = 0;
  std::int64_t failed_draws = 0;
  double seconds = 0.0;
  double seconds_fusion = 0.0;
};

/// Result of DetectPlanes.
struct DetectResult {
  std::vector<Plane> planes;
  /// One per plane.
  std::vector<PlaneSupportInfo> support;
  /// `segment` indexes the INPUT segments; sorted by segment, then plane.
  std::vector<Membership> memberships;
  DetectStats stats;
  std::vector<std::string> warnings;
};

/// Result of SanitizeScene.
struct SanitizedScene {
  /// The repaired scene, world coordinates.
  SceneData scene;
  /// Per segment of `scene`, its index in the input (ascending).
  std::vector<std::uint32_t> input_segment;
  /// One sentence per kind of repair, e.g. "412 segments dropped: zero or near-zero length".
  std::vector<std::string> warnings;
};

/// Result of ReadScene.
struct ReadSceneResult {
  SceneData scene;
  /// What the reader fixed or ignored, one sentence each.
  std::vector<std::string> warnings;
};

}  // namespace v1
}  // namespace linesurf
