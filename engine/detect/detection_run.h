#pragma once
// One RANSAC run of per-block detection as a function of its own input (the block's lines, its
// random stream, eps and the options), so that it gives the same planes in this process or as a
// work unit in another one (engine/pipeline/detection_work_units.h); and the interface through
// which DetectInBlocks hands its rounds of runs to such a place (internal to engine/detect).

#include <cstdint>
#include <span>
#include <vector>

#include "engine/core/geometry.h"
#include "engine/core/run_context.h"
#include "engine/detect/detect_planes.h"
#include "engine/detect/detection_blocks.h"
#include "engine/detect/plane_fusion.h"

namespace linesurf::detect {

/// One run of a round: the block and what its RANSAC draws from.
struct DetectionRunRequest {
  const DetectionBlock* block = nullptr;  ///< key and segments (scene line ids)
  std::size_t run = 0;  ///< index among the runs: blocks, then children in order of creation
  std::uint64_t seed = 0;        ///< the run's random stream
  bool may_split = false;        ///< replaced by its children if it reaches max_planes
  bool report_progress = false;  ///< the RANSAC's own progress is the detection's (no grid)
};

struct DetectionRunOutcome {
  std::vector<SupportedPlane> planes;  ///< inliers as positions in the block's segment list
  std::int64_t candidates_evaluated = 0;
  std::int64_t failed_draws = 0;
  bool capped = false;  ///< the RANSAC reached max_planes
  bool split = false;   ///< capped and may_split: no planes, the children run instead
};

/// The RANSAC of one block on `block_lines` (the block's segments in order).
[[nodiscard]] DetectionRunOutcome RunDetectionBlock(std::span<const Segment3> block_lines,
                                                    const DetectionRunRequest& request,
                                                    const PlaneDetectionOptions& options,
                                                    double epsilon,
                                                    const RunContext& ctx);

/// Where the rounds of per-block detection run when not in this process's task arena.
class DetectionRunner {
 public:
  virtual ~DetectionRunner() = default;
  /// The outcomes of `round`, in its order; throws when they cannot all be had now.
  virtual std::vector<DetectionRunOutcome> RunRound(std::span<const Segment3> lines,
                                                    std::span<const DetectionRunRequest> round,
                                                    const PlaneDetectionOptions& options,
                                                    double epsilon,
                                                    const RunContext& ctx) = 0;
};

}  // namespace linesurf::detect
