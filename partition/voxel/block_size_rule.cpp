#include "partition/voxel/block_size_rule.h"

#include "engine/core/exception.h"
#include "partition/voxel/block_grid.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace linesurf::partition {
namespace {

constexpr const char* kBlockSizeRuleStage = "block_size_rule";
/// Halvings stop here whatever the density (2^18 blocks along the longest axis).
constexpr int kMaxHalvings = 18;

double MedianLength(std::span<const Segment3> segments) {
  std::vector<double> lengths;
  lengths.reserve(segments.size());
  for (const Segment3& s : segments) lengths.push_back(s.Length());
  const auto mid = lengths.begin() + static_cast<std::ptrdiff_t>(lengths.size() / 2);
  std::nth_element(lengths.begin(), mid, lengths.end());
  return *mid;
}

/// The occupied base blocks of `grid` (by midpoint) and the distinct (block, plane) pairs of
/// the segments' memberships.
std::pair<std::size_t, std::size_t> Occupancy(std::span<const Segment3> segments,
                                              std::span<const PlaneMembership> memberships,
                                              const BlockGrid& grid) {
  std::vector<std::int64_t> linear;
  std::vector<std::pair<std::int64_t, std::uint32_t>> block_planes;
  linear.reserve(segments.size());
  for (std::size_t i = 0; i < segments.size(); ++i) {
    const std::int64_t b = grid.LinearIndex(grid.Locate(segments[i].Midpoint()));
    linear.push_back(b);
    if (memberships.empty()) continue;
    for (std::uint8_t k = 0; k < memberships[i].count; ++k) {
      block_planes.emplace_back(b, memberships[i].planes[k].value());
    }
  }
  std::sort(linear.begin(), linear.end());
  std::sort(block_planes.begin(), block_planes.end());
  return {static_cast<std::size_t>(std::unique(linear.begin(), linear.end()) - linear.begin()),
          static_cast<std::size_t>(std::unique(block_planes.begin(), block_planes.end()) -
                                   block_planes.begin())};
}

BlockGrid Grid(const Box3& box, double size) {
  Expected<BlockGrid> g = BlockGrid::Create(box, size);
  if (!g) throw LinesurfException(g.error());
  return std::move(g).value();
}

}  // namespace

Status BlockSizeRule::Validate() const {
  if (!(target_segments_per_block > 0.0) || !std::isfinite(target_segments_per_block)) {
    return Error{
        ErrorCode::kInvalidOptions, kBlockSizeRuleStage, "target_segments_per_block must be > 0"};
  }
  if (!(target_planes_per_block > 0.0) || !std::isfinite(target_planes_per_block)) {
    return Error{
        ErrorCode::kInvalidOptions, kBlockSizeRuleStage, "target_planes_per_block must be > 0"};
  }
  if (!(min_block_lengths > 0.0) || !std::isfinite(min_block_lengths)) {
    return Error{ErrorCode::kInvalidOptions, kBlockSizeRuleStage, "min_block_lengths must be > 0"};
  }
  return {};
}

Expected<BlockSizeChoice> ChooseBlockSize(std::span<const Segment3> segments,
                                          const Box3& box,
                                          const BlockSizeRule& rule,
                                          std::span<const PlaneMembership> memberships) noexcept {
  if (Status ok = rule.Validate(); !ok) return ok.error();
  if (!memberships.empty() && memberships.size() != segments.size()) {
    return Error{
        ErrorCode::kInvalidInput, kBlockSizeRuleStage, "one membership per segment expected"};
  }
  return CatchAll(kBlockSizeRuleStage, [&]() -> BlockSizeChoice {
    const double longest = box.Extent().maxCoeff();
    LINESURF_THROW_IF(!(longest > 0.0) || !std::isfinite(longest),
                      kInvalidInput,
                      kBlockSizeRuleStage,
                      "the scene box must have a finite, non-zero extent");
    BlockSizeChoice choice;
    choice.block_size = longest;
    choice.occupied_blocks = segments.empty() ? 0 : 1;
    choice.mean_segments_per_block = static_cast<double>(segments.size());
    if (segments.empty()) return choice;
    choice.mean_planes_per_block =
        static_cast<double>(Occupancy(segments, memberships, Grid(box, longest)).second);
    const double floor = rule.min_block_lengths * MedianLength(segments);
    while ((choice.mean_segments_per_block > rule.target_segments_per_block ||
            choice.mean_planes_per_block > rule.target_planes_per_block) &&
           choice.halvings < kMaxHalvings) {
      const double size = std::ldexp(longest, -(choice.halvings + 1));
      if (size < floor) {
        choice.limited_by_length = true;
        break;
      }
      const BlockGrid grid = Grid(box, size);
      choice.block_size = size;
      ++choice.halvings;
      const auto [occupied, block_planes] = Occupancy(segments, memberships, grid);
      choice.occupied_blocks = occupied;
      choice.mean_segments_per_block =
          static_cast<double>(segments.size()) / static_cast<double>(occupied);
      choice.mean_planes_per_block =
          static_cast<double>(block_planes) / static_cast<double>(occupied);
    }
    return choice;
  });
}

}  // namespace linesurf::partition
