// The small valid inputs hostile cases start from (generated, never committed).

#include "tests/robustness/hostile_case.h"

#include <array>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>

namespace linesurf::robustness {

int ExitCodeOf(ErrorCode code) {
  switch (code) {
    case ErrorCode::kInvalidOptions:
      return 2;
    case ErrorCode::kInvalidInput:
      return 3;
    case ErrorCode::kDegenerate:
    case ErrorCode::kSolverFailed:
    case ErrorCode::kResourceExhausted:
      return 4;
    case ErrorCode::kCancelled:
      return 5;
    case ErrorCode::kInternal:
      break;
  }
  return 70;
}

void WriteFile(const std::filesystem::path& path, const std::string& content) {
  std::ofstream(path, std::ios::binary) << content;
}

namespace {

using Point = std::array<double, 3>;

std::string PointText(const Point& p) {
  char buffer[96];
  std::snprintf(buffer, sizeof(buffer), "[%.17g, %.17g, %.17g]", p[0], p[1], p[2]);
  return buffer;
}

}  // namespace

std::string CubeSceneJson() {
  // The 12 edges of the cube [-1, 1]^3, each seen from the 8 viewpoints at (+-4, +-4, +-4).
  std::ostringstream views;
  views << "[";
  for (int v = 0; v < 8; ++v) {
    views << (v ? ", " : "")
          << PointText({v & 1 ? 4.0 : -4.0, v & 2 ? 4.0 : -4.0, v & 4 ? 4.0 : -4.0});
  }
  views << "]";
  std::ostringstream json;
  json << "{\"lines\": [";
  bool first = true;
  for (int axis = 0; axis < 3; ++axis) {
    for (int corner = 0; corner < 4; ++corner) {
      Point a{}, b{};
      const int u = (axis + 1) % 3, w = (axis + 2) % 3;
      a[axis] = -1.0;
      b[axis] = 1.0;
      a[u] = b[u] = corner & 1 ? 1.0 : -1.0;
      a[w] = b[w] = corner & 2 ? 1.0 : -1.0;
      json << (first ? "" : ",") << "\n  {\"pt1\": " << PointText(a)
           << ", \"pt2\": " << PointText(b) << ", \"pt_views\": " << views.str() << "}";
      first = false;
    }
  }
  json << "\n]}\n";
  return json.str();
}

std::string CubeOff(double scale) {
  std::ostringstream off;
  off.precision(17);
  off << "OFF\n8 6 0\n";
  for (int v = 0; v < 8; ++v) {
    off << (v & 1 ? scale : 0.0) << " " << (v & 2 ? scale : 0.0) << " " << (v & 4 ? scale : 0.0)
        << "\n";
  }
  off << "4 0 2 3 1\n4 4 5 7 6\n4 0 1 5 4\n4 2 6 7 3\n4 0 4 6 2\n4 1 3 7 5\n";
  return off.str();
}

}  // namespace linesurf::robustness
