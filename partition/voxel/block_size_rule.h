#pragma once
// The automatic block size of the block engine (docs/design/block_engine.md, section 1): from
// the scene's density (segments and planes per occupied block), bounded by its longest extent.

#include "linesurf/error.h"

#include "engine/core/geometry.h"
#include "engine/core/scene.h"

#include <span>

namespace linesurf::partition {

/// The sizes the rule tries.
enum class BlockSizeLadder {
  /// L / 2^k (L the longest extent of the box), halved while a target is missed: the size
  /// depends on the scene's extent, so a city of 1,000 buildings got blocks 0.8x those of a
  /// city of 100 and 13.3x its cells (detection's cubes keep it: their results are documented).
  kHalvingsOfTheExtent,
  /// floor * 2^(k/4) (floor = min_block_lengths median segment lengths), grown while every
  /// target is met: the size depends on the density alone, so cells grow with the scene.
  kQuarterOctavesFromTheFloor,
};

struct BlockSizeRule {
  BlockSizeLadder ladder = BlockSizeLadder::kQuarterOctavesFromTheFloor;
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
  int steps = 0;             ///< halvings of the extent, or quarter octaves above the floor
  bool whole_scene = false;  ///< block_size is the longest extent: one block
  std::size_t occupied_blocks = 0;       ///< base blocks holding a midpoint at that size
  double mean_segments_per_block = 0.0;  ///< segments / occupied_blocks
  double mean_planes_per_block = 0.0;    ///< distinct planes per occupied block, by midpoint
  bool limited_by_length = false;        ///< a target is missed at the min_block_lengths floor
};

/// A size of rule.ladder, at most the longest extent L of `box` and at least
/// rule.min_block_lengths median segment lengths (the floor), at which the occupied base blocks
/// hold on average at most rule.target_segments_per_block segments and (when `memberships` are
/// given, one per segment) at most rule.target_planes_per_block distinct planes:
/// - kHalvingsOfTheExtent: the largest L / 2^k that meets the targets, or the last above the
///   floor;
/// - kQuarterOctavesFromTheFloor: the size before the first floor * 2^(k/4) that misses a
///   target (the means are not monotone in the size: the first miss, not the last fit, keeps
///   blocks as small as the density asks), the floor if it misses one, L if none does.
/// A scene with no segment gets one block.
[[nodiscard]] Expected<BlockSizeChoice> ChooseBlockSize(
    std::span<const Segment3> segments,
    const Box3& box,
    const BlockSizeRule& rule,
    std::span<const PlaneMembership> memberships = {}) noexcept;

}  // namespace linesurf::partition
