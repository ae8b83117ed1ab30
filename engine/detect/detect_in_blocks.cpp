#include "engine/detect/detect_in_blocks.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cstdint>
#include <mutex>
#include <utility>

#include "engine/core/exception.h"
#include "engine/core/rng.h"
#include "engine/detect/detect_stage.h"

namespace linesurf::detect {
namespace {
/// Tags the random streams of per-block detection (block b draws from (seed, kBlockStream, b)).
constexpr std::uint64_t kBlockStream = 0xb10c0000b10c0000ULL;

/// The block grid of per-block detection run on its own: whole cubes of side block_size from the
/// minimum of the lines' midpoints, floor(extent / block_size) + 1 per axis, so every midpoint
/// lies inside the grid (not on its last face) and results are those of the round-1 cubes.
partition::BlockGrid DetectionGrid(std::span<const Segment3> lines, double block_size) {
  const Box3 box = MidpointBox(lines);
  const Eigen::Vector3d blocks = (box.Extent() / block_size).array().floor() + 1.0;
  Expected<partition::BlockGrid> grid =
      partition::BlockGrid::CreateWholeBlocks(box.min, block_size, blocks);
  LINESURF_THROW_IF(!grid,
                    kInvalidOptions,
                    kDetectPlanesStage,
                    "PlaneDetectionOptions.block_size "
                        << block_size << " does not fit a scene of extent "
                        << box.Extent().maxCoeff() << ": " << grid.error().message);
  return std::move(grid).value();
}

/// Whether a block whose RANSAC reached max_planes is replaced by its 8 children: the options
/// allow it, the block lies on a grid below the deepest level, and it holds more home lines than
/// max_planes planes of min_support lines of its own need (a smaller block reached the cap on
/// shared or halo lines, which halving would not cure; the bound also ends the recursion).
bool SplitAtCap(const DetectionBlock& block,
                const DetectionLayout& layout,
                const PlaneDetectionOptions& options) {
  const std::size_t lines_for_cap =
      static_cast<std::size_t>(options.max_planes) * static_cast<std::size_t>(options.min_support);
  return options.split_blocks_at_cap && layout.grid.has_value() &&
         block.key.level < partition::kMaxBlockLevel &&
         block.home_segments.size() > lines_for_cap;
}

/// The finished share of the detection, summed and reported under a lock.
struct BlockProgress {
  std::mutex mutex;
  double done = 0.0;
};

/// One block's run: its request and outcome, and its children when it was split.
struct BlockRun {
  DetectionBlock block;
  double progress_share = 0.0;  ///< of the whole detection, handed on to its children
  DetectionRunOutcome outcome;
  std::vector<std::size_t> child_runs;  ///< indices of the children's runs
};

std::size_t AddRun(std::vector<BlockRun>& runs, DetectionBlock block, double progress_share) {
  BlockRun& run = runs.emplace_back();
  run.block = std::move(block);
  run.progress_share = progress_share;
  return runs.size() - 1;
}

/// The requests of the runs of `round`: a single block keeps options.seed, so it reproduces the
/// monolithic method exactly; run r of several draws from its own stream.
std::vector<DetectionRunRequest> RoundRequests(const std::vector<std::size_t>& round,
                                               const std::vector<BlockRun>& runs,
                                               const DetectionLayout& layout,
                                               const PlaneDetectionOptions& options) {
  std::vector<DetectionRunRequest> requests;
  requests.reserve(round.size());
  for (const std::size_t r : round) {
    const bool single = layout.blocks.size() == 1 && r == 0;
    requests.push_back(DetectionRunRequest{
        .block = &runs[r].block,
        .run = r,
        .seed = single ? options.seed : MixSeed(options.seed, RngStage::kDetect, kBlockStream, r),
        .may_split = SplitAtCap(runs[r].block, layout, options),
        .report_progress = !layout.grid.has_value()});
  }
  return requests;
}

/// The outcomes of `requests` in this process: blocks in parallel, progress per finished block.
std::vector<DetectionRunOutcome> RunRoundHere(std::span<const Segment3> lines,
                                              std::span<const DetectionRunRequest> requests,
                                              const std::vector<BlockRun>& runs,
                                              const PlaneDetectionOptions& options,
                                              double epsilon,
                                              const RunContext& ctx,
                                              BlockProgress& progress) {
  std::vector<DetectionRunOutcome> outcomes(requests.size());
  tbb::parallel_for(std::size_t{0}, requests.size(), [&](std::size_t i) {
    const DetectionRunRequest& request = requests[i];
    const std::vector<SegmentId>& ids = request.block->segments;
    // A single block holds every line in order: it works on `lines` itself, without a copy.
    const bool whole = ids.size() == lines.size();
    std::vector<Segment3> local;
    if (!whole) {
      local.reserve(ids.size());
      for (const SegmentId id : ids) local.push_back(lines[id.index()]);
    }
    outcomes[i] = RunDetectionBlock(whole ? lines : std::span<const Segment3>(local), request,
                                    options, epsilon, ctx);
    if (outcomes[i].split) return;
    const std::lock_guard lock(progress.mutex);
    progress.done += runs[request.run].progress_share;
    ctx.ReportProgress(kDetectPlanesStage, std::min(progress.done, 1.0));
  });
  return outcomes;
}

/// Adds the runs of the children of the split runs of `round`, in order; returns them.
std::vector<std::size_t> NextRound(std::span<const Segment3> lines,
                                   const DetectionLayout& layout,
                                   const PlaneDetectionOptions& options,
                                   const std::vector<std::size_t>& round,
                                   std::vector<BlockRun>& runs) {
  std::vector<std::size_t> next;
  for (const std::size_t r : round) {
    if (!runs[r].outcome.split) continue;
    std::vector<DetectionBlock> children =
        SplitDetectionBlock(lines, *layout.grid, runs[r].block, options.block_halo);
    const double share = runs[r].progress_share / static_cast<double>(children.size());
    for (DetectionBlock& child : children) {
      const std::size_t c = AddRun(runs, std::move(child), share);
      runs[r].child_runs.push_back(c);
      next.push_back(c);
    }
  }
  return next;
}

/// Appends the planes of run `r` (or, when it was split, of its children in order) to `planes`,
/// inliers as scene ids, and adds its counts to `stats`.
void CollectRun(std::vector<BlockRun>& runs,
                std::size_t r,
                std::vector<SupportedPlane>& planes,
                PlaneDetectionStats& stats) {
  BlockRun& run = runs[r];
  stats.candidates_evaluated += run.outcome.candidates_evaluated;
  stats.failed_draws += run.outcome.failed_draws;
  for (const std::size_t child : run.child_runs) CollectRun(runs, child, planes, stats);
  if (run.outcome.split) return;
  ++stats.blocks;
  if (run.outcome.capped) ++stats.capped_blocks;
  const std::vector<SegmentId>& ids = run.block.segments;
  for (SupportedPlane& plane : run.outcome.planes) {
    for (SegmentId& s : plane.inliers) s = ids[s.index()];  // ascending stays ascending
    planes.push_back(std::move(plane));
  }
}
}  // namespace

DetectionLayout SplitIntoBlocks(std::span<const Segment3> lines,
                                const PlaneDetectionOptions& options) {
  DetectionLayout layout;
  if (options.block_size > 0.0) {
    if (lines.empty()) return layout;
    layout.grid = DetectionGrid(lines, options.block_size);
    BlockLayout block_layout;
    block_layout.halo = options.block_halo;
    block_layout.max_home_segments = static_cast<std::size_t>(options.block_max_segments);
    layout.blocks = AssignDetectionBlocks(lines, *layout.grid, block_layout);
    return layout;
  }
  DetectionBlock all;
  all.segments.reserve(lines.size());
  for (std::size_t i = 0; i < lines.size(); ++i) all.segments.emplace_back(i);
  all.home_segments = all.segments;
  layout.blocks.push_back(std::move(all));
  return layout;
}

std::vector<SupportedPlane> DetectInBlocks(std::span<const Segment3> lines,
                                           const DetectionLayout& layout,
                                           const PlaneDetectionOptions& options,
                                           double epsilon,
                                           const RunContext& ctx,
                                           PlaneDetectionStats& stats,
                                           DetectionRunner* runner) {
  std::vector<BlockRun> runs;
  std::vector<std::size_t> round;
  for (const DetectionBlock& block : layout.blocks) {
    round.push_back(AddRun(runs, block, 1.0 / static_cast<double>(layout.blocks.size())));
  }
  BlockProgress progress;
  while (!round.empty()) {
    const std::vector<DetectionRunRequest> requests = RoundRequests(round, runs, layout, options);
    std::vector<DetectionRunOutcome> outcomes =
        runner != nullptr ? runner->RunRound(lines, requests, options, epsilon, ctx)
                          : RunRoundHere(lines, requests, runs, options, epsilon, ctx, progress);
    LINESURF_THROW_IF(outcomes.size() != requests.size(), kInternal, kDetectPlanesStage,
                      "a detection round gave " << outcomes.size() << " outcomes for "
                                                << requests.size() << " runs");
    for (std::size_t i = 0; i < round.size(); ++i) runs[round[i]].outcome = std::move(outcomes[i]);
    round = NextRound(lines, layout, options, round, runs);
  }
  std::vector<SupportedPlane> planes;
  for (std::size_t r = 0; r < layout.blocks.size(); ++r) CollectRun(runs, r, planes, stats);
  return planes;
}

}  // namespace linesurf::detect
