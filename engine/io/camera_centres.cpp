#include "engine/io/camera_centres.h"

#include "engine/core/exception.h"
#include "engine/io/file_access.h"
#include "engine/io/text_lines.h"

namespace linesurf::io {
namespace {

constexpr const char* kCameraCentresStage = "read_cameras";

}  // namespace

CameraCentres ReadNvmCameraCentres(const std::filesystem::path& path) {
  const std::string file = path.string();
  const std::string text = ReadWholeFile(path, kCameraCentresStage);
  LineReader reader(text);
  std::vector<std::string_view> tokens;
  LINESURF_THROW_IF(!reader.Next(tokens) || tokens.empty() || tokens[0] != "NVM_V3",
                    kInvalidInput,
                    kCameraCentresStage,
                    file << ": line 1: expected the NVM_V3 header");
  // FixedK parameters, when present, share the header line: they are not needed for centres.
  long long count = -1;
  while (reader.Next(tokens)) {
    if (tokens.empty()) continue;
    LINESURF_THROW_IF(tokens.size() != 1 || !ParseInt(tokens[0], count) || count < 0,
                      kInvalidInput,
                      kCameraCentresStage,
                      file << ": line " << reader.line_number() << ": expected the camera count");
    break;
  }
  LINESURF_THROW_IF(count < 0, kInvalidInput, kCameraCentresStage, file << ": no camera count");
  CameraCentres centres;
  for (long long c = 0; c < count; ++c) {
    LINESURF_THROW_IF(
        !reader.Next(tokens),
        kInvalidInput,
        kCameraCentresStage,
        file << ": camera " << c << ": unexpected end of file (" << count << " cameras announced)");
    // The name may contain spaces: the 10 numbers are the last tokens of the line.
    double values[10];
    const bool ok =
        tokens.size() >= 11 && ParseFiniteNumbers(tokens, tokens.size() - 10, 10, values);
    LINESURF_THROW_IF(!ok,
                      kInvalidInput,
                      kCameraCentresStage,
                      file << ": line " << reader.line_number() << ": camera " << c
                           << ": expected '<name> <focal> <qw qx qy qz> <cx cy cz> <radial> 0'");
    centres.emplace(c, Vec3(values[5], values[6], values[7]));
  }
  return centres;
}

}  // namespace linesurf::io
