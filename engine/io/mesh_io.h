#pragma once
// Polygon mesh files: PLY (binary little-endian by default, ASCII on request), OBJ and OFF
// (docs/user/formats.md). The format follows the file extension (.ply, .obj, .off; any case).

#include <filesystem>

#include "linesurf/error.h"
#include "engine/core/polygon_mesh.h"

namespace linesurf::io {

struct MeshWriteOptions {
  /// PLY only: write `format ascii 1.0` instead of binary little-endian (OBJ/OFF are always text).
  bool ascii = false;
  /// Split every face with more than 3 vertices into triangles (FaceTriangles: the fan around
  /// its first vertex when convex, ear clipping when not); default keeps polygons.
  bool triangulate = false;
};

/// @brief Writes `mesh` (coordinates as stored, in metres). Binary PLY stores doubles; text
/// formats use the shortest text that reads back to the same double. Written to a temporary name
/// then renamed. Fails with kInvalidInput on an unknown extension, a face with fewer than 3
/// vertices or an index out of range, a non-finite coordinate, or an unwritable path.
[[nodiscard]] Status WriteMesh(const PolygonMesh& mesh, const std::filesystem::path& path,
                               const MeshWriteOptions& options = {}) noexcept;

/// @brief Reads a PLY (ascii, binary little or big endian; float or double vertices; any integer
/// list types), OBJ (`v`, `f` with `a`, `a/b`, `a/b/c`, `a//c` forms and negative indices; other
/// records ignored) or OFF file. Fails with kInvalidInput naming the file and the line (text) or
/// element (binary) at fault.
[[nodiscard]] Expected<PolygonMesh> ReadMesh(const std::filesystem::path& path) noexcept;

}  // namespace linesurf::io
