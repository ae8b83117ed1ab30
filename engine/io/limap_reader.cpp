#include "engine/io/limap_reader.h"

#include "engine/core/exception.h"
#include "engine/io/file_access.h"
#include "engine/io/text_lines.h"
#include "engine/io/viewpoint_table.h"

#include <set>
#include <string>
#include <vector>

namespace linesurf::io {
namespace {

constexpr const char* kLimapReaderStage = "read_limap";

}  // namespace

bool LooksLikeLimapTracks(std::string_view text) {
  LineReader reader(text);
  std::vector<std::string_view> tokens;
  while (reader.Next(tokens)) {
    if (tokens.empty()) continue;
    long long count = 0;
    return tokens.size() == 1 && ParseInt(tokens[0], count);
  }
  return false;
}

Scene ReadLimapTracks(const std::filesystem::path& path, const CameraCentres& centres) {
  const std::string file = path.string();
  const std::string text = ReadWholeFile(path, kLimapReaderStage);
  LineReader reader(text);
  std::vector<std::string_view> tokens;
  // The next line, which must exist: `what` names it in the error.
  auto next_line = [&](const char* what) {
    LINESURF_THROW_IF(
        !reader.Next(tokens),
        kInvalidInput,
        kLimapReaderStage,
        file << ": line " << reader.line_number() + 1 << ": file ends before " << what);
  };
  auto where = [&] { return file + ": line " + std::to_string(reader.line_number()); };
  do {
    next_line("the track count");
  } while (tokens.empty());
  long long count = 0;
  LINESURF_THROW_IF(tokens.size() != 1 || !ParseInt(tokens[0], count) || count < 0,
                    kInvalidInput,
                    kLimapReaderStage,
                    where() << ": expected the number of tracks");

  Scene scene;
  ViewpointTable views(scene.viewpoints);
  std::vector<ViewpointId> row;
  for (long long t = 0; t < count; ++t) {
    do {
      next_line("the next track");
    } while (tokens.empty());
    long long track_id = 0;
    long long n_lines = 0;
    long long n_images = 0;
    LINESURF_THROW_IF(tokens.size() != 3 || !ParseInt(tokens[0], track_id) ||
                          !ParseInt(tokens[1], n_lines) || !ParseInt(tokens[2], n_images) ||
                          n_lines < 0 || n_images < 0,
                      kInvalidInput,
                      kLimapReaderStage,
                      where() << ": track " << t << ": expected 'track_id n_lines n_images'");
    Segment3 seg;
    for (Vec3* p : {&seg.p1, &seg.p2}) {
      next_line("the track's 3D endpoint");
      double v[3];
      LINESURF_THROW_IF(tokens.size() != 3 || !ParseFiniteNumbers(tokens, 0, 3, v),
                        kInvalidInput,
                        kLimapReaderStage,
                        where() << ": track " << t << ": expected 3 finite coordinates");
      *p = Vec3(v[0], v[1], v[2]);
    }
    next_line("the track's image ids");
    const std::size_t n = static_cast<std::size_t>(n_lines);
    LINESURF_THROW_IF(tokens.size() != n,
                      kInvalidInput,
                      kLimapReaderStage,
                      where() << ": track " << t << ": " << n_lines << " image ids expected, "
                              << tokens.size() << " found");
    row.clear();
    std::set<long long> distinct;
    for (std::size_t k = 0; k < n; ++k) {
      long long image = 0;
      LINESURF_THROW_IF(
          !ParseInt(tokens[k], image),
          kInvalidInput,
          kLimapReaderStage,
          where() << ": track " << t << ": image id '" << tokens[k] << "' is not an integer");
      const auto it = centres.find(image);
      LINESURF_THROW_IF(it == centres.end(),
                        kInvalidInput,
                        kLimapReaderStage,
                        where() << ": track " << t << ": image id " << image
                                << " is not in the camera model (" << centres.size()
                                << " cameras)");
      distinct.insert(image);
      row.push_back(views.Intern(it->second));
    }
    LINESURF_THROW_IF(distinct.size() != static_cast<std::size_t>(n_images),
                      kInvalidInput,
                      kLimapReaderStage,
                      where() << ": track " << t << ": " << distinct.size()
                              << " distinct image ids, the track header announces " << n_images);
    next_line("the track's line ids");
    LINESURF_THROW_IF(tokens.size() != n,
                      kInvalidInput,
                      kLimapReaderStage,
                      where() << ": track " << t << ": " << n_lines << " line ids expected, "
                              << tokens.size() << " found");
    scene.segments.push_back(seg);
    scene.observations.AddRow(row);
  }
  while (reader.Next(tokens)) {
    LINESURF_THROW_IF(!tokens.empty(),
                      kInvalidInput,
                      kLimapReaderStage,
                      where() << ": text after the " << count << " announced tracks");
  }
  return scene;
}

}  // namespace linesurf::io
