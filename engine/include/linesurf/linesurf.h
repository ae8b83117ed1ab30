#pragma once
/// @file linesurf.h
/// @brief The linesurf facade: watertight piecewise-planar meshes from 3D line segments seen
/// from known viewpoints (Langlois, Boulch & Marlet, 3DV 2019). Include only this header.
///
/// Every call is synchronous, re-entrant and noexcept: errors come back as Expected<T> (codes in
/// error.h); the library never prints, never aborts and keeps no global state. Determinism:
/// the same input, options and seed give the same output bytes for any thread count.
///
/// @code
///   linesurf::Expected<linesurf::ReadSceneResult> read = linesurf::ReadScene("lines.json");
///   if (!read) return fail(read.error());
///   linesurf::ReconstructOptions options;
///   options.scene_mode = linesurf::SceneMode::kExterior;
///   auto result = linesurf::Reconstruct(read->scene.View(), options);
///   if (!result) return fail(result.error());
///   linesurf::Status written = linesurf::WriteMesh("house.ply", result->mesh);
/// @endcode
///
/// Threads: work runs in a oneTBB task arena of ReconstructOptions::num_threads (0 = all
/// cores), shared with the host's own oneTBB scheduler; the library never sets process-wide
/// limits (tbb::global_control).

#include "linesurf/error.h"
#include "linesurf/evaluation.h"
#include "linesurf/export.h"
#include "linesurf/option_schema.h"
#include "linesurf/options.h"
#include "linesurf/report.h"
#include "linesurf/result.h"
#include "linesurf/run_control.h"
#include "linesurf/types.h"
#include "linesurf/version.h"
#include "linesurf/work_units.h"

#include <memory>
#include <span>
#include <string>

namespace linesurf {
inline namespace v3 {

/// @brief The whole method: sanitise, planes (detected or given), cell complex, evidence, LP
/// labelling, surface extraction.
/// @param[in] scene views of the host's arrays, read during the call only.
/// @return kInvalidOptions (bad options), kInvalidInput (an index out of range, nothing usable,
/// no given planes), kDegenerate (no plane), kSolverFailed, kResourceExhausted, kCancelled,
/// kInternal.
[[nodiscard]] LINESURF_API Expected<ReconstructResult> Reconstruct(
    const InputScene& scene,
    const ReconstructOptions& options,
    const RunControl& control = {}) noexcept;

/// @brief Plane detection only (the scene is sanitised first; given planes are ignored).
/// @return kInvalidOptions, kInvalidInput, kCancelled, kResourceExhausted, kInternal.
[[nodiscard]] LINESURF_API Expected<DetectResult> DetectPlanes(
    const InputScene& scene, const DetectOptions& options, const RunControl& control = {}) noexcept;

/// @brief DetectPlanes on an owned scene, returning also the sanitised scene with the detected
/// planes (residuals and extra fields kept), ready for WriteScene or WriteVertexGroups.
/// @return the errors of DetectPlanes.
[[nodiscard]] LINESURF_API Expected<DetectedScene> DetectScenePlanes(
    const SceneData& scene, const DetectOptions& options, const RunControl& control = {}) noexcept;

/// @brief A prepared reconstruction, for solving again with other weights without detecting
/// planes or building the cell complex again (the reference's line_based_recons_param
/// workflow): Prepare once, then Solve as often as wanted.
///
/// Prepare runs sanitation, plane detection (or takes the given planes), builds the cell
/// complex and decides the scene mode. Solve computes the evidence with the given weights,
/// solves the LP and extracts the surface. Solve(options.weights) gives exactly the mesh of
/// Reconstruct(scene, options). Only the EnergyWeights change between solves; sigma,
/// samples_per_sigma, structural_as_textural, the solver options and triangulate stay those
/// given to Prepare.
///
/// A Reconstruction owns its data (the scene is copied); it is movable, not copyable. Solve is
/// const and may run concurrently on one object from several threads.
class LINESURF_API Reconstruction {
 public:
  /// @return the errors of Reconstruct up to the cell complex.
  [[nodiscard]] static Expected<Reconstruction> Prepare(const InputScene& scene,
                                                        const ReconstructOptions& options,
                                                        const RunControl& control = {}) noexcept;

  /// @return the errors of Reconstruct from the evidence on; kInvalidOptions for a negative
  /// or non-finite weight.
  [[nodiscard]] Expected<ReconstructResult> Solve(const EnergyWeights& weights,
                                                  const RunControl& control = {}) const noexcept;

  /// The options given to Prepare.
  [[nodiscard]] const ReconstructOptions& Options() const noexcept;

  Reconstruction(Reconstruction&&) noexcept;
  Reconstruction& operator=(Reconstruction&&) noexcept;
  ~Reconstruction();

 private:
  struct Impl;
  explicit Reconstruction(std::unique_ptr<Impl> impl) noexcept;
  std::unique_ptr<Impl> impl_;
};

/// @brief Reads a scene file: reference JSON, Line3D++ .txt or LIMAP alltracks.txt (with
/// options.nvm or options.colmap) or OBJ lines (docs/user/formats.md). World coordinates as stored.
/// @return kInvalidOptions (unknown format, missing or extra camera files), kInvalidInput
/// naming the file and the line or JSON path at fault.
[[nodiscard]] LINESURF_API Expected<ReadSceneResult> ReadScene(
    const std::string& path, const ReadOptions& options = {}) noexcept;

/// @brief The validation every reconstruction starts with, on its own: drops non-finite and
/// zero-length segments, bad viewpoints, observations and planes, repeated memberships (each
/// counted in the warnings; docs/user/formats.md lists the repairs). Residuals and extra fields are
/// kept for the segments that stay.
/// @return kInvalidInput (an index out of range, no usable segment left).
[[nodiscard]] LINESURF_API Expected<SanitizedScene> SanitizeScene(const SceneData& scene) noexcept;

/// @brief Writes `scene` as reference JSON (planes and plane_index when it has them). The same
/// scene always gives the same bytes; written to a temporary name and renamed.
/// @return kInvalidInput (an index out of range, a non-finite value, an unwritable path).
[[nodiscard]] LINESURF_API Status WriteScene(const std::string& path,
                                             const SceneData& scene) noexcept;

/// @brief Reads a polygon mesh from PLY (ASCII or binary little/big endian), OBJ or OFF, chosen by
/// the extension; faces keep their vertex order.
/// @return kInvalidInput (missing or unreadable file, unknown extension, malformed content); the
/// message names the file and the line (text) or element (binary) at fault.
[[nodiscard]] LINESURF_API Expected<Mesh> ReadMesh(const std::string& path) noexcept;

/// @brief Writes a mesh as PLY (binary unless options.ascii), OBJ or OFF, chosen by the
/// extension; the same bytes as `linesurf reconstruct -o`. Written to a temporary name and
/// renamed.
/// @return kInvalidInput (unknown extension, bad face, non-finite coordinate, unwritable path).
[[nodiscard]] LINESURF_API Status WriteMesh(const std::string& path,
                                            const Mesh& mesh,
                                            const MeshWriteOptions& options = {}) noexcept;

/// @brief Writes the planes of `scene` as PolyFit / abspy vertex groups (.vg: the segments'
/// endpoints, grouped by plane; docs/user/formats.md). Written to a temporary name and renamed.
/// @return kInvalidInput (an index out of range, a non-finite value, an unwritable path), naming
/// the file.
[[nodiscard]] LINESURF_API Status WriteVertexGroups(const std::string& path,
                                                    const SceneData& scene) noexcept;

/// @brief The validity classes of `mesh` as the boundary of solids (MeshValidity: closed,
/// 2-manifold, oriented, coincident vertices, degenerate, zero-area and non-planar faces,
/// self-intersection; docs/user/formats.md "Validity"), the checker Reconstruct runs on every result.
/// @return kInvalidInput (an index out of range, inconsistent face offsets, a coordinate
/// beyond the bound).
[[nodiscard]] LINESURF_API Expected<MeshValidity> CheckMesh(const Mesh& mesh) noexcept;

/// @brief Precision and completeness of `result` against `ground_truth` (both in the same frame
/// and units), distances both ways and the validity of `result` (linesurf/evaluation.h);
/// `linesurf evaluate RESULT GT` prints the same numbers.
/// @param visible_from when not empty, completeness only counts ground-truth samples that one of
///   these viewpoints sees unoccluded by the ground truth.
/// @return kInvalidOptions, kInvalidInput (a mesh without area, bad indices; the message starts
/// with "ground truth" when it is about `ground_truth`), kCancelled. Deterministic for any
/// thread count.
[[nodiscard]] LINESURF_API Expected<EvaluationResult> EvaluateMesh(
    const Mesh& result,
    const Mesh& ground_truth,
    const EvaluationOptions& options = {},
    std::span<const Vector3> visible_from = {},
    const RunControl& control = {}) noexcept;

/// @brief The figures without ground truth (SurfaceQuality, linesurf/stats.h) of `mesh` against
/// the segments of `lines` (same frame): data fit, visibility consistency, components, floating
/// fragments, planes on no face. The scene is sanitised; its planes are used when it gives them
/// with memberships, detected with `options` otherwise; eps is `options.detection.epsilon` or
/// estimated. `linesurf evaluate RESULT --lines INPUT` prints the same numbers.
/// @return kInvalidOptions, kInvalidInput (a bad scene, a mesh without area), kCancelled.
/// Deterministic for any thread count.
[[nodiscard]] LINESURF_API Expected<SurfaceQuality> MeasureSurfaceQuality(
    const Mesh& mesh,
    const SceneData& lines,
    const DetectOptions& options = {},
    const RunControl& control = {}) noexcept;

/// @brief Writes a mesh as CityJSON 2.0: one Building per connected component, a Solid (LoD 2.2)
/// whose surfaces are the component's faces joined per plane (holes as inner rings), a
/// semantic surface per plane of `planes` and class (docs/user/formats.md); the same bytes as
/// `linesurf reconstruct -o m.city.json`. Written to a temporary name and renamed.
/// @return kInvalidInput (bad face, non-finite coordinate, unwritable path), kInvalidOptions
/// (options.crs not "EPSG:CODE").
[[nodiscard]] LINESURF_API Status WriteCityJson(const std::string& path,
                                                const Mesh& mesh,
                                                std::span<const Plane> planes,
                                                const GeoreferenceOptions& options) noexcept;

/// WriteCityJson with default options (no CRS stated).
[[nodiscard]] LINESURF_API Status WriteCityJson(const std::string& path,
                                                const Mesh& mesh,
                                                std::span<const Plane> planes) noexcept;

/// @brief The buildings of WriteCityJson as CityJSONSeq (`.city.jsonl`: a CityJSON header line,
/// then one CityJSONFeature per building and line); the same bytes as
/// `linesurf reconstruct -o m.city.jsonl`. Written to a temporary name and renamed.
/// @return as WriteCityJson.
[[nodiscard]] LINESURF_API Status WriteCityJsonSeq(const std::string& path,
                                                   const Mesh& mesh,
                                                   std::span<const Plane> planes,
                                                   const GeoreferenceOptions& options = {}) noexcept;

/// True for a name ending in ".city.json" or ".cityjson" (case-insensitive): CityJSON by name.
[[nodiscard]] LINESURF_API bool IsCityJsonPath(const std::string& path) noexcept;

/// @brief Writes a mesh as IFC4 (STEP text) for BIM tools: an IfcBuilding per connected
/// component with one IfcBuildingElementProxy whose faceted B-rep faces are those of
/// WriteCityJson (one per plane, holes as inner bounds), metres, the site placed at the mesh's
/// minimum corner in whole metres, options.crs as IfcProjectedCRS (docs/user/formats.md); the same
/// bytes as `linesurf reconstruct -o m.ifc`. Written to a temporary name and renamed.
/// @return as WriteCityJson.
[[nodiscard]] LINESURF_API Status WriteIfc(const std::string& path,
                                           const Mesh& mesh,
                                           std::span<const Plane> planes,
                                           const GeoreferenceOptions& options = {}) noexcept;

/// True for a name ending in ".ifc" (case-insensitive): IFC by name.
[[nodiscard]] LINESURF_API bool IsIfcPath(const std::string& path) noexcept;

/// True for a name ending in ".jsonl" (case-insensitive, e.g. ".city.jsonl"): CityJSONSeq by name.
[[nodiscard]] LINESURF_API bool IsCityJsonSeqPath(const std::string& path) noexcept;

}  // namespace v3
}  // namespace linesurf
