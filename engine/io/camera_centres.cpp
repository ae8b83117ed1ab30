#include "engine/io/camera_centres.h"

#include <Eigen/Geometry>

#include <cmath>

#include "engine/core/exception.h"
#include "engine/io/file_access.h"
#include "engine/io/text_lines.h"

namespace linesurf::io {
namespace {

constexpr const char* kStage = "read_cameras";

bool ParseNumbers(const std::vector<std::string_view>& tokens, std::size_t first, std::size_t n,
                  double* out) {
  if (tokens.size() < first + n) return false;
  for (std::size_t k = 0; k < n; ++k) {
    if (!ParseDouble(tokens[first + k], out[k]) || !std::isfinite(out[k])) return false;
  }
  return true;
}

}  // namespace

CameraCentres ReadNvmCameraCentres(const std::filesystem::path& path) {
  const std::string file = path.string();
  const std::string text = ReadWholeFile(path, kStage);
  LineReader reader(text);
  std::vector<std::string_view> tokens;
  LINESURF_THROW_IF(!reader.Next(tokens) || tokens.empty() || tokens[0] != "NVM_V3", kInvalidInput,
                    kStage, file << ": line 1: expected the NVM_V3 header");
  // FixedK parameters, when present, share the header line: they are not needed for centres.
  long long count = -1;
  while (reader.Next(tokens)) {
    if (tokens.empty()) continue;
    LINESURF_THROW_IF(tokens.size() != 1 || !ParseInt(tokens[0], count) || count < 0,
                      kInvalidInput, kStage,
                      file << ": line " << reader.line_number() << ": expected the camera count");
    break;
  }
  LINESURF_THROW_IF(count < 0, kInvalidInput, kStage, file << ": no camera count");
  CameraCentres centres;
  for (long long c = 0; c < count; ++c) {
    LINESURF_THROW_IF(!reader.Next(tokens), kInvalidInput, kStage,
                      file << ": camera " << c << ": unexpected end of file (" << count
                           << " cameras announced)");
    // The name may contain spaces: the 10 numbers are the last tokens of the line.
    double values[10];
    const bool ok = tokens.size() >= 11 && ParseNumbers(tokens, tokens.size() - 10, 10, values);
    LINESURF_THROW_IF(!ok, kInvalidInput, kStage,
                      file << ": line " << reader.line_number() << ": camera " << c
                           << ": expected '<name> <focal> <qw qx qy qz> <cx cy cz> <radial> 0'");
    centres.emplace(c, Vec3(values[5], values[6], values[7]));
  }
  return centres;
}

CameraCentres ReadColmapCameraCentres(const std::filesystem::path& path) {
  const std::filesystem::path images =
      std::filesystem::is_directory(path) ? path / "images.txt" : path;
  const std::string file = images.string();
  const std::string text = ReadWholeFile(images, kStage);
  LineReader reader(text);
  std::vector<std::string_view> tokens;
  CameraCentres centres;
  bool in_header = true;
  while (reader.Next(tokens)) {
    if (in_header && (tokens.empty() || tokens[0].front() == '#')) continue;
    in_header = false;
    if (tokens.empty()) continue;  // trailing blank lines
    const std::size_t line = reader.line_number();
    long long image_id = 0;
    double v[7];  // qw qx qy qz tx ty tz
    LINESURF_THROW_IF(tokens.size() < 10 || !ParseInt(tokens[0], image_id) ||
                          !ParseNumbers(tokens, 1, 7, v),
                      kInvalidInput, kStage,
                      file << ": line " << line
                           << ": expected 'IMAGE_ID QW QX QY QZ TX TY TZ CAMERA_ID NAME'");
    const Eigen::Quaterniond q(v[0], v[1], v[2], v[3]);
    LINESURF_THROW_IF(!(q.norm() > 0.0), kInvalidInput, kStage,
                      file << ": line " << line << ": zero quaternion");
    const Eigen::Matrix3d r = q.normalized().toRotationMatrix();
    const Vec3 centre = -(r.transpose() * Vec3(v[4], v[5], v[6]));
    LINESURF_THROW_IF(!centres.emplace(image_id, centre).second, kInvalidInput, kStage,
                      file << ": line " << line << ": IMAGE_ID " << image_id << " repeated");
    reader.Next(tokens);  // the POINTS2D line of this image (possibly empty)
  }
  return centres;
}

}  // namespace linesurf::io
