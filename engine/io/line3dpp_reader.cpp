#include "engine/io/line3dpp_reader.h"

#include <cmath>

#include "engine/core/exception.h"
#include "engine/io/file_access.h"
#include "engine/io/text_lines.h"
#include "engine/io/viewpoint_table.h"

namespace linesurf::io {
namespace {

constexpr const char* kLine3dppReaderStage = "read_line3dpp";

}  // namespace

Scene ReadLine3dpp(const std::filesystem::path& path, const CameraCentres& centres) {
  const std::string file = path.string();
  const std::string text = ReadWholeFile(path, kLine3dppReaderStage);
  Scene scene;
  ViewpointTable views(scene.viewpoints);
  LineReader reader(text);
  std::vector<std::string_view> tokens;
  std::vector<Segment3> cluster;
  std::vector<ViewpointId> row;
  std::vector<Residual2> residuals;
  while (reader.Next(tokens)) {
    if (tokens.empty()) continue;
    const std::size_t line = reader.line_number();
    std::size_t next = 0;
    // Reads the next token as a finite number; `what` names it in the error.
    auto number = [&](const char* what) {
      double v = 0.0;
      LINESURF_THROW_IF(next >= tokens.size(),
                        kInvalidInput,
                        kLine3dppReaderStage,
                        file << ": line " << line << ": ended before " << what);
      const std::string_view t = tokens[next++];
      LINESURF_THROW_IF(
          !ParseDouble(t, v) || !std::isfinite(v),
          kInvalidInput,
          kLine3dppReaderStage,
          file << ": line " << line << ": " << what << ": '" << t << "' is not a finite number");
      return v;
    };
    auto count = [&](const char* what) {
      long long n = 0;
      LINESURF_THROW_IF(next >= tokens.size() || !ParseInt(tokens[next], n) || n < 0,
                        kInvalidInput,
                        kLine3dppReaderStage,
                        file << ": line " << line << ": expected " << what);
      ++next;
      return static_cast<std::size_t>(n);
    };
    const std::size_t n = count("the number of 3D segments");
    LINESURF_THROW_IF(tokens.size() < 1 + 6 * n,
                      kInvalidInput,
                      kLine3dppReaderStage,
                      file << ": line " << line << ": " << n << " segments need " << 6 * n
                           << " numbers, the line has " << tokens.size() - 1);
    cluster.clear();
    for (std::size_t s = 0; s < n; ++s) {
      Segment3 seg;
      for (int k = 0; k < 3; ++k) seg.p1[k] = number("segment endpoint");
      for (int k = 0; k < 3; ++k) seg.p2[k] = number("segment endpoint");
      cluster.push_back(seg);
    }
    const std::size_t m = count("the number of observations after the segments");
    LINESURF_THROW_IF(tokens.size() != next + 6 * m,
                      kInvalidInput,
                      kLine3dppReaderStage,
                      file << ": line " << line << ": " << m << " observations need " << 6 * m
                           << " values (cam_id seg_id u1 v1 u2 v2), the line has "
                           << tokens.size() - next);
    row.clear();
    residuals.clear();
    for (std::size_t o = 0; o < m; ++o) {
      long long cam = 0;
      LINESURF_THROW_IF(!ParseInt(tokens[next], cam),
                        kInvalidInput,
                        kLine3dppReaderStage,
                        file << ": line " << line << ": observation " << o << ": camera id '"
                             << tokens[next] << "' is not an integer");
      const auto it = centres.find(cam);
      LINESURF_THROW_IF(it == centres.end(),
                        kInvalidInput,
                        kLine3dppReaderStage,
                        file << ": line " << line << ": observation " << o << ": camera id " << cam
                             << " is not in the camera model (" << centres.size() << " cameras)");
      next += 2;  // cam_id, seg_id
      Residual2 r;
      for (double& v : r) v = number("2D residual");
      row.push_back(views.Intern(it->second));
      residuals.push_back(r);
    }
    for (const Segment3& seg : cluster) {
      scene.segments.push_back(seg);
      scene.observations.AddRow(row);
      scene.residuals.insert(scene.residuals.end(), residuals.begin(), residuals.end());
    }
  }
  return scene;
}

}  // namespace linesurf::io
