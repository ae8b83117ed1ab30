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

/// What both ladders measure against.
struct RuleInput {
  std::span<const Segment3> segments;
  std::span<const PlaneMembership> memberships;
  const Box3& box;
  const BlockSizeRule& rule;
  double longest = 0.0;  ///< the longest extent of the box
  double floor = 0.0;    ///< rule.min_block_lengths median segment lengths
};

/// The rule's means at block size `size`.
BlockSizeChoice Measure(const RuleInput& in, double size) {
  BlockSizeChoice choice;
  choice.block_size = size;
  const auto [occupied, block_planes] = Occupancy(in.segments, in.memberships, Grid(in.box, size));
  choice.occupied_blocks = occupied;
  choice.mean_segments_per_block =
      static_cast<double>(in.segments.size()) / static_cast<double>(occupied);
  choice.mean_planes_per_block = static_cast<double>(block_planes) / static_cast<double>(occupied);
  return choice;
}

bool MeetsTargets(const BlockSizeChoice& choice, const BlockSizeRule& rule) {
  return choice.mean_segments_per_block <= rule.target_segments_per_block &&
         choice.mean_planes_per_block <= rule.target_planes_per_block;
}

BlockSizeChoice HalveTheExtent(const RuleInput& in) {
  BlockSizeChoice choice = Measure(in, in.longest);
  while (!MeetsTargets(choice, in.rule) && choice.steps < kMaxHalvings) {
    const double size = std::ldexp(in.longest, -(choice.steps + 1));
    if (size < in.floor) {
      choice.limited_by_length = true;
      break;
    }
    const int steps = choice.steps + 1;
    choice = Measure(in, size);
    choice.steps = steps;
  }
  return choice;
}

BlockSizeChoice ClimbFromTheFloor(const RuleInput& in) {
  BlockSizeChoice choice = Measure(in, std::min(in.floor, in.longest));
  choice.limited_by_length = !MeetsTargets(choice, in.rule);
  if (choice.limited_by_length || in.floor >= in.longest) return choice;
  for (int steps = 1;; ++steps) {
    const double size = std::min(in.floor * std::exp2(0.25 * steps), in.longest);
    BlockSizeChoice next = Measure(in, size);
    if (!MeetsTargets(next, in.rule)) return choice;
    next.steps = steps;
    choice = next;
    if (size == in.longest) return choice;
  }
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
    if (segments.empty()) {
      choice.block_size = longest;
    } else {
      const RuleInput in{.segments = segments,
                         .memberships = memberships,
                         .box = box,
                         .rule = rule,
                         .longest = longest,
                         .floor = rule.min_block_lengths * MedianLength(segments)};
      choice = rule.ladder == BlockSizeLadder::kHalvingsOfTheExtent ? HalveTheExtent(in)
                                                                    : ClimbFromTheFloor(in);
    }
    choice.whole_scene = choice.block_size == longest;
    return choice;
  });
}

}  // namespace linesurf::partition
