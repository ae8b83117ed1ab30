#include "engine/pipeline/block_partition.h"

#include "engine/core/exception.h"
#include "partition/voxel/crowded_blocks.h"
#include "partition/voxel/face_clearance.h"
#include "partition/voxel/split_face_chooser.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>
#include <vector>

namespace linesurf::pipeline {
namespace {

constexpr char kBlockPartitionStage[] = "block_partition";
/// Cuts stop before the grid holds more than this many times its uncut blocks: each face cuts
/// a whole slab, so cuts spread over many slabs multiply the blocks (Andalusian: 224 -> 1,890).
constexpr std::int64_t kMaxCutGrowth = 16;
/// ... but a small grid may always reach this many blocks: one block cut 4 deep on every axis.
constexpr std::int64_t kMinCutBudget = 4096;
/// Beyond a few cuts a block holds pieces of segments rather than structures.
constexpr std::int32_t kMaxCrowdedCutDepth = 4;

/// Inlier segments of every plane, from the memberships (ascending).
std::vector<std::vector<SegmentId>> InliersOf(const Scene& scene) {
  std::vector<std::vector<SegmentId>> inliers(scene.planes.size());
  for (std::size_t s = 0; s < scene.memberships.size(); ++s) {
    const PlaneMembership& m = scene.memberships[SegmentId(s)];
    for (std::uint8_t k = 0; k < m.count; ++k) {
      LINESURF_THROW_IF(m.planes[k].index() >= scene.planes.size(),
                        kInvalidInput,
                        kBlockPartitionStage,
                        "segment " << s << " names plane " << m.planes[k].index() << " of "
                                   << scene.planes.size());
      inliers[m.planes[k].index()].emplace_back(s);
    }
  }
  return inliers;
}

}  // namespace

Status ValidateBlockSize(double block_size) {
  if (std::isfinite(block_size) && block_size >= 0.0) return {};
  return Error{
      ErrorCode::kInvalidOptions, kBlockPartitionStage, "block_size must be finite and >= 0"};
}

Status BlockPartitionOptions::Validate() const {
  if (Status s = ValidateBlockSize(block_size); !s) return s;
  if (Status s = size_rule.Validate(); !s) return s;
  if (crowded_cut_depth < 0 || crowded_cut_depth > kMaxCrowdedCutDepth) {
    return Error{ErrorCode::kInvalidOptions,
                 kBlockPartitionStage,
                 "crowded_cut_depth must be in [0, " + std::to_string(kMaxCrowdedCutDepth) +
                     "], got " + std::to_string(crowded_cut_depth)};
  }
  if (Status s = support.Validate(); !s) return s;
  return complex.Validate();
}

Expected<BlockPartition> BuildBlockPartition(const Scene& scene,
                                             const Box3& box,
                                             const BlockPartitionOptions& options,
                                             const RunContext& ctx) noexcept {
  if (Status ok = options.Validate(); !ok) return ok.error();
  return CatchAll(kBlockPartitionStage, [&]() -> BlockPartition {
    LINESURF_THROW_IF(!scene.planes.empty() && !scene.HasMemberships(),
                      kInvalidInput,
                      kBlockPartitionStage,
                      "the block partition needs the planes' inliers (segment memberships)");
    BlockPartition out;
    BlockPartitionStats& stats = out.stats;
    stats.automatic_size = options.block_size == 0.0 && !options.one_block;
    // One block: a side no extent of the box exceeds gives one block along every axis.
    stats.block_size = options.one_block ? box.Extent().maxCoeff() : options.block_size;
    const std::vector<std::vector<SegmentId>> inliers = InliersOf(scene);
    if (stats.automatic_size) {
      stats.size_choice = ValueOrThrow(partition::ChooseBlockSize(
          scene.segments.raw(), box, options.size_rule, scene.memberships.raw()));
      stats.block_size = partition::SizeClearOfParallelPlanes(
          box, stats.size_choice.block_size, scene.planes.raw(), scene.segments.raw(), inliers);
    }
    partition::BlockGrid grid = ValueOrThrow(partition::BlockGrid::Create(box, stats.block_size));

    const auto start = std::chrono::steady_clock::now();
    for (const auto& list : inliers) stats.planes_without_inliers += list.empty() ? 1 : 0;
    const auto support = [&] {
      return ValueOrThrow(partition::ComputePlaneSupport(
          grid, scene.segments.raw(), scene.planes.raw(), inliers, options.support, ctx));
    };
    out.regions = support();
    if (stats.automatic_size && options.crowded_planes_per_block > 0) {
      const partition::SplitFaceChooser chooser(
          box, stats.block_size, scene.planes.raw(), scene.segments.raw(), inliers);
      partition::CutDepths depths = partition::UncutDepths(grid);
      const std::int64_t max_blocks = std::max(kMaxCutGrowth * grid.NumBaseBlocks(), kMinCutBudget);
      // Each round cuts intervals one deeper, so at most crowded_cut_depth rounds cut anything.
      for (std::int32_t round = 0; round < options.crowded_cut_depth; ++round) {
        const std::size_t added =
            ValueOrThrow(partition::CutCrowdedBlocks(out.regions,
                                                     options.crowded_planes_per_block,
                                                     options.crowded_cut_depth,
                                                     max_blocks,
                                                     chooser,
                                                     grid,
                                                     depths));
        if (added == 0) break;
        stats.crowded_split_faces += added;
        out.regions = support();
      }
      stats.crowded_blocks_left =
          partition::CountCrowdedBlocks(out.regions, options.crowded_planes_per_block);
    }
    stats.dims = grid.dims();
    stats.seconds_support =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

    out.complexes = ValueOrThrow(partition::BuildBlockComplexes(
        grid, scene.planes.raw(), out.regions, options.complex, ctx));
    return out;
  });
}

}  // namespace linesurf::pipeline
