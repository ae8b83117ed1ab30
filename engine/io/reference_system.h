#pragma once
// The coordinate reference system of GeoreferenceOptions, "EPSG:CODE", as the writers of
// georeferenced formats name it.

#include <string>

namespace linesurf::io {

/// The digits of `crs` ("EPSG:CODE", case-insensitive prefix).
/// @throws LinesurfException kInvalidOptions naming the field when `crs` is not of that form.
[[nodiscard]] std::string EpsgCode(const std::string& crs);

}  // namespace linesurf::io
