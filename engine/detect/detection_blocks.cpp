#include "engine/detect/detection_blocks.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <tuple>

namespace linesurf::detect {
namespace {

using partition::BlockGrid;
using partition::BlockKey;

using Key = std::array<std::int64_t, 3>;  // (z, y, x): the listing order

struct Members {
  std::vector<SegmentId> ids;       ///< home and halo segments, ascending
  std::vector<SegmentId> home_ids;  ///< segments whose midpoint lies in the block itself
};

Key ListingKey(const Eigen::Vector3i& index) { return {index.z(), index.y(), index.x()}; }

/// The base blocks holding `ids`: home by midpoint, halo of `halo` scene units around each block.
std::map<Key, Members> DistributeToBase(std::span<const Segment3> segments,
                                        std::span<const SegmentId> ids,
                                        const BlockGrid& grid,
                                        double halo) {
  std::map<Key, Members> blocks;
  for (const SegmentId id : ids) {
    const Vec3 m = segments[id.index()].Midpoint();
    const Eigen::Vector3i home = grid.Locate(m);
    const Eigen::Vector3i lo = grid.Locate(m - Vec3::Constant(halo));
    const Eigen::Vector3i hi = grid.Locate(m + Vec3::Constant(halo));
    blocks[ListingKey(home)].home_ids.push_back(id);
    for (int z = lo.z(); z <= hi.z(); ++z) {
      for (int y = lo.y(); y <= hi.y(); ++y) {
        for (int x = lo.x(); x <= hi.x(); ++x) blocks[{z, y, x}].ids.push_back(id);
      }
    }
  }
  return blocks;
}

/// Where x lies along `axis` relative to the children of `parent`: -1 below it, 0 or 1 in a
/// child, 2 above it.
int ChildOffset(const BlockGrid& grid, const BlockKey& parent, int axis, double x) {
  const std::int64_t first = 2 * std::int64_t{parent.index[axis]};
  const std::int32_t level = parent.level + 1;
  if (x < grid.Face(axis, level, first)) return -1;
  if (x < grid.Face(axis, level, first + 1)) return 0;
  return x < grid.Face(axis, level, first + 2) ? 1 : 2;
}

/// The children of `parent` (keys 0..1 per axis) holding its members: the parent's home
/// segments have one home child; every member goes to the children within `halo` of it.
std::map<Key, Members> DistributeToChildren(std::span<const Segment3> segments,
                                            const Members& parent_members,
                                            const BlockGrid& grid,
                                            const BlockKey& parent,
                                            double halo) {
  std::map<Key, Members> children;
  for (const SegmentId id : parent_members.ids) {
    const Vec3 m = segments[id.index()].Midpoint();
    const bool is_home =
        std::binary_search(parent_members.home_ids.begin(), parent_members.home_ids.end(), id);
    Key home{};
    Key lo{};
    Key hi{};
    for (int a = 0; a < 3; ++a) {  // key order is (z, y, x)
      // A home segment on the grid box's maximum (closed there) stays in the upper child.
      home[2 - a] = std::clamp(ChildOffset(grid, parent, a, m[a]), 0, 1);
      lo[2 - a] = std::max(ChildOffset(grid, parent, a, m[a] - halo), 0);
      hi[2 - a] = std::min(ChildOffset(grid, parent, a, m[a] + halo), 1);
      if (is_home) {
        lo[2 - a] = std::min(lo[2 - a], home[2 - a]);
        hi[2 - a] = std::max(hi[2 - a], home[2 - a]);
      }
    }
    if (is_home) children[home].home_ids.push_back(id);
    for (std::int64_t z = lo[0]; z <= hi[0]; ++z) {
      for (std::int64_t y = lo[1]; y <= hi[1]; ++y) {
        for (std::int64_t x = lo[2]; x <= hi[2]; ++x) children[{z, y, x}].ids.push_back(id);
      }
    }
  }
  return children;
}

/// Appends the children of `parent` that hold home segments of `members`, in key order.
void EmitChildren(std::span<const Segment3> segments,
                  const Members& members,
                  const BlockGrid& grid,
                  const BlockKey& parent,
                  const BlockLayout& layout,
                  std::vector<DetectionBlock>& out);

/// Appends the blocks of `blocks` (keys relative to `origin` at `level`) in key order, splitting
/// the crowded ones.
void Emit(std::span<const Segment3> segments,
          std::map<Key, Members>& blocks,
          const BlockGrid& grid,
          const BlockKey& origin,
          const BlockLayout& layout,
          std::vector<DetectionBlock>& out) {
  for (auto& [key, members] : blocks) {
    if (members.home_ids.empty()) continue;  // halo only: its segments' home blocks detect them
    DetectionBlock block;
    block.key = {origin.level,
                 origin.index + Eigen::Vector3i(static_cast<int>(key[2]),
                                                static_cast<int>(key[1]),
                                                static_cast<int>(key[0]))};
    block.box = grid.BlockBox(block.key);
    const bool crowded = layout.max_home_segments > 0 &&
                         members.home_ids.size() > layout.max_home_segments &&
                         block.key.level < partition::kMaxBlockLevel;
    if (!crowded) {
      block.segments = std::move(members.ids);
      block.home_segments = std::move(members.home_ids);
      out.push_back(std::move(block));
      continue;
    }
    EmitChildren(segments, members, grid, block.key, layout, out);
  }
}

void EmitChildren(std::span<const Segment3> segments,
                  const Members& members,
                  const BlockGrid& grid,
                  const BlockKey& parent,
                  const BlockLayout& layout,
                  std::vector<DetectionBlock>& out) {
  const double child_side = std::ldexp(grid.block_size(), -(parent.level + 1));
  std::map<Key, Members> children =
      DistributeToChildren(segments, members, grid, parent, layout.halo * child_side);
  Emit(segments, children, grid, {parent.level + 1, 2 * parent.index}, layout, out);
}

}  // namespace

Box3 MidpointBox(std::span<const Segment3> segments) {
  Box3 box;
  for (const Segment3& s : segments) box.Extend(s.Midpoint());
  return box;
}

std::vector<DetectionBlock> AssignDetectionBlocks(std::span<const Segment3> segments,
                                                  const BlockGrid& grid,
                                                  const BlockLayout& layout) {
  std::vector<SegmentId> all(segments.size());
  for (std::size_t i = 0; i < segments.size(); ++i) all[i] = SegmentId(i);
  std::map<Key, Members> base =
      DistributeToBase(segments, all, grid, layout.halo * grid.block_size());
  std::vector<DetectionBlock> out;
  Emit(segments, base, grid, {0, Eigen::Vector3i::Zero()}, layout, out);
  return out;
}

std::vector<DetectionBlock> SplitDetectionBlock(std::span<const Segment3> segments,
                                                const BlockGrid& grid,
                                                const DetectionBlock& block,
                                                double halo) {
  std::vector<DetectionBlock> out;
  EmitChildren(segments,
               Members{block.segments, block.home_segments},
               grid,
               block.key,
               BlockLayout{.halo = halo, .max_home_segments = 0},
               out);
  return out;
}

}  // namespace linesurf::detect
