#pragma once
// The regularisation elements of the block engine that lie on block faces and block edges
// (docs/design/block_engine.md, "Energy terms on seams" and section 4): every edge piece and
// vertex of the partition refined by the block faces that lies on a face shared by blocks (not
// on the scene box), once, with the cells of every block around it and their parity signs.
//
// Signs. Around an edge or vertex on block faces, the planes through it come from several
// blocks (the block faces are planes too). A cell of a block that a plane through the element
// does not reach (a plane of another block) is split by it virtually into pieces of one label
// and alternating signs; one such plane makes the pieces cancel, so the cell leaves the group.
// Every other cell gets nu = product of its sides of all planes through the element, the
// 2-colouring of the arrangement of those planes. On an edge of three cells (a plane P reaching
// only one side: cells c1, c2 of one block and c3 of the other) this gives the pairwise term
// |x_c1 - x_c2|, which is 1 exactly when the surface bends at the edge. A cell cut virtually by
// two or more planes is also left out (an approximation; such pencils on block faces are rare).

#include "linesurf/error.h"

#include "engine/core/run_context.h"
#include "engine/core/strong_id.h"
#include "partition/arrangement/block_complexes.h"

#include <cstdint>
#include <vector>

namespace linesurf::partition {

/// A cell of one block: `block` indexes BlockComplexes::blocks.
struct BlockCell {
  std::uint32_t block = 0;
  CellId cell;
  friend auto operator<=>(const BlockCell&, const BlockCell&) = default;
};

/// weight * |sum nu_c x_c| over the cells: an edge piece (weight per length) or a vertex.
struct SeamParityGroup {
  double length = 0.0;             ///< of the edge piece (rounded geometry); 0 for a vertex
  std::vector<BlockCell> cells;    ///< ascending, distinct, at least one
  std::vector<std::int8_t> signs;  ///< nu of each cell, +1 or -1
};

struct SeamRegularisation {
  /// Edge pieces on block faces and block edges, by line then along it.
  std::vector<SeamParityGroup> edges;
  /// Vertices on block faces, edges and corners, by their canonical global triple.
  std::vector<SeamParityGroup> vertices;
  std::size_t edges_with_dropped_cells = 0;  ///< pieces where a plane reaches only some blocks
};

/// The seam elements of `complexes` (faces in parallel in an arena of ctx.num_threads; the
/// result does not depend on the thread count). Errors: kCancelled.
[[nodiscard]] Expected<SeamRegularisation> ComputeSeamRegularisation(
    const BlockComplexes& complexes, const RunContext& ctx) noexcept;

}  // namespace linesurf::partition
