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
}  // namespace

std::vector<DetectionBlock> AssignDetectionBlocks(std::span<const Segment3> segments,
                                                  double block_size,
                                                  double halo) {
  Box3 box;
  for (const Segment3& s : segments) box.Extend(s.Midpoint());
  if (box.IsEmpty()) return {};
  const Vec3 extent = box.Extent();
  LINESURF_THROW_IF(extent.maxCoeff() / block_size > kMaxBlocksPerAxis,
                    kInvalidOptions,
                    kStage,
                    "PlaneDetectionOptions.block_size "
                        << block_size << " is too small for a scene of extent " << extent.maxCoeff()
                        << " (more than 2^20 blocks along one axis)");
  using Key = std::tuple<std::int64_t, std::int64_t, std::int64_t>;  // (z, y, x): the listing order
  struct Members {
    std::vector<SegmentId> ids;
    bool home = false;  ///< some segment's midpoint lies in the block itself
  };
  std::map<Key, Members> blocks;
  for (std::size_t i = 0; i < segments.size(); ++i) {
    const Vec3 rel = (segments[i].Midpoint() - box.min) / block_size;
    const double h = halo / block_size;
    std::array<std::int64_t, 3> home{};
    std::array<std::int64_t, 3> lo{};
    std::array<std::int64_t, 3> hi{};
    for (int a = 0; a < 3; ++a) {
      lo[a] = static_cast<std::int64_t>(std::floor(rel[a] - h));
      hi[a] = static_cast<std::int64_t>(std::floor(rel[a] + h));
      home[a] = static_cast<std::int64_t>(std::floor(rel[a]));
    }
    blocks[{home[2], home[1], home[0]}].home = true;
    for (std::int64_t z = lo[2]; z <= hi[2]; ++z) {
      for (std::int64_t y = lo[1]; y <= hi[1]; ++y) {
        for (std::int64_t x = lo[0]; x <= hi[0]; ++x) blocks[{z, y, x}].ids.emplace_back(i);
      }
    }
  }
  std::vector<DetectionBlock> out;
  out.reserve(blocks.size());
  for (auto& [key, members] : blocks) {
    if (!members.home) continue;  // halo only: its segments' home blocks detect them
    DetectionBlock block;
    std::tie(block.z, block.y, block.x) = key;
    block.segments = std::move(members.ids);  // ascending: segments were visited in order
    out.push_back(std::move(block));
  }
  return out;
}

}  // namespace linesurf::detect
