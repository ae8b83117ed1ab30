#pragma once
// A closed mesh read as buildings: connected parts, their faces joined per plane into polygons
// with holes, each tagged with a semantic class. What the CityJSON writers serialise
// (docs/user/formats.md); plain data, world coordinates.

#include "engine/core/geometry.h"
#include "engine/core/polygon_mesh.h"
#include "engine/io/planar_polygons.h"

#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace linesurf::io {

/// Semantic classes of a building's surfaces (CityJSON 2.0 names). The exterior classes for a
/// part that encloses a volume, the interior ones for a part seen from inside (a room).
enum class SurfaceClass { kRoof, kGround, kWall, kCeiling, kFloor, kInteriorWall };

[[nodiscard]] const char* CityJsonName(SurfaceClass type);

/// One semantic surface: a class, and the detected plane its polygons lie on if any.
struct CitySurface {
  std::optional<std::size_t> plane;
  SurfaceClass type = SurfaceClass::kWall;
};

struct CityPolygon {
  PlanarPolygon shape;  ///< indices into the mesh's vertices
  std::size_t surface;  ///< index into CityBuilding::surfaces
};

struct CityBuilding {
  /// The part encloses a positive volume (faces outward); else it is seen from inside.
  bool solid = true;
  std::vector<CityPolygon> polygons;
  std::vector<CitySurface> surfaces;  ///< one per (plane, class), in first-polygon order
};

struct CityModel {
  std::vector<CityBuilding> buildings;  ///< in the order of their first face
  Box3 box;                             ///< of the vertices the faces use
};

/// @brief The buildings of `mesh` (faces counter-clockwise seen from outside, world
/// coordinates): one per connected part (faces sharing vertices); a face lies on a plane of
/// `planes` when the normals agree within 0.5 degrees and every vertex is within 1e-7 of the
/// mesh's bounding-box diagonal; a face is a wall when its normal is within 10 degrees of
/// vertical (`up` is up; not zero), else a roof or ground (floor or ceiling inside). Faces of one plane,
/// class and orientation are joined by JoinIntoPlanarPolygons; faces on no plane stay as they
/// are.
/// @throws LinesurfException kInvalidInput naming `file` on a face with fewer than 3 vertices,
/// an index out of range or a non-finite coordinate.
[[nodiscard]] CityModel BuildCityModel(const PolygonMesh& mesh,
                                       std::span<const Plane3> planes,
                                       const Vec3& up,
                                       const std::string& file);

}  // namespace linesurf::io
