#pragma once
// Closed meshes as IFC4 buildings (STEP physical file, ISO 10303-21) for BIM tools
// (docs/user/formats.md).

#include "linesurf/error.h"
#include "linesurf/options.h"

#include "engine/core/geometry.h"
#include "engine/core/polygon_mesh.h"

#include <filesystem>
#include <span>

namespace linesurf::io {

/// True for the extension that selects the IFC writer: `.ifc` (any case).
[[nodiscard]] bool IsIfcPath(const std::filesystem::path& path);

/// @brief Writes `mesh` (world coordinates in metres, faces counter-clockwise seen from
/// outside) as an IFC4 file: IfcProject (metre, square metre, cubic metre, radian) with one
/// IfcSite, and per part of BuildCityModel an IfcBuilding holding one IfcBuildingElementProxy
/// whose Body is an IfcFacetedBrep (a part that encloses a volume) or an
/// IfcShellBasedSurfaceModel of an open shell (a room seen from inside); its faces are the
/// part's polygons joined per plane, holes as inner bounds. Coordinates are stored relative to
/// the site's placement, the mesh's minimum corner rounded down to whole metres, so large
/// georeferenced coordinates keep their precision; with options.crs, IfcProjectedCRS names it
/// and IfcMapConversion maps the project's coordinates to it unchanged. GUIDs are derived from
/// the entity's position in the file: the same mesh gives the same bytes. Written to a
/// temporary name then renamed.
/// @return kInvalidInput on a face with fewer than 3 vertices or an index out of range, a
/// non-finite coordinate or an unwritable path; kInvalidOptions on a crs not "EPSG:CODE".
[[nodiscard]] Status WriteIfc(const PolygonMesh& mesh,
                              std::span<const Plane3> planes,
                              const GeoreferenceOptions& options,
                              const std::filesystem::path& path) noexcept;

}  // namespace linesurf::io
