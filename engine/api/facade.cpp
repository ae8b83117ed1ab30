// The facade entry points (linesurf/linesurf.h): convert, call the engine, convert back. Every
// entry point is noexcept and turns any exception into an Error (CatchAll).

#include "linesurf/linesurf.h"

#include "engine/api/host_context.h"
#include "engine/api/options_conversion.h"
#include "engine/api/result_conversion.h"
#include "engine/api/scene_conversion.h"
#include "engine/core/exception.h"
#include "engine/io/cityjson_write.h"
#include "engine/io/ifc_write.h"
#include "engine/io/mesh_io.h"
#include "engine/io/reference_json.h"
#include "engine/io/vertex_groups_write.h"
#include "engine/pipeline/detect_scene_planes.h"
#include "engine/pipeline/evaluate_mesh.h"
#include "engine/pipeline/mesh_validity.h"
#include "engine/pipeline/quality_against_lines.h"
#include "engine/pipeline/sanitize_scene.h"

#include <optional>
#include <span>
#include <vector>

namespace linesurf {
inline namespace v3 {
namespace {

/// ValueOrThrow for a check of what goes into `path`: the error names the file.
template <typename T>
T ValueOrThrowFor(Expected<T>&& e, const std::string& path) {
  if (!e) {
    Error named = e.error();
    named.message = path + ": " + named.message;
    throw LinesurfException(std::move(named));
  }
  return std::move(e.value());
}

void ThrowIfInvalid(const Status& s) {
  if (!s) throw LinesurfException(s.error());
}

/// The engine scene of an owned scene (residuals, extra fields and empty memberships kept); an
/// index error names `path` when given (the file the scene goes to).
Scene ToEngineSceneData(const SceneData& scene, const std::string& path = {}) {
  Expected<Scene> engine_scene = api::ToEngineScene(scene.View(), scene.residuals);
  Scene out = path.empty() ? ValueOrThrow(std::move(engine_scene))
                           : ValueOrThrowFor(std::move(engine_scene), path);
  if (scene.has_memberships) out.memberships.resize(out.NumSegments());
  out.extra_fields = scene.extra_fields;
  return out;
}

/// Sanitation and detection, with the options checked first.
pipeline::DetectedScene Detect(Scene scene,
                               const DetectOptions& options,
                               const RunControl& control) {
  ThrowIfInvalid(options.Validate());
  const api::HostContext host(control, options.num_threads);
  return ValueOrThrow(pipeline::SanitizeAndDetectPlanes(
      std::move(scene), {}, api::ToEngineOptions(options.detection, options.seed), host.Context()));
}

/// Runs `write` (io::WriteCityJson, WriteCityJsonSeq or WriteIfc) on the engine's mesh and planes.
template <typename Write>
Status WriteCityModel(const char* stage,
                      const std::string& path,
                      const Mesh& mesh,
                      std::span<const Plane> planes,
                      const GeoreferenceOptions& options,
                      Write write) {
  return CatchAll(stage, [&] {
    ThrowIfInvalid(options.Validate());
    const PolygonMesh engine_mesh = ValueOrThrowFor(ToPolygonMesh(mesh), path);
    std::vector<Plane3> engine_planes;
    engine_planes.reserve(planes.size());
    for (const Plane& p : planes) {
      engine_planes.push_back(Plane3{ToVec3(p.point), ToVec3(p.normal)});
    }
    ThrowIfInvalid(write(engine_mesh, engine_planes, options, path));
  });
}

/// `classify` (an io path predicate) without letting std::filesystem's allocation escape.
template <typename Classify>
bool IsPathOf(const std::string& path, Classify classify) noexcept {
  try {
    return classify(path);
  } catch (...) {
    return false;
  }
}

}  // namespace

const char* LibraryVersion() noexcept { return LINESURF_VERSION_STRING; }

Expected<ReconstructResult> Reconstruct(const InputScene& scene,
                                        const ReconstructOptions& options,
                                        const RunControl& control) noexcept {
  return CatchAll("reconstruct", [&]() -> ReconstructResult {
    ThrowIfInvalid(options.Validate());
    const Scene engine_scene = ValueOrThrow(api::ToEngineScene(scene));
    const api::HostContext host(control, options.num_threads);
    return api::ToPublicResult(ValueOrThrow(
        pipeline::Reconstruct(engine_scene, api::ToEngineOptions(options), host.Context())));
  });
}

Expected<DetectResult> DetectPlanes(const InputScene& scene,
                                    const DetectOptions& options,
                                    const RunControl& control) noexcept {
  return CatchAll("detect", [&]() -> DetectResult {
    return api::ToPublicResult(Detect(ValueOrThrow(api::ToEngineScene(scene)), options, control),
                               options.detection.max_planes);
  });
}

Expected<DetectedScene> DetectScenePlanes(const SceneData& scene,
                                          const DetectOptions& options,
                                          const RunControl& control) noexcept {
  return CatchAll("detect", [&]() -> DetectedScene {
    const pipeline::DetectedScene detected = Detect(ToEngineSceneData(scene), options, control);
    return DetectedScene{api::ToSceneData(detected.scene),
                         api::ToPublicResult(detected, options.detection.max_planes),
                         detected.given_planes};
  });
}

struct Reconstruction::Impl {
  ReconstructOptions options;
  pipeline::PreparedReconstruction prepared;
};

Reconstruction::Reconstruction(std::unique_ptr<Impl> impl) noexcept : impl_(std::move(impl)) {}
Reconstruction::Reconstruction(Reconstruction&&) noexcept = default;
Reconstruction& Reconstruction::operator=(Reconstruction&&) noexcept = default;
Reconstruction::~Reconstruction() = default;

Expected<Reconstruction> Reconstruction::Prepare(const InputScene& scene,
                                                 const ReconstructOptions& options,
                                                 const RunControl& control) noexcept {
  return CatchAll("prepare", [&]() -> Reconstruction {
    ThrowIfInvalid(options.Validate());
    const Scene engine_scene = ValueOrThrow(api::ToEngineScene(scene));
    const api::HostContext host(control, options.num_threads);
    auto impl = std::make_unique<Impl>();
    impl->options = options;
    impl->prepared = ValueOrThrow(pipeline::PrepareReconstruction(
        engine_scene, api::ToEngineOptions(options), host.Context()));
    return Reconstruction(std::move(impl));
  });
}

Expected<ReconstructResult> Reconstruction::Solve(const EnergyWeights& weights,
                                                  const RunControl& control) const noexcept {
  return CatchAll("solve", [&]() -> ReconstructResult {
    LINESURF_THROW_IF(!impl_, kInvalidOptions, "solve", "this Reconstruction was moved from");
    ThrowIfInvalid(ValidateOptionValues(weights));
    pipeline::ReconstructOptions engine_options = api::ToEngineOptions(impl_->options);
    engine_options.energy.weights = weights;
    const api::HostContext host(control, impl_->options.num_threads);
    return api::ToPublicResult(
        ValueOrThrow(pipeline::SolvePrepared(impl_->prepared, engine_options, host.Context())));
  });
}

const ReconstructOptions& Reconstruction::Options() const noexcept { return impl_->options; }

Expected<ReadSceneResult> ReadScene(const std::string& path, const ReadOptions& options) noexcept {
  return CatchAll("read_scene", [&]() -> ReadSceneResult {
    io::SceneReadResult read =
        ValueOrThrow(io::ReadSceneWithWarnings(path, api::ToEngineOptions(options)));
    return ReadSceneResult{api::ToSceneData(read.scene), std::move(read.warnings)};
  });
}

Expected<SanitizedScene> SanitizeScene(const SceneData& scene) noexcept {
  return CatchAll("sanitize", [&]() -> SanitizedScene {
    // The input's axes: what is converted or described keeps its coordinates.
    pipeline::SanitizeOptions options;
    options.align_to_data_frame = false;
    pipeline::SanitizeResult sane =
        ValueOrThrow(pipeline::SanitizeScene(ToEngineSceneData(scene), options));
    SanitizedScene out{api::ToSceneData(sane.scene), {}, std::move(sane.warnings)};
    out.input_segment.reserve(sane.input_segment.size());
    for (const SegmentId s : sane.input_segment) out.input_segment.push_back(s.value());
    return out;
  });
}

Status WriteScene(const std::string& path, const SceneData& scene) noexcept {
  return CatchAll("write_scene", [&] {
    ThrowIfInvalid(io::WriteReferenceJson(ToEngineSceneData(scene, path), path));
  });
}

Expected<Mesh> ReadMesh(const std::string& path) noexcept {
  return CatchAll("read_mesh", [&] { return ToMesh(ValueOrThrow(io::ReadMesh(path))); });
}

Status WriteMesh(const std::string& path,
                 const Mesh& mesh,
                 const MeshWriteOptions& options) noexcept {
  return CatchAll("write_mesh", [&] {
    const PolygonMesh engine_mesh = ValueOrThrow(ToPolygonMesh(mesh));
    ThrowIfInvalid(io::WriteMesh(engine_mesh, path, api::ToEngineOptions(options)));
  });
}

Status WriteVertexGroups(const std::string& path, const SceneData& scene) noexcept {
  return CatchAll("write_vertex_groups", [&] {
    ThrowIfInvalid(io::WriteVertexGroups(ToEngineSceneData(scene, path), path));
  });
}

Expected<MeshValidity> CheckMesh(const Mesh& mesh) noexcept {
  return CatchAll("check_mesh", [&] {
    return ValueOrThrow(CheckMeshValidity(ValueOrThrow(ToPolygonMesh(mesh))));
  });
}

Expected<EvaluationResult> EvaluateMesh(const Mesh& result,
                                        const Mesh& ground_truth,
                                        const EvaluationOptions& options,
                                        std::span<const Vector3> visible_from,
                                        const RunControl& control) noexcept {
  return CatchAll("evaluate_mesh", [&] {
    ThrowIfInvalid(options.Validate());
    std::optional<std::vector<Vec3>> viewpoints;
    if (!visible_from.empty()) {
      viewpoints.emplace();
      for (const Vector3& v : visible_from) viewpoints->push_back(ToVec3(v));
    }
    const api::HostContext host(control, options.num_threads);
    return ValueOrThrow(pipeline::EvaluateMesh(ValueOrThrow(ToPolygonMesh(result)),
                                               ValueOrThrow(ToPolygonMesh(ground_truth)), options,
                                               viewpoints, &host.Context()));
  });
}

Expected<SurfaceQuality> MeasureSurfaceQuality(const Mesh& mesh,
                                               const SceneData& lines,
                                               const DetectOptions& options,
                                               const RunControl& control) noexcept {
  return CatchAll("quality", [&] {
    ThrowIfInvalid(options.Validate());
    const api::HostContext host(control, options.num_threads);
    return ValueOrThrow(pipeline::MeasureQualityAgainstLines(
        ValueOrThrow(ToPolygonMesh(mesh)), ToEngineSceneData(lines),
        api::ToEngineOptions(options.detection, options.seed), host.Context()));
  });
}

Status WriteCityJson(const std::string& path,
                     const Mesh& mesh,
                     std::span<const Plane> planes,
                     const GeoreferenceOptions& options) noexcept {
  return WriteCityModel("write_cityjson", path, mesh, planes, options,
                        [](const auto&... args) { return io::WriteCityJson(args...); });
}

Status WriteCityJson(const std::string& path,
                     const Mesh& mesh,
                     std::span<const Plane> planes) noexcept {
  return WriteCityJson(path, mesh, planes, GeoreferenceOptions{});
}

Status WriteCityJsonSeq(const std::string& path,
                        const Mesh& mesh,
                        std::span<const Plane> planes,
                        const GeoreferenceOptions& options) noexcept {
  return WriteCityModel("write_cityjson", path, mesh, planes, options,
                        [](const auto&... args) { return io::WriteCityJsonSeq(args...); });
}

Status WriteIfc(const std::string& path,
                const Mesh& mesh,
                std::span<const Plane> planes,
                const GeoreferenceOptions& options) noexcept {
  return WriteCityModel("write_ifc", path, mesh, planes, options,
                        [](const auto&... args) { return io::WriteIfc(args...); });
}

bool IsIfcPath(const std::string& path) noexcept {
  return IsPathOf(path, [](const std::string& p) { return io::IsIfcPath(p); });
}

bool IsCityJsonPath(const std::string& path) noexcept {
  return IsPathOf(path, [](const std::string& p) { return io::IsCityJsonPath(p); });
}

bool IsCityJsonSeqPath(const std::string& path) noexcept {
  return IsPathOf(path, [](const std::string& p) { return io::IsCityJsonSeqPath(p); });
}

}  // namespace v3
}  // namespace linesurf
