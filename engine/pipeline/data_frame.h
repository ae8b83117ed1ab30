#pragma once
// The data's own frame: the axes the line directions of a building follow and the up direction
// the viewpoints imply. Reconstruction runs in it, so that its axis-aligned steps (the scene box,
// the block grids, the segment BVH) turn with the scene and the mesh does not depend on the
// frame the input came in (docs/design/real_data.md, "The frame").

#include <string>

#include <Eigen/Core>

#include "engine/core/scene.h"

namespace linesurf::pipeline {

/// How the up direction was told from the data.
enum class UpEvidence {
  kNone,                ///< no frame was found (too few line directions): the input's frame
  kViewpointSpread,     ///< the axis along which the viewpoints spread least
  kLineSpread,          ///< two axes of as little viewpoint spread: the one the lines span more
  kInputZ,              ///< no viewpoint: the axis nearest the input's z
};

/// "none" / "viewpoint_spread" / "line_spread" / "input_z".
[[nodiscard]] const char* UpEvidenceName(UpEvidence evidence) noexcept;

/// The frame of a scene's data, in the scene's coordinates.
struct DataFrame {
  /// Columns x, y, z of the frame (a rotation): z is `up`, x the horizontal axis most line
  /// length follows. The identity when `found` is false.
  Eigen::Matrix3d axes = Eigen::Matrix3d::Identity();
  bool found = false;
  /// The up direction (unit): +z of the frame, with its sign from where the viewpoints are.
  Vec3 up = Vec3::UnitZ();
  UpEvidence up_evidence = UpEvidence::kNone;
  /// Why the sign of `up` is what it is, one sentence for the report.
  std::string up_sign_reason;
  /// Share of the line length within kAxisToleranceDegrees of one of the three axes.
  double axis_share = 0.0;
};

/// Lines within this angle of an axis count for it.
inline constexpr double kAxisToleranceDegrees = 5.0;

/// @brief The frame of `scene`'s data: the dominant line direction, the dominant direction
/// orthogonal to it and their cross product, named and signed by rules that turn with the data
/// (so a rotated scene gets the rotated frame). Deterministic and serial; O(n) per candidate axis
/// over at most kMaxFrameSamples segments.
[[nodiscard]] DataFrame EstimateDataFrame(const Scene& scene);

/// @brief The up of a room seen from inside: its cameras stand nearer the ceiling than the floor,
/// so the floor is the end of the lines (5 % quantiles along the frame's up axis) farther from
/// the median viewpoint. Turns frame.up (not the axes) when that rule disagrees, and says so.
/// `scene` is in the frame (`world_from_local.rotation` holds frame.axes); nothing changes when
/// the frame was not found or the scene has no viewpoint.
void OrientUpInside(const Scene& scene, DataFrame& frame);

/// Segments sampled (every k-th, by id) for the direction statistics.
inline constexpr std::size_t kMaxFrameSamples = 200000;

}  // namespace linesurf::pipeline
