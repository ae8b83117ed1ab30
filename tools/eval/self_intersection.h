#pragma once
/// @file self_intersection.h
/// @brief The self-intersection check of `linesurf evaluate` on a facade mesh (linesurf/types.h),
/// for the commands that hold only facade types.

#include "linesurf/error.h"
#include "linesurf/types.h"

namespace linesurf {

/// @brief Whether two faces of `mesh` intersect other than at a shared edge or vertex
/// (MeshTopology::self_intersecting of CheckMeshTopology).
/// @return kInvalidInput for inconsistent face offsets or an index out of range.
[[nodiscard]] Expected<bool> IntersectsItself(const Mesh& mesh) noexcept;

}  // namespace linesurf
