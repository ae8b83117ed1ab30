#include "solver/lp/dual_ascent.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace linesurf::solver {
namespace {

// Relative tolerance under which two values of a term's dual count as equal (the flat top).
constexpr double kFlat = 1e-12;

class Ascent {
 public:
  explicit Ascent(const ReducedEnergy& r)
      : r_(r),
        cost_(r.unary),
        pair_(r.pairs.size(), 0.0),
        structural_(r.structural_weights.size(), 0.0),
        parity_(r.parity_weights.size(), 0.0) {}

  void Pass() {
    for (std::size_t t = 0; t < r_.pairs.size(); ++t) {
      const auto& p = r_.pairs[t];
      cols_.assign({p.a, p.b});
      signs_.assign({1, -1});
      pair_[t] = Update(pair_[t], 0.0, -p.weight, p.weight);
    }
    for (std::size_t g = 0; g < structural_.size(); ++g) {
      cols_.assign(r_.structural_columns.begin() + r_.structural_offsets[g],
                   r_.structural_columns.begin() + r_.structural_offsets[g + 1]);
      signs_.assign(cols_.size(), -1);
      structural_[g] = Update(structural_[g], 1.0, 0.0, r_.structural_weights[g]);
    }
    for (std::size_t g = 0; g < parity_.size(); ++g) {
      cols_.assign(r_.parity_columns.begin() + r_.parity_offsets[g],
                   r_.parity_columns.begin() + r_.parity_offsets[g + 1]);
      signs_.assign(r_.parity_signs.begin() + r_.parity_offsets[g],
                    r_.parity_signs.begin() + r_.parity_offsets[g + 1]);
      parity_[g] =
          Update(parity_[g], r_.parity_constants[g], -r_.parity_weights[g], r_.parity_weights[g]);
    }
  }

  // The dual value, recomputed from the multipliers (not from the running costs).
  [[nodiscard]] double Bound() const {
    std::vector<double> cost(r_.unary);
    double bound = r_.constant;
    for (std::size_t t = 0; t < pair_.size(); ++t) {
      cost[r_.pairs[t].a] += pair_[t];
      cost[r_.pairs[t].b] -= pair_[t];
    }
    for (std::size_t g = 0; g < structural_.size(); ++g) {
      bound += structural_[g];
      for (std::uint32_t k = r_.structural_offsets[g]; k < r_.structural_offsets[g + 1]; ++k) {
        cost[r_.structural_columns[k]] -= structural_[g];
      }
    }
    for (std::size_t g = 0; g < parity_.size(); ++g) {
      bound += r_.parity_constants[g] * parity_[g];
      for (std::uint32_t k = r_.parity_offsets[g]; k < r_.parity_offsets[g + 1]; ++k) {
        cost[r_.parity_columns[k]] += r_.parity_signs[k] * parity_[g];
      }
    }
    for (double c : cost) bound += std::min(0.0, c);
    return bound;
  }

 private:
  // kappa delta + sum_j min(0, e_j + sign_j delta), e_j the costs without this term.
  [[nodiscard]] double Value(double kappa, double delta) const {
    double value = kappa * delta;
    for (std::size_t j = 0; j < cols_.size(); ++j) {
      value += std::min(0.0, rest_[j] + signs_[j] * delta);
    }
    return value;
  }

  // The term's multiplier that maximises its part of the dual (the middle of the flat top),
  // with the cells' costs updated.
  double Update(double old, double kappa, double lo, double hi) {
    rest_.resize(cols_.size());
    candidates_.assign({lo, hi});
    for (std::size_t j = 0; j < cols_.size(); ++j) {
      rest_[j] = cost_[cols_[j]] - signs_[j] * old;
      candidates_.push_back(std::clamp(-signs_[j] * rest_[j], lo, hi));
    }
    std::sort(candidates_.begin(), candidates_.end());
    double best = -INFINITY;
    for (double c : candidates_) best = std::max(best, Value(kappa, c));
    const double flat = kFlat * (1.0 + std::abs(best));
    double first = hi, last = lo;
    for (double c : candidates_) {
      if (Value(kappa, c) >= best - flat) {
        first = std::min(first, c);
        last = std::max(last, c);
      }
    }
    const double delta = 0.5 * (first + last);
    for (std::size_t j = 0; j < cols_.size(); ++j) cost_[cols_[j]] = rest_[j] + signs_[j] * delta;
    return delta;
  }

  const ReducedEnergy& r_;
  std::vector<double> cost_;
  std::vector<double> pair_, structural_, parity_;
  std::vector<std::uint32_t> cols_;
  std::vector<std::int8_t> signs_;
  std::vector<double> rest_, candidates_;
};

}  // namespace

DualAscentResult DualAscentBound(const ReducedEnergy& reduced,
                                 int max_passes,
                                 double relative_gain) {
  Ascent ascent(reduced);
  DualAscentResult result;
  result.bound = ascent.Bound();
  for (int pass = 0; pass < max_passes; ++pass) {
    ascent.Pass();
    const double bound = ascent.Bound();
    ++result.passes;
    const bool small = bound - result.bound <= relative_gain * (1.0 + std::abs(bound));
    result.bound = std::max(result.bound, bound);
    if (small) break;
  }
  return result;
}

}  // namespace linesurf::solver
