#include "engine/io/read_scene.h"

#include "engine/core/exception.h"
#include "engine/io/camera_centres.h"
#include "engine/io/line3dpp_reader.h"
#include "engine/io/mesh_format.h"
#include "engine/io/obj_lines_reader.h"
#include "engine/io/reference_json.h"

namespace linesurf::io {
namespace {

constexpr const char* kStage = "read_scene";

}  // namespace

SceneFormat ResolveSceneFormat(const std::filesystem::path& path,
                               const SceneReadOptions& options) {
  if (options.format != SceneFormat::kAuto) return options.format;
  const std::string ext = LowerExtension(path);
  if (ext == ".json") return SceneFormat::kReferenceJson;
  if (ext == ".txt") return SceneFormat::kLine3dpp;
  if (ext == ".obj") return SceneFormat::kObjLines;
  return SceneFormat::kAuto;
}

Status SceneReadOptions::Validate(SceneFormat resolved) const {
  auto bad = [](const std::string& message) {
    return Error{ErrorCode::kInvalidOptions, kStage, message};
  };
  if (resolved == SceneFormat::kAuto) {
    return bad("unknown input format: expected a .json (reference JSON), .txt (Line3D++) or "
               ".obj (v/l lines) file");
  }
  const bool has_nvm = !nvm.empty();
  const bool has_colmap = !colmap.empty();
  if (resolved == SceneFormat::kLine3dpp && has_nvm == has_colmap) {
    return bad("a Line3D++ .txt input needs its camera centres from exactly one of an NVM file "
               "(--nvm FILE) or a COLMAP text model (--colmap DIR)");
  }
  if (resolved != SceneFormat::kLine3dpp && (has_nvm || has_colmap)) {
    return bad("--nvm/--colmap apply to Line3D++ .txt inputs only");
  }
  return {};
}

Expected<SceneReadResult> ReadSceneWithWarnings(const std::filesystem::path& path,
                                                const SceneReadOptions& options) noexcept {
  const SceneFormat format = ResolveSceneFormat(path, options);
  if (Status valid = options.Validate(format); !valid) return valid.error();
  if (format == SceneFormat::kReferenceJson) {
    auto json = ReadReferenceJsonWithWarnings(path);
    if (!json) return json.error();
    return SceneReadResult{std::move(json->scene), std::move(json->warnings)};
  }
  return CatchAll(kStage, [&]() -> SceneReadResult {
    SceneReadResult result;
    if (format == SceneFormat::kObjLines) {
      result.scene = ReadObjLines(path);
      result.warnings.push_back("OBJ lines carry no viewpoints: usable for plane detection only");
    } else {
      const CameraCentres centres = options.nvm.empty() ? ReadColmapCameraCentres(options.colmap)
                                                        : ReadNvmCameraCentres(options.nvm);
      result.scene = ReadLine3dpp(path, centres);
      result.scene.extra_fields.emplace_back("original_L3Dpp_file", path.filename().string());
    }
    return result;
  });
}

Expected<Scene> ReadScene(const std::filesystem::path& path,
                          const SceneReadOptions& options) noexcept {
  auto result = ReadSceneWithWarnings(path, options);
  if (!result) return result.error();
  return std::move(result->scene);
}

}  // namespace linesurf::io
