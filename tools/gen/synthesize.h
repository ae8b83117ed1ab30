#pragma once
/// @file synthesize.h
/// @brief Seeded synthetic scenes with ground truth: 3D segments seen from viewpoints, the solid
/// they were drawn from (closed, 2-manifold, outward oriented) and the true planes.
///
/// Families (metric units, see docs/user/synthetic.md): "cube" (the 12 edges of a cube of side 2, the
/// robustness toy of Langlois et al. 2019), "house" (gable-roofed box with windows and a door),
/// "lshape" (an L-shaped flat-roofed building), "room" (the inside of a room with niches and a
/// table; viewpoints inside), "floor" (a storey of three rooms with doors between them, seen from
/// inside), "city" (N buildings on a grid, viewpoints along the streets).
///
/// Determinism: the same spec (including the seed) gives identical output on every run and for
/// every thread count (counter-based random streams, one per building / line / segment).

#include <array>
#include <cstdint>
#include <vector>

#include "linesurf/error.h"
#include "engine/core/geometry.h"
#include "engine/core/polygon_mesh.h"
#include "engine/core/scene.h"
#include "tools/gen/synth_spec.h"

namespace linesurf::synth {

/// Why a segment exists.
enum class SegmentKind : std::uint8_t {
  kStructural,  ///< on a sharp edge of the ground truth; supports its two true planes
  kTextural,    ///< on a face (window, door, paintings...); supports the face's plane
  kOutlier,     ///< random; supports no plane
};

/// Name of a kind: "structural", "textural" or "outlier".
const char* SegmentKindName(SegmentKind kind) noexcept;

/// Segments of each kind, indexed by SegmentKind (structural, textural, outlier).
[[nodiscard]] std::array<std::size_t, 3> CountKinds(const std::vector<SegmentKind>& kinds) noexcept;

struct SyntheticScene {
  /// The spec that produced the scene (family defaults not filled in).
  SynthSpec spec;
  /// Segments, viewpoints, observations; planes = the true planes and memberships = the true
  /// plane(s) of each segment (none for outliers). world_from_local is identity.
  Scene scene;
  /// The solid: closed, 2-manifold, outward oriented (normals from matter to empty space).
  PolygonMesh ground_truth;
  /// Planes of the ground-truth faces, deduplicated (same order as scene.planes).
  std::vector<Plane3> true_planes;
  /// One per segment.
  std::vector<SegmentKind> kinds;
  /// True when the viewpoints are inside the solid's cavity (room), false when outside.
  bool interior = false;
  /// Volume of the ground truth computed from the family's dimensions (not from the mesh).
  double ground_truth_volume = 0.0;
  /// True line pieces dropped because no viewpoint sees them.
  std::size_t num_hidden_dropped = 0;
};

/// The data's up direction in the frame of `spec`: the z axis turned by its rotation (unit).
[[nodiscard]] std::array<double, 3> UpDirection(const SynthSpec& spec);

/// Builds the scene described by `spec`. Errors: kInvalidOptions for a bad spec.
[[nodiscard]] Expected<SyntheticScene> Synthesize(const SynthSpec& spec) noexcept;

}  // namespace linesurf::synth
