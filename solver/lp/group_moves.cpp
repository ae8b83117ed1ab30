#include "solver/lp/group_moves.h"

#include "engine/core/exception.h"
#include "engine/core/parallel.h"
#include "solver/energy/term_incidence.h"
#include "solver/lp/joint_label_walk.h"
#include "solver/lp/round_labels.h"

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <cmath>

namespace linesurf::solver {
namespace {

// Sweeps of single flips between group sweeps.
constexpr int kFlipPasses = 10;
// Moves per parallel task (a move walks up to 2^8 labellings).
constexpr std::size_t kMovesPerTask = 64;

// Every term in order: pairs, structural groups, parity groups.
template <typename Visit>
void ForEachTerm(const EnergyInput& e, Visit&& visit) {
  for (std::size_t p = 0; p < e.NumPairs(); ++p) {
    visit(TermRef{TermKind::kPair, static_cast<std::uint32_t>(p)});
  }
  for (std::size_t g = 0; g < e.NumStructuralGroups(); ++g) {
    visit(TermRef{TermKind::kStructural, static_cast<std::uint32_t>(g)});
  }
  for (std::size_t g = 0; g < e.NumParityGroups(); ++g) {
    visit(TermRef{TermKind::kParity, static_cast<std::uint32_t>(g)});
  }
}

class GroupMover {
 public:
  GroupMover(const EnergyInput& e, std::span<const CellId> free)
      : e_(e),
        free_(free.begin(), free.end()),
        incidence_(e, free),
        walks_([this] { return JointLabelWalk(e_, free_, incidence_); }),
        dirty_(free.size(), 0) {}

  // Marks the free cells of every term whose cells carry different labels, and the free cells
  // whose own unary cost prefers the other label.
  void MarkSurface(const std::vector<std::uint8_t>& labels) {
    for (std::size_t i = 0; i < free_.size(); ++i) {
      const CellId c = free_[i];
      const double keep = labels[c.index()] != 0 ? e_.cost_if_full[c] : e_.cost_if_empty[c];
      const double flip = labels[c.index()] != 0 ? e_.cost_if_empty[c] : e_.cost_if_full[c];
      if (flip < keep) dirty_[i] = 1;
    }
    ForEachTerm(e_, [&](TermRef t) {
      CellId pair[2];
      const auto cells = TermCells(e_, t, pair);
      bool mixed = false;
      for (CellId c : cells) mixed = mixed || labels[c.index()] != labels[cells[0].index()];
      if (mixed) MarkFree(cells, dirty_);
    });
  }

  // ImproveLabels on the mover's free cells and incidence (built once, not once per pass).
  std::size_t Flip(int max_passes, std::vector<std::uint8_t>& labels) const {
    return ImproveLabels(e_, free_, incidence_, max_passes, labels);
  }

  // Marks the free cells sharing a term with a cell whose label differs between `a` and `b`.
  void MarkAroundChanges(const std::vector<std::uint8_t>& a, const std::vector<std::uint8_t>& b) {
    for (std::size_t i = 0; i < free_.size(); ++i) {
      if (a[free_[i].index()] != b[free_[i].index()]) MarkAround(i, dirty_);
    }
  }

  // One sweep over the terms touching a marked cell, in term order; clears the marks. Returns
  // cells changed. With more than one thread the moves are first evaluated in parallel from the
  // labels at the start of the sweep; then, in term order, a move whose cells' local energies no
  // earlier move of the sweep has changed takes its evaluated labelling, any other is evaluated
  // again. Either way each move sees the labels the serial sweep would: the same result.
  std::size_t Sweep(std::vector<std::uint8_t>& labels, const RunContext& ctx) {
    const std::vector<std::uint8_t> marked = std::move(dirty_);
    dirty_.assign(marked.size(), 0);
    const std::vector<Move> moves = MovesTouching(marked);
    std::vector<std::uint32_t> evaluated;
    if (ArenaConcurrency(ctx.num_threads) > 1) evaluated = EvaluateInParallel(moves, labels, ctx);
    std::vector<std::uint8_t> stale(evaluated.empty() ? 0 : free_.size(), 0);
    std::size_t changed = 0;
    for (std::size_t i = 0; i < moves.size(); ++i) {
      const std::span<const std::uint32_t> slots = moves[i].Slots();
      bool current = !evaluated.empty();
      for (std::uint32_t s : slots) current = current && stale[s] == 0;
      const std::uint32_t code = current ? evaluated[i] : walks_.local().BestFlips(slots, labels);
      if (code == 0) continue;
      changed += Apply(slots, code, labels, stale);
    }
    return changed;
  }

 private:
  void MarkFree(std::span<const CellId> cells, std::vector<std::uint8_t>& marks) const {
    for (CellId c : cells) {
      const std::uint32_t s = incidence_.Slot(c);
      if (s != TermIncidence::kNone) marks[s] = 1;
    }
  }

  // Marks the free cell at `slot` and every free cell it shares a term with.
  void MarkAround(std::uint32_t slot, std::vector<std::uint8_t>& marks) const {
    solver::MarkAround(e_, incidence_, slot, marks);
  }

  // The free cells (slots) of one term whose joint labelling a sweep optimises.
  struct Move {
    std::uint32_t slots[kMaxJointCells];
    std::uint8_t size = 0;
    [[nodiscard]] std::span<const std::uint32_t> Slots() const { return {slots, size}; }
  };

  // The terms with 2 to kMaxJointCells free cells, one of them marked, in term order.
  [[nodiscard]] std::vector<Move> MovesTouching(const std::vector<std::uint8_t>& marked) const {
    std::vector<Move> moves;
    ForEachTerm(e_, [&](TermRef t) {
      CellId pair[2];
      Move move;
      bool touched = false;
      for (CellId c : TermCells(e_, t, pair)) {
        const std::uint32_t s = incidence_.Slot(c);
        if (s == TermIncidence::kNone) continue;
        if (move.size == kMaxJointCells) return;
        move.slots[move.size++] = s;
        touched = touched || marked[s] != 0;
      }
      if (move.size >= 2 && touched) moves.push_back(move);
    });
    return moves;
  }

  // The best flips of every move under `labels`, in parallel.
  std::vector<std::uint32_t> EvaluateInParallel(const std::vector<Move>& moves,
                                                const std::vector<std::uint8_t>& labels,
                                                const RunContext& ctx) {
    std::vector<std::uint32_t> codes(moves.size(), 0);
    RunInArena(ctx, [&] {
      tbb::parallel_for(tbb::blocked_range<std::size_t>(0, moves.size(), kMovesPerTask),
                        [&](const tbb::blocked_range<std::size_t>& range) {
                          JointLabelWalk& walk = walks_.local();
                          for (std::size_t i = range.begin(); i != range.end(); ++i) {
                            codes[i] = walk.BestFlips(moves[i].Slots(), labels);
                          }
                        });
    });
    return codes;
  }

  // Flips the cells of `code` and marks the free cells around them for the next sweep and, when
  // `stale` is not empty, as stale: a flipped cell changes the local energy of every free cell
  // it shares a term with (itself included), so their parallel evaluations no longer hold.
  // Returns the cells flipped.
  std::size_t Apply(std::span<const std::uint32_t> slots,
                    std::uint32_t code,
                    std::vector<std::uint8_t>& labels,
                    std::vector<std::uint8_t>& stale) {
    std::size_t changed = 0;
    for (std::size_t j = 0; j < slots.size(); ++j) {
      if (((code >> j) & 1u) == 0) continue;
      labels[CellOf(slots[j]).index()] ^= 1u;
      ++changed;
      MarkAround(slots[j], dirty_);
      if (!stale.empty()) MarkAround(slots[j], stale);
    }
    return changed;
  }

  [[nodiscard]] CellId CellOf(std::uint32_t slot) const { return free_[slot]; }

  const EnergyInput& e_;
  std::vector<CellId> free_;
  TermIncidence incidence_;
  // One walk (and its scratch of two words per term) per thread, kept across sweeps.
  tbb::enumerable_thread_specific<JointLabelWalk> walks_;
  std::vector<std::uint8_t> dirty_;
};

}  // namespace

std::size_t ImproveByGroupMoves(const EnergyInput& energy,
                                int max_passes,
                                const RunContext& ctx,
                                std::vector<std::uint8_t>& labels) {
  LINESURF_ASSERT(labels.size() == energy.NumCells());
  const std::vector<CellId> free = energy.FreeCells();
  if (free.empty() || max_passes <= 0) return 0;
  GroupMover mover(energy, free);
  mover.MarkSurface(labels);
  std::size_t changed = 0;
  for (int pass = 0; pass < max_passes; ++pass) {
    const std::size_t moved = mover.Sweep(labels, ctx);
    const std::vector<std::uint8_t> before = labels;
    const std::size_t flipped = mover.Flip(kFlipPasses, labels);
    if (flipped > 0) mover.MarkAroundChanges(before, labels);
    changed += moved + flipped;
    if (moved + flipped == 0) break;
  }
  return changed;
}

}  // namespace linesurf::solver
