#include "solver/energy/sub_energy.h"

#include "engine/core/exception.h"

#include <algorithm>

namespace linesurf::solver {

SubEnergy RestrictEnergy(const EnergyInput& energy,
                         const TermIncidence& incidence,
                         std::span<const CellId> chosen,
                         const std::vector<std::uint8_t>& labels) {
  SubEnergy sub;
  std::vector<TermRef> terms;
  for (CellId c : chosen) {
    const std::uint32_t slot = incidence.Slot(c);
    LINESURF_ASSERT(slot != TermIncidence::kNone);
    const auto touching = incidence.Terms(slot);
    terms.insert(terms.end(), touching.begin(), touching.end());
  }
  const auto key = [](const TermRef& t) {
    return (static_cast<std::uint64_t>(t.kind) << 32) | t.index;
  };
  std::sort(terms.begin(), terms.end(), [&](const TermRef& a, const TermRef& b) {
    return key(a) < key(b);
  });
  terms.erase(std::unique(terms.begin(),
                          terms.end(),
                          [&](const TermRef& a, const TermRef& b) { return key(a) == key(b); }),
              terms.end());

  // Local ids: chosen cells first, then the others in order of first appearance in `terms`.
  std::vector<std::pair<CellId, CellId>> local_of;  // (full id, local id), sorted by full id
  for (CellId c : chosen) {
    const CellId local =
        sub.energy.AddCell(energy.cost_if_empty[c], energy.cost_if_full[c], energy.fixed[c]);
    sub.cells.push_back(c);
    local_of.emplace_back(c, local);
  }
  std::sort(local_of.begin(), local_of.end());
  const auto local = [&](CellId c) {
    auto it = std::lower_bound(local_of.begin(),
                               local_of.end(),
                               std::make_pair(c, CellId{}),
                               [](const auto& a, const auto& b) { return a.first < b.first; });
    if (it != local_of.end() && it->first == c) return it->second;
    const CellId id =
        sub.energy.AddCell(0.0, 0.0, labels[c.index()] != 0 ? CellFix::kFull : CellFix::kEmpty);
    sub.cells.push_back(c);
    local_of.insert(it, {c, id});
    return id;
  };
  std::vector<CellId> cells;
  for (const TermRef& t : terms) {
    cells.clear();
    if (t.kind == TermKind::kPair) {
      const PairTerm& p = energy.pairs[t.index];
      const CellId a = local(p.a);  // in order: local ids must not depend on the compiler
      const CellId b = local(p.b);
      sub.energy.AddPair(a, b, p.weight);
    } else if (t.kind == TermKind::kStructural) {
      for (CellId c : energy.StructuralGroup(t.index)) cells.push_back(local(c));
      sub.energy.AddStructuralGroup(cells, energy.structural_weights[t.index]);
    } else {
      for (CellId c : energy.ParityGroup(t.index)) cells.push_back(local(c));
      sub.energy.AddParityGroup(cells, energy.ParitySigns(t.index), energy.parity_weights[t.index]);
    }
  }
  return sub;
}

}  // namespace linesurf::solver
