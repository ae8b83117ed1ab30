#include "solver/lp/joint_label_walk.h"

#include "engine/core/exception.h"
#include "solver/lp/round_labels.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>

namespace linesurf::solver {

JointLabelWalk::JointLabelWalk(const EnergyInput& energy,
                               std::span<const CellId> free,
                               const TermIncidence& incidence)
    : e_(energy),
      free_(free),
      incidence_(incidence),
      seen_in_(energy.NumPairs() + energy.NumStructuralGroups() + energy.NumParityGroups(), 0),
      index_(seen_in_.size(), 0) {}

std::uint32_t JointLabelWalk::List(TermRef t, const std::vector<std::uint8_t>& labels) {
  std::size_t key = t.index;
  if (t.kind != TermKind::kPair) key += e_.NumPairs();
  if (t.kind == TermKind::kParity) key += e_.NumStructuralGroups();
  if (seen_in_[key] == walk_) return index_[key];
  seen_in_[key] = walk_;
  index_[key] = static_cast<std::uint32_t>(kinds_.size());
  kinds_.push_back(t.kind);
  const auto x = [&](CellId c) { return double(labels[c.index()]); };
  double sum = 0.0;
  if (t.kind == TermKind::kPair) {
    sum = x(e_.pairs[t.index].a) - x(e_.pairs[t.index].b);
    weights_.push_back(e_.pairs[t.index].weight);
  } else if (t.kind == TermKind::kStructural) {
    for (CellId c : e_.StructuralGroup(t.index)) sum += x(c);
    weights_.push_back(e_.structural_weights[t.index]);
  } else {
    weights_.push_back(e_.parity_weights[t.index]);
    sum = e_.parity_constants[t.index];
    const auto cells = e_.ParityGroup(t.index);
    const auto nu = e_.ParitySigns(t.index);
    for (std::size_t i = 0; i < cells.size(); ++i) sum += nu[i] * x(cells[i]);
  }
  sums_.push_back(sum);
  return index_[key];
}

double JointLabelWalk::Coefficient(TermRef t, CellId c) const {
  if (t.kind == TermKind::kPair) return e_.pairs[t.index].a == c ? 1.0 : -1.0;
  if (t.kind == TermKind::kStructural) return 1.0;
  const auto cells = e_.ParityGroup(t.index);
  const auto at = std::find(cells.begin(), cells.end(), c);
  LINESURF_ASSERT(at != cells.end());
  return e_.ParitySigns(t.index)[static_cast<std::size_t>(at - cells.begin())];
}

std::uint32_t JointLabelWalk::BestFlips(std::span<const std::uint32_t> slots,
                                        const std::vector<std::uint8_t>& labels) {
  LINESURF_ASSERT(slots.size() <= kMaxJointCells);
  if (walk_ == kLastWalk) {
    std::fill(seen_in_.begin(), seen_in_.end(), 0);
    walk_ = 0;
  }
  ++walk_;
  kinds_.clear();
  weights_.clear();
  sums_.clear();
  entries_.clear();
  // The cells' terms (in incidence order) and their local energies, as LocalEnergy sums them.
  std::uint8_t label[kMaxJointCells];
  std::size_t first_entry[kMaxJointCells + 1];
  double scale = 1.0;
  for (std::size_t j = 0; j < slots.size(); ++j) {
    const CellId c = free_[slots[j]];
    label[j] = labels[c.index()];
    first_entry[j] = entries_.size();
    const double x = label[j];
    double local = e_.cost_if_empty[c] * (1.0 - x) + e_.cost_if_full[c] * x;
    for (const TermRef& t : incidence_.Terms(slots[j])) {
      const std::uint32_t term = List(t, labels);
      entries_.push_back({term, Coefficient(t, c)});
      local += Energy(term, sums_[term]);
    }
    scale += std::abs(local);
  }
  first_entry[slots.size()] = entries_.size();

  double delta = 0.0, best = 0.0;
  std::uint32_t best_code = 0;
  const std::uint32_t count = 1u << slots.size();
  for (std::uint32_t i = 1; i < count; ++i) {
    const std::size_t j = static_cast<std::size_t>(std::countr_zero(i));
    const CellId c = free_[slots[j]];
    const double x = label[j];
    const double y = 1.0 - x;
    double current = e_.cost_if_empty[c] * (1.0 - x) + e_.cost_if_full[c] * x;
    double flipped = e_.cost_if_empty[c] * (1.0 - y) + e_.cost_if_full[c] * y;
    const double step = y - x;
    for (std::size_t k = first_entry[j]; k < first_entry[j + 1]; ++k) {
      const Entry& entry = entries_[k];
      const double sum = sums_[entry.term];
      const double moved = sum + entry.coefficient * step;
      current += Energy(entry.term, sum);
      flipped += Energy(entry.term, moved);
      sums_[entry.term] = moved;
    }
    label[j] ^= 1u;
    delta += flipped - current;
    if (delta < best) {
      best = delta;
      best_code = i ^ (i >> 1);
    }
  }
  return best < -kImproveTolerance * scale ? best_code : 0;
}

}  // namespace linesurf::solver
