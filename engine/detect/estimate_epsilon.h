#pragma once
/// @file estimate_epsilon.h
/// @brief The inlier tolerance eps from the data (`--epsilon auto`, docs/design/plane_detection.md):
/// eps = k x the noise scale of the endpoint-to-plane residuals of the segments' planes. With
/// given planes and memberships the residuals are theirs (scale from their median); otherwise
/// probe detections find the largest planes, starting from eps_0 = 2 % of the median segment
/// length, and the scale is the likelihood estimate of truncated_noise_scale.h; the probes widen
/// until one covers the noise (or eps changes by less than 10 %). Every quantity is a length
/// ratio, so a scene scaled by s gets s x eps.

#include "linesurf/error.h"

#include "engine/core/run_context.h"
#include "engine/core/scene.h"
#include "engine/detect/detect_planes.h"

namespace linesurf {

/// @brief Resolves the eps of `options` for `scene`: the given value, relative_epsilon x the
/// scene diagonal, or (neither set) the estimate above: from the scene's planes and memberships
/// when it has some with a non-zero residual scale, else from probe detections.
/// @return kInvalidOptions, kDegenerate (a relative eps on a scene of zero extent), kCancelled.
/// Deterministic for any thread count.
[[nodiscard]] Expected<EpsilonEstimate> ResolveEpsilon(const Scene& scene,
                                                       const PlaneDetectionOptions& options,
                                                       const RunContext& ctx) noexcept;

/// @brief The estimate from the scene's own planes and memberships (source "planes"); eps 0 and
/// no residuals when the scene has none, or only exact data (noise scale 0).
[[nodiscard]] EpsilonEstimate EstimateEpsilonFromPlanes(const Scene& scene,
                                                        double epsilon_over_noise);

}  // namespace linesurf
