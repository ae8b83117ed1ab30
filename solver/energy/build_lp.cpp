#include "solver/energy/build_lp.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "engine/core/exception.h"

namespace linesurf::solver {

namespace {

/// Value of a fixed cell (0 or 1).
int FixedValue(const EnergyInput& energy, CellId c) {
  return energy.fixed[c] == CellFix::kFull ? 1 : 0;
}

/// A column per free cell (in id order) with its unary; the unaries of fixed cells go to the
/// constant.
void ReduceCells(const EnergyInput& energy, ReducedEnergy& out) {
  const std::size_t n = energy.NumCells();
  out.column_of_cell.assign(n, kNoColumn);
  for (std::size_t c = 0; c < n; ++c) {
    const CellId id(c);
    const CellFix fix = energy.fixed[id];
    if (fix == CellFix::kFree) {
      out.column_of_cell[c] = static_cast<std::uint32_t>(out.cell_of_column.size());
      out.cell_of_column.push_back(id);
      // cost_if_empty * (1 - x) + cost_if_full * x
      out.constant += energy.cost_if_empty[id];
      out.unary.push_back(energy.cost_if_full[id] - energy.cost_if_empty[id]);
    } else if (fix == CellFix::kEmpty) {
      out.constant += energy.cost_if_empty[id];
    } else {
      out.constant += energy.cost_if_full[id];
    }
  }
}

/// Pair terms between two free cells stay pairs; with a fixed cell they become unaries or
/// constants.
void ReducePairs(const EnergyInput& energy, ReducedEnergy& out) {
  const auto fixed_value = [&](CellId c) { return FixedValue(energy, c); };
  for (const PairTerm& t : energy.pairs) {
    if (!(t.weight > 0.0)) continue;
    const std::uint32_t ca = out.column_of_cell[t.a.index()];
    const std::uint32_t cb = out.column_of_cell[t.b.index()];
    if (ca != kNoColumn && cb != kNoColumn) {
      out.pairs.push_back({ca, cb, t.weight});
    } else if (ca == kNoColumn && cb == kNoColumn) {
      out.constant += t.weight * std::abs(fixed_value(t.a) - fixed_value(t.b));
    } else {
      const std::uint32_t col = ca != kNoColumn ? ca : cb;
      const int v = fixed_value(ca != kNoColumn ? t.b : t.a);
      if (v == 0) {
        out.unary[col] += t.weight;  // |x - 0| = x
      } else {
        out.constant += t.weight;  // |x - 1| = 1 - x
        out.unary[col] -= t.weight;
      }
    }
  }
}

/// Structural groups over their free cells: none left or a full cell give constants, one free
/// cell a unary.
void ReduceStructuralGroups(const EnergyInput& energy, ReducedEnergy& out) {
  const auto fixed_value = [&](CellId c) { return FixedValue(energy, c); };
  std::vector<std::uint32_t> cols;
  for (std::size_t g = 0; g < energy.NumStructuralGroups(); ++g) {
    const double w = energy.structural_weights[g];
    if (!(w > 0.0)) continue;
    cols.clear();
    bool has_full = false;
    for (CellId c : energy.StructuralGroup(g)) {
      const std::uint32_t col = out.column_of_cell[c.index()];
      if (col != kNoColumn) {
        cols.push_back(col);
      } else if (fixed_value(c) == 1) {
        has_full = true;
      }
    }
    if (has_full) continue;  // max(0, 1 - sum) = 0
    if (cols.empty()) {
      out.constant += w;
    } else if (cols.size() == 1) {
      out.constant += w;  // max(0, 1 - x) = 1 - x on [0,1]
      out.unary[cols[0]] -= w;
    } else {
      out.structural_columns.insert(out.structural_columns.end(), cols.begin(), cols.end());
      out.structural_offsets.push_back(static_cast<std::uint32_t>(out.structural_columns.size()));
      out.structural_weights.push_back(w);
    }
  }
}

/// Parity groups over their free cells, the fixed cells folded into the constant k.
void ReduceParityGroups(const EnergyInput& energy, ReducedEnergy& out) {
  const auto fixed_value = [&](CellId c) { return FixedValue(energy, c); };
  std::vector<std::uint32_t> cols;
  std::vector<std::int8_t> signs;
  for (std::size_t g = 0; g < energy.NumParityGroups(); ++g) {
    const double w = energy.parity_weights[g];
    if (!(w > 0.0)) continue;
    cols.clear();
    signs.clear();
    std::int32_t k = energy.parity_constants[g];
    const auto cells = energy.ParityGroup(g);
    const auto nu = energy.ParitySigns(g);
    for (std::size_t i = 0; i < cells.size(); ++i) {
      const std::uint32_t col = out.column_of_cell[cells[i].index()];
      if (col != kNoColumn) {
        cols.push_back(col);
        signs.push_back(nu[i]);
      } else {
        k += nu[i] * fixed_value(cells[i]);
      }
    }
    if (cols.empty()) {
      out.constant += w * std::abs(k);
    } else if (cols.size() == 1) {
      // |nu x + k| is linear on [0,1] since k is an integer: |k| + x (|k + nu| - |k|).
      out.constant += w * std::abs(k);
      out.unary[cols[0]] += w * (std::abs(k + signs[0]) - std::abs(k));
    } else {
      out.parity_columns.insert(out.parity_columns.end(), cols.begin(), cols.end());
      out.parity_signs.insert(out.parity_signs.end(), signs.begin(), signs.end());
      out.parity_offsets.push_back(static_cast<std::uint32_t>(out.parity_columns.size()));
      out.parity_weights.push_back(w);
      out.parity_constants.push_back(k);
    }
  }
}

}  // namespace

ReducedEnergy ReduceEnergy(const EnergyInput& energy) {
  ReducedEnergy out;
  ReduceCells(energy, out);
  ReducePairs(energy, out);
  ReduceStructuralGroups(energy, out);
  ReduceParityGroups(energy, out);
  return out;
}

double ReducedEnergy::Evaluate(std::span<const double> x) const {
  LINESURF_ASSERT(x.size() == NumFree());
  double e = constant;
  for (std::size_t j = 0; j < x.size(); ++j) e += unary[j] * x[j];
  for (const Pair& p : pairs) e += p.weight * std::abs(x[p.a] - x[p.b]);
  for (std::size_t g = 0; g < structural_weights.size(); ++g) {
    double sum = 0.0;
    for (std::uint32_t k = structural_offsets[g]; k < structural_offsets[g + 1]; ++k) {
      sum += x[structural_columns[k]];
    }
    e += structural_weights[g] * std::max(0.0, 1.0 - sum);
  }
  for (std::size_t g = 0; g < parity_weights.size(); ++g) {
    double sum = parity_constants[g];
    for (std::uint32_t k = parity_offsets[g]; k < parity_offsets[g + 1]; ++k) {
      sum += parity_signs[k] * x[parity_columns[k]];
    }
    e += parity_weights[g] * std::abs(sum);
  }
  return e;
}

LpShape ShapeOfLp(const ReducedEnergy& r) {
  LpShape shape;
  shape.columns = r.NumFree() + r.pairs.size() + r.structural_weights.size() +
                  r.parity_weights.size();
  shape.rows = 2 * r.pairs.size() + r.structural_weights.size() + 2 * r.parity_weights.size();
  shape.nonzeros = 6 * r.pairs.size() + r.structural_columns.size() + r.structural_weights.size() +
                   2 * (r.parity_columns.size() + r.parity_weights.size());
  return shape;
}

LpModel BuildLpModel(const ReducedEnergy& r) {
  LpModel lp;
  lp.objective_offset = r.constant;
  const LpShape shape = ShapeOfLp(r);
  const std::size_t num_cols = shape.columns;
  const std::size_t num_rows = shape.rows;
  const std::size_t num_nz = shape.nonzeros;
  LINESURF_THROW_IF(num_nz >= 0xFFFFFFFFu || num_cols >= kNoColumn, kResourceExhausted,
                    "build_lp", "LP too large for 32-bit indices: " << num_nz << " nonzeros");
  lp.objective.reserve(num_cols);
  lp.col_lower.reserve(num_cols);
  lp.col_upper.reserve(num_cols);
  lp.row_lower.reserve(num_rows);
  lp.row_upper.reserve(num_rows);
  lp.row_offsets.reserve(num_rows + 1);
  lp.row_columns.reserve(num_nz);
  lp.row_values.reserve(num_nz);

  for (double u : r.unary) lp.AddColumn(u, 0.0, 1.0);
  const std::uint32_t first_pair = static_cast<std::uint32_t>(lp.NumColumns());
  for (const auto& p : r.pairs) lp.AddColumn(p.weight, 0.0, kLpInfinity);
  const std::uint32_t first_structural = static_cast<std::uint32_t>(lp.NumColumns());
  for (double w : r.structural_weights) lp.AddColumn(w, 0.0, kLpInfinity);
  const std::uint32_t first_parity = static_cast<std::uint32_t>(lp.NumColumns());
  for (double w : r.parity_weights) lp.AddColumn(w, 0.0, kLpInfinity);

  std::vector<std::uint32_t> cols;
  std::vector<double> vals;
  for (std::size_t i = 0; i < r.pairs.size(); ++i) {
    const auto& p = r.pairs[i];
    const std::uint32_t s = first_pair + static_cast<std::uint32_t>(i);
    const std::uint32_t c[3] = {s, p.a, p.b};
    const double v1[3] = {1.0, -1.0, 1.0};
    const double v2[3] = {1.0, 1.0, -1.0};
    lp.AddRow(c, v1, 0.0, kLpInfinity);
    lp.AddRow(c, v2, 0.0, kLpInfinity);
  }
  for (std::size_t g = 0; g < r.structural_weights.size(); ++g) {
    cols.assign(1, first_structural + static_cast<std::uint32_t>(g));
    vals.assign(1, 1.0);
    for (std::uint32_t k = r.structural_offsets[g]; k < r.structural_offsets[g + 1]; ++k) {
      cols.push_back(r.structural_columns[k]);
      vals.push_back(1.0);
    }
    lp.AddRow(cols, vals, 1.0, kLpInfinity);
  }
  for (std::size_t g = 0; g < r.parity_weights.size(); ++g) {
    const double k = r.parity_constants[g];
    for (const double side : {-1.0, 1.0}) {
      cols.assign(1, first_parity + static_cast<std::uint32_t>(g));
      vals.assign(1, 1.0);
      for (std::uint32_t i = r.parity_offsets[g]; i < r.parity_offsets[g + 1]; ++i) {
        cols.push_back(r.parity_columns[i]);
        vals.push_back(side * r.parity_signs[i]);
      }
      lp.AddRow(cols, vals, side < 0.0 ? k : -k, kLpInfinity);
    }
  }
  return lp;
}

std::vector<double> ExpandToCells(const EnergyInput& energy, const ReducedEnergy& reduced,
                                  std::span<const double> column_values) {
  std::vector<double> x(energy.NumCells());
  for (std::size_t c = 0; c < x.size(); ++c) {
    const std::uint32_t col = reduced.column_of_cell[c];
    if (col != kNoColumn) {
      x[c] = column_values[col];
    } else {
      x[c] = energy.fixed[CellId(c)] == CellFix::kFull ? 1.0 : 0.0;
    }
  }
  return x;
}

}  // namespace linesurf::solver
