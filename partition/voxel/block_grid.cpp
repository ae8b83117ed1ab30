#include "partition/voxel/block_grid.h"

#include "engine/core/exception.h"

#include <algorithm>
#include <cmath>

namespace linesurf::partition {
namespace {

constexpr const char* kBlockGridStage = "block_grid";
/// Keeps the indices of the deepest level within int32: 2^18 base blocks times 2^12.
constexpr double kMaxBlocksPerAxis = 1 << 18;

}  // namespace

namespace {

void CheckBlockSize(double block_size) {
  LINESURF_THROW_IF(!(block_size > 0.0) || !std::isfinite(block_size),
                    kInvalidOptions,
                    kBlockGridStage,
                    "block_size must be a positive finite length, got " << block_size);
}

void CheckBlockCount(const Eigen::Vector3d& blocks, const BlockGridOptions& options) {
  LINESURF_THROW_IF(blocks.prod() > static_cast<double>(options.max_blocks),
                    kResourceExhausted,
                    kBlockGridStage,
                    "block grid of " << blocks.transpose() << " blocks exceeds max_blocks "
                                     << options.max_blocks);
  LINESURF_THROW_IF((blocks.array() > kMaxBlocksPerAxis).any(),
                    kResourceExhausted,
                    kBlockGridStage,
                    "block grid of " << blocks.transpose() << " blocks exceeds "
                                     << kMaxBlocksPerAxis << " blocks along one axis");
}

}  // namespace

BlockGrid BlockGrid::Make(const Vec3& origin,
                          double block_size,
                          const Eigen::Vector3d& blocks,
                          const Vec3* clip_max,
                          const BlockGridOptions& options) {
  CheckBlockCount(blocks, options);
  BlockGrid grid;
  grid.block_size_ = block_size;
  grid.dims_ = blocks.cast<int>();
  for (int a = 0; a < 3; ++a) {
    std::vector<double>& table = grid.faces_[a];
    table.resize(grid.dims_[a] + 1);
    for (int i = 0; i <= grid.dims_[a]; ++i) table[i] = origin[a] + i * block_size;
    if (clip_max != nullptr) table.back() = (*clip_max)[a];
    for (int i = 0; i < grid.dims_[a]; ++i) {
      LINESURF_THROW_IF(!(table[i] < table[i + 1]) || !std::isfinite(table[i + 1]),
                        kInvalidOptions,
                        kBlockGridStage,
                        "block_size " << block_size << " gives an empty block along axis " << a);
    }
    grid.box_.min[a] = table.front();
    grid.box_.max[a] = table.back();
  }
  return grid;
}

Expected<BlockGrid> BlockGrid::Create(const Box3& box,
                                      double block_size,
                                      const BlockGridOptions& options) noexcept {
  return CatchAll(kBlockGridStage, [&]() -> BlockGrid {
    CheckBlockSize(block_size);
    LINESURF_THROW_IF(box.IsEmpty() || !box.min.allFinite() || !box.max.allFinite() ||
                          !(box.min.array() < box.max.array()).all(),
                      kInvalidInput,
                      kBlockGridStage,
                      "the grid box must be finite with min < max on every axis");
    const Eigen::Vector3d blocks = (box.Extent() / block_size).array().ceil().max(1.0);
    return Make(box.min, block_size, blocks, &box.max, options);
  });
}

Expected<BlockGrid> BlockGrid::CreateWholeBlocks(const Vec3& origin,
                                                 double block_size,
                                                 const Eigen::Vector3d& blocks,
                                                 const BlockGridOptions& options) noexcept {
  return CatchAll(kBlockGridStage, [&]() -> BlockGrid {
    CheckBlockSize(block_size);
    LINESURF_THROW_IF(!origin.allFinite() || !blocks.allFinite() || (blocks.array() < 1.0).any(),
                      kInvalidInput,
                      kBlockGridStage,
                      "a grid needs a finite origin and at least one block per axis");
    return Make(origin, block_size, blocks.array().floor().matrix(), nullptr, options);
  });
}

Expected<BlockGrid> BlockGrid::WithFaces(const std::array<std::vector<double>, 3>& faces,
                                         const BlockGridOptions& options) const noexcept {
  return CatchAll(kBlockGridStage, [&]() -> BlockGrid {
    BlockGrid grid = *this;
    for (int a = 0; a < 3; ++a) {
      std::vector<double>& table = grid.faces_[a];
      for (const double x : faces[a]) {
        LINESURF_THROW_IF(
            !(x > box_.min[a] && x < box_.max[a]),
            kInvalidInput,
            kBlockGridStage,
            "added face " << x << " along axis " << a << " is not strictly inside the box");
        table.push_back(x);
      }
      std::sort(table.begin(), table.end());
      table.erase(std::unique(table.begin(), table.end()), table.end());
      grid.dims_[a] = static_cast<int>(table.size()) - 1;
    }
    CheckBlockCount(grid.dims_.cast<double>(), options);
    return grid;
  });
}

double BlockGrid::Face(int axis, std::int32_t level, std::int64_t index) const {
  if (level == 0) {
    // A key outside the grid would read past the face table (ASan found one in a test).
    LINESURF_ASSERT(index >= 0 && index <= dims_[axis]);
    return faces_[axis][static_cast<std::size_t>(index)];
  }
  if (index % 2 == 0) return Face(axis, level - 1, index / 2);
  return 0.5 * (Face(axis, level - 1, index / 2) + Face(axis, level - 1, index / 2 + 1));
}

Box3 BlockGrid::BlockBox(const BlockKey& key) const {
  Box3 out;
  for (int a = 0; a < 3; ++a) {
    out.min[a] = Face(a, key.level, key.index[a]);
    out.max[a] = Face(a, key.level, std::int64_t{key.index[a]} + 1);
  }
  return out;
}

int BlockGrid::LocateAxis(int axis, double x) const {
  const std::vector<double>& table = faces_[axis];
  // First face above x, minus one: face[i] <= x < face[i + 1].
  const auto above = std::upper_bound(table.begin(), table.end(), x);
  const auto i = static_cast<int>(above - table.begin()) - 1;
  return std::clamp(i, 0, dims_[axis] - 1);
}

Eigen::Vector3i BlockGrid::Locate(const Vec3& p) const {
  return {LocateAxis(0, p.x()), LocateAxis(1, p.y()), LocateAxis(2, p.z())};
}

BlockKey BlockGrid::ChildHolding(const BlockKey& parent, const Vec3& p) const {
  BlockKey child{parent.level + 1, 2 * parent.index};
  for (int a = 0; a < 3; ++a) {
    if (p[a] >= Face(a, child.level, std::int64_t{child.index[a]} + 1)) ++child.index[a];
  }
  return child;
}

std::array<BlockKey, 8> BlockGrid::Children(const BlockKey& parent) const {
  std::array<BlockKey, 8> out;
  for (int c = 0; c < 8; ++c) {
    out[c] = {parent.level + 1,
              2 * parent.index + Eigen::Vector3i(c & 1, (c >> 1) & 1, (c >> 2) & 1)};
  }
  return out;
}

Eigen::Vector3i BlockGrid::BaseFromLinear(std::int64_t linear) const {
  const std::int64_t nx = dims_.x(), ny = dims_.y();
  return {static_cast<int>(linear % nx),
          static_cast<int>((linear / nx) % ny),
          static_cast<int>(linear / (nx * ny))};
}

}  // namespace linesurf::partition
