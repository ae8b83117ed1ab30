// Labelling solve per backend on grid-shaped energies with the real term kinds
// (tests/support/random_energy.h: unary textural and viewpoint costs, pairwise visibility and
// area, structural triples, parity groups on every grid edge, boundary cells fixed empty).
//
//   linesurf_bench_solver --benchmark_filter='Solve/clp/20'     one backend, one size
//   BM_CompareWithClp reports, per backend, objective and label differences against Clp.
// Sizes: n^3 cells with n = 10, 14 (small), 20 (8k), 30 (27k), 58 (195k). Each run is one solve (Iterations(1)):
// the solves take seconds to minutes, so repetitions are left to --benchmark_repetitions.
// Local search (10 passes) runs after rounding; rounded_obj is the energy before it.

#include <benchmark/benchmark.h>

#include <string>
#include <vector>

#include <cholmod.h>

#include "solver/energy/build_lp.h"
#include "solver/lp/lp_backend.h"
#include "tests/support/random_energy.h"

namespace linesurf::solver {
namespace {

constexpr SolverBackend kBackends[] = {
    SolverBackend::kClp, SolverBackend::kPdhg, SolverBackend::kClpBarrier, SolverBackend::kMaxflow};

EnergyInput Grid(int n, bool higher_order) {
  testing::GridEnergySpec spec;
  spec.nx = spec.ny = spec.nz = n;
  if (!higher_order) {
    spec.structural_weight = 0.0;
    spec.edge_weight = 0.0;
  }
  return testing::GridEnergy(spec);
}

void Report(benchmark::State& state, const LabelingResult& r) {
  state.counters["lp_columns"] = static_cast<double>(r.lp_columns);
  state.counters["lp_rows"] = static_cast<double>(r.lp_rows);
  state.counters["lp_nonzeros"] = static_cast<double>(r.lp_nonzeros);
  state.counters["relaxed_obj"] = r.relaxed_objective;
  state.counters["labels_obj"] = r.labels_objective;
  state.counters["iterations"] = static_cast<double>(r.iterations);
  state.counters["fractional"] = static_cast<double>(r.fractional_cells);
  state.counters["rounded_obj"] = r.rounded_objective;
}

// state.range(0): grid side n; range(1): backend index; range(2): threads; range(3): 1 = with
// structural and parity terms (maxflow needs 0).
void BM_Solve(benchmark::State& state) {
  const EnergyInput energy = Grid(static_cast<int>(state.range(0)), state.range(3) != 0);
  LabelingOptions options;
  options.backend = kBackends[state.range(1)];
  options.improve.local_search_passes = 10;
  RunContext ctx;
  ctx.num_threads = static_cast<int>(state.range(2));
  LabelingResult last;
  for (auto _ : state) {
    auto result = SolveLabeling(energy, options, ctx);
    if (!result) {
      state.SkipWithError(result.error().ToString().c_str());
      return;
    }
    last = std::move(result).value();
  }
  state.SetLabel(std::string(SolverBackendName(options.backend)) +
                 " cells=" + std::to_string(energy.NumCells()));
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * energy.NumCells()));
  Report(state, last);
}

// Solves with Clp and with backend range(1); reports the relative objective difference of the
// rounded labels and the number of cells labelled differently.
void BM_CompareWithClp(benchmark::State& state) {
  const EnergyInput energy = Grid(static_cast<int>(state.range(0)), state.range(2) != 0);
  LabelingOptions clp_options;
  clp_options.backend = SolverBackend::kClp;
  clp_options.improve.local_search_passes = 10;
  LabelingOptions options;
  options.improve.local_search_passes = 10;
  options.backend = kBackends[state.range(1)];
  RunContext ctx;
  for (auto _ : state) {
    auto reference = SolveLabeling(energy, clp_options, ctx);
    auto other = SolveLabeling(energy, options, ctx);
    if (!reference || !other) {
      state.SkipWithError("solve failed");
      return;
    }
    std::size_t differ = 0;
    for (std::size_t c = 0; c < energy.NumCells(); ++c) {
      differ += reference->labels[c] != other->labels[c] ? 1 : 0;
    }
    state.counters["clp_labels_obj"] = reference->labels_objective;
    state.counters["labels_obj"] = other->labels_objective;
    state.counters["rel_obj_diff"] =
        (other->labels_objective - reference->labels_objective) / reference->labels_objective;
    state.counters["clp_relaxed_obj"] = reference->relaxed_objective;
    state.counters["relaxed_obj"] = other->relaxed_objective;
    state.counters["labels_differ"] = static_cast<double>(differ);
    state.counters["clp_fractional"] = static_cast<double>(reference->fractional_cells);
    state.counters["clp_rounded_obj"] = reference->rounded_objective;
    state.counters["rounded_obj"] = other->rounded_objective;
  }
  state.SetLabel(std::string(SolverBackendName(options.backend)) +
                 " vs clp, cells=" + std::to_string(energy.NumCells()));
}

// Full energies: clp and pdhg at 8k, 27k, 195k cells; pdhg at 1 and 2 threads.
BENCHMARK(BM_Solve)
    ->ArgNames({"n", "backend", "threads", "higher_order"})
    ->Args({10, 0, 1, 1})
    ->Args({14, 0, 1, 1})
    ->Args({10, 1, 1, 1})
    ->Args({14, 1, 1, 1})
    ->Args({20, 0, 1, 1})
    ->Args({30, 0, 1, 1})
    ->Args({58, 0, 1, 1})
    ->Args({20, 1, 1, 1})
    ->Args({30, 1, 1, 1})
    ->Args({58, 1, 1, 1})
    ->Args({20, 1, 2, 1})
    ->Args({30, 1, 2, 1})
    ->Args({58, 1, 2, 1})
    ->Args({10, 2, 1, 1})
    ->Args({14, 2, 1, 1})
    ->Args({20, 2, 1, 1})
    // Pairwise-only energies, where maxflow is exact.
    ->Args({20, 3, 1, 0})
    ->Args({30, 3, 1, 0})
    ->Args({58, 3, 1, 0})
    ->Args({58, 0, 1, 0})
    ->Iterations(1)
    ->Unit(benchmark::kSecond)
    ->UseRealTime();

BENCHMARK(BM_CompareWithClp)
    ->ArgNames({"n", "backend", "higher_order"})
    ->Args({10, 1, 1})
    ->Args({14, 1, 1})
    ->Args({20, 1, 1})
    ->Args({30, 1, 1})
    ->Args({20, 3, 0})
    ->Args({30, 3, 0})
    ->Iterations(1)
    ->Unit(benchmark::kSecond)
    ->UseRealTime();

// What a normal-equations interior point (Clp's barrier with CHOLMOD plugged in as its
// Cholesky) would have to factor: CHOLMOD's symbolic analysis of A A^T for the LP of the grid
// energy, with CHOLMOD's default ordering choice (AMD, then METIS when AMD's fill is poor).
void BM_CholmodAnalyze(benchmark::State& state) {
  const LpModel lp = BuildLpModel(ReduceEnergy(Grid(static_cast<int>(state.range(0)), true)));
  cholmod_common common;
  cholmod_start(&common);
  common.print = 0;
  // A^T in compressed columns is A in compressed rows.
  cholmod_sparse* at = cholmod_allocate_sparse(lp.NumColumns(), lp.NumRows(), lp.NumNonzeros(),
                                               1, 1, 0, CHOLMOD_PATTERN, &common);
  auto* p = static_cast<int*>(at->p);
  auto* i = static_cast<int*>(at->i);
  for (std::size_t r = 0; r <= lp.NumRows(); ++r) p[r] = static_cast<int>(lp.row_offsets[r]);
  for (std::size_t k = 0; k < lp.NumNonzeros(); ++k) i[k] = static_cast<int>(lp.row_columns[k]);
  cholmod_sparse* a = cholmod_transpose(at, 0, &common);
  for (auto _ : state) {
    cholmod_factor* factor = cholmod_analyze(a, &common);  // A unsymmetric: orders A A^T
    benchmark::DoNotOptimize(factor);
    state.counters["nnz_L"] = common.method[common.selected].lnz;
    state.counters["flops_per_factor"] = common.method[common.selected].fl;
    state.counters["ordering"] = common.method[common.selected].ordering;
    cholmod_free_factor(&factor, &common);
  }
  state.counters["rows"] = static_cast<double>(lp.NumRows());
  cholmod_free_sparse(&a, &common);
  cholmod_free_sparse(&at, &common);
  cholmod_finish(&common);
}
BENCHMARK(BM_CholmodAnalyze)
    ->ArgNames({"n"})
    ->Arg(14)
    ->Arg(20)
    ->Arg(30)
    ->Iterations(1)
    ->Unit(benchmark::kSecond)
    ->UseRealTime();

}  // namespace
}  // namespace linesurf::solver

BENCHMARK_MAIN();
