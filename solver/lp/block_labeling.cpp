#include "solver/lp/block_labeling.h"

#include "engine/core/exception.h"
#include "engine/core/parallel.h"
#include "solver/energy/sub_energy.h"
#include "solver/energy/term_incidence.h"
#include "solver/lp/band_fixing.h"
#include "solver/lp/cell_blocks.h"
#include "solver/lp/group_moves.h"
#include "solver/lp/round_labels.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/partitioner.h>

#include <chrono>
#include <cmath>
#include <limits>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace linesurf::solver {
namespace {

constexpr const char* kStage = "solve_labeling";
// The bound source of a block decided by max-flow alone.
constexpr const char* kCertificate = "pairwise certificate";

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
  std::string backend;
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
    out.backend = "maxflow";
    out.relaxed.assign(labels.begin(), labels.begin() + static_cast<std::ptrdiff_t>(num_chosen));
  } else {
    Expected<LabelingResult> solved = SolveLabeling(sub.energy, inner, serial);
    if (!solved) throw LinesurfException(solved.error());
    LabelingResult& r = *solved;
    labels = std::move(r.labels);
    out.objective = r.labels_objective;
    out.lower_bound = r.lower_bound;
    out.bound_source = r.lower_bound_source;
    out.backend = r.backend;
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
              std::span<const std::uint32_t> block_of_cell,
              const LabelingOptions& options,
              const RunContext& ctx)
      : energy_(energy),
        options_(options),
        ctx_(ctx),
        blocks_(MakeCellBlocks(energy, block_of_cell)),
        free_(energy.FreeCells()),
        incidence_(energy, free_),
        start_(std::chrono::steady_clock::now()) {
    inner_ = options;
    inner_.backend = options.block_backend;
    inner_.time_limit_seconds = options.time_limit_seconds;
  }

  LabelingResult Run() {
    LabelingResult result;
    result.labels.assign(energy_.NumCells(), 0);
    for (std::size_t c = 0; c < energy_.NumCells(); ++c) {
      result.labels[c] = energy_.fixed[CellId(c)] == CellFix::kFull ? 1 : 0;
    }
    result.relaxed.assign(result.labels.begin(), result.labels.end());
    const double fixed_energy = FixedEnergy(energy_, result.labels);

    SolveInteriors(result, fixed_energy);
    RoundedLabels rounded = RoundLabels(energy_, result.relaxed);
    result.fractional_cells = rounded.fractional_cells;
    result.tie_cells = rounded.tie_cells;
    result.rounded_objective = energy_.Evaluate(std::span<const std::uint8_t>(rounded.labels));
    Coordinate(result);
    result.local_search_flips = ImproveLabels(energy_, options_.local_search_passes, result.labels);
    result.group_move_changes =
        ImproveByGroupMoves(energy_, options_.group_move_passes, result.labels);
    result.labels_objective = energy_.Evaluate(std::span<const std::uint8_t>(result.labels));
    result.relaxed_objective = energy_.Evaluate(std::span<const double>(result.relaxed));
    result.lower_bound = std::min(result.lower_bound, result.labels_objective);
    result.blocks = 0;
    for (std::size_t b = 0; b < blocks_.NumBlocks(); ++b) {
      result.blocks += blocks_.cells[BlockId(b)].empty() ? 0 : 1;
    }
    result.block_colours = blocks_.num_colours;
    result.crossing_terms = blocks_.crossing_terms;
    result.backend = "blocks";
    result.status = "optimal";
    result.method =
        "blocks (" + std::to_string(result.blocks) + " blocks, " +
        std::to_string(blocks_.num_colours) + " colours; block solves: " + CountBackends() + "), " +
        std::to_string(result.block_sweeps) + " coordination sweeps with the seams fixed";
    if (options_.local_search_passes > 0) result.method += ", local search";
    if (options_.group_move_passes > 0) result.method += ", group moves";
    result.seconds = Elapsed();
    return result;
  }

 private:
  // Step 1: every block's interior energy at once; their bounds sum to the lower bound.
  void SolveInteriors(LabelingResult& result, double fixed_energy) {
    std::vector<std::uint32_t> list;
    for (std::uint32_t b = 0; b < blocks_.NumBlocks(); ++b) {
      if (!blocks_.cells[BlockId(b)].empty()) list.push_back(b);
    }
    std::vector<BlockOutcome> outcomes(blocks_.NumBlocks());
    ForBlocks(ctx_, list, outcomes, [&](std::uint32_t b) {
      const auto cells = blocks_.cells[BlockId(b)];
      return SolveBlock(InteriorEnergy(energy_, incidence_, cells), cells.size(), inner_, ctx_);
    });
    double bound = fixed_energy;
    for (std::uint32_t b : list) {
      const BlockOutcome& o = outcomes[b];
      bound += o.lower_bound;  // -infinity when one block proves nothing
      Count(result, o);
      const auto cells = blocks_.cells[BlockId(b)];
      for (std::size_t i = 0; i < cells.size(); ++i) {
        result.labels[cells[i].index()] = o.labels[i];
        result.relaxed[cells[i].index()] = o.relaxed[i];
      }
    }
    result.lower_bound = bound;
    Log("interior solves of " + std::to_string(list.size()) + " blocks done");
    result.lower_bound_source = "block split: the blocks' interior bounds (" +
                                CountSources(outcomes) +
                                ") plus the fixed terms, the terms across blocks counted 0";
    CheckTime();
  }

  // Step 2: alternating seam fixing by colour until no block is left to re-solve.
  void Coordinate(LabelingResult& result) {
    std::vector<std::uint8_t> dirty(blocks_.NumBlocks(), 0);
    for (std::size_t b = 0; b < blocks_.NumBlocks(); ++b) {
      dirty[b] = blocks_.cells[BlockId(b)].empty() ? 0 : 1;
    }
    std::vector<BlockOutcome> outcomes(blocks_.NumBlocks());
    for (int sweep = 0; sweep < options_.block_sweeps; ++sweep) {
      bool any = false;
      for (std::uint32_t colour = 0; colour < blocks_.num_colours; ++colour) {
        std::vector<std::uint32_t> list;
        for (std::uint32_t b = 0; b < blocks_.NumBlocks(); ++b) {
          if (dirty[b] != 0 && blocks_.colour[b] == colour) list.push_back(b);
        }
        if (list.empty()) continue;
        any = true;
        const std::vector<std::uint8_t>& labels = result.labels;
        ForBlocks(ctx_, list, outcomes, [&](std::uint32_t b) {
          const auto cells = blocks_.cells[BlockId(b)];
          const SubEnergy sub = RestrictEnergy(energy_, incidence_, cells, labels);
          std::vector<std::uint8_t> local(sub.cells.size());
          for (std::size_t i = 0; i < local.size(); ++i) local[i] = labels[sub.cells[i].index()];
          BlockOutcome o = SolveBlock(sub, cells.size(), inner_, ctx_);
          o.start_objective = sub.energy.Evaluate(std::span<const std::uint8_t>(local));
          return o;
        });
        for (std::uint32_t b : list) {  // blocks of one colour share no term: order is free
          dirty[b] = 0;
          BlockOutcome& o = outcomes[b];
          Count(result, o);
          const double tolerance = kImproveTolerance * (1.0 + std::abs(o.start_objective));
          if (!(o.objective < o.start_objective - tolerance)) continue;
          const auto cells = blocks_.cells[BlockId(b)];
          for (std::size_t i = 0; i < cells.size(); ++i)
            result.labels[cells[i].index()] = o.labels[i];
          ++result.block_improvements;
          for (BlockId m : blocks_.neighbours[BlockId(b)]) dirty[m.index()] = 1;
          o = BlockOutcome{};
        }
        CheckTime();
      }
      if (!any) break;
      ++result.block_sweeps;
      Log("coordination sweep " + std::to_string(sweep + 1) + " done, " +
          std::to_string(result.block_improvements) + " block improvements so far");
    }
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
    ctx_.Log(LogLevel::kInfo, kStage, text.str());
  }

  [[nodiscard]] double Elapsed() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  }

  void CheckTime() const {
    ctx_.ThrowIfCancelled(kStage);
    LINESURF_THROW_IF(
        options_.time_limit_seconds > 0.0 && Elapsed() > options_.time_limit_seconds,
        kSolverFailed,
        kStage,
        "blocks stopped at the time limit of " << options_.time_limit_seconds << " s");
  }

  const EnergyInput& energy_;
  const LabelingOptions& options_;
  const RunContext& ctx_;
  LabelingOptions inner_;
  CellBlocks blocks_;
  std::vector<CellId> free_;
  TermIncidence incidence_;
  std::chrono::steady_clock::time_point start_;
  std::map<std::string, std::size_t> backends_;
};

}  // namespace

LabelingResult SolveInBlocks(const EnergyInput& energy,
                             std::span<const std::uint32_t> block_of_cell,
                             const LabelingOptions& options,
                             const RunContext& ctx) {
  return BlockSolver(energy, block_of_cell, options, ctx).Run();
}

}  // namespace linesurf::solver
