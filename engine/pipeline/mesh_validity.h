#pragma once
/// @file mesh_validity.h
/// @brief The one checker of meshes as solid boundaries (MeshValidity, linesurf/result.h): run
/// on every reconstruction by the facade, by `linesurf evaluate` and by the tests. Its edge and
/// fan counts are those of engine/pipeline/mesh_topology.h over the non-degenerate faces; the
/// geometric checks (zero-area and non-planar faces, self-intersection) are its own.

#include "engine/core/polygon_mesh.h"
#include "linesurf/error.h"
#include "linesurf/result.h"

#include <string>
#include <vector>

namespace linesurf {

/// @brief Checks `mesh` for every class of MeshValidity.
/// @return the checks, or kInvalidInput for an index out of range. Deterministic; O(F log F)
/// plus CGAL's self-intersection test (AABB box intersection, O(F log F) typical).
Expected<MeshValidity> CheckMeshValidity(const PolygonMesh& mesh) noexcept;

/// @brief kDegenerate naming every class that makes `validity` unusable as a surface (not
/// closed, not 2-manifold at an edge, not oriented, degenerate or non-planar faces,
/// self-intersection); success otherwise.
[[nodiscard]] Status RefuseBrokenSurface(const MeshValidity& validity);

/// One warning per class that a valid solid must not have but a usable surface may (coincident
/// vertices, touching triangles, zero-area faces); empty when there is none.
[[nodiscard]] std::vector<std::string> SolidValidityWarnings(const MeshValidity& validity);

}  // namespace linesurf
