#pragma once
// The input scene: segments, shared viewpoints, observations, optional planes and memberships.
// Coordinates are in a local frame (see Scene::world_from_local); readers recentre on load.

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "engine/core/csr.h"
#include "engine/core/geometry.h"
#include "engine/core/strong_id.h"

namespace linesurf {

/// Which planes a segment supports: 0 (unassigned), 1 (textural) or 2 (structural).
struct PlaneMembership {
  std::array<PlaneId, 2> planes{};
  std::uint8_t count = 0;

  [[nodiscard]] bool Contains(PlaneId p) const {
    return (count > 0 && planes[0] == p) || (count > 1 && planes[1] == p);
  }
  /// Adds `p` if there is room and it is not there yet; returns whether it was added.
  bool Add(PlaneId p) {
    if (count >= 2 || Contains(p)) return false;
    planes[count++] = p;
    return true;
  }
};

/// A 2D observation of a segment in one image (pixels), when the format carries it.
using Residual2 = std::array<double, 4>;

struct Scene {
  IdVector<SegmentId, Segment3> segments;
  /// Camera centres, deduplicated: observations refer to them by id.
  IdVector<ViewpointId, Vec3> viewpoints;
  /// Row s lists the viewpoints that observed segment s (input order kept).
  Csr<SegmentId, ViewpointId> observations;
  /// Parallel to observations.items() when every observation has a residual; empty otherwise.
  std::vector<Residual2> residuals;
  /// Detected or given planes (empty when none).
  IdVector<PlaneId, Plane3> planes;
  /// One entry per segment when planes are given, empty otherwise.
  IdVector<SegmentId, PlaneMembership> memberships;
  /// world = local + world_from_local.translation.
  Rigid3 world_from_local;
  /// Free-form string fields a format carries at top level (e.g. "original_L3Dpp_file").
  std::vector<std::pair<std::string, std::string>> extra_fields;

  [[nodiscard]] std::size_t NumSegments() const { return segments.size(); }
  [[nodiscard]] bool HasMemberships() const { return !memberships.empty(); }
};

}  // namespace linesurf
