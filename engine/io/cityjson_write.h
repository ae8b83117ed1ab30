#pragma once
// Closed meshes as CityJSON 2.0 buildings, as one document or as a CityJSONSeq stream, for city
// and BIM pipelines (docs/user/formats.md).

#include "linesurf/error.h"
#include "linesurf/options.h"

#include "engine/core/geometry.h"
#include "engine/core/polygon_mesh.h"

#include <filesystem>
#include <span>

namespace linesurf::io {

/// True for the extensions that select the CityJSON writer: `.city.json` and `.cityjson`.
[[nodiscard]] bool IsCityJsonPath(const std::filesystem::path& path);

/// True for the extensions that select the CityJSONSeq writer: `.city.jsonl` and `.jsonl`.
[[nodiscard]] bool IsCityJsonSeqPath(const std::filesystem::path& path);

/// @brief Writes `mesh` (world coordinates, faces counter-clockwise seen from outside) as a
/// CityJSON 2.0 file: one `Building` per part of BuildCityModel, each with one LoD 2.2
/// geometry, a `Solid` when the part encloses a positive volume, else a `CompositeSurface`
/// (the inside of a room), whose surfaces are the part's polygons joined per plane (holes as
/// inner rings). Every polygon gets a semantic surface, one per (plane, class), with attributes
/// `plane_index` and `plane` [a, b, c, d] (ax+by+cz+d = 0) when it lies on a plane of
/// `planes`. Vertices quantised by the `transform` (translate: the box's minimum corner, scale:
/// a power of ten at most 1e-9 of the largest extent), positions that quantise alike written
/// once, repeated ring points dropped. `metadata` holds the `geographicalExtent` and, with
/// options.crs, the `referenceSystem`. Written to a temporary name then renamed.
/// @return kInvalidInput on a face with fewer than 3 vertices or an index out of range, a
/// non-finite coordinate or an unwritable path; kInvalidOptions on a crs not "EPSG:CODE".
[[nodiscard]] Status WriteCityJson(const PolygonMesh& mesh,
                                   std::span<const Plane3> planes,
                                   const GeoreferenceOptions& options,
                                   const std::filesystem::path& path) noexcept;

/// @brief The same buildings as a CityJSONSeq file (one JSON object per line): first the
/// `CityJSON` header (version, transform, metadata, no objects), then one `CityJSONFeature` per
/// building with its own vertices, in building order. Written to a temporary name then renamed.
/// @return as WriteCityJson.
[[nodiscard]] Status WriteCityJsonSeq(const PolygonMesh& mesh,
                                      std::span<const Plane3> planes,
                                      const GeoreferenceOptions& options,
                                      const std::filesystem::path& path) noexcept;

}  // namespace linesurf::io
