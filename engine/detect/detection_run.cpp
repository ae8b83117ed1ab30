#include "engine/detect/detection_run.h"

#include <utility>

#include "engine/detect/ransac_detector.h"

namespace linesurf::detect {

DetectionRunOutcome RunDetectionBlock(std::span<const Segment3> block_lines,
                                      const DetectionRunRequest& request,
                                      const PlaneDetectionOptions& options,
                                      double epsilon,
                                      const RunContext& ctx) {
  PlaneDetectionStats stats;
  RansacDetector detector(RansacInput{block_lines, options, epsilon}, request.seed,
                          request.report_progress, ctx);
  detector.ExtractAll(stats);
  DetectionRunOutcome outcome;
  outcome.candidates_evaluated = stats.candidates_evaluated;
  outcome.failed_draws = stats.failed_draws;
  outcome.capped = stats.capped_blocks > 0;
  outcome.split = outcome.capped && request.may_split;
  if (!outcome.split) outcome.planes = std::move(detector.planes());
  return outcome;
}

}  // namespace linesurf::detect
