#include "engine/io/read_scene.h"

#include <algorithm>
#include <fstream>

#include "engine/core/exception.h"
#include "engine/io/camera_centres.h"
#include "engine/io/limap_reader.h"
#include "engine/io/line3dpp_reader.h"
#include "engine/io/mesh_format.h"
#include "engine/io/obj_lines_reader.h"
#include "engine/io/reference_json.h"

namespace linesurf::io {
namespace {

constexpr const char* kReadSceneStage = "read_scene";

/// Formats whose observations are camera ids resolved through an NVM or COLMAP model.
bool NeedsCameraModel(SceneFormat format) {
  return format == SceneFormat::kLine3dpp || format == SceneFormat::kLimapTracks;
}

/// The first bytes of `path` ("" when it cannot be read: the reader then reports why).
std::string FileStart(const std::filesystem::path& path) {
  constexpr std::size_t kSniffBytes = 4096;
  std::ifstream in(path, std::ios::binary);
  std::string start(kSniffBytes, '\0');
  in.read(start.data(), static_cast<std::streamsize>(start.size()));
  start.resize(static_cast<std::size_t>(std::max<std::streamsize>(in.gcount(), 0)));
  return start;
}

}  // namespace

SceneFormat ResolveSceneFormat(const std::filesystem::path& path,
                               const SceneReadOptions& options) {
  if (options.format != SceneFormat::kAuto) return options.format;
  const std::string ext = LowerExtension(path);
  if (ext == ".json") return SceneFormat::kReferenceJson;
  if (ext == ".txt") {
    return LooksLikeLimapTracks(FileStart(path)) ? SceneFormat::kLimapTracks
                                                 : SceneFormat::kLine3dpp;
  }
  if (ext == ".obj") return SceneFormat::kObjLines;
  return SceneFormat::kAuto;
}

Status SceneReadOptions::Validate(SceneFormat resolved) const {
  auto bad = [](const std::string& message) {
    return Error{ErrorCode::kInvalidOptions, kReadSceneStage, message};
  };
  if (resolved == SceneFormat::kAuto) {
    return bad("unknown input format: expected a .json (reference JSON), .txt (Line3D++ or LIMAP "
               "alltracks.txt) or .obj (v/l lines) file");
  }
  const bool has_nvm = !nvm.empty();
  const bool has_colmap = !colmap.empty();
  if (NeedsCameraModel(resolved) && has_nvm == has_colmap) {
    return bad(std::string("a ") +
               (resolved == SceneFormat::kLine3dpp ? "Line3D++" : "LIMAP alltracks") +
               " .txt input needs its camera centres from exactly one of an NVM file (--nvm "
               "FILE) or a COLMAP model (--colmap DIR, text or binary)");
  }
  if (!NeedsCameraModel(resolved) && (has_nvm || has_colmap)) {
    return bad("--nvm/--colmap apply to Line3D++ and LIMAP .txt inputs only");
  }
  return {};
}

Expected<SceneReadResult> ReadSceneWithWarnings(const std::filesystem::path& path,
                                                const SceneReadOptions& options) noexcept {
  const SceneFormat format = ResolveSceneFormat(path, options);
  if (Status valid = options.Validate(format); !valid) {
    Error error = valid.error();
    error.message = path.string() + ": " + error.message;
    return error;
  }
  if (format == SceneFormat::kReferenceJson) {
    auto json = ReadReferenceJsonWithWarnings(path);
    if (!json) return json.error();
    return SceneReadResult{std::move(json->scene), std::move(json->warnings)};
  }
  return CatchAll(kReadSceneStage, [&]() -> SceneReadResult {
    SceneReadResult result;
    if (format == SceneFormat::kObjLines) {
      result.scene = ReadObjLines(path);
      result.warnings.push_back("OBJ lines carry no viewpoints: usable for plane detection only");
    } else {
      const CameraCentres centres = options.nvm.empty() ? ReadColmapCameraCentres(options.colmap)
                                                        : ReadNvmCameraCentres(options.nvm);
      if (format == SceneFormat::kLimapTracks) {
        result.scene = ReadLimapTracks(path, centres);
      } else {
        result.scene = ReadLine3dpp(path, centres);
        result.scene.extra_fields.emplace_back("original_L3Dpp_file", path.filename().string());
      }
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
