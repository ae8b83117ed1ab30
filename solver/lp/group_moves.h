#pragma once
// Local search with moves larger than one cell: the free cells of one term (a pair, the cells
// around a structural edge, around an edge or a vertex of a parity group) take their best joint
// labelling with every other cell held. Single flips cannot leave a crease or a checkerboard of
// a parity group whose cells only pay off together; one group move can.

#include "engine/core/run_context.h"
#include "solver/energy/energy_input.h"

#include <cstdint>
#include <vector>

namespace linesurf::solver {

/// Sweeps (at most `max_passes`) over the terms in order (pairs, structural, parity), each time
/// giving the free cells of a term their best joint labelling (JointLabelWalk; terms with more
/// than kMaxJointCells free cells are skipped) when
/// that lowers the energy beyond rounding noise. The first sweep visits the terms touching a
/// cell next to the surface of `labels` (a term whose cells carry different labels) or a cell
/// whose unary cost prefers the other label; later sweeps only the terms touching a cell that
/// shares a term with a cell changed before. Single-cell flips run between
/// sweeps. Never raises the energy. The moves of a sweep are evaluated in parallel on
/// ctx.num_threads threads and taken in term order, so the labels are those of the serial sweep
/// for any thread count. Returns the number of cells changed.
std::size_t ImproveByGroupMoves(const EnergyInput& energy,
                                int max_passes,
                                const RunContext& ctx,
                                std::vector<std::uint8_t>& labels);

}  // namespace linesurf::solver
