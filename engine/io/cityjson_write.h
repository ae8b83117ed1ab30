#pragma once
// Closed meshes as CityJSON 1.1 buildings for city and BIM pipelines (docs/formats.md).

#include "linesurf/error.h"

#include "engine/core/geometry.h"
#include "engine/core/polygon_mesh.h"

#include <filesystem>
#include <span>

namespace linesurf::io {

/// True for the extensions that select the CityJSON writer: `.city.json` and `.cityjson`.
[[nodiscard]] bool IsCityJsonPath(const std::filesystem::path& path);

/// @brief Writes `mesh` (world coordinates, faces counter-clockwise seen from outside) as a
/// CityJSON 1.1 file: one `Building` per connected component (faces sharing vertices), each with
/// one LoD 2 geometry: a `Solid` when the component encloses a positive volume, else a
/// `CompositeSurface` (e.g. the inside of a room). Every face gets a semantic surface: one per
/// plane of `planes` (world coordinates) the building has faces on, `RoofSurface`,
/// `GroundSurface` or `WallSurface` from the face normal (wall within 10 degrees of vertical),
/// with attributes `plane_index` and `plane` [a, b, c, d] (ax+by+cz+d = 0); faces on no plane
/// get a surface of their type without them. Vertices are quantised (CityJSON `transform`) to
/// 1e-9 of the largest extent. Written to a temporary name then renamed.
/// @return kInvalidInput on a face with fewer than 3 vertices or an index out of range, a
/// non-finite coordinate or an unwritable path.
[[nodiscard]] Status WriteCityJson(const PolygonMesh& mesh,
                                   std::span<const Plane3> planes,
                                   const std::filesystem::path& path) noexcept;

}  // namespace linesurf::io
