// Generation time of the synthetic families (linesurf_bench_synth). City sizes are arguments.

#include <benchmark/benchmark.h>

#include "tools/gen/synthesize.h"

namespace linesurf::synth {
namespace {

void Generate(benchmark::State& state, const char* family, int size) {
  SynthSpec spec;
  spec.family = family;
  spec.size = size;
  spec.noise_sigma = 0.01;
  spec.outlier_fraction = 0.05;
  std::size_t segments = 0;
  for (auto _ : state) {
    Expected<SyntheticScene> scene = Synthesize(spec);
    if (!scene) {
      state.SkipWithError(scene.error().ToString().c_str());
      return;
    }
    segments = scene->scene.segments.size();
    benchmark::DoNotOptimize(scene->scene.segments.raw().data());
  }
  state.counters["segments"] = static_cast<double>(segments);
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(segments));
}

void BM_Cube(benchmark::State& state) { Generate(state, "cube", 0); }
void BM_House(benchmark::State& state) { Generate(state, "house", 0); }
void BM_Room(benchmark::State& state) { Generate(state, "room", 0); }
void BM_City(benchmark::State& state) {
  Generate(state, "city", static_cast<int>(state.range(0)));
}

BENCHMARK(BM_Cube)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_House)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Room)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_City)->Arg(10)->Arg(100)->Arg(1000)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace linesurf::synth

BENCHMARK_MAIN();
