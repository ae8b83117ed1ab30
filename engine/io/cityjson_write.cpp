#include "engine/io/cityjson_write.h"

#include "engine/core/exception.h"
#include "engine/core/public_vector.h"
#include "engine/io/city_model.h"
#include "engine/io/file_access.h"
#include "engine/io/mesh_format.h"
#include "engine/io/number_text.h"
#include "engine/io/reference_system.h"

#include <array>
#include <cmath>
#include <string>
#include <unordered_map>
#include <vector>

namespace linesurf::io {
namespace {

constexpr const char* kCityjsonWriteStage = "write_cityjson";
/// Quantisation step of the vertices, relative to the largest extent (CityJSON stores integers).
constexpr double kQuantumRelative = 1e-9;

using QuantisedPoint = std::array<long long, 3>;

struct QuantisedPointHash {
  std::size_t operator()(const QuantisedPoint& p) const {
    std::size_t h = 0;
    for (const long long c : p) h = h * 0x9E3779B97F4A7C15ull + std::hash<long long>{}(c);
    return h;
  }
};

/// CityJSON's `transform`: x = translate + scale * integer.
struct Quantisation {
  Vec3 translate = Vec3::Zero();
  double scale = 0.001;

  explicit Quantisation(const Box3& box) {
    if (box.IsEmpty()) return;
    translate = box.min;
    const double extent = box.Extent().maxCoeff();
    if (extent > 0.0) scale = std::pow(10.0, std::floor(std::log10(extent * kQuantumRelative)));
  }
  [[nodiscard]] QuantisedPoint Of(const Vec3& p) const {
    return {std::llround((p.x() - translate.x()) / scale),
            std::llround((p.y() - translate.y()) / scale),
            std::llround((p.z() - translate.z()) / scale)};
  }
};

/// Numbers the written vertices in order of first use; positions that quantise alike share one.
class VertexNumbering {
 public:
  std::uint32_t Number(const QuantisedPoint& p) {
    const auto [it, added] =
        number_of_.try_emplace(p, static_cast<std::uint32_t>(points_.size()));
    if (added) points_.push_back(p);
    return it->second;
  }
  [[nodiscard]] const std::vector<QuantisedPoint>& points() const { return points_; }

 private:
  std::unordered_map<QuantisedPoint, std::uint32_t, QuantisedPointHash> number_of_;
  std::vector<QuantisedPoint> points_;
};

void AppendDoubles(std::string& out, std::initializer_list<double> values) {
  out += '[';
  bool first = true;
  for (const double v : values) {
    if (!first) out += ',';
    first = false;
    AppendDouble(out, v);
  }
  out += ']';
}

void AppendSigned(std::string& out, long long value) {
  if (value < 0) out += '-';
  AppendUnsigned(out, value < 0 ? 0ull - static_cast<unsigned long long>(value)
                                : static_cast<unsigned long long>(value));
}

/// `"version", "transform", "metadata"` members of the document and of a sequence's header.
std::string HeaderMembers(const CityModel& model,
                          const Quantisation& quantisation,
                          const GeoreferenceOptions& options) {
  std::string out = "\"type\":\"CityJSON\",\"version\":\"2.0\",\"transform\":{\"scale\":";
  const double s = quantisation.scale;
  const Vec3& t = quantisation.translate;
  AppendDoubles(out, {s, s, s});
  out += ",\"translate\":";
  AppendDoubles(out, {t.x(), t.y(), t.z()});
  out += "},\"metadata\":{\"geographicalExtent\":";
  const Box3& box = model.box;
  if (box.IsEmpty()) {
    out += "[0.0,0.0,0.0,0.0,0.0,0.0]";
  } else {
    AppendDoubles(out,
                  {box.min.x(), box.min.y(), box.min.z(), box.max.x(), box.max.y(), box.max.z()});
  }
  if (!options.crs.empty()) {
    out += ",\"referenceSystem\":\"https://www.opengis.net/def/crs/EPSG/0/" + EpsgCode(options.crs) +
           '"';
  }
  out += '}';
  return out;
}

/// A polygon's rings as written: quantised, repeated points dropped, collapsed holes dropped;
/// empty when the outer ring collapses.
std::vector<std::vector<QuantisedPoint>> QuantisedRings(const PolygonMesh& mesh,
                                                        const PlanarPolygon& shape,
                                                        const Quantisation& quantisation) {
  std::vector<std::vector<QuantisedPoint>> rings;
  for (const auto& ring : shape.rings) {
    std::vector<QuantisedPoint> points;
    for (const std::uint32_t v : ring) {
      const QuantisedPoint p = quantisation.Of(mesh.vertices[v]);
      if (points.empty() || points.back() != p) points.push_back(p);
    }
    while (points.size() > 1 && points.back() == points.front()) points.pop_back();
    if (points.size() < 3) {
      if (rings.empty()) return {};
      continue;
    }
    rings.push_back(std::move(points));
  }
  return rings;
}

/// Appends `"id":{...}` for `building` on one line, its vertices numbered by `numbering`;
/// appends nothing and returns false when every polygon collapses under quantisation.
bool AppendBuilding(std::string& out,
                    const PolygonMesh& mesh,
                    const CityBuilding& building,
                    std::span<const Plane3> planes,
                    const Quantisation& quantisation,
                    const std::string& id,
                    VertexNumbering& numbering) {
  std::string boundaries;
  std::string values;
  for (const CityPolygon& polygon : building.polygons) {
    const auto rings = QuantisedRings(mesh, polygon.shape, quantisation);
    if (rings.empty()) continue;
    boundaries += boundaries.empty() ? "[" : ",[";
    for (std::size_t r = 0; r < rings.size(); ++r) {
      boundaries += r ? ",[" : "[";
      for (std::size_t i = 0; i < rings[r].size(); ++i) {
        if (i) boundaries += ',';
        AppendUnsigned(boundaries, numbering.Number(rings[r][i]));
      }
      boundaries += ']';
    }
    boundaries += ']';
    if (!values.empty()) values += ',';
    AppendUnsigned(values, polygon.surface);
  }
  if (boundaries.empty()) return false;
  const bool solid = building.solid;
  out += '"' + id + "\":{\"type\":\"Building\",\"geometry\":[{\"type\":\"";
  out += solid ? "Solid" : "CompositeSurface";
  out += "\",\"lod\":\"2.2\",\"boundaries\":";
  out += solid ? "[[" + boundaries + "]]" : "[" + boundaries + "]";
  out += ",\"semantics\":{\"surfaces\":[";
  for (std::size_t s = 0; s < building.surfaces.size(); ++s) {
    if (s) out += ',';
    out += "{\"type\":\"";
    out += CityJsonName(building.surfaces[s].type);
    out += '"';
    if (const auto p = building.surfaces[s].plane) {
      const Plane3& plane = planes[*p];
      const Vec3 n = plane.normal.normalized();
      out += ",\"plane_index\":";
      AppendUnsigned(out, *p);
      out += ",\"plane\":";
      AppendDoubles(out, {n.x(), n.y(), n.z(), -n.dot(plane.point)});
    }
    out += '}';
  }
  out += "],\"values\":";
  out += solid ? "[[" + values + "]]" : "[" + values + "]";
  out += "}}]}";
  return true;
}

/// `"vertices":[...]`, one vertex per line when `one_per_line`.
void AppendVertices(std::string& out, const VertexNumbering& numbering, bool one_per_line) {
  out += "\"vertices\":[";
  bool first = true;
  for (const QuantisedPoint& p : numbering.points()) {
    if (!first) out += ',';
    if (one_per_line) out += "\n";
    first = false;
    out += '[';
    for (int k = 0; k < 3; ++k) {
      if (k) out += ',';
      AppendSigned(out, p[k]);
    }
    out += ']';
  }
  if (one_per_line && !first) out += '\n';
  out += ']';
}

std::string BuildingId(std::size_t b) { return "building_" + std::to_string(b); }

std::string CityJsonText(const PolygonMesh& mesh,
                         std::span<const Plane3> planes,
                         const GeoreferenceOptions& options,
                         const std::string& file) {
  const CityModel model = BuildCityModel(mesh, planes, ToVec3(options.up), file);
  const Quantisation quantisation(model.box);
  std::string out = "{" + HeaderMembers(model, quantisation, options) + ",\n\"CityObjects\":{";
  VertexNumbering numbering;
  bool first = true;
  for (std::size_t b = 0; b < model.buildings.size(); ++b) {
    std::string object = first ? "\n" : ",\n";
    if (!AppendBuilding(object, mesh, model.buildings[b], planes, quantisation, BuildingId(b),
                        numbering)) {
      continue;
    }
    out += object;
    first = false;
  }
  out += first ? "},\n" : "\n},\n";
  AppendVertices(out, numbering, /*one_per_line=*/true);
  out += "}\n";
  return out;
}

std::string CityJsonSeqText(const PolygonMesh& mesh,
                            std::span<const Plane3> planes,
                            const GeoreferenceOptions& options,
                            const std::string& file) {
  const CityModel model = BuildCityModel(mesh, planes, ToVec3(options.up), file);
  const Quantisation quantisation(model.box);
  std::string out =
      "{" + HeaderMembers(model, quantisation, options) + ",\"CityObjects\":{},\"vertices\":[]}\n";
  for (std::size_t b = 0; b < model.buildings.size(); ++b) {
    const std::string id = BuildingId(b);
    VertexNumbering numbering;
    std::string feature = "{\"type\":\"CityJSONFeature\",\"id\":\"" + id + "\",\"CityObjects\":{";
    if (!AppendBuilding(feature, mesh, model.buildings[b], planes, quantisation, id, numbering)) {
      continue;
    }
    feature += "},";
    AppendVertices(feature, numbering, /*one_per_line=*/false);
    out += feature + "}\n";
  }
  return out;
}

}  // namespace


bool IsCityJsonPath(const std::filesystem::path& path) {
  if (LowerExtension(path) == ".cityjson") return true;
  return LowerExtension(path) == ".json" && LowerExtension(path.stem()) == ".city";
}

bool IsCityJsonSeqPath(const std::filesystem::path& path) {
  return LowerExtension(path) == ".jsonl";
}

Status WriteCityJson(const PolygonMesh& mesh,
                     std::span<const Plane3> planes,
                     const GeoreferenceOptions& options,
                     const std::filesystem::path& path) noexcept {
  return CatchAll(kCityjsonWriteStage, [&] {
    WriteFileAtomically(
        path, CityJsonText(mesh, planes, options, path.string()), kCityjsonWriteStage);
  });
}

Status WriteCityJsonSeq(const PolygonMesh& mesh,
                        std::span<const Plane3> planes,
                        const GeoreferenceOptions& options,
                        const std::filesystem::path& path) noexcept {
  return CatchAll(kCityjsonWriteStage, [&] {
    WriteFileAtomically(
        path, CityJsonSeqText(mesh, planes, options, path.string()), kCityjsonWriteStage);
  });
}

}  // namespace linesurf::io
