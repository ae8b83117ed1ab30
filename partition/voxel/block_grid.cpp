#include "partition/voxel/block_grid.h"

#include <openvdb/openvdb.h>

#include <algorithm>
#include <cmath>
#include <map>

#include "engine/core/exception.h"

namespace linesurf::partition {
namespace {

constexpr const char* kStage = "block_grid";

// Visits the integer cells crossed by segment a->b (in block units), Amanatides-Woo.
template <typename Visit>
void WalkCells(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3i& dims,
               Visit&& visit) {
  const auto clamp_cell = [&](const Eigen::Vector3d& p) {
    Eigen::Vector3i c;
    for (int k = 0; k < 3; ++k) c[k] = std::clamp(static_cast<int>(std::floor(p[k])), 0, dims[k] - 1);
    return c;
  };
  Eigen::Vector3i cell = clamp_cell(a);
  const Eigen::Vector3i last = clamp_cell(b);
  const Eigen::Vector3d d = b - a;
  Eigen::Vector3i step;
  Eigen::Vector3d t_max, t_delta;
  for (int k = 0; k < 3; ++k) {
    step[k] = d[k] > 0 ? 1 : (d[k] < 0 ? -1 : 0);
    if (step[k] == 0) {
      t_max[k] = t_delta[k] = std::numeric_limits<double>::infinity();
    } else {
      const double boundary = cell[k] + (step[k] > 0 ? 1.0 : 0.0);
      t_max[k] = (boundary - a[k]) / d[k];
      t_delta[k] = 1.0 / std::abs(d[k]);
    }
  }
  const int max_steps = (last - cell).cwiseAbs().sum() + 1;
  for (int i = 0; i < max_steps; ++i) {
    visit(cell);
    if (cell == last) return;
    int k = 0;
    if (t_max[1] < t_max[k]) k = 1;
    if (t_max[2] < t_max[k]) k = 2;
    if (t_max[k] > 1.0) return;
    cell[k] += step[k];
    if (cell[k] < 0 || cell[k] >= dims[k]) return;
    t_max[k] += t_delta[k];
  }
}

}  // namespace

Box3 BlockGrid::BlockBox(BlockId b) const {
  Box3 out;
  out.min = box.min + block_coords[b.index()].cast<double>() * block_size;
  out.max = out.min + Eigen::Vector3d::Constant(block_size);
  return out;
}

Expected<BlockGrid> BuildBlockGrid(std::span<const Segment3> segments, const Box3& box,
                                   const BlockGridOptions& options) noexcept {
  return CatchAll(kStage, [&]() -> BlockGrid {
    LINESURF_THROW_IF(!(options.block_size > 0.0) || !std::isfinite(options.block_size),
                      kInvalidOptions, kStage,
                      "block_size must be a positive finite length, got " << options.block_size);
    LINESURF_THROW_IF(box.IsEmpty(), kInvalidInput, kStage, "the scene box is empty");
    BlockGrid grid;
    grid.block_size = options.block_size;
    grid.box.min = box.min;
    const Eigen::Vector3d blocks = (box.Extent() / options.block_size).array().ceil().max(1.0);
    LINESURF_THROW_IF(blocks.prod() > static_cast<double>(options.max_blocks), kResourceExhausted,
                      kStage, "block grid of " << blocks.transpose() << " blocks exceeds max_blocks "
                                               << options.max_blocks);
    grid.dims = blocks.cast<int>();
    grid.box.max = box.min + grid.dims.cast<double>() * options.block_size;

    // Sparse occupancy: an OpenVDB grid maps block coordinates to a dense slot index, so empty
    // space costs nothing however large the box.
    openvdb::Int32Grid::Ptr slots = openvdb::Int32Grid::create(-1);
    auto accessor = slots->getAccessor();
    std::vector<std::vector<SegmentId>> members;
    std::vector<Eigen::Vector3i> coords;
    for (std::size_t s = 0; s < segments.size(); ++s) {
      const Eigen::Vector3d a = (segments[s].p1 - box.min) / options.block_size;
      const Eigen::Vector3d b = (segments[s].p2 - box.min) / options.block_size;
      WalkCells(a, b, grid.dims, [&](const Eigen::Vector3i& c) {
        const openvdb::Coord key(c.x(), c.y(), c.z());
        int slot = accessor.getValue(key);
        if (slot < 0) {
          slot = static_cast<int>(members.size());
          accessor.setValue(key, slot);
          members.emplace_back();
          coords.push_back(c);
        }
        if (members[slot].empty() || members[slot].back() != SegmentId(s)) {
          members[slot].push_back(SegmentId(s));
        }
      });
    }
    // Canonical order: by linear block index, independent of segment order.
    std::vector<std::size_t> order(coords.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    const auto linear = [&](const Eigen::Vector3i& c) {
      return (static_cast<std::int64_t>(c.z()) * grid.dims.y() + c.y()) * grid.dims.x() + c.x();
    };
    std::sort(order.begin(), order.end(),
              [&](std::size_t i, std::size_t j) { return linear(coords[i]) < linear(coords[j]); });
    for (std::size_t i : order) {
      grid.block_coords.push_back(coords[i]);
      grid.block_segments.AddRow(members[i]);
    }
    return grid;
  });
}

}  // namespace linesurf::partition
