#pragma once
/// @file options.h
/// @brief Options of the facade calls: plain aggregates with defaults; Validate() names the first
/// offending field. Lengths are in scene units (metres for metric scenes), angles in degrees.
/// The defaults are the engine's (docs/user/embedding.md lists them with their rationale).

#include "linesurf/error.h"
#include "linesurf/export.h"

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace linesurf {
inline namespace v3 {

/// Largest num_threads accepted (the CLI's -j bound too).
inline constexpr int kMaxThreads = 256;

/// RANSAC plane detection with multiple support (docs/design/plane_detection.md).
struct DetectionParameters {
  /// Inlier tolerance eps (> 0). Unset (default): estimated from the data (eps auto,
  /// docs/design/plane_detection.md), so metric scenes, SfM units and noisier clouds need no value.
  /// Paper: 2 cm on metric scenes.
  std::optional<double> epsilon;
  /// eps auto: eps = epsilon_over_noise x the noise scale of the endpoint-to-plane residuals
  /// ((0, 20]; 3: the mean of two endpoint distances of a Gaussian segment stays under 2.5 sigma
  /// with probability 99.9 %, and the margin above it serves the split and real scenes of
  /// docs/design/plane_detection.md, "eps from the data").
  double epsilon_over_noise = 3.0;
  /// If set, eps = relative_epsilon x scene bounding-box diagonal instead of `epsilon`. Range
  /// (0, 0.5).
  std::optional<double> relative_epsilon;
  /// Fusion thickness as a multiple of eps (>= 1; paper: 3).
  double epsilon_fusion_factor = 3.0;
  /// Planes closer than this angle may merge (degrees, (0, 90); paper: 10).
  double theta_fusion_deg = 10.0;
  /// Minimum shared support for a merge, fraction of the smaller plane's inliers ([0, 1]; 0.2).
  double p_fusion = 0.2;
  /// Maximum candidate pairs per plane N_iter (>= 1; paper: 50000; an adaptive stop usually
  /// ends earlier).
  std::int64_t iterations = 50000;
  /// Maximum number of planes N_max (>= 1; paper: 160); per block with block_size > 0.
  std::int32_t max_planes = 160;
  /// Minimum inlier segments of a plane (>= 2; the reference uses 3).
  std::int32_t min_support = 3;
  /// One plane, one piece: when a plane's inliers fall into pieces more than this many median
  /// line lengths apart and a piece fitted on its own disagrees with the plane (by more than
  /// eps / 2 at one of its endpoints), the plane keeps only its largest piece (refitted) and the
  /// others stay free. Stops a plane tilted across two parallel roofs or walls of different
  /// buildings a few eps apart, which has more inliers than either ([0, 1000]; 0 = off, the
  /// paper's method; docs/design/plane_detection.md).
  double support_gap = 8.0;
  /// Segments on one infinite line (every endpoint within this x eps of the other's line), such
  /// as the per-camera parts of one 3D line in the reference's residual inputs, are detected as
  /// one line and all get its planes: one physical line counts once, as in the reference RANSAC,
  /// which ran before the split ([0, 0.5]; 0 = every segment on its own).
  double collinear_tolerance = 1e-3;
  /// Per-block detection: cube side (>= 0; 0 = the whole scene is one block, the monolithic
  /// method). RANSAC runs per cube on the segments whose midpoint lies in the cube dilated by the
  /// halo, cubes in parallel, then a global fusion merges the pieces of one plane found in
  /// neighbouring cubes and applies the at-most-2 rule again; max_planes then bounds each
  /// block. A scene that fits in one cube gives exactly the monolithic result. Use about one
  /// building's size on city-scale scenes.
  double block_size = 0.0;
  /// Halo of a block, fraction of its side ([0, 0.5)).
  double block_halo = 0.1;
  /// A block with more lines than this is split into 8, recursively, before its RANSAC (>= 0;
  /// 0 = never). 2,000 keeps a city block under max_planes' 160 (about one plane per 15 lines).
  std::int64_t block_max_segments = 2000;
};

/// Options of DetectPlanes.
struct DetectOptions {
  DetectionParameters detection;
  /// Worker threads: 0 = automatic, 1 = serial ([0, kMaxThreads]). Results do not depend on it.
  int num_threads = 0;
  /// Seed of every random stream: same input + options + seed => same planes.
  std::uint64_t seed = 0;

  /// @return kInvalidOptions naming the first field out of its documented range.
  [[nodiscard]] LINESURF_API Status Validate() const noexcept;
};

/// Where the planes of a reconstruction come from.
enum class PlaneSource {
  kDetect,  ///< detect them from the segments (DetectionParameters)
  kGiven,   ///< use InputScene::planes and memberships (fails when the scene has none)
};

/// Boundary condition of the scene box.
enum class SceneMode {
  kExterior,  ///< an object seen from outside: cells on the box are empty
  kInterior,  ///< a room seen from inside: cells on the box are full
  kAuto,      ///< decided from the viewpoints and planes (reported in the stats)
};

/// LP backend of the labelling (docs/design/solver.md).
enum class SolverBackend {
  kAuto,        ///< maxflow when exact, else blocks (large LPs) / clp / pdhg-energy by size
  kClp,         ///< COIN-OR Clp dual simplex: exact, the reference
  kMaxflow,     ///< exact max-flow; refused (kInvalidOptions) on energies with higher-order terms
  kPdhg,        ///< first-order primal-dual: approximate optimum, fast on large complexes
  kBand,        ///< max-flow, then the LP of the cells near that surface (heuristic)
  kCbc,         ///< COIN-OR Cbc on the integer program (small energies; optional at build time)
  kClpBarrier,  ///< Clp's barrier method (for measurements only: slow)
  kBlocks,      ///< per-block solve (blocks of cells, in parallel, with halos); large complexes
  kPdhgEnergy,  ///< first-order primal-dual on the energy's saddle form: no slack columns
};

/// How the block engine partitions the scene box (docs/design/block_engine.md): one engine,
/// one or several blocks.
enum class ComplexEngine {
  kMonolithic,  ///< the whole box as one block: one arrangement of every plane with inliers
  kBlocks,      ///< blocks of side ReconstructOptions::block_size (0: automatic)
};

/// Weights of the energy terms (docs/design/reconstruction.md). These, and only these, can change in
/// Reconstruction::Solve without rebuilding the cell complex.
struct EnergyWeights {
  /// Every weight is in [0, 1e6] (beyond, the LP loses all precision).
  /// Textural primitive term (>= 0; paper: 1).
  double textural = 1.0;
  /// Structural primitive term (>= 0; paper: 1, the reference's -cp).
  double structural = 1.0;
  /// Crease term of structural segments (>= 0): a structural segment on a surface that lies flat
  /// through its crease pays this, per length / sigma, shared by the segment's views (0 = the
  /// paper's energy). Unset: 0.2 in an interior scene, 0 in an exterior one, where lines that
  /// only happen to be coplanar (a row of sills on four walls) make false creases
  /// (docs/design/reconstruction.md; measured in docs/user/results.md, "Crease term").
  std::optional<double> crease;
  /// Visibility lambda_vis (>= 0; 1, the reference's Andalusian demo; paper: 0.1, which leaves
  /// slabs and fragments on Andalusian: docs/design/reconstruction.md, "Parameters").
  double visibility = 1.0;
  /// Edge regularisation lambda_edge per length / sigma (>= 0; 0.1, the Andalusian demo; paper:
  /// 0.01).
  double edge = 0.1;
  /// Corner regularisation lambda_corner per corner (>= 0; 0.1, the Andalusian demo; paper:
  /// 0.01).
  double corner = 0.1;
  /// Surface area per area / sigma^2 (>= 0; default 0: lines are too sparse for it).
  double area = 0.0;
  /// Viewpoint prior per observation when the viewpoint's cell is full (>= 0; reference: 1).
  double viewpoint_prior = 1.0;
  /// ComplexEngine::kBlocks, per area / sigma^2: surface on a block face that carries no plane
  /// (>= 0; 1). Unpriced, a solid of block faces costs nothing (a box of blocks, not a house).
  double open_seam = 1.0;
};

/// Options of the LP labelling.
struct SolverOptions {
  SolverBackend backend = SolverBackend::kAuto;
  /// Wall-time limit of the solve in seconds (>= 0; 0 = none); exceeding it is kSolverFailed.
  double time_limit_seconds = 0.0;
};

/// Options of the quality figures without ground truth (SurfaceQuality, docs/user/evaluation.md).
struct QualityOptions {
  /// A segment sample lies on the surface when within fit_factor x eps of it (> 0; 2, the width
  /// of the inlier slab plus the surface's own tolerance).
  double fit_factor = 2.0;
  /// Each segment is integrated at this many midpoint samples of equal sub-segments (1..1024).
  int samples_per_segment = 8;
  /// A component holding fewer distinct supported lines than this is a floating fragment (>= 0;
  /// 3, the fewest a detected plane has).
  int min_lines_per_component = 3;
};

/// Options of Reconstruct and Reconstruction::Prepare.
struct ReconstructOptions {
  PlaneSource plane_source = PlaneSource::kDetect;
  /// Plane detection (ignored with PlaneSource::kGiven); its seed is `seed`.
  DetectionParameters detection;
  SceneMode scene_mode = SceneMode::kAuto;
  EnergyWeights weights;
  /// Scale sigma of the evidence (> 0). Unset: the median segment length, so the weights mean
  /// the same at any scene scale.
  std::optional<double> sigma;
  /// Evidence samples per sigma of segment length ((0, 1000]; 4).
  double samples_per_sigma = 4.0;
  /// Ablation: structural segments count as two textural ones.
  bool structural_as_textural = false;
  SolverOptions solver;
  /// The cell complex: per-block arrangements (default) or one of the scene box.
  ComplexEngine engine = ComplexEngine::kBlocks;
  /// ComplexEngine::kBlocks: side of the base blocks, scene units (>= 0; 0 = the size rule).
  /// Must be 0 with the monolithic engine. Detection keeps its own blocks
  /// (DetectionParameters::block_size).
  double block_size = 0.0;
  /// Blocks a plane's support region is dilated by (ComplexEngine::kBlocks; [0, 64]); a fraction
  /// reaches the neighbouring blocks that an inlier comes within that share of a block of.
  double block_margin = 0.0;
  /// The box is the bounding box of segments and viewpoints grown on each side by this fraction
  /// of its extent ((0, 10]; 0.05 as the reference, so viewpoints lie in bounded cells).
  double box_margin = 0.05;
  /// Measure the surface against the segments (ReconstructStats::quality); costs one
  /// closest-point query per sample and one ray query per sample and view.
  bool measure_quality = true;
  QualityOptions quality;
  /// Drop the surface's floating fragments (solid components holding fewer than
  /// quality.min_lines_per_component supported lines) when another component holds more;
  /// counted in ReconstructStats::fragments.
  bool remove_floating_fragments = true;
  /// Where parts of the solid meet only along an edge or at a point, change the label of the
  /// cell next to it whose change costs least, so that the surface is one valid solid for GIS
  /// and BIM validators, not parts touching at split vertices (ReconstructStats::surface).
  /// Default true.
  bool repair_pinches = true;
  /// Triangulate the output faces (default: convex polygons).
  bool triangulate = false;
  /// Neighbouring faces of one plane with one outward side (split by block faces or by planes
  /// without surface there) become one polygon, which may be non-convex (not with
  /// triangulate). Default false: convex faces.
  bool merge_coplanar = false;
  /// Worker threads: 0 = automatic, 1 = serial ([0, kMaxThreads]). Results do not depend on it.
  int num_threads = 0;
  /// Seed of every random stream: same input + options + seed => same mesh bytes.
  std::uint64_t seed = 0;

  /// @return kInvalidOptions naming the first field out of its documented range.
  [[nodiscard]] LINESURF_API Status Validate() const noexcept;
};

/// Input file formats of ReadScene.
enum class SceneFormat {
  kAuto,           ///< from the extension (.json, .obj) and, for .txt, the first line
  kReferenceJson,  ///< the paper's reference JSON
  kLine3dpp,       ///< Line3D++ .txt, camera centres from `nvm` or `colmap`
  kObjLines,       ///< OBJ v + l records: segments without views (detection only)
  kLimapTracks,    ///< LIMAP alltracks.txt, camera centres from `colmap` (or `nvm`)
};

/// Options of ReadScene.
struct ReadOptions {
  SceneFormat format = SceneFormat::kAuto;
  /// Line3D++ and LIMAP only: the VisualSfM .nvm whose camera list the camera ids index.
  std::string nvm;
  /// Line3D++ and LIMAP only: a COLMAP model directory, text or binary (or its images file).
  std::string colmap;
};

/// Options of WriteMesh.
struct MeshWriteOptions {
  /// PLY only: ASCII instead of binary little-endian (OBJ and OFF are always text).
  bool ascii = false;
  /// Split faces into triangles: fans of convex faces, ear clipping of non-convex ones.
  bool triangulate = false;
};

/// Options of the writers of georeferenced formats: WriteCityJson, WriteCityJsonSeq, WriteIfc.
struct GeoreferenceOptions {
  /// Coordinate reference system of the mesh's coordinates, "EPSG:CODE" (e.g. "EPSG:7415"),
  /// written as CityJSON metadata.referenceSystem and as IFC IfcProjectedCRS; empty: none stated.
  std::string crs;
  /// The up direction of the mesh's coordinates (finite, not zero; need not be unit): faces
  /// within 10 degrees of vertical are walls, the others roofs or ground (floors or ceilings
  /// inside). `linesurf reconstruct` passes the run's own (ReconstructStats::frame.up).
  std::array<double, 3> up{0.0, 0.0, 1.0};

  [[nodiscard]] LINESURF_API Status Validate() const noexcept;
};

/// "detect" / "given" ("" for a value outside the enum).
[[nodiscard]] inline const char* PlaneSourceName(PlaneSource source) noexcept {
  switch (source) {
    case PlaneSource::kDetect:
      return "detect";
    case PlaneSource::kGiven:
      return "given";
  }
  return "";
}

/// "exterior" / "interior" / "auto" ("" for a value outside the enum).
[[nodiscard]] inline const char* SceneModeName(SceneMode mode) noexcept {
  switch (mode) {
    case SceneMode::kExterior:
      return "exterior";
    case SceneMode::kInterior:
      return "interior";
    case SceneMode::kAuto:
      return "auto";
  }
  return "";
}

/// "auto" / "clp" / "maxflow" / "pdhg" / "band" / "cbc" / "clp-barrier" / "blocks" /
/// "pdhg-energy" ("" for a value outside the enum).
[[nodiscard]] inline const char* SolverBackendName(SolverBackend backend) noexcept {
  switch (backend) {
    case SolverBackend::kAuto:
      return "auto";
    case SolverBackend::kClp:
      return "clp";
    case SolverBackend::kMaxflow:
      return "maxflow";
    case SolverBackend::kPdhg:
      return "pdhg";
    case SolverBackend::kBand:
      return "band";
    case SolverBackend::kCbc:
      return "cbc";
    case SolverBackend::kClpBarrier:
      return "clp-barrier";
    case SolverBackend::kBlocks:
      return "blocks";
    case SolverBackend::kPdhgEnergy:
      return "pdhg-energy";
  }
  return "";
}

/// "monolithic" / "blocks" ("" for a value outside the enum).
[[nodiscard]] inline const char* ComplexEngineName(ComplexEngine engine) noexcept {
  switch (engine) {
    case ComplexEngine::kMonolithic:
      return "monolithic";
    case ComplexEngine::kBlocks:
      return "blocks";
  }
  return "";
}

/// The names of an enumerated option's values, in enumerator order.
template <typename E>
struct OptionEnum;
template <>
struct OptionEnum<PlaneSource> {
  static constexpr int kCount = 2;
  static const char* Name(PlaneSource v) noexcept { return PlaneSourceName(v); }
};
template <>
struct OptionEnum<SceneMode> {
  static constexpr int kCount = 3;
  static const char* Name(SceneMode v) noexcept { return SceneModeName(v); }
};
template <>
struct OptionEnum<SolverBackend> {
  static constexpr int kCount = 9;
  static const char* Name(SolverBackend v) noexcept { return SolverBackendName(v); }
};
template <>
struct OptionEnum<ComplexEngine> {
  static constexpr int kCount = 2;
  static const char* Name(ComplexEngine v) noexcept { return ComplexEngineName(v); }
};

/// The enumerator of E named `name`, or std::nullopt.
template <typename E>
[[nodiscard]] std::optional<E> OptionEnumFromName(std::string_view name) noexcept {
  for (int i = 0; i < OptionEnum<E>::kCount; ++i) {
    if (name == OptionEnum<E>::Name(static_cast<E>(i))) return static_cast<E>(i);
  }
  return std::nullopt;
}

/// The enumerator a name above denotes; std::nullopt for any other string.
[[nodiscard]] inline std::optional<PlaneSource> PlaneSourceFromName(
    std::string_view name) noexcept {
  return OptionEnumFromName<PlaneSource>(name);
}
[[nodiscard]] inline std::optional<SceneMode> SceneModeFromName(std::string_view name) noexcept {
  return OptionEnumFromName<SceneMode>(name);
}
[[nodiscard]] inline std::optional<SolverBackend> SolverBackendFromName(
    std::string_view name) noexcept {
  return OptionEnumFromName<SolverBackend>(name);
}
[[nodiscard]] inline std::optional<ComplexEngine> ComplexEngineFromName(
    std::string_view name) noexcept {
  return OptionEnumFromName<ComplexEngine>(name);
}

}  // namespace v3
}  // namespace linesurf
