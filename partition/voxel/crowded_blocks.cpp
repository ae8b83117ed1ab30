#include "partition/voxel/crowded_blocks.h"

#include "engine/core/exception.h"

namespace linesurf::partition {
namespace {

constexpr const char* kCrowdedBlocksStage = "crowded_blocks";

bool IsCrowded(const PlaneSupportRegions& regions, std::size_t i, std::size_t max_planes) {
  return regions.block_planes[BlockId(i)].size() > max_planes;
}

}  // namespace

CutDepths UncutDepths(const BlockGrid& grid) {
  CutDepths depths;
  for (int a = 0; a < 3; ++a) depths[a].assign(static_cast<std::size_t>(grid.dims()[a]), 0);
  return depths;
}

std::size_t CountCrowdedBlocks(const PlaneSupportRegions& regions, std::size_t max_planes) {
  std::size_t crowded = 0;
  for (std::size_t i = 0; i < regions.blocks.size(); ++i) {
    if (IsCrowded(regions, i, max_planes)) ++crowded;
  }
  return crowded;
}

Expected<std::size_t> CutCrowdedBlocks(const PlaneSupportRegions& regions,
                                       std::size_t max_planes,
                                       std::int32_t max_depth,
                                       std::int64_t max_blocks,
                                       const SplitFaceChooser& chooser,
                                       BlockGrid& grid,
                                       CutDepths& depths) noexcept {
  return CatchAll(kCrowdedBlocksStage, [&]() -> std::size_t {
    for (int a = 0; a < 3; ++a) {
      LINESURF_THROW_IF(depths[a].size() != static_cast<std::size_t>(grid.dims()[a]),
                        kInvalidInput,
                        kCrowdedBlocksStage,
                        "cut depths of axis " << a << " do not match the grid");
    }
    std::array<std::vector<bool>, 3> cut;
    for (int a = 0; a < 3; ++a) cut[a].assign(depths[a].size(), false);
    for (std::size_t i = 0; i < regions.blocks.size(); ++i) {
      if (!IsCrowded(regions, i, max_planes)) continue;
      const Eigen::Vector3i base = grid.BaseFromLinear(regions.blocks[i]);
      for (int a = 0; a < 3; ++a) {
        const auto k = static_cast<std::size_t>(base[a]);
        if (depths[a][k] < max_depth) cut[a][k] = true;
      }
    }
    std::array<std::vector<double>, 3> faces;
    Eigen::Vector3d dims = grid.dims().cast<double>();
    for (int a = 0; a < 3; ++a) {
      const std::vector<double>& table = grid.FaceTable(a);
      for (std::size_t k = 0; k < cut[a].size(); ++k) {
        if (cut[a][k]) faces[a].push_back(chooser.Choose(a, table[k], table[k + 1]));
      }
      dims[a] += static_cast<double>(faces[a].size());
    }
    if (dims.prod() > static_cast<double>(max_blocks)) return 0;
    grid = ValueOrThrow(grid.WithFaces(faces));
    std::size_t added = 0;
    for (int a = 0; a < 3; ++a) {
      std::vector<std::int32_t> deeper;
      for (std::size_t k = 0; k < cut[a].size(); ++k) {
        const int copies = cut[a][k] ? 2 : 1;
        for (int c = 0; c < copies; ++c) deeper.push_back(depths[a][k] + (copies - 1));
      }
      LINESURF_ASSERT(deeper.size() == static_cast<std::size_t>(grid.dims()[a]));
      added += deeper.size() - depths[a].size();
      depths[a] = std::move(deeper);
    }
    return added;
  });
}

}  // namespace linesurf::partition
