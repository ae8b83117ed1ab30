#include "engine/io/ifc_write.h"

#include "engine/core/exception.h"
#include "engine/core/public_vector.h"
#include "engine/io/city_model.h"
#include "engine/io/file_access.h"
#include "engine/io/mesh_format.h"
#include "engine/io/number_text.h"
#include "engine/io/reference_system.h"

#include <array>
#include <cmath>
#include <map>
#include <string>
#include <tuple>
#include <vector>

namespace linesurf::io {
namespace {

constexpr const char* kIfcWriteStage = "write_ifc";

/// A STEP real: always with a decimal point ("1.", "1.5", "1.E-05").
std::string StepReal(double value) {
  std::string text;
  AppendDouble(text, value == 0.0 ? 0.0 : value);  // no "-0."
  if (const auto e = text.find('e'); e != std::string::npos) {
    text[e] = 'E';
    if (text.find('.') == std::string::npos) text.insert(e, ".");
  }
  if (text.size() > 2 && text.compare(text.size() - 2, 2, ".0") == 0) text.pop_back();
  return text;
}

// Appended piece by piece: GCC 12 reports false -Wrestrict overlaps in chains of operator+.
void AppendRef(std::string& out, std::size_t id) {
  out += '#';
  AppendUnsigned(out, id);
}

std::string Ref(std::size_t id) {
  std::string out;
  AppendRef(out, id);
  return out;
}

std::string RefList(const std::vector<std::size_t>& ids) {
  std::string out = "(";
  for (std::size_t i = 0; i < ids.size(); ++i) {
    if (i) out += ',';
    AppendRef(out, ids[i]);
  }
  out += ')';
  return out;
}

/// IFC's 22-character GlobalId (128 bits in its base-64 alphabet) of the n-th rooted entity:
/// n in the high word, a mix of n in the low word, so ids are unique and reproducible.
std::string Guid(std::uint64_t n) {
  static constexpr char kDigits[] =
      "0123456789ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz_$";
  std::uint64_t low = n + 0x9E3779B97F4A7C15ull;
  low = (low ^ (low >> 30)) * 0xBF58476D1CE4E5B9ull;
  low = (low ^ (low >> 27)) * 0x94D049BB133111EBull;
  low ^= low >> 31;
  const std::array<std::uint64_t, 2> words = {n, low};
  auto bit = [&](int i) { return (words[i / 64] >> (63 - i % 64)) & 1u; };  // i from the top
  std::string out;
  out += kDigits[(bit(0) << 1) | bit(1)];
  for (int c = 0; c < 21; ++c) {
    unsigned digit = 0;
    for (int k = 0; k < 6; ++k) digit = (digit << 1) | static_cast<unsigned>(bit(2 + 6 * c + k));
    out += kDigits[digit];
  }
  return out;
}

/// The DATA section: entities numbered in the order they are added.
class StepData {
 public:
  std::size_t Add(const std::string& entity) {
    AppendRef(text_, ++count_);
    text_ += '=';
    text_ += entity;
    text_ += ";\n";
    return count_;
  }
  /// A fresh GlobalId, quoted.
  std::string NewGuid() { return "'" + Guid(guids_++) + "'"; }
  [[nodiscard]] const std::string& text() const { return text_; }

 private:
  std::string text_;
  std::size_t count_ = 0;
  std::uint64_t guids_ = 0;
};

std::string PointText(const Vec3& p) {
  return "IFCCARTESIANPOINT((" + StepReal(p.x()) + "," + StepReal(p.y()) + "," +
         StepReal(p.z()) + "))";
}

/// The building's faces and their shell; returns the representation item.
std::size_t AddBody(StepData& data,
                    const PolygonMesh& mesh,
                    const CityBuilding& building,
                    const Vec3& origin) {
  // One point per position the building uses (split copies of a vertex are one point).
  std::map<std::tuple<double, double, double>, std::size_t> point_of;
  auto point = [&](std::uint32_t v) {
    const Vec3& p = mesh.vertices[v];
    const auto [it, added] = point_of.try_emplace({p.x(), p.y(), p.z()}, 0);
    if (added) it->second = data.Add(PointText(p - origin));
    return it->second;
  };
  std::vector<std::size_t> faces;
  for (const CityPolygon& polygon : building.polygons) {
    std::vector<std::size_t> bounds;
    for (std::size_t r = 0; r < polygon.shape.rings.size(); ++r) {
      std::vector<std::size_t> points;
      for (const std::uint32_t v : polygon.shape.rings[r]) {
        const std::size_t p = point(v);
        if (points.empty() || points.back() != p) points.push_back(p);
      }
      while (points.size() > 1 && points.back() == points.front()) points.pop_back();
      if (points.size() < 3) continue;
      const std::size_t loop = data.Add("IFCPOLYLOOP(" + RefList(points) + ")");
      bounds.push_back(data.Add(std::string(r == 0 ? "IFCFACEOUTERBOUND(" : "IFCFACEBOUND(") +
                                Ref(loop) + ",.T.)"));
    }
    if (!bounds.empty()) faces.push_back(data.Add("IFCFACE(" + RefList(bounds) + ")"));
  }
  if (building.solid) {
    const std::size_t shell = data.Add("IFCCLOSEDSHELL(" + RefList(faces) + ")");
    return data.Add("IFCFACETEDBREP(" + Ref(shell) + ")");
  }
  const std::size_t shell = data.Add("IFCOPENSHELL(" + RefList(faces) + ")");
  return data.Add("IFCSHELLBASEDSURFACEMODEL((" + Ref(shell) + "))");
}

std::string IfcText(const PolygonMesh& mesh,
                    std::span<const Plane3> planes,
                    const GeoreferenceOptions& options,
                    const std::string& file) {
  const CityModel model = BuildCityModel(mesh, planes, ToVec3(options.up), file);
  // The site sits at the minimum corner in whole metres: local coordinates stay small.
  const Vec3 origin = model.box.IsEmpty() ? Vec3(Vec3::Zero()) : Vec3(model.box.min.array().floor());
  StepData data;
  std::vector<std::size_t> units;
  for (const char* unit : {"LENGTHUNIT.,$,.METRE.", "AREAUNIT.,$,.SQUARE_METRE.",
                           "VOLUMEUNIT.,$,.CUBIC_METRE.", "PLANEANGLEUNIT.,$,.RADIAN."}) {
    units.push_back(data.Add(std::string("IFCSIUNIT(*,.") + unit + ")"));
  }
  const std::size_t unit_assignment = data.Add("IFCUNITASSIGNMENT(" + RefList(units) + ")");
  const std::size_t zero = data.Add(PointText(Vec3::Zero()));
  const std::size_t identity = data.Add("IFCAXIS2PLACEMENT3D(" + Ref(zero) + ",$,$)");
  const std::size_t context = data.Add("IFCGEOMETRICREPRESENTATIONCONTEXT($,'Model',3,1.E-05," +
                                       Ref(identity) + ",$)");
  const std::size_t project =
      data.Add("IFCPROJECT(" + data.NewGuid() + ",$,'linesurf reconstruction',$,$,$,$,(" +
               Ref(context) + ")," + Ref(unit_assignment) + ")");
  if (!options.crs.empty()) {
    const std::size_t crs =
        data.Add("IFCPROJECTEDCRS('EPSG:" + EpsgCode(options.crs) + "',$,$,$,$,$,$)");
    data.Add("IFCMAPCONVERSION(" + Ref(context) + "," + Ref(crs) + ",0.,0.,0.,$,$,$)");
  }
  const std::size_t site_origin = data.Add(PointText(origin));
  const std::size_t site_axes = data.Add("IFCAXIS2PLACEMENT3D(" + Ref(site_origin) + ",$,$)");
  const std::size_t site_placement = data.Add("IFCLOCALPLACEMENT($," + Ref(site_axes) + ")");
  const std::size_t site = data.Add("IFCSITE(" + data.NewGuid() + ",$,'Site',$,$," +
                                    Ref(site_placement) + ",$,$,.ELEMENT.,$,$,$,$,$)");
  data.Add("IFCRELAGGREGATES(" + data.NewGuid() + ",$,$,$," + Ref(project) + ",(" + Ref(site) +
           "))");
  std::vector<std::size_t> buildings;
  for (std::size_t b = 0; b < model.buildings.size(); ++b) {
    const std::string name = "'building_" + std::to_string(b) + "'";
    const std::size_t placement =
        data.Add("IFCLOCALPLACEMENT(" + Ref(site_placement) + "," + Ref(identity) + ")");
    const std::size_t building = data.Add("IFCBUILDING(" + data.NewGuid() + ",$," + name +
                                          ",$,$," + Ref(placement) + ",$,$,.ELEMENT.,$,$,$)");
    buildings.push_back(building);
    const std::size_t item = AddBody(data, mesh, model.buildings[b], origin);
    const std::size_t representation =
        data.Add("IFCSHAPEREPRESENTATION(" + Ref(context) + ",'Body','" +
                 (model.buildings[b].solid ? "Brep" : "SurfaceModel") + "',(" + Ref(item) + "))");
    const std::size_t shape =
        data.Add("IFCPRODUCTDEFINITIONSHAPE($,$,(" + Ref(representation) + "))");
    const std::size_t element_placement =
        data.Add("IFCLOCALPLACEMENT(" + Ref(placement) + "," + Ref(identity) + ")");
    const std::size_t proxy =
        data.Add("IFCBUILDINGELEMENTPROXY(" + data.NewGuid() + ",$," + name + ",$,$," +
                 Ref(element_placement) + "," + Ref(shape) + ",$,$)");
    data.Add("IFCRELCONTAINEDINSPATIALSTRUCTURE(" + data.NewGuid() + ",$,$,$,(" + Ref(proxy) +
             ")," + Ref(building) + ")");
  }
  if (!buildings.empty()) {
    data.Add("IFCRELAGGREGATES(" + data.NewGuid() + ",$,$,$," + Ref(site) + "," +
             RefList(buildings) + ")");
  }
  // No name or time stamp in the header: the same mesh gives the same bytes wherever written.
  std::string out =
      "ISO-10303-21;\nHEADER;\nFILE_DESCRIPTION(('ViewDefinition [ReferenceView]'),'2;1');\n"
      "FILE_NAME('','',(''),(''),'linesurf','linesurf','');\nFILE_SCHEMA(('IFC4'));\nENDSEC;\n"
      "DATA;\n";
  out += data.text();
  out += "ENDSEC;\nEND-ISO-10303-21;\n";
  return out;
}

}  // namespace

bool IsIfcPath(const std::filesystem::path& path) { return LowerExtension(path) == ".ifc"; }

Status WriteIfc(const PolygonMesh& mesh,
                std::span<const Plane3> planes,
                const GeoreferenceOptions& options,
                const std::filesystem::path& path) noexcept {
  return CatchAll(kIfcWriteStage, [&] {
    WriteFileAtomically(path, IfcText(mesh, planes, options, path.string()), kIfcWriteStage);
  });
}

}  // namespace linesurf::io
