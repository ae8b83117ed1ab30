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

/// Where the inlier tolerance eps of a run came from (docs/design/plane_detection.md, eps auto).
struct EpsilonEstimate {
  double epsilon = 0.0;  ///< scene units
  /// "given" (DetectionParameters::epsilon), "relative" (x scene diagonal), "planes" (residuals
  /// of the scene's own planes), "probe" (residuals of probe detections) or "none" (no segment
  /// of positive length: eps 1, nothing to detect).
  std::string source;
  /// Robust noise scale 1.4826 x median |endpoint-to-plane distance| (0 unless estimated).
  double noise_scale = 0.0;
  double initial_epsilon = 0.0;  ///< eps_0 of the probes (0 unless probed)
  int rounds = 0;                ///< probe detections run
  std::size_t residuals = 0;     ///< endpoint distances the scale was taken from
};

/// One connected component of a surface (SurfaceQuality).
struct ComponentQuality {
  std::size_t faces = 0;
  /// Signed volume (positive when outward, negative for a cavity or an interior scene's room).
  double volume = 0.0;
  /// Length of supported-segment samples within the fit distance whose nearest face is here.
  double supported_length = 0.0;
  /// Supported segments whose greater share of near samples lies on this component.
  std::size_t supported_segments = 0;
  /// Distinct lines among them (collinear parts of one line count once).
  std::size_t supported_lines = 0;
  /// Holds fewer than QualityOptions::min_lines_per_component lines.
  bool floating = false;
};

/// Quality of a surface without ground truth (docs/user/evaluation.md): fit to the segments that
/// support a plane, sight rays not blocked, components and floating fragments.
struct SurfaceQuality {
  double epsilon = 0.0;                ///< eps the figures were measured with (scene units)
  double fit_distance = 0.0;           ///< fit_factor x eps
  std::size_t supported_segments = 0;  ///< segments on at least one plane
  double supported_length = 0.0;       ///< their total length
  /// Share of the supported length within fit_distance of the surface, [0, 1].
  double data_fit = 0.0;
  /// Share of the (supported segment, viewpoint) sight-ray length not blocked by the surface
  /// before the segment, [0, 1]; 1 without views. A ray to a sample is blocked by a face it
  /// crosses unless the sample lies within fit_distance of that face's plane (the face it lies
  /// on: noise must not count as occlusion, even for grazing rays).
  double visibility_consistency = 0.0;
  /// The same over every segment with views (outliers included).
  double visibility_consistency_all = 0.0;
  /// Components, largest |volume| first (ties by first face).
  std::vector<ComponentQuality> components;
  double enclosed_volume = 0.0;          ///< sum of the components' |volume|
  double largest_component_share = 0.0;  ///< |volume| of the largest / enclosed_volume
  std::size_t floating_fragments = 0;
  /// Planes (indices into the result's planes) on which no face of positive area lies (all its
  /// vertices within eps), ascending.
  std::vector<std::uint32_t> planes_off_surface;
};

/// Numbers of a reconstruction (docs/design/reconstruction.md explains each). The engine fills this
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
  std::size_t capped_blocks = 0;  ///< detection blocks that stopped at max_planes, unsplit
  /// The eps of detection (or, with given planes, of the quality figures) and how it was chosen.
  EpsilonEstimate epsilon;
  std::array<std::size_t, 3> segments_with_planes{};  ///< on 0, 1, 2 planes
  std::size_t planes_in_complex = 0;                  ///< planes that split the box
  std::string engine;           ///< the cell complex: "monolithic" or "blocks"
  double block_size = 0.0;      ///< base block side (blocks engine; 0 for monolithic)
  /// Whether the size rule chose block_size (blocks engine with block_size 0), and its figures
  /// at the size it chose, before block_size was moved off planes parallel to the faces: means
  /// over the occupied blocks, and whether a target was still missed at the rule's floor of
  /// min_block_lengths median segment lengths (docs/design/block_engine.md 1). 0 / false when
  /// the size is given.
  bool block_size_automatic = false;
  double mean_segments_per_block = 0.0;
  double mean_planes_per_block = 0.0;
  bool block_size_at_floor = false;
  double detection_block_size = 0.0;  ///< detection cube side (0 = the whole scene at once)
  std::size_t blocks = 0;       ///< base blocks (1 for monolithic)
  std::size_t seam_facets = 0;  ///< facets of the seam overlay (blocks engine)
  /// Faces added to the automatic grid to cut blocks crowded with planes, and the blocks still
  /// crowded after the last round (blocks engine).
  std::size_t crowded_split_faces = 0;
  std::size_t crowded_blocks = 0;
  std::size_t cells = 0;
  std::size_t facets = 0;
  std::size_t edges = 0;
  std::size_t vertices = 0;
  std::string scene_mode;         ///< "exterior" or "interior" (resolved)
  std::string scene_mode_reason;  ///< why, for SceneMode::kAuto
  double sigma = 0.0;             ///< the scale used
  double crease_weight = 0.0;     ///< the crease weight used (resolved for the scene mode)
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
  /// Floating fragments removed from the surface (ReconstructOptions::remove_floating_fragments),
  /// their total volume and the supported segments they held. full_cells and split_vertices
  /// describe the labelling's surface before the removal.
  std::size_t removed_fragments = 0;
  double removed_fragment_volume = 0.0;
  std::size_t removed_fragment_segments = 0;
  /// Figures without ground truth (valid when quality_measured; see
  /// ReconstructOptions::measure_quality).
  SurfaceQuality quality;
  bool quality_measured = false;
  std::size_t peak_memory_bytes = 0;  ///< process peak RSS at the end of the run
};

/// What a mesh is as the boundary of solids: the classes of ISO 19107 / val3dity that GIS and
/// BIM validators check (docs/user/formats.md, "Validity"). Connectivity is by vertex index: two
/// vertices at one position are two vertices, counted in num_coincident_vertices. CheckMesh
/// fills it; Reconstruct refuses a result that is not closed, 2-manifold at its edges, oriented,
/// free of degenerate and non-planar faces and of self-intersection, and warns of the rest.
struct MeshValidity {
  /// No boundary edge: every undirected edge is used by exactly two faces (and the mesh has faces).
  bool closed = false;
  /// Every edge is used by at most two faces and the faces around every vertex form one fan.
  bool two_manifold = false;
  /// Every edge used by two faces is traversed once in each direction.
  bool oriented = false;
  /// Closed, oriented and with positive signed volume (normals point outwards).
  bool outward = false;
  /// num_intersecting_triangle_pairs > 0.
  bool self_intersecting = false;
  /// Connected components, faces linked through shared edges.
  std::size_t num_components = 0;
  std::size_t num_faces = 0;
  std::size_t num_vertices = 0;
  /// Vertices at the bit-identical position of another vertex (split where parts touch).
  std::size_t num_coincident_vertices = 0;
  std::size_t num_boundary_edges = 0;
  std::size_t num_non_manifold_edges = 0;    ///< used by more than two faces
  std::size_t num_non_manifold_vertices = 0;  ///< whose incident faces form several fans
  std::size_t num_degenerate_faces = 0;       ///< fewer than 3 distinct vertices, or one twice
  /// Faces thinner than 1e-9 of the bounding-box diagonal (twice the area over the longest
  /// edge): zero-area faces up to the rounding of their vertices.
  std::size_t num_zero_area_faces = 0;
  /// Faces with a vertex farther than 1e-9 of the bounding-box diagonal from the plane of the
  /// face (Newell's normal through the centroid).
  std::size_t num_non_planar_faces = 0;
  /// Pairs of triangles of the triangulated faces that intersect other than at a shared edge
  /// or vertex (CGAL self_intersections), and have no corner position in common.
  std::size_t num_intersecting_triangle_pairs = 0;
  /// Pairs that meet at a corner position without sharing the vertex (coincident copies):
  /// parts touching at split vertices.
  std::size_t num_touching_triangle_pairs = 0;
  /// Signed volume enclosed (divergence theorem over the faces); meaningful when closed.
  double signed_volume = 0.0;
  double area = 0.0;

  /// Every class clear: closed, 2-manifold, oriented, and no count above is non-zero.
  [[nodiscard]] bool IsValid() const noexcept {
    return num_faces > 0 && closed && two_manifold && oriented && !self_intersecting &&
           num_coincident_vertices == 0 && num_degenerate_faces == 0 &&
           num_zero_area_faces == 0 && num_non_planar_faces == 0 &&
           num_touching_triangle_pairs == 0;
  }
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
  std::size_t segments = 0;          ///< after sanitation
  std::int64_t lines = 0;            ///< distinct lines (collinear parts merged)
  double epsilon = 0.0;              ///< the eps used
  EpsilonEstimate epsilon_estimate;  ///< how it was chosen
  std::int64_t blocks = 0;
  std::int32_t planes_before_fusion = 0;
  std::int32_t planes = 0;
  std::int32_t merges = 0;
  std::int64_t memberships_dropped = 0;  ///< by the at-most-2 rule across blocks
  std::int64_t capped_blocks = 0;        ///< blocks stopped at max_planes, unsplit
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
  /// Sanitation warnings, then the plane-cap warning when a block stopped at max_planes.
  std::vector<std::string> warnings;
};

/// Result of DetectScenePlanes.
struct DetectedScene {
  /// The sanitised scene holding the detected planes and memberships (the input's own planes
  /// dropped), world coordinates, residuals and extra fields kept: what `linesurf detect -o`
  /// writes.
  SceneData scene;
  /// The planes, support, memberships (indexing the input segments), stats and warnings, as
  /// DetectPlanes returns them.
  DetectResult detection;
  /// Planes the input carried (ignored by detection).
  std::size_t given_planes = 0;
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
