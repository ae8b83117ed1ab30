#pragma once
// Conversions between the facade's plain types (linesurf/types.h) and the engine's Scene and
// PolygonMesh. Index checks happen here, so the engine only ever sees consistent scenes.

#include "linesurf/error.h"
#include "linesurf/types.h"

#include "engine/core/polygon_mesh.h"
#include "engine/core/public_mesh.h"
#include "engine/core/public_vector.h"
#include "engine/core/scene.h"

#include <array>
#include <span>
#include <vector>

namespace linesurf::api {

/// @brief The engine scene of `input` (world coordinates, identity world_from_local).
/// Observations are grouped by segment, keeping their relative order. With planes, every
/// segment gets a membership entry (empty unless listed); repeated memberships count once.
/// @param residuals empty, or one per observation (reordered with them).
/// @return kInvalidInput naming the first observation or membership whose index is out of
/// range, a segment with more than two planes, or a residual count that does not match.
[[nodiscard]] Expected<Scene> ToEngineScene(const InputScene& input,
                                            std::span<const std::array<double, 4>> residuals = {});

/// The scene in world coordinates (local + world_from_local, bit-exact where the translation is
/// zero: ToWorldExact), with residuals and extra fields.
[[nodiscard]] SceneData ToSceneData(const Scene& scene);

/// Per engine segment s with memberships, {input_segment[s], plane} sorted by segment then plane.
[[nodiscard]] std::vector<Membership> ToMemberships(
    const IdVector<SegmentId, PlaneMembership>& memberships,
    const IdVector<SegmentId, SegmentId>& input_segment);

/// Planes moved from the local frame to world coordinates (ToWorldExact).
[[nodiscard]] std::vector<Plane> ToWorldPlanes(const IdVector<PlaneId, Plane3>& planes,
                                               const Rigid3& world_from_local);

}  // namespace linesurf::api
