#pragma once
// A check of conforming meshes for tests: no vertex lies inside another face's edge.

#include "engine/core/polygon_mesh.h"

#include <cstddef>

namespace linesurf::testing {

/// (face edge, vertex) pairs where the vertex lies strictly inside the edge, by rounded
/// coordinates with a tolerance of 1e-9 of the edge length; vertices at an end's position do not
/// count (split copies of it). O(corners x vertices): for test-sized meshes.
std::size_t CountTJunctions(const PolygonMesh& mesh);

}  // namespace linesurf::testing
