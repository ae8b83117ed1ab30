#include "engine/io/cityjson_write.h"

#include "engine/core/disjoint_sets.h"
#include "engine/core/exception.h"
#include "engine/core/vector_area.h"
#include "engine/io/file_access.h"
#include "engine/io/mesh_format.h"
#include "engine/io/number_text.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <tuple>
#include <vector>

namespace linesurf::io {
namespace {

constexpr const char* kCityjsonWriteStage = "write_cityjson";
/// A face is a wall when its normal is within this angle of horizontal.
constexpr double kWallMaxTiltDeg = 10.0;
/// A face lies on a plane when the normals agree within this angle and every vertex is within
/// kOnPlaneRelative of the mesh's bounding-box diagonal (faces are cut from the planes exactly;
/// only the rounding of the vertices to doubles separates them).
constexpr double kSameNormalDeg = 0.5;
constexpr double kOnPlaneRelative = 1e-7;
/// Quantisation step of the vertices, relative to the largest extent (CityJSON stores integers).
constexpr double kQuantumRelative = 1e-9;

enum class SurfaceType { kRoof, kGround, kWall };

const char* SurfaceTypeName(SurfaceType type) {
  switch (type) {
    case SurfaceType::kRoof:
      return "RoofSurface";
    case SurfaceType::kGround:
      return "GroundSurface";
    case SurfaceType::kWall:
      return "WallSurface";
  }
  return "WallSurface";
}

/// Newell's normal of a polygon (unit length; zero for a degenerate face).
Vec3 FaceNormal(const PolygonMesh& mesh, std::span<const std::uint32_t> face) {
  const Vec3 n = TwiceVectorArea(mesh.vertices, face);
  const double length = n.norm();
  return length > 0.0 ? Vec3(n / length) : Vec3(Vec3::Zero());
}

/// The plane `face` lies on (smallest largest vertex distance among those within tolerance),
/// or -1.
long long FacePlane(const PolygonMesh& mesh,
                    std::span<const std::uint32_t> face,
                    const Vec3& normal,
                    std::span<const Plane3> planes,
                    double tolerance) {
  const double min_cos = std::cos(kSameNormalDeg * M_PI / 180.0);
  long long best = -1;
  double best_distance = tolerance;
  for (std::size_t p = 0; p < planes.size(); ++p) {
    if (std::abs(planes[p].normal.normalized().dot(normal)) < min_cos) continue;
    double distance = 0.0;
    for (const std::uint32_t v : face) {
      distance = std::max(
          distance, std::abs(planes[p].SignedDistance(mesh.vertices[v])) / planes[p].normal.norm());
    }
    if (distance <= best_distance) {
      best_distance = distance;
      best = static_cast<long long>(p);
    }
  }
  return best;
}

SurfaceType TypeOf(const Vec3& normal) {
  if (std::abs(normal.z()) <= std::sin(kWallMaxTiltDeg * M_PI / 180.0)) return SurfaceType::kWall;
  return normal.z() > 0.0 ? SurfaceType::kRoof : SurfaceType::kGround;
}

void AppendDoubles(std::string& out, std::initializer_list<double> values) {
  out += '[';
  bool first = true;
  for (const double v : values) {
    if (!first) out += ", ";
    first = false;
    AppendDouble(out, v);
  }
  out += ']';
}

void AppendSigned(std::string& out, long long value) {
  if (value < 0) out += '-';
  AppendUnsigned(out, static_cast<unsigned long long>(value < 0 ? -value : value));
}

std::string CityJsonText(const PolygonMesh& mesh,
                         std::span<const Plane3> planes,
                         const std::string& file) {
  const std::size_t num_faces = mesh.NumFaces();
  DisjointSets sets(mesh.vertices.size());
  std::vector<bool> used(mesh.vertices.size(), false);
  Box3 box;
  for (std::size_t f = 0; f < num_faces; ++f) {
    const auto face = mesh.Face(f);
    LINESURF_THROW_IF(face.size() < 3,
                      kInvalidInput,
                      kCityjsonWriteStage,
                      file << ": face " << f << " has " << face.size() << " vertices");
    for (const std::uint32_t v : face) {
      LINESURF_THROW_IF(v >= mesh.vertices.size(),
                        kInvalidInput,
                        kCityjsonWriteStage,
                        file << ": face " << f << ": vertex " << v << " out of range ("
                             << mesh.vertices.size() << " vertices)");
      LINESURF_THROW_IF(!mesh.vertices[v].allFinite(),
                        kInvalidInput,
                        kCityjsonWriteStage,
                        file << ": vertex " << v << " is not finite");
      sets.Union(face[0], v);
      used[v] = true;
      box.Extend(mesh.vertices[v]);
    }
  }
  // Components numbered by their first face; vertices renumbered in index order, used only.
  std::map<std::size_t, std::size_t> component_of_root;
  std::vector<std::size_t> component(num_faces);
  for (std::size_t f = 0; f < num_faces; ++f) {
    const std::size_t root = sets.Find(mesh.Face(f)[0]);
    component[f] = component_of_root.try_emplace(root, component_of_root.size()).first->second;
  }
  std::vector<std::uint32_t> new_index(mesh.vertices.size(), 0);
  std::uint32_t next = 0;
  for (std::size_t v = 0; v < used.size(); ++v) {
    if (used[v]) new_index[v] = next++;
  }
  const Vec3 translate = box.IsEmpty() ? Vec3(Vec3::Zero()) : box.min;
  const double extent = box.IsEmpty() ? 0.0 : box.Extent().maxCoeff();
  const double scale =
      extent > 0.0 ? std::pow(10.0, std::floor(std::log10(extent * kQuantumRelative))) : 0.001;
  const double tolerance = kOnPlaneRelative * (box.IsEmpty() ? 0.0 : box.Extent().norm());

  // Per face: normal, plane, semantic type; per component: signed volume (about `translate`).
  std::vector<Vec3> normals(num_faces);
  std::vector<long long> face_plane(num_faces);
  std::vector<double> volume(component_of_root.size(), 0.0);
  for (std::size_t f = 0; f < num_faces; ++f) {
    const auto face = mesh.Face(f);
    normals[f] = FaceNormal(mesh, face);
    face_plane[f] = FacePlane(mesh, face, normals[f], planes, tolerance);
    const Vec3 a = mesh.vertices[face[0]] - translate;
    for (std::size_t i = 1; i + 1 < face.size(); ++i) {
      volume[component[f]] +=
          a.dot(
              (mesh.vertices[face[i]] - translate).cross(mesh.vertices[face[i + 1]] - translate)) /
          6.0;
    }
  }

  std::string out = "{\n  \"type\": \"CityJSON\",\n  \"version\": \"1.1\",\n";
  out += "  \"transform\": {\"scale\": ";
  AppendDoubles(out, {scale, scale, scale});
  out += ", \"translate\": ";
  AppendDoubles(out, {translate.x(), translate.y(), translate.z()});
  out += "},\n  \"metadata\": {\"geographicalExtent\": ";
  if (box.IsEmpty()) {
    out += "[0.0, 0.0, 0.0, 0.0, 0.0, 0.0]";
  } else {
    AppendDoubles(out,
                  {box.min.x(), box.min.y(), box.min.z(), box.max.x(), box.max.y(), box.max.z()});
  }
  out += "},\n  \"CityObjects\": {";
  std::vector<std::vector<std::size_t>> faces_of(component_of_root.size());
  for (std::size_t f = 0; f < num_faces; ++f) faces_of[component[f]].push_back(f);
  for (std::size_t c = 0; c < faces_of.size(); ++c) {
    const bool solid = volume[c] > 0.0;
    // Semantic surfaces of this building: one per (plane, type), in first-face order.
    std::map<std::pair<long long, SurfaceType>, std::size_t> surface_index;
    std::vector<std::pair<long long, SurfaceType>> surfaces;
    std::vector<std::size_t> face_surface;
    for (const std::size_t f : faces_of[c]) {
      const auto key = std::make_pair(face_plane[f], TypeOf(normals[f]));
      const auto [it, added] = surface_index.try_emplace(key, surfaces.size());
      if (added) surfaces.push_back(key);
      face_surface.push_back(it->second);
    }
    out += c ? ",\n" : "\n";
    out += "    \"building_";
    AppendUnsigned(out, c);
    out += "\": {\n      \"type\": \"Building\",\n      \"geometry\": [{\n        \"type\": \"";
    out += solid ? "Solid" : "CompositeSurface";
    out += "\",\n        \"lod\": \"2\",\n        \"boundaries\": ";
    out += solid ? "[[" : "[";
    for (std::size_t k = 0; k < faces_of[c].size(); ++k) {
      out += k ? ", [[" : "[[";
      const auto face = mesh.Face(faces_of[c][k]);
      for (std::size_t i = 0; i < face.size(); ++i) {
        if (i) out += ", ";
        AppendUnsigned(out, new_index[face[i]]);
      }
      out += "]]";
    }
    out += solid ? "]],\n" : "],\n";
    out += "        \"semantics\": {\n          \"surfaces\": [";
    for (std::size_t s = 0; s < surfaces.size(); ++s) {
      out += s ? ",\n            {\"type\": \"" : "\n            {\"type\": \"";
      out += SurfaceTypeName(surfaces[s].second);
      out += '"';
      const long long p = surfaces[s].first;
      if (p >= 0) {
        const Plane3& plane = planes[static_cast<std::size_t>(p)];
        const Vec3 n = plane.normal.normalized();
        out += ", \"plane_index\": ";
        AppendSigned(out, p);
        out += ", \"plane\": ";
        AppendDoubles(out, {n.x(), n.y(), n.z(), -n.dot(plane.point)});
      }
      out += '}';
    }
    out += "\n          ],\n          \"values\": ";
    out += solid ? "[[" : "[";
    for (std::size_t k = 0; k < face_surface.size(); ++k) {
      if (k) out += ", ";
      AppendUnsigned(out, face_surface[k]);
    }
    out += solid ? "]]\n" : "]\n";
    out += "        }\n      }]\n    }";
  }
  out += faces_of.empty() ? "},\n" : "\n  },\n";
  out += "  \"vertices\": [";
  bool first = true;
  for (std::size_t v = 0; v < used.size(); ++v) {
    if (!used[v]) continue;
    out += first ? "\n    [" : ",\n    [";
    first = false;
    for (int k = 0; k < 3; ++k) {
      if (k) out += ", ";
      AppendSigned(out, std::llround((mesh.vertices[v][k] - translate[k]) / scale));
    }
    out += ']';
  }
  out += first ? "]\n}\n" : "\n  ]\n}\n";
  return out;
}

}  // namespace

bool IsCityJsonPath(const std::filesystem::path& path) {
  if (LowerExtension(path) == ".cityjson") return true;
  return LowerExtension(path) == ".json" && LowerExtension(path.stem()) == ".city";
}

Status WriteCityJson(const PolygonMesh& mesh,
                     std::span<const Plane3> planes,
                     const std::filesystem::path& path) noexcept {
  return CatchAll(kCityjsonWriteStage, [&] {
    WriteFileAtomically(path, CityJsonText(mesh, planes, path.string()), kCityjsonWriteStage);
  });
}

}  // namespace linesurf::io
