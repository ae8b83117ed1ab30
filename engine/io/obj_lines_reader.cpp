#include "engine/io/obj_lines_reader.h"

#include <cmath>

#include "engine/core/exception.h"
#include "engine/io/file_access.h"
#include "engine/io/text_lines.h"

namespace linesurf::io {

Scene ReadObjLines(const std::filesystem::path& path) {
  constexpr const char* kObjLinesReaderStage = "read_obj_lines";
  const std::string file = path.string();
  const std::string text = ReadWholeFile(path, kObjLinesReaderStage);
  std::vector<Vec3> vertices;
  Scene scene;
  LineReader reader(text);
  std::vector<std::string_view> tokens;
  std::vector<std::uint32_t> polyline;
  const std::vector<ViewpointId> no_views;
  while (reader.Next(tokens)) {
    if (tokens.empty()) continue;
    const std::size_t line = reader.line_number();
    if (tokens[0] == "v") {
      Vec3 v;
      LINESURF_THROW_IF(tokens.size() < 4,
                        kInvalidInput,
                        kObjLinesReaderStage,
                        file << ": line " << line << ": expected 'v x y z'");
      for (int k = 0; k < 3; ++k) {
        const std::string_view t = tokens[static_cast<std::size_t>(k) + 1];
        LINESURF_THROW_IF(!ParseDouble(t, v[k]) || !std::isfinite(v[k]),
                          kInvalidInput,
                          kObjLinesReaderStage,
                          file << ": line " << line << ": '" << t << "' is not a finite number");
      }
      vertices.push_back(v);
    } else if (tokens[0] == "l") {
      LINESURF_THROW_IF(tokens.size() < 3,
                        kInvalidInput,
                        kObjLinesReaderStage,
                        file << ": line " << line << ": a line needs at least 2 vertices");
      polyline.clear();
      for (std::size_t k = 1; k < tokens.size(); ++k) {
        const std::string_view ref = tokens[k].substr(0, tokens[k].find('/'));
        long long index = 0;
        const auto n = static_cast<long long>(vertices.size());
        const bool ok = ParseInt(ref, index) && index != 0;
        const long long zero_based = index > 0 ? index - 1 : n + index;
        LINESURF_THROW_IF(!ok || zero_based < 0 || zero_based >= n,
                          kInvalidInput,
                          kObjLinesReaderStage,
                          file << ": line " << line << ": vertex '" << tokens[k]
                               << "' out of range (" << n << " vertices so far)");
        polyline.push_back(static_cast<std::uint32_t>(zero_based));
      }
      for (std::size_t k = 0; k + 1 < polyline.size(); ++k) {
        scene.segments.push_back(Segment3{vertices[polyline[k]], vertices[polyline[k + 1]]});
        scene.observations.AddRow(no_views);
      }
    }
  }
  return scene;
}

}  // namespace linesurf::io
