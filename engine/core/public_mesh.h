#pragma once
/// @file public_mesh.h
/// @brief The facade's plain Mesh (linesurf/types.h) and the engine's PolygonMesh, both ways
/// (the facade's results and writers, the CLI's checks of a facade mesh).

#include "linesurf/error.h"
#include "linesurf/types.h"

#include "engine/core/polygon_mesh.h"

namespace linesurf {

[[nodiscard]] Mesh ToMesh(const PolygonMesh& mesh);

/// @return kInvalidInput when the face offsets do not start at 0, decrease, or end elsewhere than
/// at the number of face indices (vertex indices are checked by the writers).
[[nodiscard]] Expected<PolygonMesh> ToPolygonMesh(const Mesh& mesh);

}  // namespace linesurf
