#pragma once
/// @file build_lp.h
/// @brief EnergyInput -> LP relaxation, with fixed cells substituted as constants.
///
/// Two steps:
///  1. ReduceEnergy substitutes every fixed cell by its label. A pairwise term with one fixed
///     cell becomes a unary term (|x - 0| = x, |x - 1| = 1 - x on [0,1]); a structural group
///     holding a full cell vanishes, its empty cells drop out, and a group with one free cell
///     becomes 1 - x; a parity group keeps k = its constant + sum of nu over its full cells,
///     |nu x + k| with one free cell is linear on [0,1] (k is an integer) and folds too. Terms
///     without free cells and terms of zero weight go to the constant or away. What remains is
///     an energy over free cells only: unary coefficients, pairs, structural and parity groups
///     of at least two free cells.
///  2. BuildLpModel writes the LP in canonical order:
///       columns: free cells by CellId (column j = j-th free cell), then one slack per pair,
///                structural group, parity group (in that order, each by term index);
///       rows:    pairs (2 each), structural groups (1 each), parity groups (2 each), same order.
///     Every row is "A x >= lower" (upper = +inf); cells are boxed in [0,1], slacks in [0, inf):
///       pair s:        s - x_a + x_b >= 0,  s + x_a - x_b >= 0           (s >= |x_a - x_b|)
///       structural t:  t + sum x >= 1                                   (t >= max(0, 1 - sum x))
///       parity p:      p - sum nu x >= k,  p + sum nu x >= -k          (p >= |sum nu x + k|)
///     objective_offset holds the constant, so LpModel::Evaluate(optimum) equals the energy.

#include <cstdint>
#include <span>
#include <vector>

#include "solver/energy/energy_input.h"
#include "solver/lp/lp_model.h"

namespace linesurf::solver {

/// Column index of a fixed cell.
inline constexpr std::uint32_t kNoColumn = 0xFFFFFFFFu;

/// The energy over free cells only; cells are columns 0..NumFree()-1 (free cells in id order).
struct ReducedEnergy {
  /// CellId of each column.
  std::vector<CellId> cell_of_column;
  /// Column of each cell (kNoColumn for fixed cells); size = number of cells.
  std::vector<std::uint32_t> column_of_cell;
  /// Energy = constant + sum_j unary[j] * x_j + the terms below.
  double constant = 0.0;
  std::vector<double> unary;

  struct Pair {
    std::uint32_t a = 0;
    std::uint32_t b = 0;
    double weight = 0.0;
  };
  /// weight * |x_a - x_b| between two free columns.
  std::vector<Pair> pairs;

  /// weight * max(0, 1 - sum x) over >= 2 free columns.
  std::vector<std::uint32_t> structural_offsets{0};
  std::vector<std::uint32_t> structural_columns;
  std::vector<double> structural_weights;

  /// weight * |sum nu x + offset| over >= 2 free columns.
  std::vector<std::uint32_t> parity_offsets{0};
  std::vector<std::uint32_t> parity_columns;
  std::vector<std::int8_t> parity_signs;
  std::vector<double> parity_weights;
  std::vector<std::int32_t> parity_constants;

  [[nodiscard]] std::size_t NumFree() const { return cell_of_column.size(); }
  [[nodiscard]] bool HasHigherOrderTerms() const {
    return !structural_weights.empty() || !parity_weights.empty();
  }
  /// Energy of free-column values x (constant included); equals EnergyInput::Evaluate of the
  /// full labelling that puts fixed cells at their label.
  [[nodiscard]] double Evaluate(std::span<const double> x) const;
};

/// Step 1 (see the file comment). `energy` must pass Validate().
[[nodiscard]] ReducedEnergy ReduceEnergy(const EnergyInput& energy);

/// Step 2 (see the file comment).
[[nodiscard]] LpModel BuildLpModel(const ReducedEnergy& reduced);

/// The size of BuildLpModel(reduced), without building it.
struct LpShape {
  std::size_t columns = 0;
  std::size_t rows = 0;
  std::size_t nonzeros = 0;
};
[[nodiscard]] LpShape ShapeOfLp(const ReducedEnergy& reduced);

/// Full labelling (one value per cell) from free-column values: fixed cells at their label.
[[nodiscard]] std::vector<double> ExpandToCells(const EnergyInput& energy,
                                                const ReducedEnergy& reduced,
                                                std::span<const double> column_values);

}  // namespace linesurf::solver
