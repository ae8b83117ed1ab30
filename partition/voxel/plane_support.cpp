#include "partition/voxel/plane_support.h"

#include "engine/core/exception.h"
#include "engine/core/parallel.h"
#include "partition/voxel/active_blocks.h"

#include <tbb/parallel_for.h>

#include <algorithm>

namespace linesurf::partition {
namespace {

constexpr const char* kPlaneSupportStage = "plane_support";
constexpr int kMaxMarginBlocks = 64;

std::vector<std::int64_t> RegionOf(const BlockGrid& grid,
                                   std::span<const Segment3> segments,
                                   std::span<const SegmentId> inliers,
                                   int margin) {
  std::vector<std::int64_t> touched;
  for (const SegmentId s : inliers) {
    for (const Eigen::Vector3i& c : BlocksCrossed(grid, segments[s.index()])) {
      touched.push_back(grid.LinearIndex(c));
    }
  }
  std::sort(touched.begin(), touched.end());
  touched.erase(std::unique(touched.begin(), touched.end()), touched.end());
  return DilateBlocks(grid, touched, margin);
}

}  // namespace

Status PlaneSupportOptions::Validate() const {
  if (margin_blocks < 0 || margin_blocks > kMaxMarginBlocks) {
    return Error{ErrorCode::kInvalidOptions,
                 kPlaneSupportStage,
                 "margin_blocks must be in [0, " + std::to_string(kMaxMarginBlocks) + "], got " +
                     std::to_string(margin_blocks)};
  }
  return {};
}

PlaneSupportRegions RegionsFromBlockLists(std::vector<std::vector<std::int64_t>> plane_blocks) {
  PlaneSupportRegions out;
  std::vector<std::pair<std::int64_t, PlaneId>> pairs;  // (block, plane), to invert
  for (std::size_t p = 0; p < plane_blocks.size(); ++p) {
    out.plane_blocks.AddRow(plane_blocks[p]);
    for (const std::int64_t b : plane_blocks[p]) pairs.emplace_back(b, PlaneId(p));
  }
  std::sort(pairs.begin(), pairs.end());
  std::vector<PlaneId> row;
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    row.push_back(pairs[i].second);
    if (i + 1 == pairs.size() || pairs[i + 1].first != pairs[i].first) {
      out.blocks.push_back(pairs[i].first);
      out.block_planes.AddRow(row);
      row.clear();
    }
  }
  return out;
}

Expected<PlaneSupportRegions> ComputePlaneSupport(const BlockGrid& grid,
                                                  std::span<const Segment3> segments,
                                                  std::span<const std::vector<SegmentId>> inliers,
                                                  const PlaneSupportOptions& options,
                                                  const RunContext& ctx) noexcept {
  if (Status ok = options.Validate(); !ok) return ok.error();
  return CatchAll(kPlaneSupportStage, [&]() -> PlaneSupportRegions {
    for (std::size_t p = 0; p < inliers.size(); ++p) {
      for (const SegmentId s : inliers[p]) {
        LINESURF_THROW_IF(!s.IsValid() || s.index() >= segments.size(),
                          kInvalidInput,
                          kPlaneSupportStage,
                          "plane " << p << ": inlier " << s.index() << " is not a segment (of "
                                   << segments.size() << ")");
      }
    }
    std::vector<std::vector<std::int64_t>> regions(inliers.size());
    RunInArena(ctx, [&] {
      tbb::parallel_for(std::size_t{0}, inliers.size(), [&](std::size_t p) {
        if (ctx.ShouldStop()) return;
        regions[p] = RegionOf(grid, segments, inliers[p], options.margin_blocks);
      });
    });
    ctx.ThrowIfCancelled(kPlaneSupportStage);
    return RegionsFromBlockLists(std::move(regions));
  });
}

}  // namespace linesurf::partition
