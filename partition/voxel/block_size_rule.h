#pragma once
// The automatic block size of the block engine (docs/design/block_engine.md, section 1): from
// the scene's scale (its longest extent) and density (segments and planes per occupied block).

#include "linesurf/error.h"

#include "engine/core/geometry.h"
#include "engine/core/scene.h"

#include <span>

namespace linesurf::partition {

struct BlockSizeRule {
  /// Largest mean number of segments (by midpoint) per occupied base block (> 0).
  double target_segments_per_block = 2000.0;
  /// Largest mean number of distinct planes of the segments (by midpoint) per occupied base
  /// block (> 0): the cells of a block grow with the cube of its planes, so this bounds the
  /// partition where segments alone do not (city-100: 82.5 m blocks and 1.34M cells by
  /// segments only).
  double target_planes_per_block = 6.0;
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
  double mean_planes_per_block = 0.0;    ///< distinct planes per occupied block, by midpoint
  bool limited_by_length = false;        ///< the min_block_lengths floor stopped the halving
};

/// The largest size L / 2^k (L the longest extent of `box`, k >= 0) at which the occupied base
/// blocks hold on average at most rule.target_segments_per_block segments and (when
/// `memberships` are given, one per segment) at most rule.target_planes_per_block distinct
/// planes, but not below rule.min_block_lengths median segment lengths. A scene with no segment
/// gets one block.
[[nodiscard]] Expected<BlockSizeChoice> ChooseBlockSize(
    std::span<const Segment3> segments,
    const Box3& box,
    const BlockSizeRule& rule,
    std::span<const PlaneMembership> memberships = {}) noexcept;

}  // namespace linesurf::partition
