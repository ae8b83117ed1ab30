#include "engine/io/city_model.h"

#include "engine/core/disjoint_sets.h"
#include "engine/core/exception.h"
#include "engine/core/vector_area.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>

namespace linesurf::io {
namespace {

constexpr const char* kCityModelStage = "city_model";
constexpr double kWallMaxTiltDeg = 10.0;
/// Faces are cut from the planes exactly; only the rounding of their vertices to doubles
/// separates them from their plane.
constexpr double kSameNormalDeg = 0.5;
constexpr double kOnPlaneRelative = 1e-7;

/// Newell's normal of a polygon (unit length; zero for a degenerate face).
Vec3 FaceNormal(const PolygonMesh& mesh, std::span<const std::uint32_t> face) {
  const Vec3 n = TwiceVectorArea(mesh.vertices, face);
  const double length = n.norm();
  return length > 0.0 ? Vec3(n / length) : Vec3(Vec3::Zero());
}

/// The plane `face` lies on (smallest largest vertex distance among those within tolerance).
std::optional<std::size_t> FacePlane(const PolygonMesh& mesh,
                                     std::span<const std::uint32_t> face,
                                     const Vec3& normal,
                                     std::span<const Plane3> planes,
                                     double tolerance) {
  const double min_cos = std::cos(kSameNormalDeg * M_PI / 180.0);
  std::optional<std::size_t> best;
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
      best = p;
    }
  }
  return best;
}

/// `up` is unit.
SurfaceClass ClassOf(const Vec3& normal, const Vec3& up, bool solid) {
  const double rise = normal.dot(up);
  const bool wall = std::abs(rise) <= std::sin(kWallMaxTiltDeg * M_PI / 180.0);
  if (solid) {
    if (wall) return SurfaceClass::kWall;
    return rise > 0.0 ? SurfaceClass::kRoof : SurfaceClass::kGround;
  }
  // Seen from inside, a face's normal points into the room.
  if (wall) return SurfaceClass::kInteriorWall;
  return rise > 0.0 ? SurfaceClass::kFloor : SurfaceClass::kCeiling;
}

void CheckFaces(const PolygonMesh& mesh, const std::string& file) {
  for (std::size_t f = 0; f < mesh.NumFaces(); ++f) {
    const auto face = mesh.Face(f);
    LINESURF_THROW_IF(face.size() < 3,
                      kInvalidInput,
                      kCityModelStage,
                      file << ": face " << f << " has " << face.size() << " vertices");
    for (const std::uint32_t v : face) {
      LINESURF_THROW_IF(v >= mesh.vertices.size(),
                        kInvalidInput,
                        kCityModelStage,
                        file << ": face " << f << ": vertex " << v << " out of range ("
                             << mesh.vertices.size() << " vertices)");
      LINESURF_THROW_IF(!mesh.vertices[v].allFinite(),
                        kInvalidInput,
                        kCityModelStage,
                        file << ": vertex " << v << " is not finite");
    }
  }
}

/// The faces of each connected part (faces sharing vertices), parts in first-face order.
std::vector<std::vector<std::uint32_t>> FacesOfParts(const PolygonMesh& mesh) {
  DisjointSets sets(mesh.vertices.size());
  for (std::size_t f = 0; f < mesh.NumFaces(); ++f) {
    for (const std::uint32_t v : mesh.Face(f)) sets.Union(mesh.Face(f)[0], v);
  }
  std::map<std::size_t, std::size_t> part_of_root;
  std::vector<std::vector<std::uint32_t>> faces_of;
  for (std::uint32_t f = 0; f < mesh.NumFaces(); ++f) {
    const auto [it, added] = part_of_root.try_emplace(sets.Find(mesh.Face(f)[0]), faces_of.size());
    if (added) faces_of.emplace_back();
    faces_of[it->second].push_back(f);
  }
  return faces_of;
}

/// Six times the signed volume the faces enclose, about `origin` (for precision).
double SixVolume(const PolygonMesh& mesh, std::span<const std::uint32_t> faces,
                 const Vec3& origin) {
  double sum = 0.0;
  for (const std::uint32_t f : faces) {
    const auto face = mesh.Face(f);
    const Vec3 a = mesh.vertices[face[0]] - origin;
    for (std::size_t i = 1; i + 1 < face.size(); ++i) {
      sum += a.dot((mesh.vertices[face[i]] - origin).cross(mesh.vertices[face[i + 1]] - origin));
    }
  }
  return sum;
}

CityBuilding BuildBuilding(const PolygonMesh& mesh,
                           std::span<const std::uint32_t> faces,
                           std::span<const Plane3> planes,
                           const Vec3& up,
                           const Box3& box) {
  CityBuilding building;
  building.solid = SixVolume(mesh, faces, box.min) > 0.0;
  const double tolerance = kOnPlaneRelative * box.Extent().norm();
  // Faces joined per (plane, class, side of the plane); a face on no plane is a group alone.
  using GroupKey = std::tuple<std::size_t, SurfaceClass, bool>;
  std::map<GroupKey, std::size_t> group_of_key;
  std::vector<std::vector<std::uint32_t>> groups;
  std::vector<CitySurface> group_surface;
  std::vector<Vec3> group_normal;
  for (const std::uint32_t f : faces) {
    const Vec3 normal = FaceNormal(mesh, mesh.Face(f));
    const std::optional<std::size_t> plane =
        FacePlane(mesh, mesh.Face(f), normal, planes, tolerance);
    const CitySurface surface{plane, ClassOf(normal, up, building.solid)};
    std::size_t group = groups.size();
    if (plane) {
      const bool side = planes[*plane].normal.dot(normal) > 0.0;
      group = group_of_key.try_emplace({*plane, surface.type, side}, groups.size()).first->second;
    }
    if (group == groups.size()) {
      groups.emplace_back();
      group_surface.push_back(surface);
      group_normal.push_back(plane ? Vec3(planes[*plane].normal.normalized()) : normal);
      if (plane && group_normal.back().dot(normal) < 0.0) group_normal.back() *= -1.0;
    }
    groups[group].push_back(f);
  }
  std::map<std::pair<std::optional<std::size_t>, SurfaceClass>, std::size_t> surface_of_key;
  for (std::size_t g = 0; g < groups.size(); ++g) {
    const CitySurface& surface = group_surface[g];
    const auto [it, added] =
        surface_of_key.try_emplace({surface.plane, surface.type}, building.surfaces.size());
    if (added) building.surfaces.push_back(surface);
    for (PlanarPolygon& shape : JoinIntoPlanarPolygons(mesh, groups[g], group_normal[g])) {
      building.polygons.push_back({std::move(shape), it->second});
    }
  }
  return building;
}

/// One pass of a ring through a point: the ring (an index into the building's rings) and the
/// point's position in it.
struct RingPass {
  std::size_t ring;
  std::size_t position;
};

/// True when `p` and every point of `between` lie strictly between `a` and `b` along the
/// segment and within `tolerance` of it.
bool AllStraightBetween(const PolygonMesh& mesh,
                        std::uint32_t a,
                        std::uint32_t b,
                        std::uint32_t p,
                        const std::vector<std::uint32_t>& between,
                        double tolerance) {
  const Vec3& pa = mesh.vertices[a];
  const Vec3 ab = mesh.vertices[b] - pa;
  if (!(ab.squaredNorm() > 0.0)) return false;
  auto straight = [&](std::uint32_t v) {
    const Vec3 ap = mesh.vertices[v] - pa;
    const double t = ap.dot(ab) / ab.squaredNorm();
    return t > 0.0 && t < 1.0 && (ap - t * ab).norm() <= tolerance;
  };
  return straight(p) && std::all_of(between.begin(), between.end(), straight);
}

/// Drops from the rings of `building` the points that only the two polygons on either side of
/// one edge chain use and that lie straight (within `tolerance`) between their remaining ring
/// neighbours: block seams and planes that end on a face leave such points along edges. Both
/// rings lose the point at once and keep the same neighbours, so the shell stays closed. A
/// point three or more rings pass is a corner of the shell, where three or more polygons meet,
/// and stays whatever its angles: at a gable's ridge end next to the points where a stray
/// plane cut the roof edges a tenth of a millimetre away, every ring looks straight within the
/// tolerance, and dropping the ridge end from all of them would join polygons that do not meet
/// (test CityJson.RidgeEndNextToSliverCutStaysAndTheShellStaysClosed). A point only one ring
/// passes (the rim of an open surface) is dropped when straight. Each dropped point stays within
/// `tolerance` of the edge that replaces it and of the points it replaced; points are visited in
/// index order, so the result is deterministic.
void DropStraightRingPoints(const PolygonMesh& mesh, double tolerance, CityBuilding& building) {
  std::vector<std::vector<std::uint32_t>*> rings;
  for (CityPolygon& polygon : building.polygons) {
    for (auto& ring : polygon.shape.rings) rings.push_back(&ring);
  }
  std::map<std::uint32_t, std::vector<RingPass>> passes_of;
  // Per ring position: the neighbouring positions still in the ring, and the dropped points
  // the edge from this position to the next one replaces.
  std::vector<std::vector<std::size_t>> next(rings.size());
  std::vector<std::vector<std::size_t>> previous(rings.size());
  std::vector<std::vector<std::vector<std::uint32_t>>> replaced(rings.size());
  std::vector<std::size_t> size(rings.size());
  std::vector<std::vector<bool>> kept(rings.size());
  for (std::size_t r = 0; r < rings.size(); ++r) {
    const std::size_t n = rings[r]->size();
    size[r] = n;
    next[r].resize(n);
    previous[r].resize(n);
    replaced[r].resize(n);
    kept[r].assign(n, true);
    for (std::size_t i = 0; i < n; ++i) {
      next[r][i] = (i + 1) % n;
      previous[r][i] = (i + n - 1) % n;
      passes_of[(*rings[r])[i]].push_back({r, i});
    }
  }
  auto vertex = [&](std::size_t r, std::size_t i) { return (*rings[r])[i]; };
  // Unlinks position i of ring r; the edge before it takes over what both edges replaced.
  auto unlink = [&](std::size_t r, std::size_t i) {
    const std::size_t before = previous[r][i];
    const std::size_t after = next[r][i];
    auto& merged = replaced[r][before];
    merged.push_back(vertex(r, i));
    merged.insert(merged.end(), replaced[r][i].begin(), replaced[r][i].end());
    next[r][before] = after;
    previous[r][after] = before;
    kept[r][i] = false;
    --size[r];
  };
  for (const auto& [v, passes] : passes_of) {
    if (passes.size() > 2) continue;
    const auto [r, i] = passes.front();
    if (size[r] <= 3) continue;
    const std::uint32_t a = vertex(r, previous[r][i]);
    const std::uint32_t b = vertex(r, next[r][i]);
    if (passes.size() == 2) {
      // The other ring must run the same chain backwards: b -> v -> a.
      const auto [s, j] = passes.back();
      if (size[s] <= 3 || vertex(s, previous[s][j]) != b || vertex(s, next[s][j]) != a) {
        continue;
      }
    }
    std::vector<std::uint32_t> between = replaced[r][previous[r][i]];
    between.insert(between.end(), replaced[r][i].begin(), replaced[r][i].end());
    if (!AllStraightBetween(mesh, a, b, v, between, tolerance)) continue;
    for (const auto& [s, j] : passes) unlink(s, j);
  }
  for (std::size_t r = 0; r < rings.size(); ++r) {
    std::vector<std::uint32_t> remaining;
    for (std::size_t i = 0; i < rings[r]->size(); ++i) {
      if (kept[r][i]) remaining.push_back(vertex(r, i));
    }
    *rings[r] = std::move(remaining);
  }
}

}  // namespace

const char* CityJsonName(SurfaceClass type) {
  switch (type) {
    case SurfaceClass::kRoof:
      return "RoofSurface";
    case SurfaceClass::kGround:
      return "GroundSurface";
    case SurfaceClass::kWall:
      return "WallSurface";
    case SurfaceClass::kCeiling:
      return "CeilingSurface";
    case SurfaceClass::kFloor:
      return "FloorSurface";
    case SurfaceClass::kInteriorWall:
      return "InteriorWallSurface";
  }
  return "WallSurface";
}

CityModel BuildCityModel(const PolygonMesh& mesh,
                         std::span<const Plane3> planes,
                         const Vec3& up,
                         const std::string& file) {
  CheckFaces(mesh, file);
  const Vec3 unit_up = up.normalized();
  CityModel model;
  for (const std::uint32_t v : mesh.face_indices) model.box.Extend(mesh.vertices[v]);
  const double tolerance = kOnPlaneRelative * model.box.Extent().norm();
  for (const auto& faces : FacesOfParts(mesh)) {
    model.buildings.push_back(BuildBuilding(mesh, faces, planes, unit_up, model.box));
    DropStraightRingPoints(mesh, tolerance, model.buildings.back());
  }
  return model;
}

}  // namespace linesurf::io
