#include "partition/voxel/crowded_blocks.h"

namespace linesurf::partition {

std::size_t CountCrowdedBlocks(const PlaneSupportRegions& regions, std::size_t max_planes) {
  std::size_t crowded = 0;
  for (std::size_t i = 0; i < regions.blocks.size(); ++i) {
    if (regions.block_planes[BlockId(i)].size() > max_planes) ++crowded;
  }
  return crowded;
}

std::array<std::vector<double>, 3> FacesSplittingCrowdedBlocks(const BlockGrid& grid,
                                                               const PlaneSupportRegions& regions,
                                                               std::size_t max_planes,
                                                               double min_length,
                                                               const SplitFaceChooser& chooser) {
  std::array<std::vector<bool>, 3> split;
  for (int a = 0; a < 3; ++a) split[a].assign(static_cast<std::size_t>(grid.dims()[a]), false);
  for (std::size_t i = 0; i < regions.blocks.size(); ++i) {
    if (regions.block_planes[BlockId(i)].size() <= max_planes) continue;
    const Eigen::Vector3i base = grid.BaseFromLinear(regions.blocks[i]);
    for (int a = 0; a < 3; ++a) split[a][static_cast<std::size_t>(base[a])] = true;
  }
  std::array<std::vector<double>, 3> faces;
  for (int a = 0; a < 3; ++a) {
    const std::vector<double>& table = grid.FaceTable(a);
    for (std::size_t i = 0; i < split[a].size(); ++i) {
      if (split[a][i] && table[i + 1] - table[i] >= min_length) {
        faces[a].push_back(chooser.Choose(a, table[i], table[i + 1]));
      }
    }
  }
  return faces;
}

}  // namespace linesurf::partition
