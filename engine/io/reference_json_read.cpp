// Streaming (SAX) reader of the reference JSON format. A DOM parse of a 100 MB file costs several
// times the file size in memory (docs/user/formats.md has the measurements); this reader keeps only
// the path to the current value and the scene being built.

#include <nlohmann/json.hpp>

#include <array>
#include <cmath>
#include <cstdint>
#include <set>
#include <sstream>

#include "engine/core/exception.h"
#include "engine/io/file_access.h"
#include "engine/io/reference_json.h"
#include "engine/io/viewpoint_table.h"

namespace linesurf::io {
namespace {

constexpr const char* kReferenceJsonReadStage = "read_reference_json";

enum class Field : std::uint8_t {
  kUnknown,
  kLines,
  kPlanes,
  kPt1,
  kPt2,
  kPtViews,
  kPlaneIndex,
  kResiduals,
  kInlier,
  kNormal,
};

Field LineField(const std::string& key) {
  if (key == "pt1") return Field::kPt1;
  if (key == "pt2") return Field::kPt2;
  if (key == "pt_views") return Field::kPtViews;
  if (key == "plane_index") return Field::kPlaneIndex;
  if (key == "residual_per_pt_view") return Field::kResiduals;
  return Field::kUnknown;
}

Field PlaneField(const std::string& key) {
  if (key == "inlier") return Field::kInlier;
  if (key == "normal") return Field::kNormal;
  return Field::kUnknown;
}

/// One open JSON container on the path to the current value.
struct Frame {
  bool is_array = false;
  std::size_t index = 0;  ///< arrays: index of the next value
  std::string key;        ///< objects: the current key
  Field field = Field::kUnknown;
  std::uint32_t seen = 0;  ///< objects: bit mask of the fields seen (duplicate detection)
};

/// The line being read.
struct LineRecord {
  std::array<double, 3> p1{}, p2{};
  std::vector<std::array<double, 3>> views;
  std::vector<Residual2> residuals;
  std::vector<std::int64_t> plane_index;
  bool has_residuals = false;
};

class SceneSax {
 public:
  explicit SceneSax(std::string file) : file_(std::move(file)) {}

  // ---- nlohmann SAX interface ----
  bool null() { return Scalar(ValueKind::kNull, 0.0, nullptr); }
  bool boolean(bool) { return Scalar(ValueKind::kOther, 0.0, nullptr); }
  bool number_integer(std::int64_t v) { return Integer(v); }
  bool number_unsigned(std::uint64_t v) {
    if (v <= static_cast<std::uint64_t>(INT64_MAX)) return Integer(static_cast<std::int64_t>(v));
    if (frames_.size() == 4 && Inner() == Field::kPlaneIndex) return Integer(INT64_MAX);
    return Scalar(ValueKind::kNumber, static_cast<double>(v), nullptr);
  }
  bool number_float(double v, const std::string& text) { return Scalar(ValueKind::kNumber, v, &text); }
  bool string(std::string& s) {
    if (frames_.size() == 1 && Top() == Field::kUnknown) {
      scene_.extra_fields.emplace_back(frames_[0].key, s);
    }
    return Scalar(ValueKind::kString, 0.0, nullptr);
  }
  bool binary(nlohmann::json::binary_t&) { return Scalar(ValueKind::kOther, 0.0, nullptr); }
  bool start_object(std::size_t) { return Open(false); }
  bool start_array(std::size_t) { return Open(true); }
  bool key(std::string& k) { return Key(k); }
  bool end_object() { return Close(); }
  bool end_array() { return Close(); }
  bool parse_error(std::size_t position, const std::string& last_token,
                   const nlohmann::json::exception& ex) {
    std::ostringstream msg;
    if (ex.id == 406) {
      msg << Path() << ": not a finite number ('" << last_token << "' overflows a double)";
    } else {
      std::string what = ex.what();
      const auto bracket = what.find("] ");
      if (bracket != std::string::npos) what = what.substr(bracket + 2);
      const bool at_end = what.find("unexpected end of input") != std::string::npos;
      msg << (at_end ? "truncated JSON: " : "malformed JSON: ") << what
          << " (byte offset " << position << (frames_.empty() ? "" : ", in " + Path()) << ")";
      if (!last_token.empty() && (last_token.back() == 'N' || last_token.back() == 'I' ||
                                  last_token.back() == 'n' || last_token.back() == 'i')) {
        msg << "; JSON has no NaN or Infinity literal";
      }
    }
    return Fail(msg.str());
  }

  [[nodiscard]] const std::string& error() const { return error_; }
  ReferenceJsonReadResult Finish();

 private:
  enum class ValueKind { kNull, kNumber, kString, kOther, kArray, kObject };

  bool Fail(const std::string& message) {
    if (error_.empty()) error_ = file_ + ": " + message;
    return false;
  }

  /// Appends one path step: "[i]" for arrays, ".key" (or "key" at the top) for objects.
  static void AppendStep(std::string& path, const Frame& f, bool first) {
    if (f.is_array) {
      path.push_back('[');
      path.append(std::to_string(f.index));
      path.push_back(']');
    } else if (!f.key.empty()) {
      if (!first) path.push_back('.');
      path.append(f.key);
    }
  }
  /// The JSON path of the current value, e.g. "lines[12].pt_views[0][2]".
  [[nodiscard]] std::string Path() const {
    std::string path = PathTo(frames_.size());
    return path.empty() ? std::string("top level") : path;
  }
  /// The path through the first `depth` open containers, e.g. PathTo(3) = "lines[12].pt1".
  [[nodiscard]] std::string PathTo(std::size_t depth) const {
    std::string path;
    for (std::size_t d = 0; d < depth && d < frames_.size(); ++d) {
      AppendStep(path, frames_[d], d == 0);
    }
    return path;
  }

  /// Top-level field of the current value (frames_[0].field), kUnknown when at depth 0.
  [[nodiscard]] Field Top() const { return frames_.empty() ? Field::kUnknown : frames_[0].field; }
  /// Field inside a line/plane object (depth >= 3), kUnknown otherwise.
  [[nodiscard]] Field Inner() const {
    return frames_.size() >= 3 ? frames_[2].field : Field::kUnknown;
  }

  bool Key(const std::string& k) {
    Frame& f = frames_.back();
    f.key = k;
    if (frames_.size() == 1) {
      f.field = k == "lines" ? Field::kLines : k == "planes" ? Field::kPlanes : Field::kUnknown;
    } else if (frames_.size() == 3 && Top() == Field::kLines) {
      f.field = LineField(k);
    } else if (frames_.size() == 3 && Top() == Field::kPlanes) {
      f.field = PlaneField(k);
    } else {
      f.field = Field::kUnknown;
    }
    if (f.field != Field::kUnknown) {
      const std::uint32_t bit = 1u << static_cast<unsigned>(f.field);
      if ((f.seen & bit) != 0) return Fail(Path() + ": duplicate key");
      f.seen |= bit;
    } else if (frames_.size() == 3) {
      unknown_keys_.insert(PathTo(1) + "[]." + k);
    }
    return true;
  }

  bool Open(bool is_array) {
    if (!Check(is_array ? ValueKind::kArray : ValueKind::kObject, 0.0, nullptr)) return false;
    frames_.push_back(Frame{is_array, 0, {}, Field::kUnknown, 0});
    if (frames_.size() == 3 && !is_array) {
      if (Top() == Field::kLines) line_ = LineRecord{};
      if (Top() == Field::kPlanes) plane_ = Plane3{Vec3::Zero(), Vec3::Zero()};
    }
    if (frames_.size() == 4 && Inner() == Field::kResiduals && Top() == Field::kLines) {
      line_.has_residuals = true;
    }
    if (frames_.size() == 5 && (Inner() == Field::kPtViews || Inner() == Field::kResiduals)) {
      if (Inner() == Field::kPtViews) line_.views.push_back({});
      if (Inner() == Field::kResiduals) line_.residuals.push_back({});
    }
    return true;
  }

  bool Close() {
    const std::size_t depth = frames_.size();
    const std::size_t count = frames_.back().index;
    const bool in_lines = Top() == Field::kLines;
    const Field inner = Inner();
    if (depth == 4 && (inner == Field::kPt1 || inner == Field::kPt2 || inner == Field::kInlier ||
                       inner == Field::kNormal) && count != 3) {
      return Fail(PathTo(3) + ": expected 3 coordinates [x,y,z], got " + std::to_string(count));
    }
    if (depth == 5 && inner == Field::kPtViews && count != 3) {
      return Fail(PathTo(3) + ": not a list of [x,y,z] triples (element " +
                  std::to_string(frames_[3].index) + " has " + std::to_string(count) +
                  " values)");
    }
    if (depth == 5 && inner == Field::kResiduals && count != 4) {
      return Fail(PathTo(3) + ": not a list of [u1,v1,u2,v2] lists (element " +
                  std::to_string(frames_[3].index) + " has " + std::to_string(count) +
                  " values)");
    }
    if (depth == 3 && in_lines && !FinishLine()) return false;
    if (depth == 3 && Top() == Field::kPlanes && !FinishPlane()) return false;
    frames_.pop_back();
    if (!frames_.empty() && frames_.back().is_array) {
      ++frames_.back().index;
    }
    return true;
  }

  bool Integer(std::int64_t v) {
    if (frames_.size() == 4 && Inner() == Field::kPlaneIndex) {
      line_.plane_index.push_back(v);
      ++frames_.back().index;
      return true;
    }
    return Scalar(ValueKind::kNumber, static_cast<double>(v), nullptr);
  }

  bool Scalar(ValueKind kind, double v, const std::string* text) {
    if (!Check(kind, v, text)) return false;
    if (kind == ValueKind::kNumber) Store(v);
    if (!frames_.empty() && frames_.back().is_array) ++frames_.back().index;
    return true;
  }

  /// Validates that a value of `kind` may appear at the current position.
  bool Check(ValueKind kind, double v, const std::string* text) {
    const std::size_t depth = frames_.size();
    if (depth == 0) {
      return kind == ValueKind::kObject ? true : Fail("top level: expected a JSON object {...}");
    }
    const Field top = Top();
    if (top == Field::kUnknown) {  // unknown top-level fields are skipped (strings kept)
      if (depth == 1 && kind != ValueKind::kString) {
        unknown_keys_.insert(frames_[0].key + " (top level, not a string)");
      }
      return true;
    }
    const char* what = top == Field::kLines ? "lines" : "planes";
    if (depth == 1) {
      if (kind == ValueKind::kArray || kind == ValueKind::kNull) return true;
      return Fail(std::string(what) + ": not a list");
    }
    if (depth == 2) {
      return kind == ValueKind::kObject ? true : Fail(Path() + ": not an object");
    }
    const Field inner = Inner();
    if (inner == Field::kUnknown) return true;
    const bool is_point = inner == Field::kPt1 || inner == Field::kPt2 ||
                          inner == Field::kInlier || inner == Field::kNormal;
    if (depth == 3) {
      if (kind == ValueKind::kArray) return true;
      if (kind == ValueKind::kNull && !is_point) return true;
      return Fail(Path() + ": " + ShapeName(inner));
    }
    if (kind == ValueKind::kNumber) {
      if (!std::isfinite(v)) {
        return Fail(Path() + ": not a finite number" + (text ? " ('" + *text + "')" : ""));
      }
      if (depth == 4 && is_point) {
        if (frames_.back().index < 3) return true;
        return Fail(PathTo(3) + ": expected 3 coordinates [x,y,z], got more");
      }
      if (depth == 5 && (inner == Field::kPtViews || inner == Field::kResiduals)) return true;
      if (depth == 4 && inner == Field::kPlaneIndex) {
        return Fail(Path() + ": not an integer plane index");
      }
      return Fail(PathTo(3) + ": " + ShapeName(inner));
    }
    if (depth == 4 && kind == ValueKind::kArray &&
        (inner == Field::kPtViews || inner == Field::kResiduals)) {
      return true;
    }
    if (depth == 4 && is_point) return Fail(Path() + ": not a number");
    if (depth == 4 && inner == Field::kPlaneIndex) {
      return Fail(Path() + ": not an integer plane index");
    }
    if (depth == 5) return Fail(Path() + ": not a number");
    return Fail(PathTo(3) + ": " + ShapeName(inner));
  }

  static std::string ShapeName(Field f) {
    switch (f) {
      case Field::kPtViews: return "not a list of [x,y,z] triples";
      case Field::kResiduals: return "not a list of [u1,v1,u2,v2] lists";
      case Field::kPlaneIndex: return "not a list of plane indices";
      default: return "not an [x,y,z] list";
    }
  }

  void Store(double v) {
    const std::size_t depth = frames_.size();
    const std::size_t i = frames_.back().index;
    switch (Inner()) {
      case Field::kPt1: line_.p1[i] = v; break;  // i < 3: Check() rejected more
      case Field::kPt2: line_.p2[i] = v; break;
      case Field::kInlier: plane_.point[static_cast<Eigen::Index>(i)] = v; break;
      case Field::kNormal: plane_.normal[static_cast<Eigen::Index>(i)] = v; break;
      case Field::kPtViews:
        if (depth == 5 && i < 3) line_.views.back()[i] = v;
        break;
      case Field::kResiduals:
        if (depth == 5 && i < 4) line_.residuals.back()[i] = v;
        break;
      default: break;
    }
  }

  bool FinishLine();
  bool FinishPlane();

  std::string file_;
  std::string error_;
  std::vector<Frame> frames_;
  LineRecord line_;
  Plane3 plane_;
  Scene scene_;
  bool any_plane_index_ = false;
  std::size_t lines_with_views_ = 0;
  std::size_t lines_with_residuals_ = 0;
  std::vector<std::int64_t> plane_index_items_;
  std::vector<std::size_t> plane_index_offsets_{0};
  ViewpointTable view_ids_{scene_.viewpoints};
  std::set<std::string> unknown_keys_;                               // ordered: warnings
  std::vector<ViewpointId> row_;
};

bool SceneSax::FinishLine() {
  const std::uint32_t seen = frames_.back().seen;
  const std::string at = PathTo(2);
  for (Field f : {Field::kPt1, Field::kPt2, Field::kPtViews}) {
    if ((seen & (1u << static_cast<unsigned>(f))) == 0) {
      return Fail(at + "." + (f == Field::kPt1 ? "pt1" : f == Field::kPt2 ? "pt2" : "pt_views") +
                  ": missing");
    }
  }
  if ((seen & (1u << static_cast<unsigned>(Field::kPlaneIndex))) != 0) any_plane_index_ = true;
  const bool has_residuals = line_.has_residuals;
  if (has_residuals && line_.residuals.size() != line_.views.size()) {
    return Fail(at + ".residual_per_pt_view: " + std::to_string(line_.residuals.size()) +
                " entries for " + std::to_string(line_.views.size()) + " pt_views");
  }
  scene_.segments.push_back(Segment3{Vec3(line_.p1[0], line_.p1[1], line_.p1[2]),
                                     Vec3(line_.p2[0], line_.p2[1], line_.p2[2])});
  row_.clear();
  for (const auto& v : line_.views) row_.push_back(view_ids_.Intern(Vec3(v[0], v[1], v[2])));
  scene_.observations.AddRow(row_);
  if (!line_.views.empty()) ++lines_with_views_;
  if (has_residuals) {
    if (!line_.views.empty()) ++lines_with_residuals_;
    scene_.residuals.insert(scene_.residuals.end(), line_.residuals.begin(),
                            line_.residuals.end());
  }
  plane_index_items_.insert(plane_index_items_.end(), line_.plane_index.begin(),
                            line_.plane_index.end());
  plane_index_offsets_.push_back(plane_index_items_.size());
  return true;
}

bool SceneSax::FinishPlane() {
  const std::uint32_t seen = frames_.back().seen;
  const std::string at = PathTo(2);
  if ((seen & (1u << static_cast<unsigned>(Field::kInlier))) == 0) {
    return Fail(at + ".inlier: missing");
  }
  if ((seen & (1u << static_cast<unsigned>(Field::kNormal))) == 0) {
    return Fail(at + ".normal: missing");
  }
  const double norm = plane_.normal.norm();
  if (!(norm > 0.0) || !std::isfinite(norm)) {
    return Fail(at + ".normal: zero length" + (std::isfinite(norm) ? "" : " or overflow"));
  }
  scene_.planes.push_back(plane_);  // renormalisation is sanitation's job: values kept as read
  return true;
}

ReferenceJsonReadResult SceneSax::Finish() {
  ReferenceJsonReadResult result;
  std::vector<std::string>& warnings = result.warnings;
  const std::size_t num_planes = scene_.planes.size();
  const std::size_t num_lines = scene_.segments.size();
  if (any_plane_index_ || !scene_.planes.empty()) {
    scene_.memberships.resize(num_lines);
    std::size_t repeated = 0, beyond_two = 0;
    for (std::size_t s = 0; s < num_lines; ++s) {
      PlaneMembership& m = scene_.memberships[SegmentId(s)];
      for (std::size_t k = plane_index_offsets_[s]; k < plane_index_offsets_[s + 1]; ++k) {
        const std::int64_t p = plane_index_items_[k];
        LINESURF_THROW_IF(p < 0 || static_cast<std::uint64_t>(p) >= num_planes,
                          kInvalidInput,
                          kReferenceJsonReadStage,
                          file_ << ": lines[" << s << "].plane_index["
                                << k - plane_index_offsets_[s] << "]: " << p << " out of range ("
                                << num_planes << " planes)");
        const PlaneId id(static_cast<std::size_t>(p));
        if (m.Contains(id)) {
          ++repeated;
        } else if (!m.Add(id)) {
          ++beyond_two;
        }
      }
    }
    if (repeated > 0) {
      warnings.push_back(std::to_string(repeated) +
                         " plane_index entries repeat a plane of the same line: kept once");
    }
    if (beyond_two > 0) {
      warnings.push_back(std::to_string(beyond_two) +
                         " plane_index entries beyond the second of a line: dropped");
    }
  }
  if (lines_with_residuals_ > 0 && lines_with_residuals_ < lines_with_views_) {
    warnings.push_back("residual_per_pt_view present on " + std::to_string(lines_with_residuals_) +
                       " of " + std::to_string(lines_with_views_) +
                       " lines with views: all residuals dropped");
    scene_.residuals.clear();
  }
  for (const std::string& k : unknown_keys_) warnings.push_back("unknown key " + k + ": ignored");
  result.scene = std::move(scene_);
  return result;
}

}  // namespace

Expected<ReferenceJsonReadResult> ReadReferenceJsonWithWarnings(
    const std::filesystem::path& path) noexcept {
  return CatchAll(kReferenceJsonReadStage, [&]() -> ReferenceJsonReadResult {
    const std::string content = ReadWholeFile(path, kReferenceJsonReadStage);
    SceneSax sax(path.string());
    const bool ok = nlohmann::json::sax_parse(content.data(), content.data() + content.size(),
                                              &sax, nlohmann::json::input_format_t::json,
                                              /*strict=*/true);
    if (!ok || !sax.error().empty()) {
      ThrowError(ErrorCode::kInvalidInput,
                 kReferenceJsonReadStage,
                 sax.error().empty() ? path.string() + ": malformed JSON" : sax.error());
    }
    return sax.Finish();
  });
}

Expected<Scene> ReadReferenceJson(const std::filesystem::path& path) noexcept {
  auto result = ReadReferenceJsonWithWarnings(path);
  if (!result) return result.error();
  return std::move(result->scene);
}

}  // namespace linesurf::io
