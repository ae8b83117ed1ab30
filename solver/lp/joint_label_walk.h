#pragma once
// The best joint labelling of a few free cells with every other cell held: a Gray-code walk over
// their 2^k labellings. Each term around the cells keeps its label sum (x_a - x_b for a pair,
// sum x for a structural group, sum nu x for a parity group) up to date, so a flip costs one
// step per term of the flipped cell instead of a pass over the term's cells. The sums are exact
// integers, so every local energy the walk compares is the same double LocalEnergy
// (term_incidence.h) gives for those labels.

#include "solver/energy/energy_input.h"
#include "solver/energy/term_incidence.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

namespace linesurf::solver {

/// Cells a walk takes at most (2^8 labellings).
inline constexpr std::size_t kMaxJointCells = 8;

class JointLabelWalk {
 public:
  /// `incidence` lists the terms of `free` (the free cells of `energy`, slot i = free[i]); both
  /// must outlive the walk. Holds scratch of two words per term: one walk per thread.
  JointLabelWalk(const EnergyInput& energy,
                 std::span<const CellId> free,
                 const TermIncidence& incidence);

  /// The cells at `slots` (at most kMaxJointCells, distinct) relabelled for the lowest energy,
  /// every other cell at its label in `labels`: the bits of the slots to flip (bit j for
  /// slots[j]), 0 unless that lowers the energy by more than kImproveTolerance x (1 + the sum of
  /// the cells' |local energy|). Ties go to the labelling the walk meets first.
  [[nodiscard]] std::uint32_t BestFlips(std::span<const std::uint32_t> slots,
                                        const std::vector<std::uint8_t>& labels);

 private:
  // One term of a cell in the walk: which listed term, and the change of its sum per unit
  // change of the cell's label.
  struct Entry {
    std::uint32_t term;
    double coefficient;
  };

  // The walk's index of term t, listing it with its label sum on first sight.
  std::uint32_t List(TermRef t, const std::vector<std::uint8_t>& labels);
  [[nodiscard]] double Coefficient(TermRef t, CellId c) const;
  // TermEnergy's expressions, on the kept sum.
  [[nodiscard]] double Energy(std::uint32_t term, double sum) const {
    const double w = weights_[term];
    return kinds_[term] == TermKind::kStructural ? w * std::max(0.0, 1.0 - sum) : w * std::abs(sum);
  }

  const EnergyInput& e_;
  std::span<const CellId> free_;
  const TermIncidence& incidence_;
  // Per term of the energy (pairs, structural groups, parity groups): the walk that last listed
  // it, and its index in that walk. Walks are numbered from 1 (0: never listed); after
  // kLastWalk the stamps are cleared and numbering starts again.
  static constexpr std::uint32_t kLastWalk = std::numeric_limits<std::uint32_t>::max();
  std::vector<std::uint32_t> seen_in_;
  std::vector<std::uint32_t> index_;
  std::uint32_t walk_ = 0;
  // The listed terms: kind, weight and label sum.
  std::vector<TermKind> kinds_;
  std::vector<double> weights_;
  std::vector<double> sums_;
  std::vector<Entry> entries_;
};

}  // namespace linesurf::solver
