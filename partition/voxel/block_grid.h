#pragma once
// The one block grid of the block engine (DESIGN section 3, docs/design/block_engine.md): a box
// cut into base blocks of side `block_size` with integer coordinates; the partition cuts crowded
// slabs with added faces (WithFaces), detection refines crowded blocks into octree children.
// Every block-face coordinate comes from one function of (axis, level, index) backed by one
// table per axis, so neighbouring blocks share their faces bit for bit.

#include "linesurf/error.h"

#include "engine/core/geometry.h"

#include <Eigen/Core>

#include <array>
#include <cstdint>
#include <vector>

namespace linesurf::partition {

/// A block: `index` counts, from the grid's minimum corner, the blocks of level `level`, whose
/// faces are the table entries (level 0, the base blocks) and their midpoints, level by level
/// (side block_size / 2^level on a grid without added faces).
struct BlockKey {
  std::int32_t level = 0;
  Eigen::Vector3i index = Eigen::Vector3i::Zero();

  friend bool operator==(const BlockKey& a, const BlockKey& b) {
    return a.level == b.level && a.index == b.index;
  }
};

/// Deepest refinement level (a base block split 12 times has children of side s / 4096).
inline constexpr std::int32_t kMaxBlockLevel = 12;

struct BlockGridOptions {
  /// Refuse grids with more base blocks than this (guards against absurd sizes).
  std::size_t max_blocks = std::size_t{1} << 24;
};

class BlockGrid {
 public:
  /// The grid of `box` (finite, min < max on every axis) with base blocks of side `block_size`
  /// (> 0): n_a = max(1, ceil(extent_a / block_size)) blocks along axis a, the last one clipped
  /// to box.max. Errors: kInvalidOptions (bad size), kInvalidInput (bad box),
  /// kResourceExhausted (more than options.max_blocks blocks).
  [[nodiscard]] static Expected<BlockGrid> Create(const Box3& box,
                                                  double block_size,
                                                  const BlockGridOptions& options = {}) noexcept;

  /// The grid of `blocks` whole blocks per axis (>= 1, fractions dropped) from `origin`: every
  /// block is a cube of side block_size, the box ends at the last table entry. Errors as above.
  [[nodiscard]] static Expected<BlockGrid> CreateWholeBlocks(
      const Vec3& origin,
      double block_size,
      const Eigen::Vector3d& blocks,
      const BlockGridOptions& options = {}) noexcept;

  /// This grid with the coordinates `faces[a]` added to the face table of each axis a: every
  /// base block a new face crosses is cut in two, along the whole slab, so every face stays
  /// shared by exactly two blocks (or one and the box). Coordinates must lie strictly inside the
  /// box; those already in a table are ignored. block_size() keeps the nominal side. Errors:
  /// kInvalidInput (a coordinate not finite or not inside the box), kResourceExhausted as
  /// Create.
  [[nodiscard]] Expected<BlockGrid> WithFaces(const std::array<std::vector<double>, 3>& faces,
                                              const BlockGridOptions& options = {}) const noexcept;

  [[nodiscard]] const Box3& box() const { return box_; }
  /// The side of the base blocks before WithFaces split some (the nominal side).
  [[nodiscard]] double block_size() const { return block_size_; }
  /// Base blocks along each axis.
  [[nodiscard]] const Eigen::Vector3i& dims() const { return dims_; }
  [[nodiscard]] std::int64_t NumBaseBlocks() const {
    return static_cast<std::int64_t>(dims_.x()) * dims_.y() * dims_.z();
  }
  /// The face coordinates of the base blocks along `axis`: dims()[axis] + 1 increasing values,
  /// first box().min[axis], last box().max[axis].
  [[nodiscard]] const std::vector<double>& FaceTable(int axis) const { return faces_[axis]; }
  /// Coordinate of face `index` along `axis` at `level`: the table entry where index is a
  /// multiple of 2^level, else the midpoint of the two enclosing faces of level - 1. A pure
  /// function: every block asking for one face gets the same double.
  [[nodiscard]] double Face(int axis, std::int32_t level, std::int64_t index) const;
  [[nodiscard]] Box3 BlockBox(const BlockKey& key) const;
  /// The base block holding p along each axis: face[i] <= p < face[i + 1], the last block closed
  /// at box().max; coordinates outside the box are clamped to the first/last block.
  [[nodiscard]] Eigen::Vector3i Locate(const Vec3& p) const;
  /// The same along one axis.
  [[nodiscard]] int LocateAxis(int axis, double x) const;
  /// Child (0 or 1 per axis) of `parent` holding p: p at or above the parent's mid face goes to 1.
  [[nodiscard]] BlockKey ChildHolding(const BlockKey& parent, const Vec3& p) const;
  /// Children of a block, in (z, y, x) order.
  [[nodiscard]] std::array<BlockKey, 8> Children(const BlockKey& parent) const;
  /// (z * ny + y) * nx + x of a base block: the canonical listing order.
  [[nodiscard]] std::int64_t LinearIndex(const Eigen::Vector3i& base) const {
    return (static_cast<std::int64_t>(base.z()) * dims_.y() + base.y()) * dims_.x() + base.x();
  }
  [[nodiscard]] Eigen::Vector3i BaseFromLinear(std::int64_t linear) const;
  [[nodiscard]] bool IsInside(const Eigen::Vector3i& base) const {
    return (base.array() >= 0).all() && (base.array() < dims_.array()).all();
  }

 private:
  /// Face tables origin + i * block_size, the last entry replaced by clip_max when given.
  static BlockGrid Make(const Vec3& origin,
                        double block_size,
                        const Eigen::Vector3d& blocks,
                        const Vec3* clip_max,
                        const BlockGridOptions& options);

  Box3 box_;
  double block_size_ = 0.0;
  Eigen::Vector3i dims_{0, 0, 0};
  std::array<std::vector<double>, 3> faces_;
};

}  // namespace linesurf::partition
