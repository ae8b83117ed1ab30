#pragma once
/// @file stats.h
/// @brief The numbers of a reconstruction, one struct per stage of the run, held by
/// ReconstructStats (result.h) in a versioned layout (docs/design/options_and_reports.md,
/// "Stats layout and versions"). Fields keep the names they had in the flat layout of
/// linesurf 1; the report (report.h) writes each struct with its own function, under the same
/// JSON keys as before. docs/design/reconstruction.md explains each number.

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace linesurf {
inline namespace v3 {

/// The version of the layout of ReconstructStats below. It moves with every change of the
/// layout (a field added at the end of a stage struct, a stage added at the end), and the
/// library's SOVERSION moves with it. 1 was the flat layout of linesurf 1.
inline constexpr int kStatsLayoutVersion = 3;

/// Where the inlier tolerance eps of a run came from (docs/design/plane_detection.md, eps auto).
struct EpsilonEstimate {
  double epsilon = 0.0;  ///< scene units
  /// "given" (DetectionParameters::epsilon), "relative" (x scene diagonal), "planes" (residuals
  /// of the scene's own planes), "probe" (residuals of probe detections) or "none" (no segment
  /// of positive length: eps 1, nothing to detect).
  std::string source;
  /// Noise scale of the endpoint-to-plane distances (0 unless estimated): "planes", 1.4826 x
  /// their median; "probe", the maximum-likelihood scale of the last probe's, truncated at its
  /// tolerance as its inlier test truncates them.
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

/// Inputs after sanitation (report: `counts`).
struct InputStats {
  std::size_t input_segments = 0;  ///< segments read
  std::size_t segments = 0;        ///< kept by sanitation
  std::size_t viewpoints = 0;      ///< kept by sanitation
  std::size_t observations = 0;    ///< (segment, viewpoint) pairs kept by sanitation
};

/// The planes, detected or given (report: `counts`, `detection_block_size`, `epsilon`).
/// DetectStats (result.h) is DetectPlanes' own, fuller account of a detection.
struct DetectionStats {
  std::size_t planes = 0;         ///< detected or given (after sanitation)
  std::size_t capped_blocks = 0;  ///< detection blocks that stopped at max_planes, unsplit
  /// Segments on 0, 1 and 2 planes (the scene's memberships after detection).
  std::array<std::size_t, 3> segments_with_planes{};
  double detection_block_size = 0.0;  ///< detection cube side (0 = the whole scene at once)
  /// The eps of detection (or, with given planes, of the quality figures) and how it was chosen.
  EpsilonEstimate epsilon;
};

/// The block partition and its cell complexes (report: `counts`, `engine`, `block_size`,
/// `block_size_rule`).
struct ComplexStats {
  std::size_t planes_in_complex = 0;  ///< planes that split the box (those with inliers)
  std::size_t blocks = 0;             ///< base blocks (1 for one block)
  std::size_t seam_facets = 0;        ///< facets of the seam overlay
  /// Faces added to the automatic grid to cut blocks crowded with planes, and the blocks still
  /// crowded after the last round.
  std::size_t crowded_split_faces = 0;
  std::size_t crowded_blocks = 0;
  /// Sizes of the complexes, summed over the blocks.
  std::size_t cells = 0;
  std::size_t facets = 0;
  std::size_t edges = 0;
  std::size_t vertices = 0;
  std::string engine;       ///< the partition asked for: "monolithic" (one block) or "blocks"
  double block_size = 0.0;  ///< base block side (for one block the box's largest extent)
  /// Whether the size rule chose block_size (blocks engine with block_size 0), and its figures
  /// at the size it chose, before block_size was moved off planes parallel to the faces: means
  /// over the occupied blocks, and whether a target was still missed at the rule's floor of
  /// min_block_lengths median segment lengths (docs/design/block_engine.md 1). 0 / false when
  /// the size is given.
  bool block_size_automatic = false;
  double mean_segments_per_block = 0.0;
  double mean_planes_per_block = 0.0;
  bool block_size_at_floor = false;
};

/// The boundary condition (report: `scene_mode`, `scene_mode_reason`).
struct SceneModeStats {
  std::string scene_mode;         ///< "exterior" or "interior" (resolved)
  std::string scene_mode_reason;  ///< why, for SceneMode::kAuto ("" when the mode was given)
};

/// The visibility evidence and its energy (report: `counts`, `sigma`, `crease_weight`).
struct EnergyStats {
  std::size_t pair_terms = 0;
  std::size_t structural_groups = 0;
  std::size_t parity_groups = 0;
  std::size_t fixed_cells = 0;  ///< cells whose label the boundary condition fixes
  double sigma = 0.0;           ///< the scale used
  double crease_weight = 0.0;   ///< the crease weight used (resolved for the scene mode)
};

/// The labelling of the cells (report: `counts`, `solver`).
struct LabelingStats {
  std::size_t full_cells = 0;
  std::size_t lp_variables = 0;  ///< LP columns after fixed cells are substituted
  std::size_t lp_constraints = 0;
  std::size_t lp_nonzeros = 0;
  std::string solver_backend;   ///< the backend that ran ("auto" resolved)
  std::string labeling_method;  ///< how the labels were obtained (solver's method)
  std::string solver_status;
  double objective = 0.0;          ///< energy of the labels (after rounding and improvement)
  double rounded_objective = 0.0;  ///< energy of the labels right after rounding
  double relaxed_objective = 0.0;  ///< energy of the relaxed solution (LP optimum for clp)
  /// Best proven lower bound on the integral optimum (-inf: none) and what proves it.
  double lower_bound = 0.0;
  std::string lower_bound_source;
  std::size_t fractional_cells = 0;  ///< cells the relaxed solution left non-integral
};

/// The output surface (report: `mesh`). split_vertices describes the labelling's surface,
/// before floating fragments are removed; the other figures the surface returned.
struct SurfaceStats {
  std::size_t mesh_vertices = 0;
  std::size_t mesh_faces = 0;
  bool mesh_closed = false;
  bool mesh_manifold = false;
  double mesh_volume = 0.0;  ///< signed; positive for an exterior solid
  std::size_t split_vertices = 0;
  /// The pinch repair (ReconstructOptions::repair_pinches): cells relabelled, positions still
  /// held by several vertices, and the energy the relabelling added to the labelling's.
  std::size_t pinch_cells_relabelled = 0;
  std::size_t split_points = 0;
  double pinch_energy_increase = 0.0;
};

/// Floating fragments removed from the surface (ReconstructOptions::remove_floating_fragments),
/// their total volume and the supported segments they held (report: `mesh`).
struct FragmentStats {
  std::size_t removed_fragments = 0;
  double removed_fragment_volume = 0.0;
  std::size_t removed_fragment_segments = 0;
};

/// Figures without ground truth (report: `quality`, present when measured; see
/// ReconstructOptions::measure_quality).
struct QualityStats : SurfaceQuality {
  bool measured = false;
};

/// Time and memory of the run (report: `stage_seconds`, `total_seconds`, `peak_memory_bytes`).
struct ResourceStats {
  /// (stage, wall seconds) in run order: sanitize, detect, complex, scene_mode, evidence, solve,
  /// extract, ... After Reconstruction::Solve: the preparation's stages (as measured by
  /// Prepare), then this solve's.
  std::vector<std::pair<std::string, double>> stage_seconds;
  double total_seconds = 0.0;         ///< sum of the stages
  std::size_t peak_memory_bytes = 0;  ///< process peak RSS at the end of the run
};

/// The frame the run worked in (report: `frame`; docs/design/real_data.md, "The frame"). The
/// reconstruction turns the scene into its data's own axes, so that its box and block grids
/// turn with the scene, and tells the up direction from the viewpoints.
struct FrameStats {
  /// The data's axes were found (a dominant line direction and one orthogonal to it) and the
  /// run worked in them; false: in the input's axes.
  bool aligned = false;
  /// The working frame's x, y and z axes as unit vectors in the input's coordinates (z is up).
  std::array<std::array<double, 3>, 3> axes{{{1.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, {0.0, 0.0, 1.0}}};
  /// The up direction in the input's coordinates (the CityJSON and IFC writers classify roof,
  /// wall and ground by it).
  std::array<double, 3> up{0.0, 0.0, 1.0};
  /// How the up axis was told: "viewpoint_spread" (the axis along which the viewpoints spread
  /// least), "line_spread" (of two such axes, the one the lines span more), "input_z" (no
  /// viewpoint: the axis nearest the input's z) or "none" (not aligned).
  std::string up_evidence = "none";
  /// Why up points the way it does, one sentence.
  std::string up_sign;
  /// Share of the line length within 5 degrees of one of the three axes, [0, 1].
  double axis_share = 0.0;
};

}  // namespace v3
}  // namespace linesurf
