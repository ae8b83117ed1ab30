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

// Terms touching each of a list of cells, in term order (CSR).
class TermIncidence {
 public:
  TermIncidence(const EnergyInput& e, std::span<const CellId> cells) {
    std::vector<std::uint32_t> slot(e.NumCells(), kNone);
    for (std::size_t i = 0; i < cells.size(); ++i) {
      slot[cells[i].index()] = static_cast<std::uint32_t>(i);
    }
    offsets_.assign(cells.size() + 1, 0);
    // Two passes (count, fill) over the same term walk.
    for (int pass = 0; pass < 2; ++pass) {
      auto add = [&](CellId c, TermKind kind, std::size_t index) {
        const std::uint32_t s = slot[c.index()];
        if (s == kNone) return;
        if (pass == 0) {
          ++offsets_[s + 1];
        } else {
          terms_[next_[s]++] = {kind, static_cast<std::uint32_t>(index)};
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
        next_.assign(offsets_.begin(), offsets_.end() - 1);
      }
    }
  }
  [[nodiscard]] std::span<const TermRef> Terms(std::size_t i) const {
    return {terms_.data() + offsets_[i], terms_.data() + offsets_[i + 1]};
  }

 private:
  static constexpr std::uint32_t kNone = 0xFFFFFFFFu;
  std::vector<std::uint32_t> offsets_;
  std::vector<std::uint32_t> next_;
  std::vector<TermRef> terms_;
};

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

  const TermIncidence incidence(energy, ties);
  for (std::size_t i = 0; i < ties.size(); ++i) {
    const CellId c = ties[i];
    out.labels[c.index()] = 1;
    const double full = LocalEnergy(energy, incidence.Terms(i), c, out.labels);
    out.labels[c.index()] = 0;
    const double empty = LocalEnergy(energy, incidence.Terms(i), c, out.labels);
    out.labels[c.index()] = full < empty ? 1 : 0;
  }
  return out;
}

std::size_t ImproveLabels(const EnergyInput& energy, int max_passes,
                          std::vector<std::uint8_t>& labels) {
  LINESURF_ASSERT(labels.size() == energy.NumCells());
  std::vector<CellId> free;
  for (std::size_t c = 0; c < energy.NumCells(); ++c) {
    if (energy.fixed[CellId(c)] == CellFix::kFree) free.push_back(CellId(c));
  }
  if (free.empty() || max_passes <= 0) return 0;
  const TermIncidence incidence(energy, free);
  std::size_t flips = 0;
  for (int pass = 0; pass < max_passes; ++pass) {
    std::size_t pass_flips = 0;
    for (std::size_t i = 0; i < free.size(); ++i) {
      const CellId c = free[i];
      const std::uint8_t current = labels[c.index()];
      const double keep = LocalEnergy(energy, incidence.Terms(i), c, labels);
      labels[c.index()] = current ^ 1u;
      const double flip = LocalEnergy(energy, incidence.Terms(i), c, labels);
      // Flip only on a decrease beyond rounding noise, so passes terminate.
      if (flip < keep - kImproveTolerance * (1.0 + std::abs(keep))) {
        ++pass_flips;
      } else {
        labels[c.index()] = current;
      }
    }
    flips += pass_flips;
    if (pass_flips == 0) break;
  }
  return flips;
}

}  // namespace linesurf::solver
