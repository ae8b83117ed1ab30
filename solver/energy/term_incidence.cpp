#include "solver/energy/term_incidence.h"

#include <algorithm>
#include <cmath>

namespace linesurf::solver {

std::span<const CellId> TermCells(const EnergyInput& e, TermRef t, CellId (&pair)[2]) {
  if (t.kind == TermKind::kPair) {
    pair[0] = e.pairs[t.index].a;
    pair[1] = e.pairs[t.index].b;
    return pair;
  }
  return t.kind == TermKind::kStructural ? e.StructuralGroup(t.index) : e.ParityGroup(t.index);
}

void MarkAround(const EnergyInput& e,
                const TermIncidence& incidence,
                std::uint32_t slot,
                std::vector<std::uint8_t>& marks,
                std::uint8_t mark) {
  marks[slot] = mark;
  for (const TermRef& t : incidence.Terms(slot)) {
    CellId pair[2];
    for (CellId c : TermCells(e, t, pair)) {
      const std::uint32_t s = incidence.Slot(c);
      if (s != TermIncidence::kNone) marks[s] = mark;
    }
  }
}

TermIncidence::TermIncidence(const EnergyInput& e, std::span<const CellId> cells) {
  slot_.assign(e.NumCells(), kNone);
  for (std::size_t i = 0; i < cells.size(); ++i) {
    slot_[cells[i].index()] = static_cast<std::uint32_t>(i);
  }
  offsets_.assign(cells.size() + 1, 0);
  std::vector<std::uint32_t> next;
  // Two passes (count, fill) over the same term walk.
  for (int pass = 0; pass < 2; ++pass) {
    auto add = [&](CellId c, TermKind kind, std::size_t index) {
      const std::uint32_t s = slot_[c.index()];
      if (s == kNone) return;
      if (pass == 0) {
        ++offsets_[s + 1];
      } else {
        terms_[next[s]++] = {kind, static_cast<std::uint32_t>(index)};
      }
    };
    for (std::size_t p = 0; p < e.pairs.size(); ++p) {
      add(e.pairs[p].a, TermKind::kPair, p);
      add(e.pairs[p].b, TermKind::kPair, p);
    }
    for (std::size_t g = 0; g < e.NumStructuralGroups(); ++g) {
      for (CellId c : e.StructuralGroup(g)) add(c, TermKind::kStructural, g);
    }
    for (std::size_t g = 0; g < e.NumParityGroups(); ++g) {
      for (CellId c : e.ParityGroup(g)) add(c, TermKind::kParity, g);
    }
    if (pass == 0) {
      for (std::size_t i = 0; i < cells.size(); ++i) offsets_[i + 1] += offsets_[i];
      terms_.resize(offsets_.back());
      next.assign(offsets_.begin(), offsets_.end() - 1);
    }
  }
}

double TermEnergy(const EnergyInput& e, TermRef t, const std::vector<std::uint8_t>& labels) {
  if (t.kind == TermKind::kPair) {
    const PairTerm& p = e.pairs[t.index];
    return p.weight * std::abs(double(labels[p.a.index()]) - double(labels[p.b.index()]));
  }
  if (t.kind == TermKind::kStructural) {
    double sum = 0.0;
    for (CellId c : e.StructuralGroup(t.index)) sum += labels[c.index()];
    return e.structural_weights[t.index] * std::max(0.0, 1.0 - sum);
  }
  const auto cells = e.ParityGroup(t.index);
  const auto nu = e.ParitySigns(t.index);
  double sum = e.parity_constants[t.index];
  for (std::size_t i = 0; i < cells.size(); ++i) sum += nu[i] * double(labels[cells[i].index()]);
  return e.parity_weights[t.index] * std::abs(sum);
}

double LocalEnergy(const EnergyInput& e,
                   std::span<const TermRef> terms,
                   CellId cell,
                   const std::vector<std::uint8_t>& labels) {
  const double x = labels[cell.index()];
  double value = e.cost_if_empty[cell] * (1.0 - x) + e.cost_if_full[cell] * x;
  for (const TermRef& t : terms) value += TermEnergy(e, t, labels);
  return value;
}

}  // namespace linesurf::solver
