// Writer of the reference JSON format: one line object per text line, shortest round-trip
// numbers, no null, deterministic bytes.

#include "engine/core/exception.h"
#include "engine/core/world_frame.h"
#include "engine/io/file_access.h"
#include "engine/io/number_text.h"
#include "engine/io/reference_json.h"

#include <cmath>

namespace linesurf::io {
namespace {

constexpr const char* kReferenceJsonWriteStage = "write_reference_json";

void AppendJsonString(std::string& out, const std::string& s) {
  out.push_back('"');
  for (const char c : s) {
    const auto u = static_cast<unsigned char>(c);
    if (c == '"' || c == '\\') {
      out.push_back('\\');
      out.push_back(c);
    } else if (u < 0x20) {
      static constexpr char kHex[] = "0123456789abcdef";
      out.append("\\u00");
      out.push_back(kHex[u >> 4]);
      out.push_back(kHex[u & 0xF]);
    } else {
      out.push_back(c);
    }
  }
  out.push_back('"');
}

class JsonWriter {
 public:
  explicit JsonWriter(std::string path) : path_(std::move(path)) {}

  std::string& out() { return out_; }

  /// Appends "[x, y, z]" (or [a, b, c, d]); `what` names the element in errors.
  template <typename Values>
  void AppendList(const Values& values, int n, const std::string& what) {
    out_.push_back('[');
    for (int i = 0; i < n; ++i) {
      const double v = values[i];
      LINESURF_THROW_IF(!std::isfinite(v),
                        kInvalidInput,
                        kReferenceJsonWriteStage,
                        path_ << ": " << what << " holds a non-finite value; JSON cannot hold it");
      if (i > 0) out_.append(", ");
      AppendDouble(out_, v);
    }
    out_.push_back(']');
  }

 private:
  std::string path_;
  std::string out_;
};

std::string SerializeScene(const Scene& scene, const std::string& path) {
  const std::size_t num_segments = scene.NumSegments();
  LINESURF_THROW_IF(scene.observations.NumRows() != num_segments,
                    kInvalidInput,
                    kReferenceJsonWriteStage,
                    path << ": scene has " << scene.observations.NumRows()
                         << " observation rows for " << num_segments << " segments");
  LINESURF_THROW_IF(scene.HasMemberships() && scene.memberships.size() != num_segments,
                    kInvalidInput,
                    kReferenceJsonWriteStage,
                    path << ": scene has " << scene.memberships.size() << " memberships for "
                         << num_segments << " segments");
  const bool with_residuals = !scene.residuals.empty();
  LINESURF_THROW_IF(with_residuals && scene.residuals.size() != scene.observations.NumItems(),
                    kInvalidInput,
                    kReferenceJsonWriteStage,
                    path << ": scene has " << scene.residuals.size() << " residuals for "
                         << scene.observations.NumItems() << " observations");
  const Rigid3& t = scene.world_from_local;
  JsonWriter w(path);
  std::string& out = w.out();
  out.reserve(num_segments * 200 + scene.planes.size() * 120 + 64);
  out.push_back('{');
  for (const auto& [key, value] : scene.extra_fields) {
    AppendJsonString(out, key);
    out.append(": ");
    AppendJsonString(out, value);
    out.append(", ");
  }
  out.append("\"lines\": [");
  std::size_t item = 0;
  for (std::size_t s = 0; s < num_segments; ++s) {
    const SegmentId id(s);
    const std::string at = "lines[" + std::to_string(s) + "]";
    out.append(s == 0 ? "\n{\"pt1\": " : ",\n{\"pt1\": ");
    w.AppendList(ToWorldExact(scene.segments[id].p1, t), 3, at + ".pt1");
    out.append(", \"pt2\": ");
    w.AppendList(ToWorldExact(scene.segments[id].p2, t), 3, at + ".pt2");
    out.append(", \"pt_views\": [");
    const auto row = scene.observations[id];
    for (std::size_t k = 0; k < row.size(); ++k) {
      LINESURF_THROW_IF(row[k].index() >= scene.viewpoints.size(),
                        kInvalidInput,
                        kReferenceJsonWriteStage,
                        path << ": " << at << ".pt_views[" << k << "]: viewpoint id "
                             << row[k].value() << " out of range");
      if (k > 0) out.append(", ");
      w.AppendList(ToWorldExact(scene.viewpoints[row[k]], t), 3, at + ".pt_views");
    }
    out.push_back(']');
    if (scene.HasMemberships()) {
      const PlaneMembership& m = scene.memberships[id];
      out.append(", \"plane_index\": [");
      for (std::uint8_t k = 0; k < m.count; ++k) {
        LINESURF_THROW_IF(m.planes[k].index() >= scene.planes.size(),
                          kInvalidInput,
                          kReferenceJsonWriteStage,
                          path << ": " << at << ".plane_index[" << int{k} << "]: plane id "
                               << m.planes[k].value() << " out of range (" << scene.planes.size()
                               << " planes)");
        if (k > 0) out.append(", ");
        AppendUnsigned(out, m.planes[k].value());
      }
      out.push_back(']');
    }
    if (with_residuals) {
      out.append(", \"residual_per_pt_view\": [");
      for (std::size_t k = 0; k < row.size(); ++k, ++item) {
        if (k > 0) out.append(", ");
        w.AppendList(scene.residuals[item], 4, at + ".residual_per_pt_view");
      }
      out.push_back(']');
    }
    out.push_back('}');
  }
  out.append(num_segments == 0 ? "]" : "\n]");
  if (!scene.planes.empty() || scene.HasMemberships()) {
    out.append(", \"planes\": [");
    for (std::size_t p = 0; p < scene.planes.size(); ++p) {
      const Plane3& plane = scene.planes[PlaneId(p)];
      const std::string at = "planes[" + std::to_string(p) + "]";
      out.append(p == 0 ? "\n{\"inlier\": " : ",\n{\"inlier\": ");
      w.AppendList(ToWorldExact(plane.point, t), 3, at + ".inlier");
      out.append(", \"normal\": ");
      w.AppendList(t.Rotate(plane.normal), 3, at + ".normal");
      out.push_back('}');
    }
    out.append(scene.planes.empty() ? "]" : "\n]");
  }
  out.append("}\n");
  return std::move(out);
}

}  // namespace

Status WriteReferenceJson(const Scene& scene, const std::filesystem::path& path) noexcept {
  return CatchAll(kReferenceJsonWriteStage, [&] {
    const std::string text = SerializeScene(scene, path.string());
    WriteFileAtomically(path, text, kReferenceJsonWriteStage);
  });
}

}  // namespace linesurf::io
