#include "solver/lp/block_labeling.h"

#include "engine/core/exception.h"
#include "engine/core/parallel.h"
#include "solver/energy/sub_energy.h"
#include "solver/energy/term_incidence.h"
#include "solver/lp/band_fixing.h"
#include "solver/lp/cell_blocks.h"
#include "solver/lp/dual_ascent.h"
#include "solver/lp/group_moves.h"
#include "solver/lp/round_labels.h"
#include "solver/lp/window_polish.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/partitioner.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iterator>
#include <limits>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace linesurf::solver {
namespace {

constexpr const char* kBlockLabelingStage = "solve_labeling";
// The bound source of a block decided by max-flow alone.
constexpr const char* kCertificate = "pairwise certificate";
// A pass of the dual ascent that raises the bound by less than this (relative) ends it.
constexpr double kAscentGain = 1e-4;
constexpr const char* kPairwiseBound =
    "pairwise optimum (max-flow of the unary and pairwise terms, the others >= 0)";

// What one solve of a block's sub-energy gives, for its chosen cells (the block's free cells).
struct BlockOutcome {
  bool solved = false;
  std::vector<std::uint8_t> labels;
  std::vector<double> relaxed;
  /// Sub-energy of `labels`, and of the labels it started from (coordination sweeps).
  double objective = 0.0;
  double start_objective = 0.0;
  double lower_bound = 0.0;
  /// kCertificate when no LP was solved, else the inner result's bound source.
  std::string bound_source;
  std::string method;
  std::size_t lp_columns = 0;
  std::int64_t iterations = 0;
};

// Minimises a block's sub-energy: the exact max-flow shortcut, else the inner SolveLabeling.
BlockOutcome SolveBlock(const SubEnergy& sub,
                        std::size_t num_chosen,
                        const LabelingOptions& inner,
                        const RunContext& ctx) {
  RunContext serial;  // one thread per block: the blocks are the parallel grain
  serial.num_threads = 1;
  serial.is_cancelled = [&ctx] { return ctx.ShouldStop(); };
  BlockOutcome out;
  out.solved = true;
  std::vector<std::uint8_t> labels = PairwiseLabels(sub.energy, serial);
  if (HigherOrderEnergy(sub.energy, labels) == 0.0) {
    out.objective = sub.energy.Evaluate(std::span<const std::uint8_t>(labels));
    out.lower_bound = out.objective;
    out.bound_source = kCertificate;
    out.relaxed.assign(labels.begin(), labels.begin() + static_cast<std::ptrdiff_t>(num_chosen));
  } else {
    Expected<LabelingResult> solved = SolveLabeling(sub.energy, inner, serial);
    if (!solved) throw LinesurfException(solved.error());
    LabelingResult& r = *solved;
    labels = std::move(r.labels);
    out.objective = r.labels_objective;
    out.lower_bound = r.lower_bound;
    out.bound_source = r.lower_bound_source;
    out.method = r.method;
    out.lp_columns = r.lp_columns;
    out.iterations = r.iterations;
    out.relaxed.assign(r.relaxed.begin(),
                       r.relaxed.begin() + static_cast<std::ptrdiff_t>(num_chosen));
  }
  labels.resize(num_chosen);
  out.labels = std::move(labels);
  return out;
}

// Runs solve(b) for every listed block in parallel; results by block id.
template <typename Solve>
void ForBlocks(const RunContext& ctx,
               const std::vector<std::uint32_t>& list,
               std::vector<BlockOutcome>& outcomes,
               const Solve& solve) {
  RunInArena(ctx, [&] {
    tbb::parallel_for(
        tbb::blocked_range<std::size_t>(0, list.size(), 1),
        [&](const tbb::blocked_range<std::size_t>& range) {
          for (std::size_t i = range.begin(); i != range.end(); ++i) {
            outcomes[list[i]] = solve(list[i]);
          }
        },
        tbb::simple_partitioner{});
  });
}

// The energy of the cells and terms without a free cell: the same for every labelling.
double FixedEnergy(const EnergyInput& energy, const std::vector<std::uint8_t>& labels) {
  double total = 0.0;
  for (std::size_t c = 0; c < energy.NumCells(); ++c) {
    const CellFix f = energy.fixed[CellId(c)];
    if (f == CellFix::kEmpty) total += energy.cost_if_empty[CellId(c)];
    if (f == CellFix::kFull) total += energy.cost_if_full[CellId(c)];
  }
  const auto all_fixed = [&](std::span<const CellId> cells) {
    for (CellId c : cells) {
      if (energy.fixed[c] == CellFix::kFree) return false;
    }
    return true;
  };
  for (std::size_t p = 0; p < energy.NumPairs(); ++p) {
    const PairTerm& t = energy.pairs[p];
    if (energy.fixed[t.a] != CellFix::kFree && energy.fixed[t.b] != CellFix::kFree) {
      total += TermEnergy(energy, {TermKind::kPair, static_cast<std::uint32_t>(p)}, labels);
    }
  }
  for (std::size_t g = 0; g < energy.NumStructuralGroups(); ++g) {
    if (all_fixed(energy.StructuralGroup(g))) {
      total += TermEnergy(energy, {TermKind::kStructural, static_cast<std::uint32_t>(g)}, labels);
    }
  }
  for (std::size_t g = 0; g < energy.NumParityGroups(); ++g) {
    if (all_fixed(energy.ParityGroup(g))) {
      total += TermEnergy(energy, {TermKind::kParity, static_cast<std::uint32_t>(g)}, labels);
    }
  }
  return total;
}

// "12 lp optimum, 300 pairwise certificate": how the interior bounds were proven.
std::string CountSources(const std::vector<BlockOutcome>& outcomes) {
  std::map<std::string, std::size_t> count;
  for (const BlockOutcome& o : outcomes) {
    if (o.solved) ++count[o.bound_source];
  }
  std::string text;
  for (const auto& [source, n] : count) {
    text += (text.empty() ? "" : ", ") + std::to_string(n) + " " + source;
  }
  return text;
}

class BlockSolver {
 public:
  BlockSolver(const EnergyInput& energy,
              const ReducedEnergy& reduced,
              std::span<const std::uint32_t> block_of_cell,
              const LabelingOptions& options,
              const RunContext& ctx)
      : energy_(energy),
        reduced_(reduced),
        options_(options),
        ctx_(ctx),
        blocks_(MakeCellBlocks(energy, block_of_cell)),
        block_of_cell_(block_of_cell),
        free_(energy.FreeCells()),
        incidence_(energy, free_),
        start_(std::chrono::steady_clock::now()) {
    inner_ = options;
    inner_.backend = options.blocks.backend;
    // The exact windows run once on the whole energy after the sweeps, seeded by the blocks'
    // relaxed values; inside every block solve as well they only added time (Andalusian crop:
    // 888.91 in 27.8 CPU s with them, 886.52 in 26.1 s without, by linesurf_block_labelling_study).
    inner_.improve.window_cells = 0;
  }

  LabelingResult Run() {
    LabelingResult result;
    // Start: the exact minimum of the unary and pairwise terms; its value bounds the optimum.
    result.labels = PairwiseLabels(energy_, ctx_);
    result.relaxed.assign(result.labels.begin(), result.labels.end());
    result.rounded_objective = energy_.Evaluate(std::span<const std::uint8_t>(result.labels));
    result.lower_bound = result.rounded_objective - HigherOrderEnergy(energy_, result.labels);
    result.lower_bound_source = kPairwiseBound;
    Log("max-flow start " + std::to_string(result.rounded_objective) + ", pairwise bound " +
        std::to_string(result.lower_bound));
    if (options_.blocks.split_bound) SplitBound(result);
    if (options_.blocks.bound_passes > 0) AscentBound(result);
    Sweep(result);
    const ImproveOptions& improve = options_.improve;
    result.local_search_flips = ImproveLabels(energy_, improve.local_search_passes, result.labels);
    result.group_move_changes =
        ImproveByGroupMoves(energy_, improve.group_move_passes, ctx_, result.labels);
    Log("local search " + std::to_string(result.local_search_flips) + " flips, group moves " +
        std::to_string(result.group_move_changes) + " changes");
    const WindowPolishStats polished = PolishResultInWindows(energy_, improve, ctx_, result);
    Log("windows: " + std::to_string(polished.windows) + ", " +
        std::to_string(polished.improved_windows) + " improved");
    result.labels_objective = energy_.Evaluate(std::span<const std::uint8_t>(result.labels));
    result.relaxed_objective = energy_.Evaluate(std::span<const double>(result.relaxed));
    for (CellId c : free_) {
      const double x = result.relaxed[c.index()];
      result.fractional_cells += std::abs(x - std::round(x)) > kTieTolerance ? 1 : 0;
    }
    result.lower_bound = std::min(result.lower_bound, result.labels_objective);
    result.blocks = 0;
    for (std::size_t b = 0; b < blocks_.NumBlocks(); ++b) {
      result.blocks += blocks_.cells[BlockId(b)].empty() ? 0 : 1;
    }
    result.crossing_terms = blocks_.crossing_terms;
    result.backend = SolverBackend::kBlocks;
    result.status = "optimal";
    result.method = "blocks (" + std::to_string(result.blocks) +
                    " blocks): max-flow of the pairwise part, then " +
                    std::to_string(result.block_sweeps) + " sweeps of block solves with " +
                    std::to_string(options_.blocks.halo) + "-hop halos (" + CountBackends() + ")";
    AppendImprovementSteps(improve, polished, result.method);
    result.seconds = Elapsed();
    return result;
  }

 private:
  // The bound of the Lagrangian split: every block's interior energy at once; their bounds sum
  // to a lower bound, kept when it beats the pairwise one.
  void SplitBound(LabelingResult& result) {
    std::vector<std::uint32_t> list;
    for (std::uint32_t b = 0; b < blocks_.NumBlocks(); ++b) {
      if (!blocks_.cells[BlockId(b)].empty()) list.push_back(b);
    }
    std::vector<BlockOutcome> outcomes(blocks_.NumBlocks());
    ForBlocks(ctx_, list, outcomes, [&](std::uint32_t b) {
      const auto cells = blocks_.cells[BlockId(b)];
      return SolveBlock(InteriorEnergy(energy_, incidence_, cells), cells.size(), inner_, ctx_);
    });
    double bound = FixedEnergy(energy_, result.labels);
    for (std::uint32_t b : list) {
      bound += outcomes[b].lower_bound;  // -infinity when one block proves nothing
      Count(result, outcomes[b]);
    }
    Log("interior solves of " + std::to_string(list.size()) + " blocks done, split bound " +
        std::to_string(bound) + ", pairwise bound " + std::to_string(result.lower_bound));
    if (bound > result.lower_bound) {
      result.lower_bound = bound;
      result.lower_bound_source = "block split: the blocks' interior bounds (" +
                                  CountSources(outcomes) +
                                  ") plus the fixed terms, the terms across blocks counted 0";
    }
    CheckTime();
  }

  // The Lagrangian bound of the global LP raised by coordinate ascent (dual_ascent.h), kept
  // when it beats the others.
  void AscentBound(LabelingResult& result) {
    const DualAscentResult ascent =
        DualAscentBound(reduced_, options_.blocks.bound_passes, kAscentGain);
    Log("dual ascent bound " + std::to_string(ascent.bound) + " after " +
        std::to_string(ascent.passes) + " passes");
    if (ascent.bound > result.lower_bound) {
      result.lower_bound = ascent.bound;
      result.lower_bound_source =
          "lp dual bound (coordinate ascent, " + std::to_string(ascent.passes) + " passes)";
    }
    CheckTime();
  }

  // The free cells within `blocks.halo` term hops of a block's cells, outside the block.
  [[nodiscard]] std::vector<CellId> Halo(std::uint32_t b) const {
    const auto cells = blocks_.cells[BlockId(b)];
    std::vector<CellId> ring(cells.begin(), cells.end()), halo;
    for (int hop = 0; hop < options_.blocks.halo; ++hop) {
      std::vector<CellId> next;
      for (CellId c : ring) {
        for (const TermRef& t : incidence_.Terms(incidence_.Slot(c))) {
          CellId pair[2];
          for (CellId d : TermCells(energy_, t, pair)) {
            if (energy_.fixed[d] == CellFix::kFree && block_of_cell_[d.index()] != b) {
              next.push_back(d);
            }
          }
        }
      }
      std::sort(next.begin(), next.end());
      next.erase(std::unique(next.begin(), next.end()), next.end());
      std::vector<CellId> grown;
      std::set_union(halo.begin(), halo.end(), next.begin(), next.end(), std::back_inserter(grown));
      halo.swap(grown);
      ring.swap(next);
    }
    return halo;
  }

  // Sweeps of block solves: every dirty block with its halo free, all from the same labels in
  // parallel; then, in block order, each proposal is taken when, given the labels as they are by
  // then, it lowers the energy (its change is re-evaluated, so overlapping proposals never raise
  // the energy). Blocks whose cells or neighbours changed are solved again.
  void Sweep(LabelingResult& result) {
    std::vector<std::uint8_t> dirty(blocks_.NumBlocks(), 0);
    for (std::size_t b = 0; b < blocks_.NumBlocks(); ++b) {
      dirty[b] = blocks_.cells[BlockId(b)].empty() ? 0 : 1;
    }
    std::vector<BlockOutcome> outcomes(blocks_.NumBlocks());
    std::vector<std::vector<CellId>> chosen(blocks_.NumBlocks());
    for (int sweep = 0; sweep < options_.blocks.sweeps; ++sweep) {
      std::vector<std::uint32_t> list;
      for (std::uint32_t b = 0; b < blocks_.NumBlocks(); ++b) {
        if (dirty[b] != 0) list.push_back(b);
      }
      if (list.empty()) break;
      const std::vector<std::uint8_t>& labels = result.labels;
      ForBlocks(ctx_, list, outcomes, [&](std::uint32_t b) {
        const auto cells = blocks_.cells[BlockId(b)];
        std::vector<CellId> all(cells.begin(), cells.end());
        const std::vector<CellId> halo = Halo(b);
        all.insert(all.end(), halo.begin(), halo.end());
        const SubEnergy sub = RestrictEnergy(energy_, incidence_, all, labels);
        BlockOutcome o = SolveBlock(sub, all.size(), inner_, ctx_);
        chosen[b] = std::move(all);
        return o;
      });
      std::vector<CellId> changed;
      std::vector<std::uint8_t> touched(blocks_.NumBlocks(), 0);
      for (std::uint32_t b : list) {
        dirty[b] = 0;
        BlockOutcome& o = outcomes[b];
        Count(result, o);
        const auto cells = blocks_.cells[BlockId(b)];
        for (std::size_t i = 0; i < cells.size(); ++i) {
          result.relaxed[cells[i].index()] = o.relaxed[i];
        }
        changed.clear();
        for (std::size_t i = 0; i < chosen[b].size(); ++i) {
          if (result.labels[chosen[b][i].index()] != o.labels[i]) changed.push_back(chosen[b][i]);
        }
        if (!changed.empty() && Lowers(changed, result.labels)) {
          ++result.block_improvements;
          for (CellId c : changed) touched[block_of_cell_[c.index()]] = 1;
        }
        o = BlockOutcome{};
        chosen[b].clear();
      }
      for (std::uint32_t b = 0; b < blocks_.NumBlocks(); ++b) {
        if (touched[b] == 0) continue;
        dirty[b] = 1;
        for (BlockId m : blocks_.neighbours[BlockId(b)]) dirty[m.index()] = 1;
      }
      CheckTime();
      ++result.block_sweeps;
      Log("sweep " + std::to_string(sweep + 1) + " done, " +
          std::to_string(result.block_improvements) + " proposals taken so far");
    }
  }

  // Flips `changed` in `labels` when that lowers the energy; returns whether it did.
  [[nodiscard]] bool Lowers(std::span<const CellId> changed,
                            std::vector<std::uint8_t>& labels) const {
    std::vector<CellId> sorted(changed.begin(), changed.end());
    std::sort(sorted.begin(), sorted.end());
    const SubEnergy sub = RestrictEnergy(energy_, incidence_, sorted, labels);
    std::vector<std::uint8_t> local(sub.cells.size());
    for (std::size_t i = 0; i < local.size(); ++i) local[i] = labels[sub.cells[i].index()];
    const double before = sub.energy.Evaluate(std::span<const std::uint8_t>(local));
    for (std::size_t i = 0; i < sorted.size(); ++i) local[i] ^= 1u;
    const double after = sub.energy.Evaluate(std::span<const std::uint8_t>(local));
    if (!(after < before - kImproveTolerance * (1.0 + std::abs(before)))) return false;
    for (CellId c : sorted) labels[c.index()] ^= 1u;
    return true;
  }

  void Count(LabelingResult& result, const BlockOutcome& o) {
    ++result.block_solves;
    result.block_certified += o.bound_source == kCertificate ? 1 : 0;
    result.iterations += o.iterations;
    result.block_max_lp_columns = std::max(result.block_max_lp_columns, o.lp_columns);
    ++backends_[o.bound_source == kCertificate ? std::string(kCertificate) : o.method];
  }

  // "300 pairwise certificate, 12 clp lp, rounding, ...": how the block solves went.
  [[nodiscard]] std::string CountBackends() const {
    std::string text;
    for (const auto& [how, n] : backends_) {
      text += (text.empty() ? "" : "; ") + std::to_string(n) + " " + how;
    }
    return text;
  }

  void Log(const std::string& message) const {
    std::ostringstream text;
    text.precision(3);
    text << message << " (" << std::fixed << Elapsed() << " s)";
    ctx_.Log(LogLevel::kInfo, kBlockLabelingStage, text.str());
  }

  [[nodiscard]] double Elapsed() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  }

  void CheckTime() const {
    ctx_.ThrowIfCancelled(kBlockLabelingStage);
    LINESURF_THROW_IF(
        options_.time_limit_seconds > 0.0 && Elapsed() > options_.time_limit_seconds,
        kSolverFailed,
        kBlockLabelingStage,
        "blocks stopped at the time limit of " << options_.time_limit_seconds << " s");
  }

  const EnergyInput& energy_;
  const ReducedEnergy& reduced_;
  const LabelingOptions& options_;
  const RunContext& ctx_;
  LabelingOptions inner_;
  CellBlocks blocks_;
  std::span<const std::uint32_t> block_of_cell_;
  std::vector<CellId> free_;
  TermIncidence incidence_;
  std::chrono::steady_clock::time_point start_;
  std::map<std::string, std::size_t> backends_;
};

}  // namespace

LabelingResult SolveInBlocks(const EnergyInput& energy,
                             const ReducedEnergy& reduced,
                             std::span<const std::uint32_t> block_of_cell,
                             const LabelingOptions& options,
                             const RunContext& ctx) {
  return BlockSolver(energy, reduced, block_of_cell, options, ctx).Run();
}

}  // namespace linesurf::solver
