#include "engine/detect/detect_in_blocks.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cstdint>
#include <mutex>
#include <utility>

#include "engine/core/exception.h"
#include "engine/core/rng.h"
#include "engine/detect/detect_stage.h"
#include "engine/detect/ransac_detector.h"

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

/// What every block's run reads.
struct BlockDetectionInput {
  std::span<const Segment3> lines;
  const DetectionLayout& layout;
  const PlaneDetectionOptions& options;
  double epsilon;
  const RunContext& ctx;
};

/// One block's RANSAC, or its replacement by children when it reached max_planes (SplitAtCap).
struct BlockRun {
  DetectionBlock block;
  double progress_share = 0.0;  ///< of the whole detection, handed on to its children
  std::vector<SupportedPlane> planes;
  PlaneDetectionStats stats;
  std::vector<DetectionBlock> children;  ///< set when the block is split
  std::vector<std::size_t> child_runs;   ///< indices of the children's runs
};

/// The finished share of the detection, summed and reported under a lock.
struct BlockProgress {
  std::mutex mutex;
  double done = 0.0;
};

std::size_t AddRun(std::vector<BlockRun>& runs, DetectionBlock block, double progress_share) {
  BlockRun& run = runs.emplace_back();
  run.block = std::move(block);
  run.progress_share = progress_share;
  return runs.size() - 1;
}

/// Runs the RANSAC of run `r`: keeps its planes (inliers as scene ids), or its children when it
/// reached max_planes and SplitAtCap allows.
void RunBlock(const BlockDetectionInput& in,
              std::size_t r,
              BlockRun& run,
              BlockProgress& progress) {
  const std::vector<SegmentId>& ids = run.block.segments;
  // A single block holds every line in order: it works on `lines` itself, without a copy.
  const bool single = in.layout.blocks.size() == 1 && r == 0;
  // Without a grid nothing splits: the RANSAC's own progress (planes / max_planes) is the
  // detection's.
  const bool plane_progress = !in.layout.grid.has_value();
  std::vector<Segment3> local;
  if (!single) {
    local.reserve(ids.size());
    for (const SegmentId id : ids) local.push_back(in.lines[id.index()]);
  }
  const std::uint64_t seed =
      single ? in.options.seed : MixSeed(in.options.seed, RngStage::kDetect, kBlockStream, r);
  const RansacInput ransac{
      single ? in.lines : std::span<const Segment3>(local), in.options, in.epsilon};
  RansacDetector detector(ransac, seed, plane_progress, in.ctx);
  detector.ExtractAll(run.stats);
  if (run.stats.capped_blocks > 0 && SplitAtCap(run.block, in.layout, in.options)) {
    run.children =
        SplitDetectionBlock(in.lines, *in.layout.grid, run.block, in.options.block_halo);
    run.stats.capped_blocks = 0;
    return;
  }
  run.planes = std::move(detector.planes());
  for (SupportedPlane& plane : run.planes) {
    for (SegmentId& s : plane.inliers) s = ids[s.index()];  // ascending stays ascending
  }
  const std::lock_guard lock(progress.mutex);
  progress.done += run.progress_share;
  in.ctx.ReportProgress(kDetectPlanesStage, std::min(progress.done, 1.0));
}

/// Adds the runs of the children of the runs of `round`, in order; returns them.
std::vector<std::size_t> NextRound(const std::vector<std::size_t>& round,
                                   std::vector<BlockRun>& runs) {
  std::vector<std::size_t> next;
  for (const std::size_t r : round) {
    std::vector<DetectionBlock> children = std::move(runs[r].children);
    const double share = runs[r].progress_share / static_cast<double>(children.size());
    for (DetectionBlock& child : children) {
      const std::size_t c = AddRun(runs, std::move(child), share);
      runs[r].child_runs.push_back(c);
      next.push_back(c);
    }
  }
  return next;
}

/// Appends the planes of run `r` (or, when it was split, of its children in order) to `planes`
/// and adds its counts to `stats`.
void CollectRun(std::vector<BlockRun>& runs,
                std::size_t r,
                std::vector<SupportedPlane>& planes,
                PlaneDetectionStats& stats) {
  BlockRun& run = runs[r];
  stats.candidates_evaluated += run.stats.candidates_evaluated;
  stats.failed_draws += run.stats.failed_draws;
  for (const std::size_t child : run.child_runs) CollectRun(runs, child, planes, stats);
  if (!run.child_runs.empty()) return;
  ++stats.blocks;
  stats.capped_blocks += run.stats.capped_blocks;
  for (SupportedPlane& plane : run.planes) planes.push_back(std::move(plane));
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
                                           PlaneDetectionStats& stats) {
  const BlockDetectionInput in{lines, layout, options, epsilon, ctx};
  std::vector<BlockRun> runs;
  std::vector<std::size_t> round;
  for (const DetectionBlock& block : layout.blocks) {
    round.push_back(AddRun(runs, block, 1.0 / static_cast<double>(layout.blocks.size())));
  }
  BlockProgress progress;
  while (!round.empty()) {
    tbb::parallel_for(std::size_t{0}, round.size(), [&](std::size_t i) {
      RunBlock(in, round[i], runs[round[i]], progress);
    });
    round = NextRound(round, runs);
  }
  std::vector<SupportedPlane> planes;
  for (std::size_t r = 0; r < layout.blocks.size(); ++r) CollectRun(runs, r, planes, stats);
  return planes;
}

}  // namespace linesurf::detect
