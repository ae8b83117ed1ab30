#pragma once
// Per-block exact cell complexes of the block engine (docs/design/block_engine.md, section 3):
// every base block of a BlockGrid is split by its six faces and by the planes whose support
// region reaches it; planes and block faces carry global keys; facets are typed (interior, scene
// boundary, seam); on every face shared by two blocks the two subdivisions are overlaid exactly
// into seam facets, each joining one cell of each block.

#include "linesurf/error.h"

#include "engine/core/cell_complex.h"
#include "engine/core/geometry.h"
#include "engine/core/run_context.h"
#include "engine/core/strong_id.h"
#include "partition/arrangement/build_cell_complex.h"
#include "partition/voxel/block_grid.h"
#include "partition/voxel/plane_support.h"

#include <Eigen/Core>

#include <array>
#include <compare>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace linesurf::partition {

/// Global key of a plane: a base-grid face (axis, index into the face table) or an input plane.
/// Faces order before input planes; faces by (axis, index), input planes by id.
class PlaneKey {
 public:
  PlaneKey() = default;
  static PlaneKey Face(int axis, int index) {
    return PlaneKey((static_cast<std::uint64_t>(axis) << 32) | static_cast<std::uint32_t>(index));
  }
  static PlaneKey Input(PlaneId id) { return PlaneKey(kInputBit | id.value()); }
  [[nodiscard]] bool IsFace() const { return (value_ & kInputBit) == 0; }
  [[nodiscard]] int axis() const { return static_cast<int>(value_ >> 32); }
  [[nodiscard]] int face_index() const { return static_cast<int>(value_ & 0xffffffffu); }
  [[nodiscard]] PlaneId plane() const { return PlaneId(static_cast<std::uint32_t>(value_)); }
  [[nodiscard]] std::uint64_t value() const { return value_; }
  friend auto operator<=>(PlaneKey, PlaneKey) = default;

 private:
  static constexpr std::uint64_t kInputBit = std::uint64_t{1} << 62;
  explicit PlaneKey(std::uint64_t value) : value_(value) {}
  std::uint64_t value_ = 0;
};

/// A vertex as the sorted triple of global keys of three independent planes through it.
using VertexKey = std::array<PlaneKey, 3>;

enum class FacetKind : std::uint8_t {
  kInterior,       ///< on an input plane, both cells in the block
  kSceneBoundary,  ///< on a block face that lies on the grid box
  kSeam,           ///< on a block face shared with a neighbour block
};

struct BlockComplex {
  Eigen::Vector3i base = Eigen::Vector3i::Zero();  ///< base block coordinates
  CellComplex complex;                             ///< ComplexPlane::source is the global PlaneId
  /// Global key of every complex plane (6 faces, then the input planes in increasing id).
  std::vector<PlaneKey> plane_keys;
  IdVector<FacetId, FacetKind> facet_kind;
  /// The input plane lying exactly on each box face (order of the box planes), or invalid. Such
  /// a plane cannot split the block; it is kept here so that the face's facets can stand for it.
  std::array<PlaneId, kNumBoxPlanes> face_planes{};
  CellComplexStats stats;
};

/// A facet of the overlay of one shared face: the intersection of a facet of the lower block
/// (smaller coordinate along the face's axis) and one of the upper block.
struct SeamFacet {
  FacetId lower_facet;
  FacetId upper_facet;
  CellId lower_cell;
  CellId upper_cell;
  /// Cycle of vertices, counter-clockwise seen from the lower block (from inside its cell).
  std::vector<VertexKey> vertices;
  /// Plane whose trace on the face carries edge i (vertex i to i + 1).
  std::vector<PlaneKey> edge_planes;
  std::vector<Vec3> points;  ///< rounded vertex coordinates, for output and measures only
};

struct SeamFace {
  int axis = 0;
  std::uint32_t lower_block = 0;  ///< index into BlockComplexes::blocks
  std::uint32_t upper_block = 0;
  std::vector<SeamFacet> facets;
};

struct BlockComplexesStats {
  std::size_t blocks = 0;
  std::size_t cells = 0;
  std::size_t seam_faces = 0;
  std::size_t seam_facets = 0;
  std::size_t planes_on_faces = 0;    ///< (block, face) pairs with an input plane on the face
  std::size_t plane_block_pairs = 0;  ///< sum over blocks of the planes given to the block
  double seconds_complexes = 0.0;
  double seconds_overlay = 0.0;
};

struct BlockComplexes {
  BlockGrid grid;
  /// Input planes as (a, b, c, d), exactly as the block complexes use them.
  std::vector<Eigen::Vector4d> plane_coefficients;
  /// Every base block of the grid, in increasing linear index.
  std::vector<BlockComplex> blocks;
  /// Every face shared by two base blocks, by (lower block, axis).
  std::vector<SeamFace> seams;
  BlockComplexesStats stats;
  std::vector<std::string> warnings;

  /// Coefficients of a key: faces as (e_axis, -coordinate), input planes as given.
  [[nodiscard]] Eigen::Vector4d Coefficients(PlaneKey key) const;
};

/// Global cell ids of the block engine: cell c of block b is offsets[b] + c.index(), blocks in
/// `complexes.blocks` order. `offsets` has blocks.size() + 1 entries; the last is the total
/// number of cells. Evidence, solve and stitch all number cells this way.
[[nodiscard]] std::vector<std::size_t> GlobalCellOffsets(const BlockComplexes& complexes);

/// The block of every global cell (GlobalCellOffsets numbering): the partition of the cells that
/// the per-block labelling works on.
[[nodiscard]] std::vector<std::uint32_t> BlockOfEachCell(const BlockComplexes& complexes);

/// Builds the complex of every base block of `grid` (blocks in parallel inside an arena from
/// ctx.num_threads), each split by the planes of `regions` that reach it, and the seam overlay
/// of every shared face (faces in parallel). Identical for any thread count. Errors: those of
/// BuildCellComplex (per block, naming it), kInvalidInput when `regions` names a plane that is
/// not in `planes`.
[[nodiscard]] Expected<BlockComplexes> BuildBlockComplexes(const BlockGrid& grid,
                                                           std::span<const Plane3> planes,
                                                           const PlaneSupportRegions& regions,
                                                           const CellComplexOptions& options,
                                                           const RunContext& ctx) noexcept;

/// OK, or kInternal naming the first violated invariant: every block complex is valid
/// (ValidateCellComplex) and its cell volumes sum to the block volume; facet kinds match their
/// planes; on every shared face, each side's facets and the seam facets each sum to the face
/// area, every seam facet has positive area (exactly: a vertex off an edge's line; slivers
/// round to zero area), one cell of each block (the cells of its two
/// parent facets), and every vertex exactly inside both parent facets. Areas and volumes are
/// compared with relative tolerance `relative_tolerance`.
[[nodiscard]] Status ValidateBlockComplexes(const BlockComplexes& complexes,
                                            double relative_tolerance = 1e-9) noexcept;

}  // namespace linesurf::partition
