// The facade's re-solve and cancellation (docs/user/embedding.md, "Measurements"). Run from the
// repository root:
//   LINESURF_SHARED_DIR=../shared build/bin/linesurf_bench_api --benchmark_repetitions=3
//     --benchmark_report_aggregates_only=true
// Inputs: docs/examples/house/lines.json and, when present, the Andalusian data of ../shared.

#include <benchmark/benchmark.h>

#include <atomic>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <optional>
#include <string>

#include "linesurf/linesurf.h"

namespace linesurf {
namespace {

std::optional<SceneData> Read(const std::filesystem::path& path) {
  auto read = ReadScene(path.string());
  if (!read) return std::nullopt;
  return std::move(read->scene);
}

const std::optional<SceneData>& House() {
  static const std::optional<SceneData> house = Read("docs/examples/house/lines.json");
  return house;
}

std::optional<SceneData> Andalusian() {
  const char* shared = std::getenv("LINESURF_SHARED_DIR");
  if (shared == nullptr) return std::nullopt;
  return Read(std::filesystem::path(shared) / "data/andalusian/input_lines_from_residuals.json");
}

ReconstructOptions HouseOptions() {
  ReconstructOptions o;
  o.scene_mode = SceneMode::kExterior;
  return o;
}

/// The whole method on the house (what a Solve is compared with).
void BM_ReconstructHouse(benchmark::State& state) {
  if (!House()) return state.SkipWithError("run from the repository root (house not found)");
  for (auto _ : state) {
    auto r = Reconstruct(House()->View(), HouseOptions());
    if (!r) return state.SkipWithError(r.error().ToString().c_str());
    benchmark::DoNotOptimize(r);
  }
}
BENCHMARK(BM_ReconstructHouse)->Unit(benchmark::kMillisecond);

/// A Solve with new weights on a prepared house (planes and complex reused).
void BM_SolvePreparedHouse(benchmark::State& state) {
  if (!House()) return state.SkipWithError("run from the repository root (house not found)");
  auto prepared = Reconstruction::Prepare(House()->View(), HouseOptions());
  if (!prepared) return state.SkipWithError(prepared.error().ToString().c_str());
  EnergyWeights w;
  for (auto _ : state) {
    w.visibility = w.visibility == 0.1 ? 0.5 : 0.1;
    auto r = prepared->Solve(w);
    if (!r) return state.SkipWithError(r.error().ToString().c_str());
    benchmark::DoNotOptimize(r);
  }
}
BENCHMARK(BM_SolvePreparedHouse)->Unit(benchmark::kMillisecond);

/// Andalusian with its 148 given planes: cancel requested from the progress callback at
/// `range(0)` % of the cell complex (or, with range(0) >= 100, at the first evidence report);
/// the time reported is the latency from the request to the return of Reconstruct.
void BM_CancelLatencyAndalusian(benchmark::State& state) {
  static const std::optional<SceneData> scene = Andalusian();
  if (!scene) return state.SkipWithError("LINESURF_SHARED_DIR/data/andalusian is absent");
  const double at = static_cast<double>(state.range(0)) / 100.0;
  ReconstructOptions options;
  options.plane_source = PlaneSource::kGiven;
  for (auto _ : state) {
    std::atomic<bool> cancel{false};
    std::chrono::steady_clock::time_point requested;
    RunControl control;
    control.on_progress = [&](const Progress& p) {
      const bool due = at < 1.0 ? p.stage == "cell_complex" && p.stage_fraction >= at
                                : p.stage == "evidence";
      if (!cancel && due) {
        requested = std::chrono::steady_clock::now();
        cancel = true;
      }
    };
    control.is_cancelled = [&] { return cancel.load(); };
    auto r = Reconstruct(scene->View(), options, control);
    const auto returned = std::chrono::steady_clock::now();
    if (r || r.error().code != ErrorCode::kCancelled || !cancel) {
      return state.SkipWithError("the run was not cancelled");
    }
    state.SetIterationTime(std::chrono::duration<double>(returned - requested).count());
  }
}
BENCHMARK(BM_CancelLatencyAndalusian)
    ->Arg(30)
    ->Arg(90)
    ->Arg(100)
    ->UseManualTime()
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace linesurf

BENCHMARK_MAIN();
