#include "partition/voxel/block_size_rule.h"

#include "engine/core/exception.h"
#include "partition/voxel/block_grid.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace linesurf::partition {
namespace {

constexpr const char* kStage = "block_size_rule";
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

/// Occupied base blocks of a grid of `size` by midpoint.
std::size_t OccupiedBlocks(std::span<const Segment3> segments, const BlockGrid& grid) {
  std::vector<std::int64_t> linear;
  linear.reserve(segments.size());
  for (const Segment3& s : segments) linear.push_back(grid.LinearIndex(grid.Locate(s.Midpoint())));
  std::sort(linear.begin(), linear.end());
  return static_cast<std::size_t>(std::unique(linear.begin(), linear.end()) - linear.begin());
}

}  // namespace

Status BlockSizeRule::Validate() const {
  if (!(target_segments_per_block > 0.0) || !std::isfinite(target_segments_per_block)) {
    return Error{ErrorCode::kInvalidOptions, kStage, "target_segments_per_block must be > 0"};
  }
  if (!(min_block_lengths > 0.0) || !std::isfinite(min_block_lengths)) {
    return Error{ErrorCode::kInvalidOptions, kStage, "min_block_lengths must be > 0"};
  }
  return {};
}

Expected<BlockSizeChoice> ChooseBlockSize(std::span<const Segment3> segments,
                                          const Box3& box,
                                          const BlockSizeRule& rule) noexcept {
  if (Status ok = rule.Validate(); !ok) return ok.error();
  return CatchAll(kStage, [&]() -> BlockSizeChoice {
    const double longest = box.Extent().maxCoeff();
    LINESURF_THROW_IF(!(longest > 0.0) || !std::isfinite(longest),
                      kInvalidInput,
                      kStage,
                      "the scene box must have a finite, non-zero extent");
    BlockSizeChoice choice;
    choice.block_size = longest;
    choice.occupied_blocks = segments.empty() ? 0 : 1;
    choice.mean_segments_per_block = static_cast<double>(segments.size());
    if (segments.empty()) return choice;
    const double floor = rule.min_block_lengths * MedianLength(segments);
    while (choice.mean_segments_per_block > rule.target_segments_per_block &&
           choice.halvings < kMaxHalvings) {
      const double size = std::ldexp(longest, -(choice.halvings + 1));
      if (size < floor) {
        choice.limited_by_length = true;
        break;
      }
      const BlockGrid grid = [&] {
        Expected<BlockGrid> g = BlockGrid::Create(box, size);
        if (!g) throw LinesurfException(g.error());
        return std::move(g).value();
      }();
      choice.block_size = size;
      ++choice.halvings;
      choice.occupied_blocks = OccupiedBlocks(segments, grid);
      choice.mean_segments_per_block =
          static_cast<double>(segments.size()) / static_cast<double>(choice.occupied_blocks);
    }
    return choice;
  });
}

}  // namespace linesurf::partition
