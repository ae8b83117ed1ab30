#include "engine/detect/detection_blocks.h"

#include "engine/core/exception.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <tuple>

namespace linesurf::detect {
namespace {
constexpr char kStage[] = "detect_planes";
/// Guards the integer block coordinates against absurdly small block sizes.
constexpr double kMaxBlocksPerAxis = 1 << 20;
/// Splits stop here even if a block stays crowded (its segments' midpoints nearly coincide).
constexpr int kMaxDepth = 12;

using Key = std::array<std::int64_t, 3>;  // (z, y, x): the listing order

struct Members {
  std::vector<SegmentId> ids;       ///< home and halo segments, ascending
  std::vector<SegmentId> home_ids;  ///< segments whose midpoint lies in the cube itself
};

/// Cubes of side `size` anchored at `origin`, with a halo of `halo` (scene units), holding `ids`.
/// For the children of a split block (`parent_home` set), only the cubes 0..1 along each axis
/// exist, and every home segment of the parent is the home of one child.
std::map<Key, Members> Distribute(std::span<const Segment3> segments,
                                  std::span<const SegmentId> ids,
                                  const Vec3& origin,
                                  double size,
                                  double halo,
                                  const std::vector<SegmentId>* parent_home) {
  std::map<Key, Members> cubes;
  const double h = halo / size;
  for (const SegmentId id : ids) {
    const Vec3 rel = (segments[id.index()].Midpoint() - origin) / size;
    Key home{};
    Key lo{};
    Key hi{};
    for (int a = 0; a < 3; ++a) {  // key order is (z, y, x)
      home[2 - a] = static_cast<std::int64_t>(std::floor(rel[a]));
      lo[2 - a] = static_cast<std::int64_t>(std::floor(rel[a] - h));
      hi[2 - a] = static_cast<std::int64_t>(std::floor(rel[a] + h));
    }
    bool is_home = true;
    if (parent_home != nullptr) {
      is_home = std::binary_search(parent_home->begin(), parent_home->end(), id);
      for (int a = 0; a < 3; ++a) {
        // Rounding may put a parent's home segment a hair outside: keep it in a child.
        if (is_home) home[a] = std::clamp<std::int64_t>(home[a], 0, 1);
        lo[a] = std::max<std::int64_t>(std::min(lo[a], home[a]), 0);
        hi[a] = std::min<std::int64_t>(std::max(hi[a], home[a]), 1);
      }
    }
    if (is_home) cubes[home].home_ids.push_back(id);
    for (std::int64_t z = lo[0]; z <= hi[0]; ++z) {
      for (std::int64_t y = lo[1]; y <= hi[1]; ++y) {
        for (std::int64_t x = lo[2]; x <= hi[2]; ++x) cubes[{z, y, x}].ids.push_back(id);
      }
    }
  }
  return cubes;
}

/// Appends the blocks of `cubes` in key order, splitting the crowded ones.
void Emit(std::span<const Segment3> segments,
          std::map<Key, Members>& cubes,
          const Vec3& origin,
          double size,
          const BlockLayout& layout,
          int depth,
          std::vector<DetectionBlock>& out) {
  for (auto& [key, members] : cubes) {
    if (members.home_ids.empty()) continue;  // halo only: its segments' home blocks detect them
    DetectionBlock block;
    block.box.min = origin + size * Vec3(static_cast<double>(key[2]),
                                         static_cast<double>(key[1]),
                                         static_cast<double>(key[0]));
    block.box.max = block.box.min + Vec3::Constant(size);
    block.depth = depth;
    const bool crowded = layout.max_home_segments > 0 &&
                         members.home_ids.size() > layout.max_home_segments && depth < kMaxDepth;
    if (!crowded) {
      block.segments = std::move(members.ids);
      out.push_back(std::move(block));
      continue;
    }
    const double child = 0.5 * size;
    std::map<Key, Members> children = Distribute(
        segments, members.ids, block.box.min, child, layout.halo * child, &members.home_ids);
    Emit(segments, children, block.box.min, child, layout, depth + 1, out);
  }
}

}  // namespace

std::vector<DetectionBlock> AssignDetectionBlocks(std::span<const Segment3> segments,
                                                  const BlockLayout& layout) {
  Box3 box;
  for (const Segment3& s : segments) box.Extend(s.Midpoint());
  if (box.IsEmpty()) return {};
  const double extent = box.Extent().maxCoeff();
  LINESURF_THROW_IF(extent / layout.block_size > kMaxBlocksPerAxis,
                    kInvalidOptions,
                    kStage,
                    "PlaneDetectionOptions.block_size "
                        << layout.block_size << " is too small for a scene of extent " << extent
                        << " (more than 2^20 blocks along one axis)");
  std::vector<SegmentId> all(segments.size());
  for (std::size_t i = 0; i < segments.size(); ++i) all[i] = SegmentId(i);
  std::map<Key, Members> grid = Distribute(
      segments, all, box.min, layout.block_size, layout.halo * layout.block_size, nullptr);
  std::vector<DetectionBlock> out;
  Emit(segments, grid, box.min, layout.block_size, layout, 0, out);
  return out;
}

}  // namespace linesurf::detect
