#pragma once
// An LpModel in COIN-OR's form (row-ordered CoinPackedMatrix, infinities as COIN_DBL_MAX), shared
// by the Clp and Cbc backends. Include only from backend sources (COIN headers).

#include "solver/lp/lp_model.h"

#include <vector>

#include <CoinFinite.hpp>
#include <CoinPackedMatrix.hpp>

namespace linesurf::solver {

struct CoinProblem {
  CoinPackedMatrix matrix;
  std::vector<double> col_lower, col_upper, row_lower, row_upper;
};

inline double ToCoin(double value) {
  if (value == kLpInfinity) return COIN_DBL_MAX;
  if (value == -kLpInfinity) return -COIN_DBL_MAX;
  return value;
}

/// `lp` must have at least one column.
inline CoinProblem ToCoinProblem(const LpModel& lp) {
  const int num_rows = static_cast<int>(lp.NumRows());
  const int num_cols = static_cast<int>(lp.NumColumns());
  std::vector<int> indices(lp.row_columns.begin(), lp.row_columns.end());
  std::vector<CoinBigIndex> starts(lp.row_offsets.begin(), lp.row_offsets.end());
  std::vector<int> lengths(static_cast<std::size_t>(num_rows));
  for (int r = 0; r < num_rows; ++r) {
    lengths[static_cast<std::size_t>(r)] =
        static_cast<int>(lp.row_offsets[r + 1] - lp.row_offsets[r]);
  }
  CoinProblem p{CoinPackedMatrix(false,
                                 num_cols,
                                 num_rows,
                                 static_cast<CoinBigIndex>(lp.NumNonzeros()),
                                 lp.row_values.data(),
                                 indices.data(),
                                 starts.data(),
                                 lengths.data()),
                lp.col_lower,
                lp.col_upper,
                lp.row_lower,
                lp.row_upper};
  for (auto* v : {&p.col_lower, &p.col_upper, &p.row_lower, &p.row_upper}) {
    for (double& x : *v) x = ToCoin(x);
  }
  return p;
}

}  // namespace linesurf::solver
