// The facade entry points (linesurf/linesurf.h): convert, call the engine, convert back. Every
// entry point is noexcept and turns any exception into an Error (CatchAll).

#include "linesurf/linesurf.h"

#include "engine/api/host_context.h"
#include "engine/api/options_conversion.h"
#include "engine/api/result_conversion.h"
#include "engine/api/scene_conversion.h"
#include "engine/core/exception.h"
#include "engine/io/reference_json.h"
#include "engine/pipeline/detect_scene_planes.h"
#include "engine/pipeline/sanitize_scene.h"

namespace linesurf {
inline namespace v1 {
namespace {

/// Unwraps a result or rethrows its error unchanged (CatchAll turns it back into an Error).
template <typename T>
T ValueOrThrow(Expected<T>&& e) {
  if (!e) throw LinesurfException(e.error());
  return std::move(e.value());
}

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
    ThrowIfInvalid(options.Validate());
    const api::HostContext host(control, options.num_threads);
    return api::ToPublicResult(ValueOrThrow(
        pipeline::SanitizeAndDetectPlanes(ValueOrThrow(api::ToEngineScene(scene)),
                                          {},
                                          api::ToEngineOptions(options.detection, options.seed),
                                          host.Context())));
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
    ThrowIfInvalid(api::ValidateWeights(weights));
    pipeline::ReconstructOptions engine_options = api::ToEngineOptions(impl_->options);
    api::SetEngineWeights(weights, engine_options.energy);
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
    Scene engine_scene = ValueOrThrow(api::ToEngineScene(scene.View(), scene.residuals));
    engine_scene.extra_fields = scene.extra_fields;
    pipeline::SanitizeResult sane =
        ValueOrThrow(pipeline::SanitizeScene(std::move(engine_scene), {}));
    SanitizedScene out{api::ToSceneData(sane.scene), {}, std::move(sane.warnings)};
    out.input_segment.reserve(sane.input_segment.size());
    for (const SegmentId s : sane.input_segment) out.input_segment.push_back(s.value());
    return out;
  });
}

Status WriteScene(const std::string& path, const SceneData& scene) noexcept {
  return CatchAll("write_scene", [&] {
    Scene engine_scene = ValueOrThrowFor(api::ToEngineScene(scene.View(), scene.residuals), path);
    engine_scene.extra_fields = scene.extra_fields;
    ThrowIfInvalid(io::WriteReferenceJson(engine_scene, path));
  });
}

Status WriteMesh(const std::string& path,
                 const Mesh& mesh,
                 const MeshWriteOptions& options) noexcept {
  return CatchAll("write_mesh", [&] {
    const PolygonMesh engine_mesh = ValueOrThrow(api::ToPolygonMesh(mesh));
    ThrowIfInvalid(io::WriteMesh(engine_mesh, path, api::ToEngineOptions(options)));
  });
}

}  // namespace v1
}  // namespace linesurf
