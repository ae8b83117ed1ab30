#pragma once
/// @file evaluation.h
/// @brief Options and results of the evaluation of a mesh against a ground-truth mesh
/// (EvaluateMesh, linesurf.h; `linesurf evaluate`), as in Langlois et al. 2019, Sec. 5:
/// area-uniform samples on both meshes, exact point-to-surface distances both ways, precision and
/// completeness as the share of samples under each threshold, and the validity of the result.

#include "linesurf/error.h"
#include "linesurf/export.h"
#include "linesurf/result.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace linesurf {
inline namespace v3 {

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
  /// Worker threads: 0 = automatic, 1 = serial ([0, kMaxThreads]). Results do not depend on it.
  int num_threads = 0;

  /// kInvalidOptions when a field is out of the range documented above.
  [[nodiscard]] LINESURF_API Status Validate() const noexcept;
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

}  // namespace v3
}  // namespace linesurf
