#pragma once
// The automatic block size of the block engine (docs/design/block_engine.md, section 1): from
// the scene's scale (its longest extent) and density (segments per occupied block).

#include "linesurf/error.h"

#include "engine/core/geometry.h"

#include <span>

namespace linesurf::partition {

struct BlockSizeRule {
  /// Largest mean number of segments (by midpoint) per occupied base block (> 0).
  double target_segments_per_block = 2000.0;
  /// Blocks are never smaller than this many median segment lengths (> 0), so a block holds
  /// whole structures rather than pieces of single segments.
  double min_block_lengths = 8.0;

  [[nodiscard]] Status Validate() const;
};

struct BlockSizeChoice {
  double block_size = 0.0;
  int halvings = 0;                      ///< block_size = longest extent / 2^halvings
  std::size_t occupied_blocks = 0;       ///< base blocks holding a midpoint at that size
  double mean_segments_per_block = 0.0;  ///< segments / occupied_blocks
  bool limited_by_length = false;        ///< the min_block_lengths floor stopped the halving
};

/// The largest size L / 2^k (L the longest extent of `box`, k >= 0) at which the occupied base
/// blocks hold on average at most rule.target_segments_per_block segments, but not below
/// rule.min_block_lengths median segment lengths. A scene with no segment gets one block.
[[nodiscard]] Expected<BlockSizeChoice> ChooseBlockSize(std::span<const Segment3> segments,
                                                        const Box3& box,
                                                        const BlockSizeRule& rule) noexcept;

}  // namespace linesurf::partition
