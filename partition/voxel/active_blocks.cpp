#include "partition/voxel/active_blocks.h"

#include <openvdb/openvdb.h>
#include <openvdb/tools/Morphology.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace linesurf::partition {
namespace {

openvdb::Coord ToCoord(const Eigen::Vector3i& c) { return {c.x(), c.y(), c.z()}; }

}  // namespace

std::vector<Eigen::Vector3i> BlocksCrossed(const BlockGrid& grid, const Segment3& segment) {
  const Eigen::Vector3i first = grid.Locate(segment.p1);
  const Eigen::Vector3i last = grid.Locate(segment.p2);
  std::vector<Eigen::Vector3i> out{first};
  const Vec3 d = segment.p2 - segment.p1;
  Eigen::Vector3i cell = first;
  Eigen::Vector3i step;
  for (int a = 0; a < 3; ++a) step[a] = last[a] > cell[a] ? 1 : (last[a] < cell[a] ? -1 : 0);
  // Parameter at which the segment reaches the next face along axis a (from the face table).
  const auto next_t = [&](int a) {
    if (step[a] == 0) return std::numeric_limits<double>::infinity();
    const double face = grid.FaceTable(a)[cell[a] + (step[a] > 0 ? 1 : 0)];
    return (face - segment.p1[a]) / d[a];
  };
  const int steps = (last - first).cwiseAbs().sum();
  for (int i = 0; i < steps; ++i) {
    int axis = -1;
    double best = std::numeric_limits<double>::infinity();
    for (int a = 0; a < 3; ++a) {
      if (cell[a] == last[a]) continue;  // never step past the endpoint's block on an axis
      const double t = next_t(a);
      if (axis < 0 || t < best) {
        axis = a;
        best = t;
      }
    }
    cell[axis] += step[axis];
    out.push_back(cell);
  }
  return out;
}

ActiveBlocks RasteriseSegments(const BlockGrid& grid, std::span<const Segment3> segments) {
  // Sparse slots: an OpenVDB grid maps block coordinates to a dense slot, so empty space costs
  // nothing however large the grid.
  openvdb::Int32Grid::Ptr slots = openvdb::Int32Grid::create(-1);
  auto accessor = slots->getAccessor();
  std::vector<std::vector<SegmentId>> members;
  std::vector<std::int64_t> linear;
  for (std::size_t s = 0; s < segments.size(); ++s) {
    for (const Eigen::Vector3i& c : BlocksCrossed(grid, segments[s])) {
      const openvdb::Coord key = ToCoord(c);
      int slot = accessor.getValue(key);
      if (slot < 0) {
        slot = static_cast<int>(members.size());
        accessor.setValue(key, slot);
        members.emplace_back();
        linear.push_back(grid.LinearIndex(c));
      }
      if (members[slot].empty() || members[slot].back() != SegmentId(s)) {
        members[slot].push_back(SegmentId(s));
      }
    }
  }
  std::vector<std::size_t> order(linear.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](std::size_t i, std::size_t j) {
    return linear[i] < linear[j];
  });
  ActiveBlocks out;
  for (const std::size_t i : order) {
    out.blocks.push_back(linear[i]);
    out.segments.AddRow(members[i]);
  }
  return out;
}

std::vector<std::int64_t> DilateBlocks(const BlockGrid& grid,
                                       std::span<const std::int64_t> blocks,
                                       int margin) {
  openvdb::MaskGrid::Ptr mask = openvdb::MaskGrid::create(false);
  auto& tree = mask->tree();
  for (const std::int64_t b : blocks) tree.setValueOn(ToCoord(grid.BaseFromLinear(b)));
  if (margin > 0) {
    openvdb::tools::dilateActiveValues(
        tree, margin, openvdb::tools::NN_FACE_EDGE_VERTEX, openvdb::tools::IGNORE_TILES);
  }
  std::vector<std::int64_t> out;
  out.reserve(tree.activeVoxelCount());
  for (auto it = tree.cbeginValueOn(); it; ++it) {
    const openvdb::CoordBBox bbox = it.getBoundingBox();  // one voxel, or a tile's voxels
    for (auto c = bbox.begin(); c; ++c) {
      const Eigen::Vector3i base((*c).x(), (*c).y(), (*c).z());
      if (grid.IsInside(base)) out.push_back(grid.LinearIndex(base));
    }
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

}  // namespace linesurf::partition
