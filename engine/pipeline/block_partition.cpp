#include "engine/pipeline/block_partition.h"

#include "engine/core/exception.h"
#include "partition/voxel/crowded_blocks.h"
#include "partition/voxel/face_clearance.h"

#include <chrono>
#include <cmath>
#include <string>
#include <vector>

namespace linesurf::pipeline {
namespace {

constexpr char kBlockPartitionStage[] = "block_partition";
/// Intervals shorter than this share of the block size are not split again: the blocks of the
/// size rule's floor hold whole structures, and a quarter of one still holds parts of them.
constexpr double kSmallestSplitShare = 0.5;
/// Each round halves the crowded intervals; beyond a few the blocks hold pieces of segments.
constexpr std::int32_t kMaxCrowdedSplitRounds = 4;

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
  if (crowded_split_rounds < 0 || crowded_split_rounds > kMaxCrowdedSplitRounds) {
    return Error{ErrorCode::kInvalidOptions,
                 kBlockPartitionStage,
                 "crowded_split_rounds must be in [0, " + std::to_string(kMaxCrowdedSplitRounds) +
                     "], got " + std::to_string(crowded_split_rounds)};
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
    stats.automatic_size = options.block_size == 0.0;
    stats.block_size = options.block_size;
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
      for (std::int32_t round = 0; round < options.crowded_split_rounds; ++round) {
        const std::array<std::vector<double>, 3> faces =
            partition::FacesSplittingCrowdedBlocks(grid,
                                                   out.regions,
                                                   options.crowded_planes_per_block,
                                                   kSmallestSplitShare * stats.block_size,
                                                   chooser);
        const std::size_t added = faces[0].size() + faces[1].size() + faces[2].size();
        if (added == 0) break;
        stats.crowded_split_faces += added;
        grid = ValueOrThrow(grid.WithFaces(faces));
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
