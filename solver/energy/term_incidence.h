#pragma once
// The terms of an EnergyInput that touch each cell of a list (CSR, in term order), and the
// energy of the terms touching one cell: what local moves on 0/1 labels evaluate.

#include "solver/energy/energy_input.h"

#include <cstdint>
#include <span>
#include <vector>

namespace linesurf::solver {

enum class TermKind : std::uint8_t { kPair, kStructural, kParity };
struct TermRef {
  TermKind kind;
  std::uint32_t index;
};

class TermIncidence {
 public:
  static constexpr std::uint32_t kNone = 0xFFFFFFFFu;

  TermIncidence(const EnergyInput& e, std::span<const CellId> cells);
  /// Terms touching cells[i].
  [[nodiscard]] std::span<const TermRef> Terms(std::size_t i) const {
    return {terms_.data() + offsets_[i], terms_.data() + offsets_[i + 1]};
  }
  /// i with cells[i] == c, or kNone.
  [[nodiscard]] std::uint32_t Slot(CellId c) const { return slot_[c.index()]; }

 private:
  std::vector<std::uint32_t> slot_;
  std::vector<std::uint32_t> offsets_;
  std::vector<TermRef> terms_;
};

/// The cells of term `t`, in storage order; a pair's two cells are written to `pair`.
[[nodiscard]] std::span<const CellId> TermCells(const EnergyInput& e, TermRef t, CellId (&pair)[2]);

/// Sets marks[s] = mark for the cell at `slot` of `incidence` and every cell of the list it
/// shares a term with: the cells whose local energy a change of that cell's label changes.
void MarkAround(const EnergyInput& e,
                const TermIncidence& incidence,
                std::uint32_t slot,
                std::vector<std::uint8_t>& marks,
                std::uint8_t mark = 1);

/// Energy of one term under 0/1 `labels`.
[[nodiscard]] double TermEnergy(const EnergyInput& e,
                                TermRef t,
                                const std::vector<std::uint8_t>& labels);

/// Energy of `terms` (those touching `cell`) plus the unary of `cell` under `labels`.
[[nodiscard]] double LocalEnergy(const EnergyInput& e,
                                 std::span<const TermRef> terms,
                                 CellId cell,
                                 const std::vector<std::uint8_t>& labels);

}  // namespace linesurf::solver
