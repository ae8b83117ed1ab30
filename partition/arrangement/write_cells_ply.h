#pragma once
// Debug export of a CellComplex: every cell as its own closed polyhedron, shrunk toward its
// vertex centroid so that neighbouring cells do not overlap in a viewer.

#include <filesystem>

#include "engine/core/cell_complex.h"
#include "engine/core/geometry.h"
#include "linesurf/error.h"

namespace linesurf::partition {

struct CellsPlyOptions {
  /// Each cell vertex v is written at centroid + shrink * (v - centroid). Range (0, 1].
  double shrink = 0.8;
  /// Added to every written point (e.g. world_from_local.translation to write world coordinates).
  Vec3 translation = Vec3::Zero();

  [[nodiscard]] Status Validate() const;
};

/// Writes binary little-endian PLY: float vertices; faces with vertex_indices, the int property
/// `cell` and an RGB colour from the cell's 2-colouring; faces counter-clockwise seen from
/// outside their cell.
[[nodiscard]] Status WriteCellsPly(const CellComplex& complex, const std::filesystem::path& path,
                                   const CellsPlyOptions& options = {}) noexcept;

}  // namespace linesurf::partition
