#pragma once
// The largest coordinate any input may carry, and the check of a mesh against it.

#include "engine/core/geometry.h"
#include "engine/core/polygon_mesh.h"

#include <cmath>
#include <cstdio>
#include <optional>
#include <string>

namespace linesurf {

/// Largest coordinate magnitude of any input (scenes: sanitation drops what lies beyond; meshes:
/// readers and evaluation refuse it). At 1e12 the spacing of doubles is ~1e-4, useless for
/// geometry; beyond some 1e100 products of coordinates (normals, areas, the exact predicates'
/// conversions) overflow to inf, which GMP answers with SIGFPE.
inline constexpr double kMaxAbsCoordinate = 1e12;

/// True when every coordinate of `p` is finite and within +-kMaxAbsCoordinate.
inline bool WithinCoordinateBound(const Vec3& p) {
  return (p.array().abs() <= kMaxAbsCoordinate).all();  // false for NaN
}

/// "vertex 3: coordinate 1e+120 is not finite or beyond +-1e+12" for the first vertex outside
/// the bound, nullopt when every vertex is within it.
inline std::optional<std::string> CoordinateBoundViolation(const PolygonMesh& mesh) {
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
    const Vec3& p = mesh.vertices[v];
    if (WithinCoordinateBound(p)) continue;
    int k = 0;
    while (k < 2 && std::abs(p[k]) <= kMaxAbsCoordinate) ++k;
    char text[128];
    std::snprintf(text,
                  sizeof(text),
                  "vertex %zu: coordinate %.6g is not finite or beyond +-%.6g",
                  v,
                  p[k],
                  kMaxAbsCoordinate);
    return std::string(text);
  }
  return std::nullopt;
}

}  // namespace linesurf
