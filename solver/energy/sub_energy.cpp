#include "solver/energy/sub_energy.h"

#include "engine/core/exception.h"

#include <algorithm>

namespace linesurf::solver {
namespace {

std::uint64_t Key(const TermRef& t) { return (static_cast<std::uint64_t>(t.kind) << 32) | t.index; }

// The distinct terms touching the chosen cells, in term order.
std::vector<TermRef> TouchingTerms(const TermIncidence& incidence, std::span<const CellId> chosen) {
  std::vector<TermRef> terms;
  for (CellId c : chosen) {
    const std::uint32_t slot = incidence.Slot(c);
    LINESURF_ASSERT(slot != TermIncidence::kNone);
    const auto touching = incidence.Terms(slot);
    terms.insert(terms.end(), touching.begin(), touching.end());
  }
  std::sort(terms.begin(), terms.end(), [](const TermRef& a, const TermRef& b) {
    return Key(a) < Key(b);
  });
  terms.erase(std::unique(terms.begin(),
                          terms.end(),
                          [](const TermRef& a, const TermRef& b) { return Key(a) == Key(b); }),
              terms.end());
  return terms;
}

template <typename Visit>
void ForEachCell(const EnergyInput& energy, const TermRef& t, Visit&& visit) {
  if (t.kind == TermKind::kPair) {
    visit(energy.pairs[t.index].a);
    visit(energy.pairs[t.index].b);
  } else {
    for (CellId c : t.kind == TermKind::kStructural ? energy.StructuralGroup(t.index)
                                                    : energy.ParityGroup(t.index)) {
      visit(c);
    }
  }
}

// Local ids: the chosen cells first, then the others in order of first appearance in `terms`
// (a cell of a pair: a before b). Sorting the appearances keeps this O(m log m) in the size m of
// the neighbourhood, whatever the size of the full energy.
struct LocalIds {
  std::vector<CellId> cell_of_local;
  std::vector<std::pair<CellId, CellId>> local_of;  // (full id, local id), sorted by full id

  [[nodiscard]] CellId Local(CellId c) const {
    const auto it =
        std::lower_bound(local_of.begin(),
                         local_of.end(),
                         std::make_pair(c, CellId{}),
                         [](const auto& a, const auto& b) { return a.first < b.first; });
    LINESURF_ASSERT(it != local_of.end() && it->first == c);
    return it->second;
  }
};

LocalIds NumberCells(const EnergyInput& energy,
                     std::span<const CellId> chosen,
                     const std::vector<TermRef>& terms) {
  std::vector<std::pair<CellId, std::uint32_t>> appearances;  // (full id, position)
  for (CellId c : chosen)
    appearances.emplace_back(c, static_cast<std::uint32_t>(appearances.size()));
  for (const TermRef& t : terms) {
    ForEachCell(energy, t, [&](CellId c) {
      appearances.emplace_back(c, static_cast<std::uint32_t>(appearances.size()));
    });
  }
  std::sort(appearances.begin(), appearances.end());    // by id, then first position
  std::vector<std::pair<std::uint32_t, CellId>> first;  // (first position, full id)
  for (std::size_t i = 0; i < appearances.size(); ++i) {
    if (i == 0 || appearances[i].first != appearances[i - 1].first) {
      first.emplace_back(appearances[i].second, appearances[i].first);
    }
  }
  std::sort(first.begin(), first.end());
  LocalIds ids;
  for (const auto& [position, cell] : first) {
    ids.local_of.emplace_back(cell, CellId(ids.cell_of_local.size()));
    ids.cell_of_local.push_back(cell);
  }
  std::sort(ids.local_of.begin(), ids.local_of.end());
  return ids;
}

// The sub-energy of `terms` over the chosen cells; every other cell is fixed at `label_of(c)`.
template <typename LabelOf>
SubEnergy BuildSubEnergy(const EnergyInput& energy,
                         std::span<const CellId> chosen,
                         const std::vector<TermRef>& terms,
                         LabelOf&& label_of) {
  SubEnergy sub;
  const LocalIds ids = NumberCells(energy, chosen, terms);
  sub.cells = ids.cell_of_local;
  for (std::size_t i = 0; i < sub.cells.size(); ++i) {
    const CellId c = sub.cells[i];
    if (i < chosen.size()) {
      sub.energy.AddCell(energy.cost_if_empty[c], energy.cost_if_full[c], energy.fixed[c]);
    } else {
      sub.energy.AddCell(0.0, 0.0, label_of(c) != 0 ? CellFix::kFull : CellFix::kEmpty);
    }
  }
  std::vector<CellId> cells;
  for (const TermRef& t : terms) {
    if (t.kind == TermKind::kPair) {
      const PairTerm& p = energy.pairs[t.index];
      sub.energy.AddPair(ids.Local(p.a), ids.Local(p.b), p.weight);
      continue;
    }
    cells.clear();
    ForEachCell(energy, t, [&](CellId c) { cells.push_back(ids.Local(c)); });
    if (t.kind == TermKind::kStructural) {
      sub.energy.AddStructuralGroup(cells, energy.structural_weights[t.index]);
    } else {
      sub.energy.AddParityGroup(cells,
                                energy.ParitySigns(t.index),
                                energy.parity_weights[t.index],
                                energy.parity_constants[t.index]);
    }
  }
  return sub;
}

}  // namespace

SubEnergy RestrictEnergy(const EnergyInput& energy,
                         const TermIncidence& incidence,
                         std::span<const CellId> chosen,
                         const std::vector<std::uint8_t>& labels) {
  return BuildSubEnergy(energy, chosen, TouchingTerms(incidence, chosen), [&](CellId c) {
    return labels[c.index()];
  });
}

SubEnergy InteriorEnergy(const EnergyInput& energy,
                         const TermIncidence& incidence,
                         std::span<const CellId> chosen) {
  std::vector<TermRef> terms = TouchingTerms(incidence, chosen);
  std::vector<CellId> sorted(chosen.begin(), chosen.end());
  std::sort(sorted.begin(), sorted.end());
  const auto is_chosen = [&](CellId c) {
    return std::binary_search(sorted.begin(), sorted.end(), c);
  };
  std::erase_if(terms, [&](const TermRef& t) {
    bool outside = false;
    ForEachCell(energy, t, [&](CellId c) {
      outside = outside || (energy.fixed[c] == CellFix::kFree && !is_chosen(c));
    });
    return outside;
  });
  return BuildSubEnergy(
      energy, chosen, terms, [&](CellId c) { return energy.fixed[c] == CellFix::kFull ? 1 : 0; });
}

}  // namespace linesurf::solver
