#pragma once
/// @file evaluate_mesh.h
/// @brief Compares a reconstructed mesh with a ground-truth mesh (Langlois et al. 2019, Sec. 5):
/// area-uniform samples on both, exact point-to-surface distances both ways, precision and
/// completeness as the share of samples under each threshold, plus topology of the result.

#include <cstdint>
#include <optional>
#include <vector>

#include "engine/core/geometry.h"
#include "engine/core/polygon_mesh.h"
#include "engine/core/run_context.h"
#include "linesurf/error.h"
#include "engine/pipeline/mesh_validity.h"

namespace linesurf {

struct EvaluationOptions {
  /// Distance thresholds (mesh units, metres for synthetic scenes); each > 0, increasing.
  std::vector<double> thresholds{0.02, 0.05, 0.1};
  /// Area-uniform samples drawn on each mesh; in [1, 1e7]. 100k gives shares to about +-0.3 %.
  std::size_t samples_per_mesh = 100000;
  /// Seed of the counter-based sample streams; results are identical for every thread count.
  std::uint64_t seed = 0;
  /// Visibility test: the segment viewpoint -> sample is shortened by this much at the sample
  /// end, so the sample's own face does not occlude it (mesh units); > 0.
  double visibility_offset = 1e-3;

  /// kInvalidOptions when a field is out of the range documented above.
  [[nodiscard]] Status Validate() const;
};

/// Distribution of sample-to-surface distances in one direction.
struct DistanceStats {
  std::size_t count = 0;  ///< samples measured
  double mean = 0.0;
  double median = 0.0;  ///< sorted value at index floor(0.5 (n - 1))
  double p95 = 0.0;     ///< sorted value at index floor(0.95 (n - 1)), as the reference
  double max = 0.0;
};

struct EvaluationResult {
  std::vector<double> thresholds;
  /// precision[i]: share of result samples within thresholds[i] of the ground truth (accuracy).
  std::vector<double> precision;
  /// completeness[i]: share of (visible) ground-truth samples within thresholds[i] of the result.
  std::vector<double> completeness;
  DistanceStats result_to_gt;
  DistanceStats gt_to_result;
  /// Ground-truth samples drawn, and those kept for completeness (all unless restricted to the
  /// part seen from viewpoints).
  std::size_t num_gt_samples = 0;
  std::size_t num_visible_gt_samples = 0;
  double result_area = 0.0;
  double gt_area = 0.0;
  MeshValidity topology;  ///< of the result
};

/// @brief Evaluates `result` against `ground_truth` (both in the same frame and units).
/// @param visible_from when given, completeness only counts ground-truth samples that some
///   viewpoint sees unoccluded by the ground truth (the segment viewpoint -> sample hits no face
///   before the sample).
/// @param ctx threads (an arena of ctx->num_threads) and cancellation; may be null.
/// @return kInvalidOptions, kInvalidInput (a mesh without area, bad indices), kCancelled.
/// Thread-safe, deterministic (bit-identical for any thread count), never throws.
Expected<EvaluationResult> EvaluateMesh(const PolygonMesh& result, const PolygonMesh& ground_truth,
                                        const EvaluationOptions& options,
                                        const std::optional<std::vector<Vec3>>& visible_from =
                                            std::nullopt,
                                        const RunContext* ctx = nullptr) noexcept;

}  // namespace linesurf
