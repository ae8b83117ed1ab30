#pragma once
// Builds the exact convex cell complex of planes inside a box (docs/design/cell_complex.md): the box is
// split by every plane that crosses its interior, with full incidence (see
// engine/core/cell_complex.h for the conventions). Vertices are plane triples; every side
// decision is an exact predicate; doubles are only rounded output.

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "engine/core/cell_complex.h"
#include "engine/core/geometry.h"
#include "engine/core/run_context.h"
#include "linesurf/error.h"

namespace linesurf::partition {

struct CellComplexOptions {
  /// A box centre farther than this many box diagonals from the origin gives a warning: the
  /// complex expects local (recentred) coordinates, where the filters rarely fall back to exact
  /// arithmetic. Range > 0.
  double max_centre_offset_in_diagonals = 1000.0;
  /// Fail with kResourceExhausted when the complex would exceed this many cells (0 = no limit).
  std::size_t max_cells = 0;

  [[nodiscard]] Status Validate() const;
};

struct CellComplexStats {
  std::size_t planes_input = 0;
  std::size_t planes_used = 0;
  std::size_t planes_skipped_outside = 0;   ///< the plane misses the closed box
  std::size_t planes_skipped_touching = 0;  ///< meets the box only on its boundary
  std::size_t planes_duplicate = 0;         ///< same or opposite of an earlier used plane
  std::size_t planes_invalid = 0;           ///< non-finite or zero normal
  std::uint64_t exact_fallbacks = 0;        ///< predicates the interval filter could not decide
  double seconds = 0.0;
};

struct CellComplexResult {
  CellComplex complex;
  CellComplexStats stats;
  std::vector<std::string> warnings;
};

/// The complex of `box` (local frame, non-empty) split by `planes`, inserted in input order.
/// ComplexPlane::source is the index of the input plane. Planes that miss or only touch the box,
/// duplicates (same or opposite orientation) and invalid planes are skipped and counted.
/// Runs serially on the calling thread (cancellation is polled between planes).
[[nodiscard]] Expected<CellComplexResult> BuildCellComplex(const Box3& box,
                                                           std::span<const Plane3> planes,
                                                           const CellComplexOptions& options,
                                                           const RunContext& ctx) noexcept;

/// Independent complexes, one per box (all split by the same candidate planes), built in
/// parallel with oneTBB inside an arena sized from ctx.num_threads. results[b] belongs to
/// boxes[b]; the output does not depend on the number of threads.
[[nodiscard]] Expected<std::vector<CellComplexResult>> BuildCellComplexes(
    std::span<const Box3> boxes, std::span<const Plane3> planes, const CellComplexOptions& options,
    const RunContext& ctx) noexcept;

/// As above with its own plane list per box: planes_per_box[b] splits boxes[b], and
/// ComplexPlane::source of results[b] indexes planes_per_box[b].
[[nodiscard]] Expected<std::vector<CellComplexResult>> BuildCellComplexes(
    std::span<const Box3> boxes, std::span<const std::vector<Plane3>> planes_per_box,
    const CellComplexOptions& options, const RunContext& ctx) noexcept;

}  // namespace linesurf::partition
