#pragma once
// Sanitation: the release-mode validation stage every scene goes through before any geometry
// (STYLE B4). Bad elements are fixed or dropped and counted; the scene is recentred to a local
// frame.

#include <cstddef>
#include <string>
#include <vector>

#include "linesurf/error.h"
#include "engine/core/coordinate_bound.h"
#include "engine/core/scene.h"
#include "engine/pipeline/data_frame.h"

namespace linesurf::pipeline {

struct SanitizeOptions {
  /// Segments shorter than this fraction of the scene's bounding-box diagonal (of finite segment
  /// endpoints) are dropped as zero or near-zero length. Range [0, 1). Default 1e-7: ~7 um on the
  /// 66-unit Andalusian scene, far below any real detection (shortest Andalusian segment 0.0115),
  /// but far above the rounding noise of coordinates 1e6 m from the origin (~1e-10 m).
  double min_segment_length_rel = 1e-7;
  /// A plane whose `point` lies farther than this multiple of the scene diagonal from the data
  /// centre is re-anchored at its point closest to the data centre (the plane itself is kept).
  /// Range > 0. Default 1.0: such a point is outside the data; Andalusian has 7 planes whose
  /// point sits up to ~2,000 units away, which costs precision in every plane offset.
  double max_plane_point_distance_rel = 1.0;
  /// Coordinates (of endpoints, viewpoints, plane points) larger in magnitude than this are
  /// treated like non-finite values (see kMaxAbsCoordinate). Range > 0, default 1e12.
  double max_abs_coordinate = kMaxAbsCoordinate;
  /// Plane normals shorter than this (before renormalisation) are treated as zero: the plane is
  /// dropped. Range [0, 1), default 1e-12.
  double min_normal_length = 1e-12;
  /// Translate the scene so that the centre of its segment bounding box is the origin, and
  /// record the translation in Scene::world_from_local. Default true (always wanted, except by
  /// tests that check the other repairs in isolation).
  bool recentre = true;
  /// With recentre: also turn the scene into its data's frame (EstimateDataFrame), recorded in
  /// Scene::world_from_local.rotation, so that the reconstruction does not depend on the frame
  /// of the input. Default true; false keeps the input's axes (conversions, which must not
  /// touch coordinates beyond the translation).
  bool align_to_data_frame = true;

  /// Checks every field against its documented range; the error names the first bad field.
  [[nodiscard]] Status Validate() const;
};

/// What sanitation did, one counter per kind of repair.
struct SanitizeStats {
  std::size_t input_segments = 0;
  std::size_t kept_segments = 0;
  std::size_t dropped_non_finite_segments = 0;  ///< NaN/inf or beyond max_abs_coordinate
  std::size_t dropped_short_segments = 0;       ///< shorter than the minimum length
  std::size_t dropped_bad_viewpoints = 0;       ///< non-finite or too large viewpoints
  std::size_t removed_bad_observations = 0;     ///< id out of range or a dropped viewpoint
  std::size_t removed_duplicate_views = 0;      ///< the same viewpoint twice on one segment
  std::size_t segments_without_views = 0;       ///< kept, but give no visibility evidence
  std::size_t dropped_bad_planes = 0;           ///< non-finite, too large or zero normal
  std::size_t renormalised_normals = 0;         ///< normal not unit length (beyond rounding)
  std::size_t reanchored_planes = 0;            ///< point moved onto the plane near the data
  std::size_t removed_bad_memberships = 0;      ///< plane id out of range or of a dropped plane
  std::size_t removed_repeated_memberships = 0; ///< the same plane twice on one segment
  std::size_t dropped_residuals = 0;            ///< all residuals, when any was inconsistent
};

struct SanitizeResult {
  /// The repaired scene, in the local frame (world = world_from_local.Apply(local)).
  Scene scene;
  SanitizeStats stats;
  /// Per kept segment, its id in the input scene (ascending).
  IdVector<SegmentId, SegmentId> input_segment;
  /// One sentence per non-zero repair counter, e.g. "412 segments dropped: zero or near-zero
  /// length (< 6.6e-06)".
  std::vector<std::string> warnings;
  /// The data's frame, in the input's axes (found false when not aligned).
  DataFrame frame;
};

/// @brief Drops or fixes every bad element of `scene` and recentres it (docs/user/formats.md lists the
/// repairs). Ids of kept segments, viewpoints and planes keep their relative order.
/// Deterministic and serial (linear time).
/// @return kInvalidOptions when `options` is invalid; kInvalidInput when inconsistent arrays
/// (memberships/observation rows not one per segment) are given or no segment is left.
[[nodiscard]] Expected<SanitizeResult> SanitizeScene(Scene scene,
                                                     const SanitizeOptions& options) noexcept;

}  // namespace linesurf::pipeline
