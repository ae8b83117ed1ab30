#include "solver/lp/round_labels.h"

#include <algorithm>
#include <cmath>

#include "engine/core/exception.h"
#include "solver/lp/lp_backend.h"

namespace linesurf::solver {
namespace {

enum class TermKind : std::uint8_t { kPair, kStructural, kParity };
struct TermRef {
  TermKind kind;
  std::uint32_t index;
};

// Energy of the terms touching `cell` (its unary included) under `labels`.
double LocalEnergy(const EnergyInput& e, std::span<const TermRef> terms, CellId cell,
                   const std::vector<std::uint8_t>& labels) {
  const double x = labels[cell.index()];
  double value = e.cost_if_empty[cell] * (1.0 - x) + e.cost_if_full[cell] * x;
  for (const TermRef& t : terms) {
    if (t.kind == TermKind::kPair) {
      const PairTerm& p = e.pairs[t.index];
      value += p.weight * std::abs(double(labels[p.a.index()]) - double(labels[p.b.index()]));
    } else if (t.kind == TermKind::kStructural) {
      double sum = 0.0;
      for (CellId c : e.StructuralGroup(t.index)) sum += labels[c.index()];
      value += e.structural_weights[t.index] * std::max(0.0, 1.0 - sum);
    } else {
      const auto cells = e.ParityGroup(t.index);
      const auto nu = e.ParitySigns(t.index);
      double sum = 0.0;
      for (std::size_t i = 0; i < cells.size(); ++i) sum += nu[i] * double(labels[cells[i].index()]);
      value += e.parity_weights[t.index] * std::abs(sum);
    }
  }
  return value;
}

}  // namespace

RoundedLabels RoundLabels(const EnergyInput& energy, std::span<const double> relaxed) {
  LINESURF_ASSERT(relaxed.size() == energy.NumCells());
  RoundedLabels out;
  out.labels.assign(relaxed.size(), 0);
  std::vector<CellId> ties;
  for (std::size_t c = 0; c < relaxed.size(); ++c) {
    const CellId id(c);
    const double x = relaxed[c];
    if (energy.fixed[id] != CellFix::kFree) {
      out.labels[c] = energy.fixed[id] == CellFix::kFull ? 1 : 0;
      continue;
    }
    if (std::abs(x - std::round(x)) > kTieTolerance) ++out.fractional_cells;
    if (std::abs(x - 0.5) <= kTieTolerance) {
      ties.push_back(id);
    } else {
      out.labels[c] = x > 0.5 ? 1 : 0;
    }
  }
  out.tie_cells = ties.size();
  if (ties.empty()) return out;

  // Incidence of the tie cells only: cell -> terms, in term order.
  std::vector<std::uint32_t> slot(relaxed.size(), 0xFFFFFFFFu);
  for (std::size_t i = 0; i < ties.size(); ++i) slot[ties[i].index()] = static_cast<std::uint32_t>(i);
  std::vector<std::vector<TermRef>> incidence(ties.size());
  auto add = [&](CellId c, TermKind kind, std::size_t index) {
    const std::uint32_t s = slot[c.index()];
    if (s != 0xFFFFFFFFu) incidence[s].push_back({kind, static_cast<std::uint32_t>(index)});
  };
  for (std::size_t p = 0; p < energy.pairs.size(); ++p) {
    add(energy.pairs[p].a, TermKind::kPair, p);
    add(energy.pairs[p].b, TermKind::kPair, p);
  }
  for (std::size_t g = 0; g < energy.NumStructuralGroups(); ++g) {
    for (CellId c : energy.StructuralGroup(g)) add(c, TermKind::kStructural, g);
  }
  for (std::size_t g = 0; g < energy.NumParityGroups(); ++g) {
    for (CellId c : energy.ParityGroup(g)) add(c, TermKind::kParity, g);
  }
  for (std::size_t i = 0; i < ties.size(); ++i) {
    const CellId c = ties[i];
    out.labels[c.index()] = 1;
    const double full = LocalEnergy(energy, incidence[i], c, out.labels);
    out.labels[c.index()] = 0;
    const double empty = LocalEnergy(energy, incidence[i], c, out.labels);
    out.labels[c.index()] = full < empty ? 1 : 0;
  }
  return out;
}

}  // namespace linesurf::solver
